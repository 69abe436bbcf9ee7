#include <cairn/multibody/model_builder.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <Eigen/Eigenvalues>

#include <cairn/common/cairn_assert.h>
#include <cairn/common/number_text.h>
#include <cairn/common/text_suggestions.h>

namespace cairn::multibody {
namespace {

std::string Format(const Eigen::Vector3d& v) {
  return "(" + FormatShort(v.x()) + " " + FormatShort(v.y()) + " " + FormatShort(v.z()) + ")";
}

void CheckInertia(const Body& body) {
  const double mass = body.inertia.mass();
  if (!(mass >= 0.0) || !std::isfinite(mass)) {
    throw std::invalid_argument("body '" + body.name + "': mass " + FormatShort(mass) +
                                " is negative or not finite; give a finite mass >= 0 (0 for a massless frame link)");
  }
  const Eigen::Matrix3d I = body.inertia.InertiaAboutCom();
  if (!I.allFinite() || !body.inertia.first_moment().allFinite()) {
    throw std::invalid_argument("body '" + body.name +
                                "': centre of mass or inertia is not finite; give finite <origin> and <inertia>");
  }
  if ((I - I.transpose()).cwiseAbs().maxCoeff() > 1e-12 * (1.0 + I.cwiseAbs().maxCoeff())) {
    throw std::invalid_argument("body '" + body.name + "': rotational inertia is not symmetric");
  }
  // Ascending principal moments.
  const Eigen::Vector3d eig = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues();
  const double scale = std::max(1.0, eig.cwiseAbs().maxCoeff());
  const bool ok = mass > 0.0 ? eig.minCoeff() > 0.0 : eig.minCoeff() >= -1e-12 * scale;
  if (!ok) {
    throw std::invalid_argument("body '" + body.name + "': rotational inertia about the centre of mass is not positive " +
                                (mass > 0.0 ? "definite" : "semi-definite") + " (principal moments " + Format(eig) +
                                ", mass " + FormatShort(mass) +
                                "); give ixx, iyy, izz > 0 with |ixy|, |ixz|, |iyz| small enough (e.g. those of a box "
                                "of that mass)");
  }
  // No rigid body has one principal moment above the sum of the other two (each is a sum of two of the three
  // second moments of its mass distribution). The slack allows for moments rounded to a few digits in a file.
  const double slack = kInertiaTriangleTolerance * eig.maxCoeff();
  if (eig[0] + eig[1] < eig[2] - slack) {
    throw std::invalid_argument("body '" + body.name + "': principal moments of inertia " + Format(eig) +
                                " violate the triangle inequality (" + FormatShort(eig[0]) + " + " +
                                FormatShort(eig[1]) + " < " + FormatShort(eig[2]) +
                                "), which no rigid body does; check ixx, iyy, izz and the products of inertia "
                                "(each moment must be at most the sum of the other two)");
  }
}

void CheckGeometry(const std::string& body, const Geometry& g) {
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("body '" + body + "', " + GeometryTypeName(g.type) + " '" + g.name + "': " + what);
  };
  switch (g.type) {
    case GeometryType::kBox:
      if (!(g.size.minCoeff() > 0.0) || !g.size.allFinite()) fail("box size " + Format(g.size) + " must be > 0");
      break;
    case GeometryType::kSphere:
      if (!(g.radius > 0.0) || !std::isfinite(g.radius)) fail("radius " + FormatShort(g.radius) + " must be > 0");
      break;
    case GeometryType::kCylinder:
    case GeometryType::kCapsule:
      if (!(g.radius > 0.0) || !std::isfinite(g.radius)) fail("radius " + FormatShort(g.radius) + " must be > 0");
      if (!(g.length >= 0.0) || !std::isfinite(g.length)) fail("length " + FormatShort(g.length) + " must be >= 0");
      break;
    case GeometryType::kMesh:
      if (g.mesh_path.empty()) fail("mesh has no file name; set <mesh filename=...>");
      if (!g.scale.allFinite()) fail("mesh scale " + Format(g.scale) + " must be finite");
      break;
  }
}

}  // namespace

ModelBuilder::ModelBuilder(std::string model_name) {
  model_.name_ = std::move(model_name);
  Body world;
  world.name = "world";
  model_.bodies_.push_back(world);
  Joint universe;
  universe.name = "universe";
  universe.type = JointType::kFixed;
  universe.parent = -1;
  model_.joints_.push_back(universe);
  body_names_.insert(world.name);
  joint_names_.insert(universe.name);
}

void ModelBuilder::CheckBodyIndex(int body, const char* what) const {
  if (body < 0 || body >= num_bodies()) {
    throw std::invalid_argument(std::string(what) + ": body index " + std::to_string(body) +
                                " is out of range; the builder has bodies 0.." + std::to_string(num_bodies() - 1));
  }
}

