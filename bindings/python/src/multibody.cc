// cairn.multibody: Model (from URDF), Data, the algorithms and the collision world.
//
// Algorithms that return a buffer of Data (data.M, data.tau, ...) give a read-only numpy view of it (no copy) that
// keeps the Data alive; the next algorithm call on that Data overwrites what the view shows, as in C++.

#include <limits>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cairn/common/number_text.h"
#include "cairn/multibody/body.h"
#include "cairn/multibody/center_of_mass.h"
#include "cairn/multibody/collision_world.h"
#include "cairn/multibody/configuration.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/dynamics.h"
#include "cairn/multibody/frame.h"
#include "cairn/multibody/geometry.h"
#include "cairn/multibody/gravity_torques.h"
#include "cairn/multibody/jacobians.h"
#include "cairn/multibody/joint.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/model.h"
#include "cairn/multibody/model_builder.h"
#include "cairn/multibody/package_map.h"
#include "cairn/multibody/pose.h"
#include "cairn/multibody/shape_distance.h"
#include "cairn/multibody/spatial_inertia.h"
#include "cairn/multibody/urdf_parser.h"
#include "numpy_support.h"
#include "system_support.h"

namespace cairn::python {

using namespace cairn::multibody;
using VectorRef = Eigen::Ref<const Eigen::VectorXd>;

namespace {

Eigen::Matrix4d PoseMatrix(const Pose& pose) { return pose.ToIsometry().matrix(); }

Pose PoseFromMatrix(const Eigen::Matrix4d& m) {
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  if (!(m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).isZero(1e-12) ||
      !((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-6)) {
    throw py::value_error("Pose: a 4x4 matrix must be a rigid transform (last row [0, 0, 0, 1], orthonormal rotation)");
  }
  return Pose(r, m.topRightCorner<3, 1>());
}

// Frame queries read data's per-body arrays: they must be the model's.
void CheckData(const Model& model, const Data& data, const char* caller) { CheckSizes(model, data, caller, model.nq()); }

int FrameIndex(const Model& model, py::handle frame) {
  if (py::isinstance<py::str>(frame)) return model.GetFrameIndex(frame.cast<std::string>());
  const int index = frame.cast<int>();
  if (index < 0 || index >= model.num_frames()) {
    throw py::index_error("frame " + cairn::FormatShort(index) + " is out of range [0, " +
                          cairn::FormatShort(model.num_frames()) + ")");
  }
  return index;
}

template <typename Derived>
py::array DataView(const Eigen::PlainObjectBase<Derived>& buffer, py::handle data_object) {
  return EigenView(buffer, data_object, false);
}

py::list PoseList(const std::vector<Pose>& poses) {
  py::list out;
  for (const Pose& pose : poses) out.append(pose);
  return out;
}

// Pickling a model re-reads its URDF: the state is the file and the options it was parsed with.
py::tuple ModelState(py::object self) {
  py::object source = py::none();
  PyObject** dict = _PyObject_GetDictPtr(self.ptr());
  if (dict != nullptr && *dict != nullptr) {
    PyObject* found = PyDict_GetItemString(*dict, "_cairn_urdf_source");
    if (found != nullptr) source = py::reinterpret_borrow<py::object>(found);
  }
  if (source.is_none()) {
    throw py::type_error("Model '" + self.cast<const Model&>().name() +
                         "' cannot be pickled: only models read by ParseUrdfFile are (pickling stores the file path "
                         "and re-reads it)");
  }
  return py::make_tuple(source);
}

py::tuple UrdfSource(const std::string& path, const UrdfOptions& options) {
  return py::make_tuple(path, options.floating_base, options.floating_joint_name, options.check_mesh_files,
                        options.packages.packages(), options.packages.search_paths());
}

py::object ParseFile(const std::string& path, const UrdfOptions& options) {
  std::optional<Model> model;
  {
    py::gil_scoped_release release;
    model.emplace(ParseUrdfFile(path, options));
  }
  py::object result = py::cast(std::move(*model));
  SetInstanceAttribute(result, "_cairn_urdf_source", UrdfSource(path, options));
  return result;
}

std::pair<Model, py::dict> ModelFromState(const py::tuple& state) {
  const py::tuple source = state[0].cast<py::tuple>();
  UrdfOptions options;
  const auto path = source[0].cast<std::string>();
  options.floating_base = source[1].cast<bool>();
  options.floating_joint_name = source[2].cast<std::string>();
  options.check_mesh_files = source[3].cast<bool>();
  for (const auto& [name, folder] : source[4].cast<std::map<std::string, std::string>>()) options.packages.Add(name, folder);
  for (const auto& folder : source[5].cast<std::vector<std::string>>()) options.packages.AddSearchPath(folder);
  py::dict dict;
  dict["_cairn_urdf_source"] = source;
  return {ParseUrdfFile(path, options), dict};
}

}  // namespace

void DefineMultibody(py::module_ m) {
  py::class_<Pose>(m, "Pose",
                   "A rigid transform X_AB: rotation R_AB and translation p_AB (picklable). Compose with *, map "
                   "points with pose * p.")
      .def(py::init<>(), "The identity.")
      .def(py::init<const Eigen::Matrix3d&, const Eigen::Vector3d&>(), py::arg("rotation"), py::arg("translation"),
           "From a rotation (assumed orthonormal) and a translation.")
      .def_static("FromMatrix", &PoseFromMatrix, py::arg("matrix"),
                  "From a 4x4 homogeneous transform; ValueError if it is not rigid.")
      .def("rotation", [](const Pose& p) { return Eigen::Matrix3d(p.rotation()); }, "Rotation R_AB.")
      .def("translation", [](const Pose& p) { return Eigen::Vector3d(p.translation()); }, "Translation p_AB.")
      .def("matrix", &PoseMatrix, "The 4x4 homogeneous transform.")
      .def("__mul__", [](const Pose& a, const Pose& b) { return a * b; }, py::is_operator(), "Composition.")
      .def("__mul__", [](const Pose& a, const Eigen::Vector3d& p) { return Eigen::Vector3d(a * p); },
           py::is_operator(), "Maps a point p_B to p_A.")
      .def("Inverse", &Pose::Inverse, "The inverse X_BA.")
      .def("ActMotion", &Pose::ActMotion, py::arg("m_B"), "Re-expresses a motion [w; v] given in B in A.")
      .def("ActForce", &Pose::ActForce, py::arg("f_B"), "Re-expresses a force [n; f] given in B in A.")
      .def("IsApprox", &Pose::IsApprox, py::arg("other"), py::arg("tolerance"), "Max-abs comparison.")
      .def(py::pickle([](const Pose& p) { return py::make_tuple(Eigen::Matrix3d(p.rotation()), Eigen::Vector3d(p.translation())); },
                      [](const py::tuple& t) { return Pose(t[0].cast<Eigen::Matrix3d>(), t[1].cast<Eigen::Vector3d>()); }),
           "Pickles rotation and translation.")
      .def("__repr__", [](const Pose& p) {
        return "Pose(translation=" + std::string(py::repr(py::cast(Eigen::Vector3d(p.translation())))) + ")";
      }, "Pose(translation=...).");

  py::class_<SpatialInertia>(m, "SpatialInertia", "Mass, first moment and rotational inertia about a frame's origin.")
      .def(py::init<>(), "Zero.")
      .def_static("FromMassComInertia", &SpatialInertia::FromMassComInertia, py::arg("mass"), py::arg("com"),
                  py::arg("inertia_com"), "From mass, centre of mass and inertia about the centre of mass.")
      .def("mass", &SpatialInertia::mass, "Mass.")
      .def("first_moment", [](const SpatialInertia& s) { return Eigen::Vector3d(s.first_moment()); }, "m c.")
      .def("inertia_origin", [](const SpatialInertia& s) { return Eigen::Matrix3d(s.inertia_origin()); },
           "Rotational inertia about the origin.")
      .def("com", &SpatialInertia::com, "Centre of mass (origin if massless).")
      .def("InertiaAboutCom", &SpatialInertia::InertiaAboutCom, "Rotational inertia about the centre of mass.")
      .def("Matrix", &SpatialInertia::Matrix, "The 6x6 matrix (angular rows first).")
      .def("Transformed", &SpatialInertia::Transformed, py::arg("X_AB"), "This inertia (in B) expressed in A.");

  py::enum_<JointType>(m, "JointType", "Joint kinds.")
      .value("kFixed", JointType::kFixed, "nq = nv = 0.")
      .value("kRevolute", JointType::kRevolute, "Rotation about the axis.")
      .value("kPrismatic", JointType::kPrismatic, "Translation along the axis.")
      .value("kFloating", JointType::kFloating, "nq = 7 ([x, y, z, qw, qx, qy, qz]), nv = 6.");
  py::enum_<GeometryType>(m, "GeometryType", "Shape kinds.")
      .value("kBox", GeometryType::kBox, "Full side lengths in `size`.")
      .value("kSphere", GeometryType::kSphere, "`radius`.")
      .value("kCylinder", GeometryType::kCylinder, "`radius`, `length` along z.")
      .value("kCapsule", GeometryType::kCapsule, "`radius`, cylinder `length` along z.")
      .value("kMesh", GeometryType::kMesh, "`mesh_path`, `scale`.");

  py::class_<Geometry>(m, "Geometry", "A collision or visual shape attached to a body at X_BG.")
      .def(py::init<>(), "A zero sphere.")
      .def_readwrite("name", &Geometry::name, "Shape name.")
      .def_readwrite("type", &Geometry::type, "Kind of shape.")
      .def_readwrite("X_BG", &Geometry::X_BG, "Pose in the body frame.")
      .def_readwrite("size", &Geometry::size, "Box side lengths.")
      .def_readwrite("radius", &Geometry::radius, "Sphere, cylinder and capsule radius.")
      .def_readwrite("length", &Geometry::length, "Cylinder and capsule length.")
      .def_readwrite("mesh_path", &Geometry::mesh_path, "Mesh file.")
      .def_readwrite("scale", &Geometry::scale, "Mesh scale per axis.");

  py::class_<Body>(m, "Body", "A rigid body: inertia in its own frame and its shapes.")
      .def(py::init<>(), "An unnamed massless body.")
      .def_readwrite("name", &Body::name, "Body (URDF link) name.")
      .def_readwrite("inertia", &Body::inertia, "Spatial inertia in the body frame.")
      .def_readwrite("has_inertial", &Body::has_inertial, "False if the URDF link had no <inertial>.")
      .def_readwrite("collisions", &Body::collisions, "Collision shapes.")
      .def_readwrite("visuals", &Body::visuals, "Visual shapes.");

  py::class_<Joint>(m, "Joint", "The joint connecting a body to its parent.")
      .def(py::init<>(), "A fixed joint.")
      .def_readwrite("name", &Joint::name, "Joint name.")
      .def_readwrite("type", &Joint::type, "Kind of joint.")
      .def_readwrite("parent", &Joint::parent, "Parent body index.")
      .def_readwrite("X_PJ", &Joint::X_PJ, "Joint frame in the parent body.")
      .def_readwrite("axis", &Joint::axis, "Unit axis (revolute, prismatic).")
      .def_readwrite("idx_q", &Joint::idx_q, "First configuration index.")
      .def_readwrite("idx_v", &Joint::idx_v, "First velocity index.")
      .def_readwrite("nq", &Joint::nq, "Configuration coordinates.")
      .def_readwrite("nv", &Joint::nv, "Velocity coordinates.")
      .def_readwrite("lower_limit", &Joint::lower_limit, "Lower position limit.")
      .def_readwrite("upper_limit", &Joint::upper_limit, "Upper position limit.")
      .def_readwrite("velocity_limit", &Joint::velocity_limit, "Velocity limit.")
      .def_readwrite("effort_limit", &Joint::effort_limit, "Effort limit.")
      .def_readwrite("continuous", &Joint::continuous, "True for a URDF continuous joint.");

  py::class_<Frame>(m, "Frame", "A named frame rigidly attached to a body.")
      .def_readonly("name", &Frame::name, "Frame name.")
      .def_readonly("body", &Frame::body, "Body index.")
      .def_readonly("X_BF", &Frame::X_BF, "Pose in the body frame.");

  py::class_<Model>(m, "Model", py::dynamic_attr(),
                    "An immutable kinematic tree of rigid bodies (body 0 is the world); made by ParseUrdfFile or "
                    "ModelBuilder. Models read from a file pickle as their file and options.")
      .def("name", &Model::name, "Model (URDF robot) name.")
      .def("nq", &Model::nq, "Size of a configuration.")
      .def("nv", &Model::nv, "Size of a velocity.")
      .def("num_bodies", &Model::num_bodies, "Bodies including the world.")
      .def("num_frames", &Model::num_frames, "Named frames.")
      .def("body", &Model::body, py::return_value_policy::reference_internal, py::arg("i"), "Body i.")
      .def("joint", &Model::joint, py::return_value_policy::reference_internal, py::arg("i"),
           "Joint i (the parent joint of body i).")
      .def("frame", &Model::frame, py::return_value_policy::reference_internal, py::arg("i"), "Frame i.")
      .def("parent", &Model::parent, py::arg("i"), "Parent body of body i (-1 for the world).")
      .def("GetBodyIndex", &Model::GetBodyIndex, py::arg("name"), "ValueError listing the closest names.")
      .def("GetJointIndex", &Model::GetJointIndex, py::arg("name"), "ValueError listing the closest names.")
      .def("GetFrameIndex", &Model::GetFrameIndex, py::arg("name"), "ValueError listing the closest names.")
      .def("HasBody", &Model::HasBody, py::arg("name"), "True if a body is called `name`.")
      .def("HasJoint", &Model::HasJoint, py::arg("name"), "True if a joint is called `name`.")
      .def("HasFrame", &Model::HasFrame, py::arg("name"), "True if a frame is called `name`.")
      .def("total_mass", &Model::total_mass, "Sum of the masses.")
      .def("gravity", [](const Model& self) { return Eigen::Vector3d(self.gravity()); }, "Gravity (world frame).")
      .def("WithGravity", &Model::WithGravity, py::arg("gravity"), "A copy with another gravity.")
      .def("lower_position_limits", [](const Model& s) { return Eigen::VectorXd(s.lower_position_limits()); },
           "Lower position limits per coordinate.")
      .def("upper_position_limits", [](const Model& s) { return Eigen::VectorXd(s.upper_position_limits()); },
           "Upper position limits per coordinate.")
      .def("velocity_limits", [](const Model& s) { return Eigen::VectorXd(s.velocity_limits()); },
           "Velocity limits per velocity coordinate.")
      .def("effort_limits", [](const Model& s) { return Eigen::VectorXd(s.effort_limits()); },
           "Effort limits per velocity coordinate.")
      .def("body_names", &Model::body_names, "Body names in index order.")
      .def("joint_names", &Model::joint_names, "Joint names (without the universe joint).")
      .def("frame_names", &Model::frame_names, "Frame names in index order.")
      .def(py::pickle(&ModelState, &ModelFromState), "Pickles the URDF path and options.");

  py::class_<ModelBuilder>(m, "ModelBuilder", "Assembles a Model body by body, then Build() freezes it.")
      .def(py::init<std::string>(), py::arg("model_name") = "model", "Only the world body.")
      .def("AddBody", &ModelBuilder::AddBody, py::arg("parent"), py::arg("body"), py::arg("joint"),
           "Adds `body` under body `parent` through `joint`; returns its index. ValueError on bad input.")
      .def("AddCollisionGeometry", &ModelBuilder::AddCollisionGeometry, py::arg("body"), py::arg("geometry"),
           "Adds a collision shape.")
      .def("AddVisualGeometry", &ModelBuilder::AddVisualGeometry, py::arg("body"), py::arg("geometry"),
           "Adds a visual shape.")
      .def("AddFrame", &ModelBuilder::AddFrame, py::arg("name"), py::arg("body"), py::arg("X_BF"), "Adds a frame.")
      .def("SetGravity", &ModelBuilder::SetGravity, py::arg("gravity"), "Sets gravity.")
      .def("num_bodies", &ModelBuilder::num_bodies, "Bodies so far, including the world.")
      .def("GetBodyIndex", &ModelBuilder::GetBodyIndex, py::arg("name"), "Index of an added body.")
      .def("Build", &ModelBuilder::Build, "The finished model (the builder is left empty).");

  py::class_<PackageMap>(m, "PackageMap", "Resolves package:// URIs from explicit entries and search paths.")
      .def(py::init<>(), "Empty.")
      .def("Add", &PackageMap::Add, py::arg("name"), py::arg("directory"), "Maps package `name` to `directory`.")
      .def("AddSpec", &PackageMap::AddSpec, py::arg("spec"), "Adds \"name=path\".")
      .def("AddSearchPath", &PackageMap::AddSearchPath, py::arg("directory"), "A folder whose subfolders are packages.")
      .def("ResolvePackage", &PackageMap::ResolvePackage, py::arg("name"), "The folder of package `name`.")
      .def("Contains", &PackageMap::Contains, py::arg("name"), "True if `name` resolves.")
      .def("ResolveUri", &PackageMap::ResolveUri, py::arg("uri"), py::arg("base_directory"), "Resolves a reference.")
      .def("packages", &PackageMap::packages, "The explicit entries.")
      .def("search_paths", &PackageMap::search_paths, "The search paths.");

  py::class_<UrdfOptions>(m, "UrdfOptions", "How ParseUrdfFile builds the model.")
      .def(py::init<>(), "Defaults: welded root, mesh files checked.")
      .def_readwrite("floating_base", &UrdfOptions::floating_base, "Attach the root with a floating joint.")
      .def_readwrite("floating_joint_name", &UrdfOptions::floating_joint_name, "Name of the floating joint.")
      .def_readwrite("packages", &UrdfOptions::packages, "Resolves package:// URIs.")
      .def_readwrite("check_mesh_files", &UrdfOptions::check_mesh_files, "Require referenced mesh files to exist.");

  m.def("ParseUrdfFile", &ParseFile, py::arg("path"), py::arg("options") = UrdfOptions(),
        "Parses a URDF file (without the GIL); RuntimeError starting with the file name and naming the offending "
        "element.");
  m.def("ParseUrdfString", &ParseUrdfString, py::arg("xml"), py::arg("base_directory"),
        py::arg("options") = UrdfOptions(), py::arg("source_name") = "<string>",
        "Parses URDF text; relative mesh paths resolve against `base_directory`.");

  py::class_<Data>(m, "Data",
                   "The preallocated workspace of the algorithms for one Model (one per thread). Buffers are "
                   "read-only numpy views (no copy) that keep the Data alive; each says which algorithm fills it.")
      .def(py::init<const Model&>(), py::arg("model"), "Sizes every buffer for `model`.")
      .def_readonly("nq", &Data::nq, "nq of the model.")
      .def_readonly("nv", &Data::nv, "nv of the model.")
      .def_property_readonly("X_parent", [](const Data& d) { return PoseList(d.X_parent); },
                             "Poses of the bodies in their parents (ForwardKinematics); a list of copies.")
      .def_property_readonly("X_world", [](const Data& d) { return PoseList(d.X_world); },
                             "Poses of the bodies in the world (ForwardKinematics); a list of copies.")
      .def_property_readonly("v", [](const Data& d) { return StackRows(d.v); },
                             "Body twists [w; v] in body frames, (num_bodies, 6) copy.")
      .def_property_readonly("a", [](const Data& d) { return StackRows(d.a); },
                             "Body spatial accelerations, (num_bodies, 6) copy.")
      .def_property_readonly("f", [](const Data& d) { return StackRows(d.f); },
                             "Joint forces on bodies (InverseDynamics), (num_bodies, 6) copy.")
      .def_property_readonly("subtree_mass", [](const Data& d) { return d.subtree_mass; },
                             "Subtree masses (CenterOfMass, GravityTorques).")
      .def_property_readonly("tau", [](py::object self) { return DataView(self.cast<const Data&>().tau, self); },
                             "Joint torques (InverseDynamics).")
      .def_property_readonly("gravity_torques",
                             [](py::object self) { return DataView(self.cast<const Data&>().gravity_torques, self); },
                             "Gravity torques (GravityTorques).")
      .def_property_readonly(
          "gravity_torques_derivative",
          [](py::object self) { return DataView(self.cast<const Data&>().gravity_torques_derivative, self); },
          "d(gravity torques)/dq (GravityTorquesDerivative).")
      .def_property_readonly("M", [](py::object self) { return DataView(self.cast<const Data&>().M, self); },
                             "Mass matrix (MassMatrix).")
      .def_property_readonly("nonlinear_effects",
                             [](py::object self) { return DataView(self.cast<const Data&>().nonlinear_effects, self); },
                             "C(q, v) v + g(q) (ForwardDynamics).")
      .def_property_readonly("qdd", [](py::object self) { return DataView(self.cast<const Data&>().qdd, self); },
                             "Accelerations (ForwardDynamics).")
      .def_property_readonly("com", [](py::object self) { return DataView(self.cast<const Data&>().com, self); },
                             "Centre of mass (CenterOfMass).")
      .def_property_readonly("com_jacobian",
                             [](py::object self) { return DataView(self.cast<const Data&>().com_jacobian, self); },
                             "3 x nv centre-of-mass Jacobian (CenterOfMassJacobian).")
      .def_property_readonly("joint_motion_world",
                             [](py::object self) { return DataView(self.cast<const Data&>().joint_motion_world, self); },
                             "6 x nv world motion subspace.");

  // Algorithms.
  m.def("ForwardKinematics", py::overload_cast<const Model&, Data&, const VectorRef&>(&ForwardKinematics),
        py::arg("model"), py::arg("data"), py::arg("q"), "Body poses at q (data.X_parent, data.X_world).");
  m.def("ForwardKinematics",
        py::overload_cast<const Model&, Data&, const VectorRef&, const VectorRef&>(&ForwardKinematics), py::arg("model"),
        py::arg("data"), py::arg("q"), py::arg("v"), "Also body twists (data.v).");
  m.def("ForwardKinematics",
        py::overload_cast<const Model&, Data&, const VectorRef&, const VectorRef&, const VectorRef&>(&ForwardKinematics),
        py::arg("model"), py::arg("data"), py::arg("q"), py::arg("v"), py::arg("a"),
        "Also body accelerations (data.a, without gravity).");
  m.def(
      "FramePose", [](const Model& model, const Data& data, py::handle frame) {
        CheckData(model, data, "FramePose");
        return FramePose(model, data, FrameIndex(model, frame));
      },
      py::arg("model"), py::arg("data"), py::arg("frame"), "X_WF of a frame (index or name) after ForwardKinematics.");
  m.def(
      "FrameVelocity", [](const Model& model, const Data& data, py::handle frame) {
        CheckData(model, data, "FrameVelocity");
        return FrameVelocity(model, data, FrameIndex(model, frame));
      },
      py::arg("model"), py::arg("data"), py::arg("frame"),
      "Twist of a frame in its own axes (after ForwardKinematics with velocities).");
  py::enum_<ReferenceFrame>(m, "ReferenceFrame", "How a frame Jacobian expresses the twist.")
      .value("kLocal", ReferenceFrame::kLocal, "In the frame's own axes.")
      .value("kWorldAligned", ReferenceFrame::kWorldAligned, "In world axes, linear part at the frame origin.")
      .value("kWorld", ReferenceFrame::kWorld, "Spatial twist in the world frame.");
  m.def(
      "FrameJacobian",
      [](const Model& model, const Data& data, py::handle frame, ReferenceFrame reference) {
        CheckData(model, data, "FrameJacobian");
        Eigen::MatrixXd J(6, model.nv());
        FrameJacobian(model, data, FrameIndex(model, frame), reference, J);
        return J;
      },
      py::arg("model"), py::arg("data"), py::arg("frame"), py::arg("reference"),
      "The 6 x nv Jacobian of a frame (angular rows first) from the last ForwardKinematics.");
  m.def(
      "FrameJacobian",
      [](const Model& model, Data& data, const VectorRef& q, py::handle frame, ReferenceFrame reference) {
        Eigen::MatrixXd J(6, model.nv());
        FrameJacobian(model, data, q, FrameIndex(model, frame), reference, J);
        return J;
      },
      py::arg("model"), py::arg("data"), py::arg("q"), py::arg("frame"), py::arg("reference"),
      "Computes the poses of the frame's body and ancestors at q, then the Jacobian.");
  m.def(
      "CenterOfMass",
      [](const Model& model, py::object data, const VectorRef& q) {
        return DataView(CenterOfMass(model, data.cast<Data&>(), q), data);
      },
      py::arg("model"), py::arg("data"), py::arg("q"), "Centre of mass at q (a view of data.com).");
  m.def(
      "CenterOfMassJacobian",
      [](const Model& model, py::object data, const VectorRef& q) {
        return DataView(CenterOfMassJacobian(model, data.cast<Data&>(), q), data);
      },
      py::arg("model"), py::arg("data"), py::arg("q"), "3 x nv centre-of-mass Jacobian (a view of data).");
  m.def(
      "GravityTorques",
      [](const Model& model, py::object data, const VectorRef& q) {
        return DataView(GravityTorques(model, data.cast<Data&>(), q), data);
      },
      py::arg("model"), py::arg("data"), py::arg("q"), "Torques holding q against gravity (a view of data).");
  m.def(
      "GravityTorquesDerivative",
      [](const Model& model, py::object data, const VectorRef& q) {
        return DataView(GravityTorquesDerivative(model, data.cast<Data&>(), q), data);
      },
      py::arg("model"), py::arg("data"), py::arg("q"), "d(GravityTorques)/dq, nv x nv (a view of data).");
  m.def(
      "InverseDynamics",
      [](const Model& model, py::object data, const VectorRef& q, const VectorRef& v, const VectorRef& a) {
        return DataView(InverseDynamics(model, data.cast<Data&>(), q, v, a), data);
      },
      py::arg("model"), py::arg("data"), py::arg("q"), py::arg("v"), py::arg("a"),
      "RNEA: torques producing accelerations a at (q, v) (a view of data.tau).");
  m.def(
      "MassMatrix",
      [](const Model& model, py::object data, const VectorRef& q) {
        return DataView(MassMatrix(model, data.cast<Data&>(), q), data);
      },
      py::arg("model"), py::arg("data"), py::arg("q"), "CRBA: the mass matrix M(q) (a view of data.M).");
  m.def(
      "ForwardDynamics",
      [](const Model& model, py::object data, const VectorRef& q, const VectorRef& v, const VectorRef& tau) {
        return DataView(ForwardDynamics(model, data.cast<Data&>(), q, v, tau), data);
      },
      py::arg("model"), py::arg("data"), py::arg("q"), py::arg("v"), py::arg("tau"),
      "Accelerations M^-1 (tau - C v - g) (a view of data.qdd); RuntimeError if M is not positive definite.");
  m.def("KineticEnergy", &KineticEnergy, py::arg("model"), py::arg("data"), py::arg("q"), py::arg("v"),
        "1/2 v' M(q) v.");
  m.def("PotentialEnergy", &PotentialEnergy, py::arg("model"), py::arg("data"), py::arg("q"),
        "Potential energy of gravity.");
  m.def("CentroidalMomentum", &CentroidalMomentum, py::arg("model"), py::arg("data"), py::arg("q"), py::arg("v"),
        "[k_G; l] in world axes.");

  // Configurations.
  m.def("NeutralConfiguration", &NeutralConfiguration, py::arg("model"), "Zero joints, identity floating poses.");
  m.def("Integrate", &Integrate, py::arg("model"), py::arg("q"), py::arg("v"), py::arg("dt") = 1.0, "q (+) v dt.");
  m.def("Difference", &Difference, py::arg("model"), py::arg("q0"), py::arg("q1"), "v with Integrate(q0, v) = q1.");
  m.def("ConfigurationRate", &ConfigurationRate, py::arg("model"), py::arg("q"), py::arg("v"), "dq/dt for velocity v.");
  m.def(
      "NormalizeConfiguration",
      [](const Model& model, const VectorRef& q) {
        Eigen::VectorXd out = q;
        NormalizeConfiguration(model, out);
        return out;
      },
      py::arg("model"), py::arg("q"), "q with unit floating-joint quaternions (a new array).");
  m.def(
      "RandomConfiguration",
      [](const Model& model, unsigned seed, double unlimited_range) {
        std::mt19937 rng(seed);
        return RandomConfiguration(model, rng, unlimited_range);
      },
      py::arg("model"), py::arg("seed"), py::arg("unlimited_range") = 3.141592653589793,
      "A random configuration from a std::mt19937 seeded with `seed` (deterministic).");
  m.def("IsWithinPositionLimits", &IsWithinPositionLimits, py::arg("model"), py::arg("q"), py::arg("tolerance") = 0.0,
        "True if every limited coordinate is within its limits.");
  m.def("PositionLimitViolation", &PositionLimitViolation, py::arg("model"), py::arg("q"),
        "Per coordinate, how far q lies outside its limits.");
  m.def("ClampToPositionLimits", &ClampToPositionLimits, py::arg("model"), py::arg("q"),
        "q clamped into the limits (an explicit request).");

  // Collision.
  py::class_<ShapeDistance>(m, "ShapeDistance", "Signed distance, witness points and normal, world frame.")
      .def_readonly("distance", &ShapeDistance::distance, "Signed distance (negative when overlapping).")
      .def_readonly("p_A", &ShapeDistance::p_A, "Witness point on A.")
      .def_readonly("p_B", &ShapeDistance::p_B, "Witness point on B.")
      .def_readonly("normal", &ShapeDistance::normal, "Unit normal from A towards B.");
  py::class_<CollisionPair>(m, "CollisionPair", "A pair of geometries and their signed distance.")
      .def_readonly("geometry_a", &CollisionPair::geometry_a, "First geometry (-1: none).")
      .def_readonly("geometry_b", &CollisionPair::geometry_b, "Second geometry.")
      .def_readonly("result", &CollisionPair::result, "Their ShapeDistance.");
  m.def("SphereSphereDistance", &SphereSphereDistance, py::arg("center_A"), py::arg("radius_A"), py::arg("center_B"),
        py::arg("radius_B"), "Sphere to sphere.");
  m.def("BoxSphereDistance", &BoxSphereDistance, py::arg("X_WA"), py::arg("size_A"), py::arg("center_B"),
        py::arg("radius_B"), "Box to sphere.");
  m.def("CapsuleCapsuleDistance", &CapsuleCapsuleDistance, py::arg("a_A"), py::arg("b_A"), py::arg("radius_A"),
        py::arg("a_B"), py::arg("b_B"), py::arg("radius_B"), "Capsule to capsule.");

  py::class_<CollisionWorld>(m, "CollisionWorld",
                             "The robot's collision shapes placed by forward kinematics, with environment geometry, "
                             "answering signed-distance queries.")
      .def(py::init<const Model&>(), py::arg("model"), "Takes the collision geometry of every body.")
      .def("AddBox", &CollisionWorld::AddBox, py::arg("name"), py::arg("size"), py::arg("X_WG"),
           "Adds an environment box; returns its index.")
      .def("AddSphere", &CollisionWorld::AddSphere, py::arg("name"), py::arg("radius"), py::arg("center"),
           "Adds an environment sphere.")
      .def("AddPoints", &CollisionWorld::AddPoints, py::arg("name"), py::arg("points"), py::arg("radius") = 0.0,
           "Adds a 3 x N point set inflated by `radius`.")
      .def("AddHeightField", &CollisionWorld::AddHeightField, py::arg("name"), py::arg("heights"),
           py::arg("cell_size"), py::arg("origin"), py::arg("bottom"), "Adds an elevation map (NaN = unknown).")
      .def("ExcludeBodyPair", &CollisionWorld::ExcludeBodyPair, py::arg("body_a"), py::arg("body_b"),
           "Never report this body pair.")
      .def("ExcludeGeometryPair", &CollisionWorld::ExcludeGeometryPair, py::arg("geometry_a"), py::arg("geometry_b"),
           "Never report this geometry pair.")
      .def(
          "UpdatePoses",
          [](CollisionWorld& self, const Model& model, const Data& data) {
            CheckData(model, data, "CollisionWorld.UpdatePoses");
            self.UpdatePoses(model, data);
          },
          py::arg("model"), py::arg("data"),
           "Places the robot geometries from data's poses (run ForwardKinematics first).")
      .def("num_geometries", &CollisionWorld::num_geometries, "Robot, then environment geometries.")
      .def("geometry_name", &CollisionWorld::geometry_name, py::arg("i"), "Name of geometry i.")
      .def("geometry_body", &CollisionWorld::geometry_body, py::arg("i"), "Body of geometry i (-1: environment).")
      .def("GetGeometryIndex", &CollisionWorld::GetGeometryIndex, py::arg("name"), "Index by name.")
      .def("geometry_pose", &CollisionWorld::geometry_pose, py::arg("i"), "Pose of geometry i (a copy).")
      .def("IsPairChecked", &CollisionWorld::IsPairChecked, py::arg("a"), py::arg("b"), "True if not filtered.")
      .def("ComputeDistance", &CollisionWorld::ComputeDistance, py::arg("a"), py::arg("b"),
           py::call_guard<py::gil_scoped_release>(), "Signed distance of geometries a and b.")
      .def("PairsWithin", &CollisionWorld::PairsWithin, py::arg("margin"), py::call_guard<py::gil_scoped_release>(),
           "Checked pairs closer than `margin`, ordered.")
      .def("ClosestPair", &CollisionWorld::ClosestPair, py::arg("max_distance") = std::numeric_limits<double>::infinity(),
           py::call_guard<py::gil_scoped_release>(), "The closest checked pair (geometry_a -1 if none).")
      .def(
          "DistanceGradient",
          [](const CollisionWorld& self, const Model& model, const Data& data, const CollisionPair& pair) {
            CheckData(model, data, "CollisionWorld.DistanceGradient");
            Eigen::VectorXd gradient(model.nv());
            self.DistanceGradient(model, data, pair, gradient);
            return gradient;
          },
          py::arg("model"), py::arg("data"), py::arg("pair"), "d(distance)/dq of a pair (size nv).");
}

}  // namespace cairn::python
