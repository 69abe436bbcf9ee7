#include <cairn/multibody/urdf_parser.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cairn/common/number_text.h>
#include <cairn/multibody/model_builder.h>
#include <cairn/multibody/urdf_xml_check.h>

namespace cairn::multibody {
namespace {

namespace fs = std::filesystem;

// urdfdom reports why a parse failed only through console_bridge; collect those messages so that the
// exception can carry them instead of them going to stderr.
class MessageCollector : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char* /*filename*/, int /*line*/) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) messages_.push_back(text);
  }
  std::string Joined() const {
    std::string out;
    for (const std::string& m : messages_) out += (out.empty() ? "" : "; ") + m;
    return out;
  }

 private:
  std::vector<std::string> messages_;
};

// console_bridge's handler is process-global.
std::mutex& ConsoleMutex() {
  static std::mutex mutex;
  return mutex;
}

Pose ToPose(const urdf::Pose& pose) {
  const Eigen::Quaterniond q(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
  return Pose(q.normalized().toRotationMatrix(), Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z));
}

// urdfdom's links own their children through shared pointers, so destroying the model of a long chain
// releases one link inside the destructor of the previous: a recursion as deep as the chain. Cutting the
// links apart first lets the link map free them one at a time.
class TreeDismantler {
 public:
  explicit TreeDismantler(urdf::ModelInterface* model) : model_(model) {}
  TreeDismantler(const TreeDismantler&) = delete;
  TreeDismantler& operator=(const TreeDismantler&) = delete;
  ~TreeDismantler() {
    for (auto& entry : model_->links_) {
      if (!entry.second) continue;
      entry.second->child_links.clear();
      entry.second->child_joints.clear();
      entry.second->parent_joint.reset();
    }
  }

 private:
  urdf::ModelInterface* model_;
};

class UrdfReader {
 public:
  UrdfReader(const std::string& source, const std::string& base_directory, const UrdfOptions& options)
      : source_(source), base_directory_(base_directory), options_(options) {}

  [[noreturn]] void Fail(const std::string& what) const { throw std::runtime_error(source_ + ": " + what); }

  Model Read(const std::string& xml) {
    const internal::UrdfXmlCheck check(source_);
    check.CheckSizeAndNesting(xml);
    check.CheckDocument(xml);
    urdf::ModelInterfaceSharedPtr urdf_model;
    {
      std::lock_guard<std::mutex> lock(ConsoleMutex());
      MessageCollector collector;
      console_bridge::useOutputHandler(&collector);
      try {
        urdf_model = urdf::parseURDF(xml);
      } catch (const std::exception& e) {
        console_bridge::restorePreviousOutputHandler();
        Fail(std::string("URDF parse error: ") + e.what());
      }
      console_bridge::restorePreviousOutputHandler();
      if (!urdf_model) {
        const std::string why = collector.Joined();
        Fail("not a valid URDF: " + (why.empty() ? std::string("urdfdom gave no reason") : why) +
             " (check the XML syntax and that every joint's <parent> and <child> links are defined)");
      }
    }
    const TreeDismantler dismantle_at_exit(urdf_model.get());
    ModelBuilder builder(urdf_model->getName());
    const urdf::LinkConstSharedPtr root = urdf_model->getRoot();
    if (!root) Fail("the URDF has no root link");
    if (root->name == "world") {
      if (options_.floating_base) {
        Fail("root link is 'world', so the robot is fixed by the file itself; parse it without floating_base");
      }
      AddGeometry(builder, *root, 0);
      AddTree(builder, *root, 0);
    } else {
      Joint joint;
      joint.name = options_.floating_base ? options_.floating_joint_name : root->name + "_to_world";
      joint.type = options_.floating_base ? JointType::kFloating : JointType::kFixed;
      AddTree(builder, *root, AddLink(builder, *root, 0, joint));
    }
    try {
      return builder.Build();
    } catch (const std::invalid_argument& e) {
      Fail(e.what());
    }
  }

 private:
  std::vector<urdf::LinkSharedPtr> SortedChildren(const urdf::Link& link) const {
    // urdfdom fills child_links in its joint map's (name) order; keep that, it is deterministic.
    return link.child_links;
  }