int ModelBuilder::GetBodyIndex(const std::string& name) const {
  for (int i = 0; i < num_bodies(); ++i) {
    if (model_.bodies_[static_cast<std::size_t>(i)].name == name) return i;
  }
  std::vector<std::string> names;
  for (const Body& b : model_.bodies_) names.push_back(b.name);
  throw std::invalid_argument("unknown body '" + name + "'; did you mean " + QuotedList(ClosestNames(name, names)) +
                              "?");
}

int ModelBuilder::AddBody(int parent, Body body, Joint joint) {
  CheckBodyIndex(parent, ("AddBody('" + body.name + "')").c_str());
  if (num_bodies() > kMaxModelBodies) {
    throw std::invalid_argument("AddBody('" + body.name + "'): the model already has " +
                                std::to_string(kMaxModelBodies) + " bodies besides the world, the most a model may have (kMaxModelBodies)");
  }
  if (body.name.empty()) throw std::invalid_argument("AddBody: the body needs a name");
  if (joint.name.empty()) throw std::invalid_argument("AddBody('" + body.name + "'): its joint needs a name");
  if (body_names_.count(body.name) > 0) {
    throw std::invalid_argument("body name '" + body.name + "' is used twice; body names must be unique");
  }
  if (joint_names_.count(joint.name) > 0) {
    throw std::invalid_argument("joint name '" + joint.name + "' is used twice; joint names must be unique");
  }
  CheckInertia(body);
  for (const Geometry& g : body.collisions) CheckGeometry(body.name, g);
  for (const Geometry& g : body.visuals) CheckGeometry(body.name, g);
  if (!joint.X_PJ.rotation().allFinite() || !joint.X_PJ.translation().allFinite()) {
    throw std::invalid_argument("joint '" + joint.name + "': origin is not finite");
  }
  joint.parent = parent;
  switch (joint.type) {
    case JointType::kFixed:
      joint.nq = joint.nv = 0;
      break;
    case JointType::kRevolute:
    case JointType::kPrismatic: {
      const double norm = joint.axis.norm();
      if (!(norm > 1e-12) || !std::isfinite(norm)) {
        throw std::invalid_argument("joint '" + joint.name + "': axis " + Format(joint.axis) +
                                    " has zero (or non-finite) length; give a unit axis such as (0 0 1)");
      }
      joint.axis /= norm;
      joint.nq = joint.nv = 1;
      joint.axis_index = -1;
      joint.axis_sign = 1.0;
      for (int k = 0; k < 3; ++k) {
        if (std::abs(joint.axis[k]) == 1.0) {
          joint.axis_index = k;
          joint.axis_sign = joint.axis[k];
        }
      }
      if (std::isnan(joint.lower_limit) || std::isnan(joint.upper_limit)) {
        throw std::invalid_argument("joint '" + joint.name + "': position limits [" + FormatShort(joint.lower_limit) +
                                    ", " + FormatShort(joint.upper_limit) +
                                    "] must be numbers (use -infinity and infinity for none)");
      }
      if (joint.lower_limit > joint.upper_limit) {
        throw std::invalid_argument("joint '" + joint.name + "': lower limit " + FormatShort(joint.lower_limit) +
                                    " exceeds upper limit " + FormatShort(joint.upper_limit) + "; swap them");
      }
      if (!(joint.velocity_limit >= 0.0) || !(joint.effort_limit >= 0.0)) {
        throw std::invalid_argument("joint '" + joint.name + "': velocity limit " + FormatShort(joint.velocity_limit) +
                                    " and effort limit " + FormatShort(joint.effort_limit) +
                                    " must be >= 0 (use infinity for none)");
      }
      break;
    }
    case JointType::kFloating:
      joint.nq = 7;
      joint.nv = 6;
      joint.lower_limit = -std::numeric_limits<double>::infinity();
      joint.upper_limit = std::numeric_limits<double>::infinity();
      break;
  }
  joint.origin_rotation_is_identity = joint.X_PJ.rotation() == Eigen::Matrix3d::Identity();
  joint.idx_q = model_.nq_;
  joint.idx_v = model_.nv_;
  model_.nq_ += joint.nq;
  model_.nv_ += joint.nv;
  body_names_.insert(body.name);
  joint_names_.insert(joint.name);
  model_.bodies_.push_back(std::move(body));
  model_.joints_.push_back(std::move(joint));
  return num_bodies() - 1;
}

void ModelBuilder::AddCollisionGeometry(int body, const Geometry& geometry) {
  CheckBodyIndex(body, "AddCollisionGeometry");
  CheckGeometry(model_.bodies_[static_cast<std::size_t>(body)].name, geometry);
  model_.bodies_[static_cast<std::size_t>(body)].collisions.push_back(geometry);
}

