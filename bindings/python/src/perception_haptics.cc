// cairn.perception, haptics part (seed 000): the object descriptor, the traversability memory, interaction
// planning, gist change detection, camera–antenna calibration, their systems, and the simulated world of the
// experiments (objects, sensor, antenna). Point clouds are (3, N) float64 arrays, one point a column, as in C++.

#include <memory>
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "cairn/perception/haptics/affordance_descriptor.h"
#include "cairn/perception/haptics/affordance_memory.h"
#include "cairn/perception/haptics/background_subtractor.h"
#include "cairn/perception/haptics/camera_antenna_calibrator.h"
#include "cairn/perception/haptics/change_detector.h"
#include "cairn/perception/haptics/gist_change_detector.h"
#include "cairn/perception/haptics/haptic_interaction_planner.h"
#include "cairn/perception/haptics/haptic_outcome.h"
#include "cairn/perception/haptics/interaction_planner.h"
#include "cairn/perception/haptics/object_descriptor.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"
#include "cairn/perception/haptics/rigid_transform_fit.h"
#include "cairn/perception/haptics/simulation/haptic_affordance_experiment.h"
#include "cairn/perception/haptics/simulation/antenna_probe.h"
#include "cairn/perception/haptics/simulation/haptic_object_library.h"
#include "cairn/perception/haptics/simulation/haptic_scene_object.h"
#include "cairn/perception/haptics/simulation/simulated_antenna.h"
#include "cairn/perception/haptics/simulation/simulated_depth_camera.h"
#include "cairn/perception/haptics/simulation/simulated_depth_sensor.h"
#include "cairn/perception/haptics/sphere_ransac.h"
#include "cairn/perception/haptics/traversability_memory.h"
#include "numpy_support.h"