  // Adds the links below `link` (already body `body`) depth-first, children in SortedChildren order, with an
  // explicit stack: a chain of thousands of links would overflow the call stack if this recursed.
  void AddTree(ModelBuilder& builder, const urdf::Link& link, int body) {
    std::vector<std::pair<const urdf::Link*, int>> pending;
    auto push_children = [&](const urdf::Link& parent, int parent_body) {
      const std::vector<urdf::LinkSharedPtr> children = SortedChildren(parent);
      for (auto it = children.rbegin(); it != children.rend(); ++it) pending.emplace_back(it->get(), parent_body);
    };
    push_children(link, body);
    while (!pending.empty()) {
      const auto [child, parent_body] = pending.back();
      pending.pop_back();
      push_children(*child, AddJointAndLink(builder, *child, parent_body));
    }
  }

  // Adds `link` with its parent joint below body `parent_body`; returns its body index.
  int AddJointAndLink(ModelBuilder& builder, const urdf::Link& link, int parent_body) {
    const urdf::JointSharedPtr& uj = link.parent_joint;
    if (!uj) Fail("link '" + link.name + "' has no parent joint");
    Joint joint;
    joint.name = uj->name;
    joint.X_PJ = ToPose(uj->parent_to_joint_origin_transform);
    joint.axis = Eigen::Vector3d(uj->axis.x, uj->axis.y, uj->axis.z);
    if (uj->mimic) {
      Fail("joint '" + uj->name + "' mimics joint '" + uj->mimic->joint_name +
           "'; mimic joints are not supported: remove its <mimic> element and couple the joints in the controller");
    }
    switch (uj->type) {
      case urdf::Joint::REVOLUTE:
        joint.type = JointType::kRevolute;
        break;
      case urdf::Joint::CONTINUOUS:
        joint.type = JointType::kRevolute;
        joint.continuous = true;
        break;
      case urdf::Joint::PRISMATIC:
        joint.type = JointType::kPrismatic;
        break;
      case urdf::Joint::FIXED:
        joint.type = JointType::kFixed;
        break;
      case urdf::Joint::FLOATING:
        joint.type = JointType::kFloating;
        break;
      default:
        Fail("joint '" + uj->name +
             "' has an unsupported type (planar or unknown); use fixed, revolute, "
             "continuous, prismatic or floating");
    }
    if (uj->limits && (joint.type == JointType::kRevolute || joint.type == JointType::kPrismatic)) {
      if (!joint.continuous) {
        joint.lower_limit = uj->limits->lower;
        joint.upper_limit = uj->limits->upper;
      }
      // URDF writes 0 for "not given"; a negative value was refused by the XML check (and would be by the
      // builder).
      if (uj->limits->velocity != 0.0) joint.velocity_limit = uj->limits->velocity;
      if (uj->limits->effort != 0.0) joint.effort_limit = uj->limits->effort;
    }
    return AddLink(builder, link, parent_body, joint);
  }

  int AddLink(ModelBuilder& builder, const urdf::Link& link, int parent_body, const Joint& joint) {
    Body body;
    body.name = link.name;
    if (link.inertial) {
      const urdf::Inertial& in = *link.inertial;
      body.has_inertial = true;
      if (!(in.mass >= 0.0) || !std::isfinite(in.mass)) {
        Fail("link '" + link.name + "': <mass value=\"" + FormatShort(in.mass) +
             "\"> is negative or not finite; give a mass >= 0 in kilograms");
      }
      Eigen::Matrix3d I;
      I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
      const Pose X_BI = ToPose(in.origin);
      I = X_BI.rotation() * I * X_BI.rotation().transpose();
      body.inertia = SpatialInertia::FromMassComInertia(in.mass, X_BI.translation(), I);
    }
    int index = 0;
    try {
      index = builder.AddBody(parent_body, body, joint);
    } catch (const std::invalid_argument& e) {
      Fail(std::string(e.what()) + " (link '" + link.name + "', joint '" + joint.name + "')");
    }
    AddGeometry(builder, link, index);
    return index;
  }