void ModelBuilder::AddVisualGeometry(int body, const Geometry& geometry) {
  CheckBodyIndex(body, "AddVisualGeometry");
  CheckGeometry(model_.bodies_[static_cast<std::size_t>(body)].name, geometry);
  model_.bodies_[static_cast<std::size_t>(body)].visuals.push_back(geometry);
}

void ModelBuilder::AddFrame(const std::string& name, int body, const Pose& X_BF) {
  CheckBodyIndex(body, ("AddFrame('" + name + "')").c_str());
  if (name.empty()) throw std::invalid_argument("AddFrame: the frame needs a name");
  for (const Frame& f : extra_frames_) {
    if (f.name == name)
      throw std::invalid_argument("frame name '" + name + "' is used twice; frame names must be unique");
  }
  Frame frame;
  frame.name = name;
  frame.body = body;
  frame.X_BF = X_BF;
  extra_frames_.push_back(frame);
}

void ModelBuilder::SetGravity(const Eigen::Vector3d& gravity) {
  if (!gravity.allFinite()) throw std::invalid_argument("SetGravity: gravity must be finite, e.g. (0, 0, -9.81)");
  model_.gravity_ = gravity;
}

Model ModelBuilder::Build() {
  Model& m = model_;
  const std::size_t n = m.bodies_.size();
  m.frames_.clear();
  m.body_index_.clear();
  m.joint_index_.clear();
  m.frame_index_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    Frame frame;
    frame.name = m.bodies_[i].name;
    frame.body = static_cast<int>(i);
    m.frames_.push_back(frame);
    m.body_index_[m.bodies_[i].name] = static_cast<int>(i);
    if (i > 0) m.joint_index_[m.joints_[i].name] = static_cast<int>(i);
  }
  for (const Frame& f : extra_frames_) {
    if (m.body_index_.count(f.name) > 0) {
      throw std::invalid_argument("frame name '" + f.name + "' is also a body name; frame names must be unique");
    }
    m.frames_.push_back(f);
  }
  for (std::size_t i = 0; i < m.frames_.size(); ++i) m.frame_index_[m.frames_[i].name] = static_cast<int>(i);

  const double inf = std::numeric_limits<double>::infinity();
  m.lower_position_limits_ = Eigen::VectorXd::Constant(m.nq_, -inf);
  m.upper_position_limits_ = Eigen::VectorXd::Constant(m.nq_, inf);
  m.velocity_limits_ = Eigen::VectorXd::Constant(m.nv_, inf);
  m.effort_limits_ = Eigen::VectorXd::Constant(m.nv_, inf);
  m.velocity_joint_.assign(static_cast<std::size_t>(m.nv_), 0);
  m.velocity_parent_.assign(static_cast<std::size_t>(m.nv_), -1);
  // Last velocity index of each body's nearest moving ancestor-or-self, for the dof-level parent array.
  std::vector<int> last_velocity(n, -1);
  m.total_mass_ = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    const Joint& j = m.joints_[i];
    m.total_mass_ += m.bodies_[i].inertia.mass();
    last_velocity[i] = last_velocity[static_cast<std::size_t>(j.parent)];
    for (int k = 0; k < j.nv; ++k) {
      m.velocity_parent_[static_cast<std::size_t>(j.idx_v + k)] = last_velocity[i];
      last_velocity[i] = j.idx_v + k;
      m.velocity_joint_[static_cast<std::size_t>(j.idx_v + k)] = static_cast<int>(i);
      m.velocity_limits_[j.idx_v + k] = j.velocity_limit;
      m.effort_limits_[j.idx_v + k] = j.effort_limit;
    }
    if (j.type == JointType::kRevolute || j.type == JointType::kPrismatic) {
      m.lower_position_limits_[j.idx_q] = j.lower_limit;
      m.upper_position_limits_[j.idx_q] = j.upper_limit;
    } else if (j.type == JointType::kFloating) {
      m.lower_position_limits_.segment<4>(j.idx_q + 3).setConstant(-1.0);
      m.upper_position_limits_.segment<4>(j.idx_q + 3).setConstant(1.0);
    }
  }
  // The algorithms' single-sweep recursions rely on these orderings.
  for (std::size_t i = 1; i < n; ++i)
    CAIRN_CHECK(m.joints_[i].parent >= 0 && m.joints_[i].parent < static_cast<int>(i));
  for (int iv = 0; iv < m.nv_; ++iv) CAIRN_CHECK(m.velocity_parent_[static_cast<std::size_t>(iv)] < iv);
  Model out = std::move(model_);
  model_ = Model();
  extra_frames_.clear();
  body_names_.clear();
  joint_names_.clear();
  return out;
}

}  // namespace cairn::multibody