namespace cairn::python {

using namespace cairn::perception;

void DefinePerceptionHaptics(py::module_ m) {
  m.def("DownsampleByMinDistance", &DownsampleByMinDistance, py::arg("points"), py::arg("min_distance"),
        "(3, N) points with no two kept closer than min_distance (greedy, in column order).");
  m.def("VoxelGridCentroids", &VoxelGridCentroids, py::arg("points"), py::arg("voxel"),
        "Centroids of the occupied voxels, in first-seen order.");
  m.def("KeepWithinReach", &KeepWithinReach, py::arg("points"), py::arg("center"), py::arg("radius"),
        "The points within `radius` of `center`.");

  py::class_<AffordanceDescriptor> descriptor(m, "AffordanceDescriptor",
                                              "The §3.3 object descriptor: (n, s, d, m) per histogram line (eq. 6).");
  py::class_<AffordanceDescriptor::Options>(descriptor, "Options", "The paper's defaults: 1 cm, 1 m reach, 16 x 14.")
      .def(py::init<>(), "The paper's defaults.")
      .def_readwrite("min_point_distance", &AffordanceDescriptor::Options::min_point_distance, "Down-sampling (m).")
      .def_readwrite("reach_center_C", &AffordanceDescriptor::Options::reach_center_C, "Antenna base in C.")
      .def_readwrite("reach_radius", &AffordanceDescriptor::Options::reach_radius, "Antenna reach (m).")
      .def_readwrite("columns", &AffordanceDescriptor::Options::columns, "Bins along x.")
      .def_readwrite("lines", &AffordanceDescriptor::Options::lines, "Lines along y.");
  descriptor.def(py::init<int>(), py::arg("lines") = 14, "All-zero lines.")
      .def_static("FromValues", &AffordanceDescriptor::FromValues, py::arg("values"), "From 4 values per line.")
      .def_static("FromHistogram", &AffordanceDescriptor::FromHistogram, py::arg("histogram"),
                  "The metrics of an int histogram (rows = lines).")
      .def_static("Histogram", &AffordanceDescriptor::Histogram, py::arg("points_C"), py::arg("options"),
                  "The histogram of a cloud.")
      .def_static("Compute", &AffordanceDescriptor::Compute, py::arg("points_C"), py::arg("options"),
                  "The descriptor of a (3, N) cloud in the sensor frame.")
      .def("lines", &AffordanceDescriptor::lines, "|L_H|.")
      .def_property_readonly("values", [](const AffordanceDescriptor& d) { return Eigen::VectorXd(d.values()); },
                             "The 4 |L_H| values (a copy).")
      .def("n", &AffordanceDescriptor::n, py::arg("line"), "Clusters of a line.")
      .def("s", &AffordanceDescriptor::s, py::arg("line"), "Bins of its largest cluster.")
      .def("d", &AffordanceDescriptor::d, py::arg("line"), "Points per bin.")
      .def("m", &AffordanceDescriptor::m, py::arg("line"), "Most points in one cluster.");

  py::class_<AffordanceRecall>(m, "AffordanceRecall", "The memory's answer (eqs. 12–15).")
      .def(py::init<>(), "An empty answer.")
      .def_readonly("traversable", &AffordanceRecall::traversable, "Eq. 14 (ties: False).")
      .def_readonly("confidence", &AffordanceRecall::confidence, "Eq. 15.")
      .def_readonly("confidence_traversable", &AffordanceRecall::confidence_traversable, "c+ (eq. 12).")
      .def_readonly("confidence_non_traversable", &AffordanceRecall::confidence_non_traversable, "c- (eq. 13).")
      .def_readonly("neighbours", &AffordanceRecall::neighbours, "Neighbours used.")
      .def_readonly("nearest", &AffordanceRecall::nearest, "Index of the nearest entry (-1: empty memory).")
      .def_readonly("nearest_dissimilarity", &AffordanceRecall::nearest_dissimilarity, "Its eq. 11 value.");

  py::class_<TraversabilityMemory> memory(m, "TraversabilityMemory",
                                          "The growing k-NN memory of (descriptor, traversable) tuples (§3.4).");
  py::class_<TraversabilityMemory::Options>(memory, "Options", "zeta, beta, gamma, delta = 0.5, 0.2, 2, 2; k = 5.")
      .def(py::init<>(), "The paper's defaults.")
      .def_readwrite("zeta", &TraversabilityMemory::Options::zeta, "Scale of eq. 7.")
      .def_readwrite("beta", &TraversabilityMemory::Options::beta, "Scale of eq. 8.")
      .def_readwrite("gamma", &TraversabilityMemory::Options::gamma, "Scale of eq. 9.")
      .def_readwrite("delta", &TraversabilityMemory::Options::delta, "Scale of eq. 10.")
      .def_readwrite("k", &TraversabilityMemory::Options::k, "Neighbours.");
  memory.def(py::init<>(), "Empty, the paper's options, 14 lines.")
      .def(py::init<const TraversabilityMemory::Options&, int>(), py::arg("options"), py::arg("lines") = 14,
           "Empty, with options.")
      .def_static("Dissimilarity", &TraversabilityMemory::Dissimilarity, py::arg("observed"), py::arg("stored"),
                  py::arg("options"), "Eq. 11.")
      .def("Add", &TraversabilityMemory::Add, py::arg("descriptor"), py::arg("traversable"), "Learns one outcome.")
      .def("Recall", py::overload_cast<const AffordanceDescriptor&>(&TraversabilityMemory::Recall, py::const_),
           py::arg("observed"), "The k-NN recall with the memory's k.")
      .def("Recall", py::overload_cast<const AffordanceDescriptor&, int>(&TraversabilityMemory::Recall, py::const_),
           py::arg("observed"), py::arg("k"), "The k-NN recall with another k.")
      .def("Save", &TraversabilityMemory::Save, py::arg("path"), "Writes the memory atomically.")
      .def_static("Load", &TraversabilityMemory::Load, py::arg("path"), "Reads a saved memory (RuntimeError).")
      .def("ToText", &TraversabilityMemory::ToText, "The saved text.")
      .def_static("FromText", &TraversabilityMemory::FromText, py::arg("text"), py::arg("source"),
                  "Parses the saved text.")
      .def("size", &TraversabilityMemory::size, "Entries.")
      .def("lines", &TraversabilityMemory::lines, "Descriptor lines.")
      .def("descriptor", &TraversabilityMemory::descriptor, py::arg("i"), "Entry i's descriptor.")
      .def("traversable", &TraversabilityMemory::traversable, py::arg("i"), "Entry i's label.");

  py::class_<InteractionPoint>(m, "InteractionPoint", "A candidate contact point and its criteria (eqs. 16–19).")
      .def_readonly("p_C", &InteractionPoint::p_C, "Point in C.")
      .def_readonly("height_score", &InteractionPoint::height_score, "s_h.")
      .def_readonly("centroid_score", &InteractionPoint::centroid_score, "s_c.")
      .def_readonly("density_score", &InteractionPoint::density_score, "s_d.")
      .def_readonly("score", &InteractionPoint::score, "s.");
  py::class_<InteractionPlan>(m, "InteractionPlan", "Candidates, the selected points in order, antenna targets.")
      .def(py::init<>(), "An empty plan.")
      .def_readonly("candidates", &InteractionPlan::candidates, "P, highest score first.")
      .def_readonly("selected", &InteractionPlan::selected, "I in execution order.")
      .def_readonly("targets_C", &InteractionPlan::targets_C, "Targets pushed along z_C.")
      .def_readonly("threshold", &InteractionPlan::threshold, "alpha c(o).");
  py::class_<HapticInteractionPlanner> planner(m, "HapticInteractionPlanner", "§3.5–3.6 planning and pruning.");
  py::class_<HapticInteractionPlanner::Options>(planner, "Options", "The paper's defaults; alpha 1.")
      .def(py::init<>(), "The paper's defaults.")
      .def_readwrite("voxel", &HapticInteractionPlanner::Options::voxel, "Simplification voxel (m).")
      .def_readwrite("min_candidate_spacing", &HapticInteractionPlanner::Options::min_candidate_spacing, "m.")
      .def_readwrite("ground_offset", &HapticInteractionPlanner::Options::ground_offset, "g (m).")
      .def_readwrite("sigma", &HapticInteractionPlanner::Options::sigma, "sigma (m).")
      .def_readwrite("neighbour_radius", &HapticInteractionPlanner::Options::neighbour_radius, "r (m).")
      .def_readwrite("theta_height", &HapticInteractionPlanner::Options::theta_height, "theta_h.")
      .def_readwrite("theta_centroid", &HapticInteractionPlanner::Options::theta_centroid, "theta_c.")
      .def_readwrite("theta_density", &HapticInteractionPlanner::Options::theta_density, "theta_d.")
      .def_readwrite("alpha", &HapticInteractionPlanner::Options::alpha, "alpha of eq. 21.")
      .def_readwrite("push_distance", &HapticInteractionPlanner::Options::push_distance, "Push along z_C (m).");
  planner.def(py::init<>(), "The paper's options.")
      .def(py::init<const HapticInteractionPlanner::Options&>(), py::arg("options"), "With options.")
      .def("ScoreCandidates", &HapticInteractionPlanner::ScoreCandidates, py::arg("object_C"), "P sorted.")
      .def("Prune", &HapticInteractionPlanner::Prune, py::arg("sorted"), py::arg("confidence"), "Eqs. 20–21.")
      .def_static("ExecutionOrder", &HapticInteractionPlanner::ExecutionOrder, py::arg("points"),
                  "Rightmost first, then the nearest.")
      .def("Plan", &HapticInteractionPlanner::Plan, py::arg("object_C"), py::arg("confidence"), "The whole plan.");

  py::class_<GistChangeDetector> gist(m, "GistChangeDetector", "§3.7 density-gist change detection.");
  py::class_<GistChangeDetector::Options>(gist, "Options", "voxel 0.01, omega 0.03.")
      .def(py::init<>(), "The paper's defaults.")
      .def_readwrite("voxel", &GistChangeDetector::Options::voxel, "Grid cell (m).")
      .def_readwrite("omega", &GistChangeDetector::Options::omega, "Threshold.");
  py::class_<GistChangeDetector::Result>(gist, "Result", "One comparison.")
      .def_readonly("gist", &GistChangeDetector::Result::gist, "The current gist.")
      .def_readonly("difference", &GistChangeDetector::Result::difference, "|gist - reference|.")
      .def_readonly("changed", &GistChangeDetector::Result::changed, "difference > omega.");
  gist.def(py::init<>(), "The paper's options.")
      .def(py::init<const GistChangeDetector::Options&>(), py::arg("options"), "With options.")
      .def_static("Gist", &GistChangeDetector::Gist, py::arg("points"), py::arg("voxel"), "Voxels over points.")
      .def("SetReference", &GistChangeDetector::SetReference, py::arg("points"), "Takes the reference gist.")
      .def("Compare", &GistChangeDetector::Compare, py::arg("points"), "Compares with the reference.")
      .def("reference_gist", &GistChangeDetector::reference_gist, "The reference.");

  py::class_<SphereFit>(m, "SphereFit", "A RANSAC sphere.")
      .def_readonly("center", &SphereFit::center, "Centre.")
      .def_readonly("radius", &SphereFit::radius, "Radius.")
      .def_readonly("inliers", &SphereFit::inliers, "Inlier columns.")
      .def_readonly("inlier_centroid", &SphereFit::inlier_centroid, "The paper's tip estimate.");
  py::class_<SphereRansac> ransac(m, "SphereRansac", "Seeded RANSAC sphere fitting.");
  py::class_<SphereRansac::Options>(ransac, "Options", "500 hypotheses, 3 mm, radius in [5 mm, 10 cm], seed 0.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("iterations", &SphereRansac::Options::iterations, "Hypotheses.")
      .def_readwrite("inlier_threshold", &SphereRansac::Options::inlier_threshold, "m.")
      .def_readwrite("min_radius", &SphereRansac::Options::min_radius, "m.")
      .def_readwrite("max_radius", &SphereRansac::Options::max_radius, "m.")
      .def_readwrite("seed", &SphereRansac::Options::seed, "Sampler seed.");
  ransac.def(py::init<>(), "Defaults.")
      .def(py::init<const SphereRansac::Options&>(), py::arg("options"), "With options.")
      .def("Fit", &SphereRansac::Fit, py::arg("points"), "The best sphere (RuntimeError when none).");

  py::class_<RigidTransformFit>(m, "RigidTransformFit", "M = X_AC and its residual.")
      .def_readonly("X_AC", &RigidTransformFit::X_AC, "4x4.")
      .def_readonly("rms_residual", &RigidTransformFit::rms_residual, "m.")
      .def_readonly("max_residual", &RigidTransformFit::max_residual, "m.");
  m.def("FitRigidTransform", &FitRigidTransform, py::arg("p_C"), py::arg("p_A"),
        "Eq. 5 by SVD over corresponding (3, N) columns.");
  py::class_<BackgroundSubtractor>(m, "BackgroundSubtractor", "Foreground against a reference cloud.")
      .def(py::init<const Eigen::Matrix3Xd&, double>(), py::arg("reference"), py::arg("resolution"), "From a cloud.")
      .def("Foreground", &BackgroundSubtractor::Foreground, py::arg("points"), "Points in empty reference cells.");
  py::class_<CameraAntennaCalibrator>(m, "CameraAntennaCalibrator", "§3.2 babbling calibration.")
      .def(py::init<const Eigen::Matrix3Xd&>(), py::arg("reference_C"), "Default options.")
      .def_static("Table1Points", &CameraAntennaCalibrator::Table1Points, "Table 1's tip positions in A.")
      .def(
          "AddObservation",
          [](CameraAntennaCalibrator& self, const Eigen::Vector3d& p_A, const Eigen::Matrix3Xd& cloud_C) {
            return Eigen::Vector3d(self.AddObservation(p_A, cloud_C).p_C);
          },
          py::arg("p_A"), py::arg("cloud_C"), "Fits the tip; returns its position in C.")
      .def("Solve", &CameraAntennaCalibrator::Solve, "The rigid fit.");

  py::class_<HapticOutcome>(m, "HapticOutcome", "One interaction's outcome with its descriptor and sequence.")
      .def(py::init<>(), "None yet (sequence -1).")
      .def_readwrite("sequence", &HapticOutcome::sequence, "Interaction count from 0.")
      .def_readwrite("traversable", &HapticOutcome::traversable, "Not blocked.")
      .def_readwrite("descriptor", &HapticOutcome::descriptor, "The object's descriptor.");

  py::class_<ObjectDescriptor, systems::LeafSystem>(
      m, "ObjectDescriptor", "System: input `points_C` ((3, N)); outputs `descriptor`, `object_C`.")
      .def(py::init<>(), "The paper's options.")
      .def(py::init<const AffordanceDescriptor::Options&>(), py::arg("options"), "With options.");
  py::class_<AffordanceMemory, systems::LeafSystem>(
      m, "AffordanceMemory",
      "System: inputs `descriptor`, `outcome`; outputs `recall`, `memory`; learns each outcome once per period.")
      .def(py::init<const TraversabilityMemory&, double, double>(), py::arg("initial"), py::arg("period"),
           py::arg("offset") = 0.0, "From an initial memory.");
  py::class_<InteractionPlanner, systems::LeafSystem>(
      m, "InteractionPlanner", "System: inputs `object_C`, `recall`; output `plan`.")
      .def(py::init<>(), "The paper's options.")
      .def(py::init<const HapticInteractionPlanner::Options&>(), py::arg("options"), "With options.");
  py::class_<ChangeDetector, systems::LeafSystem>(
      m, "ChangeDetector", "System: input `points_C`; output `change` = [gist, difference, changed].")
      .def(py::init<const GistChangeDetector::Options&, double>(), py::arg("options"), py::arg("period"),
           "Reference at the first update.");

  py::enum_<HapticObjectKind>(m, "HapticObjectKind", "The simulated objects (Fig. 10, 14, 16).")
      .value("kWall", HapticObjectKind::kWall, "(a)")
      .value("kRock", HapticObjectKind::kRock, "(b)")
      .value("kBigPlant", HapticObjectKind::kBigPlant, "(c)")
      .value("kShrub", HapticObjectKind::kShrub, "(d)")
      .value("kSmallShrub", HapticObjectKind::kSmallShrub, "(e)")
      .value("kTallPlants", HapticObjectKind::kTallPlants, "(f)")
      .value("kTallPlant", HapticObjectKind::kTallPlant, "(g)")
      .value("kVerticalLogs", HapticObjectKind::kVerticalLogs, "(h)")
      .value("kHorizontalLogs", HapticObjectKind::kHorizontalLogs, "(i)")
      .value("kNovelGrass", HapticObjectKind::kNovelGrass, "data set 2, object 1")
      .value("kNovelStump", HapticObjectKind::kNovelStump, "data set 2, object 2")
      .value("kShrubPatch", HapticObjectKind::kShrubPatch, "Fig. 16 (A)")
      .value("kFlimsyCanes", HapticObjectKind::kFlimsyCanes, "Fig. 16 (B)")
      .value("kTwigs", HapticObjectKind::kTwigs, "Fig. 16 (C)");
  m.def("HapticObjectName", &HapticObjectName, py::arg("kind"), "E.g. \"(d) shrub\".");
  m.def("DataSet1", &DataSet1, "The nine objects (a)–(i).");
  m.def("DataSet2", &DataSet2, "The two novel objects.");
  m.def(
      "HapticObjectTraversable",
      [](HapticObjectKind kind, std::uint64_t seed) { return MakeHapticObject(kind, seed).traversable(); },
      py::arg("kind"), py::arg("seed") = 1, "The ground truth of a simulated object.");

  py::class_<HapticSceneObject>(m, "HapticSceneObject", "A simulated object: primitives with their stiffness.")
      .def("name", &HapticSceneObject::name, "Its name.")
      .def("traversable", &HapticSceneObject::traversable, "True when no element is stiff.")
      .def("Translated", &HapticSceneObject::Translated, py::arg("offset"), "The same object moved by `offset`.");
  m.def("MakeHapticObject", &MakeHapticObject, py::arg("kind"), py::arg("seed") = 1,
        "A simulated object of `kind` at the origin (ground at z = 0).");
  py::class_<SimulatedDepthSensor> sensor(m, "SimulatedDepthSensor", "The ray-cast structured-light depth sensor.");
  py::class_<SimulatedDepthSensor::Options>(sensor, "Options", "200 x 150 px, 57 x 43 degrees, 0.4-4 m.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("width", &SimulatedDepthSensor::Options::width, "Pixels across.")
      .def_readwrite("height", &SimulatedDepthSensor::Options::height, "Pixels down.")
      .def_readwrite("min_range", &SimulatedDepthSensor::Options::min_range, "m.")
      .def_readwrite("max_range", &SimulatedDepthSensor::Options::max_range, "m.")
      .def_readwrite("noise_coefficient", &SimulatedDepthSensor::Options::noise_coefficient,
                     "Depth noise sigma = coefficient z^2.")
      .def_readwrite("render_ground", &SimulatedDepthSensor::Options::render_ground, "Also the ground plane.");
  sensor.def_static("LookingAlong", &SimulatedDepthSensor::LookingAlong, py::arg("position_W"), py::arg("yaw"),
                    "X_WC (4x4) of a sensor at a point looking horizontally along heading `yaw`.");
  py::class_<SimulatedAntenna> antenna(m, "SimulatedAntenna", "The pan-tilt-telescopic antenna.");
  py::class_<SimulatedAntenna::Options>(antenna, "Options", "Pan and tilt +-90 degrees, 5 cm-1 m, 1 cm tip.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("max_extension", &SimulatedAntenna::Options::max_extension, "m.")
      .def_readwrite("tip_radius", &SimulatedAntenna::Options::tip_radius, "m.")
      .def_readwrite("step", &SimulatedAntenna::Options::step, "Largest tip motion between checks, m.");
  py::class_<SimulatedDepthCamera, systems::LeafSystem>(
      m, "SimulatedDepthCamera",
      "System: input `X_WC` (4x4); output `points_C` ((3, N)), rendered every `period` s and held as state.")
      .def(py::init<const SimulatedDepthSensor::Options&, std::vector<HapticSceneObject>, double, std::uint64_t>(),
           py::arg("sensor"), py::arg("objects_W"), py::arg("period"), py::arg("seed"), "ValueError for bad options.");
  py::class_<AntennaProbe, systems::LeafSystem>(
      m, "AntennaProbe",
      "System: inputs `plan`, `descriptor`, `X_WC`; outputs `outcome` (HapticOutcome), `interactions`; touches the "
      "planned points every `period` s.")
      .def(py::init<const SimulatedAntenna::Options&, std::vector<HapticSceneObject>, const Eigen::Isometry3d&, int,
                    double, double>(),
           py::arg("antenna"), py::arg("objects_W"), py::arg("X_CA"), py::arg("descriptor_lines"), py::arg("period"),
           py::arg("offset") = 0.0, "ValueError for bad options.");

  py::class_<TraversabilityConfusion>(m, "TraversabilityConfusion", "counts[actual][predicted], traversable first.")
      .def_readonly("counts", &TraversabilityConfusion::counts, "2 x 2 counts.")
      .def("accuracy", &TraversabilityConfusion::accuracy, "Correct over total.")
      .def("total", &TraversabilityConfusion::total, "Total.");
  py::class_<HapticAffordanceExperiment>(m, "HapticAffordanceExperiment",
                                         "The simulated robot and the experiments of §4 (default options).")
      .def(py::init<>(), "Default robot, paper parameters, seed 1.")
      .def("Observe", &HapticAffordanceExperiment::Observe, py::arg("kind"), py::arg("approach"),
           "(3, N) points of an approach.")
      .def("Describe", &HapticAffordanceExperiment::Describe, py::arg("points_C"), "Its descriptor.")
      .def(
          "Touch",
          [](const HapticAffordanceExperiment& self, HapticObjectKind kind, int approach,
             const Eigen::Matrix3Xd& points, double confidence) {
            int planned = 0;
            const AntennaInteraction result = self.Touch(kind, approach, points, confidence, &planned);
            return py::make_tuple(result.blocked, planned);
          },
          py::arg("kind"), py::arg("approach"), py::arg("points_C"), py::arg("confidence"),
          "(blocked, planned points) of one haptic interaction.")
      .def("LeaveOneOut", &HapticAffordanceExperiment::LeaveOneOut, py::arg("kinds"), py::arg("k"),
           "Fig. 12's experiment.");

  // Matrix3Xd (the clouds of the ports above) is registered by DefinePerceptionTerrain, which module.cc runs first.
  RegisterBoundAbstractValueType<AffordanceDescriptor>("AffordanceDescriptor");
  RegisterBoundAbstractValueType<AffordanceRecall>("AffordanceRecall");
  RegisterBoundAbstractValueType<TraversabilityMemory>("TraversabilityMemory");
  RegisterBoundAbstractValueType<InteractionPlan>("InteractionPlan");
  RegisterBoundAbstractValueType<HapticOutcome>("HapticOutcome");
}

}  // namespace cairn::python