  Geometry ToGeometry(const urdf::Link& link, const urdf::GeometrySharedPtr& geometry, const urdf::Pose& origin,
                      const std::string& name, const char* kind) {
    Geometry g;
    g.name = name;
    g.X_BG = ToPose(origin);
    if (!geometry) Fail("link '" + link.name + "': " + kind + " '" + name + "' has no <geometry>");
    switch (geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& box = static_cast<const urdf::Box&>(*geometry);
        g.type = GeometryType::kBox;
        g.size = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
        break;
      }
      case urdf::Geometry::SPHERE:
        g.type = GeometryType::kSphere;
        g.radius = static_cast<const urdf::Sphere&>(*geometry).radius;
        break;
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(*geometry);
        g.type = name.rfind("capsule", 0) == 0 ? GeometryType::kCapsule : GeometryType::kCylinder;
        g.radius = cylinder.radius;
        g.length = cylinder.length;
        break;
      }
      case urdf::Geometry::MESH: {
        const auto& mesh = static_cast<const urdf::Mesh&>(*geometry);
        g.type = GeometryType::kMesh;
        g.scale = Eigen::Vector3d(mesh.scale.x, mesh.scale.y, mesh.scale.z);
        g.mesh_path = ResolveMesh(link, mesh.filename, kind);
        break;
      }
    }
    return g;
  }

  std::string ResolveMesh(const urdf::Link& link, const std::string& uri, const char* kind) {
    std::string path;
    const std::string prefix = "package://";
    try {
      if (uri.compare(0, prefix.size(), prefix) == 0) {
        const std::string rest = uri.substr(prefix.size());
        const std::string package = rest.substr(0, rest.find('/'));
        if (!options_.packages.Contains(package)) {
          // The ROS layout: an enclosing folder named after the package, with a package.xml.
          for (fs::path dir = fs::absolute(base_directory_); !dir.empty(); dir = dir.parent_path()) {
            if (dir.filename() == package && fs::exists(dir / "package.xml")) {
              options_.packages.Add(package, dir.string());
              break;
            }
            if (dir == dir.parent_path()) break;
          }
        }
      }
      path = options_.packages.ResolveUri(uri, base_directory_);
    } catch (const std::exception& e) {
      Fail("link '" + link.name + "': " + kind + " mesh '" + uri + "': " + e.what());
    }
    if (options_.check_mesh_files && !fs::is_regular_file(path)) {
      Fail("link '" + link.name + "': " + kind + " mesh '" + uri + "' resolves to '" + path +
           "', which does not exist; fix the file name or the package mapping");
    }
    return path;
  }

  void AddGeometry(ModelBuilder& builder, const urdf::Link& link, int body) {
    for (std::size_t k = 0; k < link.collision_array.size(); ++k) {
      const urdf::Collision& c = *link.collision_array[k];
      const std::string name = c.name.empty() ? link.name + "_collision_" + std::to_string(k) : c.name;
      try {
        builder.AddCollisionGeometry(body, ToGeometry(link, c.geometry, c.origin, name, "collision"));
      } catch (const std::invalid_argument& e) {
        Fail(e.what());
      }
    }
    for (std::size_t k = 0; k < link.visual_array.size(); ++k) {
      const urdf::Visual& v = *link.visual_array[k];
      const std::string name = v.name.empty() ? link.name + "_visual_" + std::to_string(k) : v.name;
      try {
        builder.AddVisualGeometry(body, ToGeometry(link, v.geometry, v.origin, name, "visual"));
      } catch (const std::invalid_argument& e) {
        Fail(e.what());
      }
    }
  }

  std::string source_;
  std::string base_directory_;
  UrdfOptions options_;
};

}  // namespace

Model ParseUrdfFile(const std::string& path, const UrdfOptions& options) {
  std::error_code error;
  if (fs::is_directory(path, error)) {
    throw std::runtime_error(path + ": is a directory, expected a URDF file; give the path of the .urdf file in it");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::runtime_error(path + ": cannot open the URDF file; check the path (relative paths are relative to '" +
                             fs::current_path().string() + "')");
  }
  // Read at most one byte more than the limit, so that a huge file or an endless one (a device, a pipe) is
  // refused without reading it all.
  std::string text;
  char buffer[1 << 16];
  while (in && text.size() <= kMaxUrdfBytes) {
    in.read(buffer, sizeof(buffer));
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw std::runtime_error(path + ": reading the URDF file failed");
  if (text.size() > kMaxUrdfBytes) {
    throw std::runtime_error(path + ": the file is larger than " + std::to_string(kMaxUrdfBytes) +
                             " bytes (64 MiB, kMaxUrdfBytes), the most a URDF may have; check that this is the URDF file");
  }
  const std::string directory = fs::absolute(fs::path(path)).parent_path().string();
  return ParseUrdfString(text, directory, options, path);
}

Model ParseUrdfString(const std::string& xml, const std::string& base_directory, const UrdfOptions& options,
                      const std::string& source_name) {
  UrdfReader reader(source_name, base_directory, options);
  return reader.Read(xml);
}

}  // namespace cairn::multibody
