// cairn.planning (the main diagram): a footstep scenario as the synthetic head camera sees it, the perception in
// front of the walk, BuildMainDiagram and RunMainDiagram.

#include <memory>
#include <string>
#include <utility>

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cv_mat_caster.h"
#include "numpy_support.h"
#include "ownership.h"
#include "cairn/planning/run/main_diagram.h"
#include "cairn/planning/run/scenario_stereo_scene.h"

namespace cairn::python {

using namespace cairn::planning;

void DefinePlanningRun(py::module_ m) {
  py::class_<HeadCamera>(m, "HeadCamera", "Where the robot's head camera looks from (ScenarioCameraPose).")
      .def(py::init<>(), "1.3 m above the start stance, pitched 70 degrees below the horizon.")
      .def_readwrite("height", &HeadCamera::height, "m above the start stance, in (0, 10].")
      .def_readwrite("pitch_deg", &HeadCamera::pitch_deg, "Optical axis below the horizon, degrees, in (0, 90].")
      .def_readwrite("behind", &HeadCamera::behind, "m behind the start stance's midpoint along the heading.");
  m.def("ScenarioCameraPose", &ScenarioCameraPose, py::arg("start"), py::arg("camera") = HeadCamera(),
        "The left camera's 4x4 pose for a head camera over `start`, looking down along its heading.");
  m.def("ScenarioStereoScene", &ScenarioStereoScene, py::arg("scenario"), py::arg("seed") = 1,
        py::arg("obstacle_material") = "metal", py::arg("floor_material") = "asphalt",
        "The scenario's material regions and obstacles as a textured, labelled SyntheticStereoScene.");
  py::class_<SyntheticCamera>(m, "SyntheticCamera", "A synthetic stereo head camera for a scenario.")
      .def(py::init<>(), "320x240, 70 degrees, 12 cm baseline, noise variance 4, HeadCamera(), seed 1.")
      .def_readwrite("width", &SyntheticCamera::width, "Pixels, in [8, 4096].")
      .def_readwrite("height", &SyntheticCamera::height, "Pixels, in [8, 4096].")
      .def_readwrite("field_of_view_deg", &SyntheticCamera::field_of_view_deg, "Horizontal, in (10, 150).")
      .def_readwrite("baseline", &SyntheticCamera::baseline, "m, in (0, 1].")
      .def_readwrite("noise_variance", &SyntheticCamera::noise_variance, "Image noise (0..255 scale), >= 0.")
      .def_readwrite("head", &SyntheticCamera::head, "HeadCamera.")
      .def_readwrite("seed", &SyntheticCamera::seed, "Textures' seed.")
      .def("Calibration", &SyntheticCamera::Calibration, "StereoCalibration: square pixels, centred principal point.");
  m.def("ScenarioCamera", &ScenarioCamera, py::arg("scenario"), py::arg("camera"), py::arg("period"),
        "A SyntheticStereoSource of the scenario's scene held at the head camera's pose, one frame per period.");

  py::class_<PerceptionSetup>(m, "PerceptionSetup", "How the main diagram perceives (PerceptionSetupFromScenario).")
      .def(py::init<>(), "Defaults; set `grid` and `segmenter` before BuildMainDiagram.")
      .def_readwrite("calibration", &PerceptionSetup::calibration, "StereoCalibration.")
      .def_readwrite("matcher", &PerceptionSetup::matcher, "StereoMatcher.Options.")
      .def_readwrite("depth", &PerceptionSetup::depth, "DisparityToDepth.Options.")
      .def_property(
          "grid",
          [](const PerceptionSetup& s) -> py::object {
            return s.grid ? py::cast(perception::OccupancyGrid(*s.grid)) : py::none();
          },
          [](PerceptionSetup& s, const perception::OccupancyGrid& grid) {
            s.grid = std::make_shared<const perception::OccupancyGrid>(grid);
          },
          "The occupancy grid's prototype (a copy is read and stored).")
      .def_readwrite("occupancy", &PerceptionSetup::occupancy, "CostCurveSensorModel.Options.")
      .def_readwrite("period", &PerceptionSetup::period, "s between fused frames after the first.")
      .def_readwrite("registry", &PerceptionSetup::registry, "MaterialRegistry.")
      .def_property(
          "segmenter",
          [](const PerceptionSetup& s) { return std::const_pointer_cast<perception::MaterialSegmenter>(s.segmenter); },
          [](PerceptionSetup& s, std::shared_ptr<perception::MaterialSegmenter> segmenter) {
            s.segmenter = std::move(segmenter);
          },
          "MaterialSegmenter (required).")
      .def_readwrite("eta", &PerceptionSetup::eta, "The friction chance constraint's level.")
      .def_readwrite("num_threads", &PerceptionSetup::num_threads, "FrictionEstimator's threads (0: one per core).")
      .def_readwrite("terrain", &PerceptionSetup::terrain, "TerrainAssemblyOptions (its eta is set from `eta`).");
  m.def(
      "PerceptionSetupFromScenario",
      [](const FootstepScenario& scenario, const perception::StereoCalibration& calibration,
         std::shared_ptr<perception::MaterialSegmenter> segmenter, double max_depth) {
        return PerceptionSetupFromScenario(scenario, calibration, std::move(segmenter), max_depth);
      },
      py::arg("scenario"), py::arg("calibration"), py::arg("segmenter"), py::arg("max_depth") = 4.0,
      "An unknown grid over the scenario's area, its registry and eta, disparities for depths 0.5 m..max_depth.");

  py::class_<MainDiagram>(m, "MainDiagram", "The main diagram and its blocks (from BuildMainDiagram).")
      .def_property_readonly(
          "walk", [](const MainDiagram& d) { return &d.walk; }, py::return_value_policy::reference_internal,
          "WalkDiagram: its `diagram` is the whole main diagram.")
      .def_property_readonly(
          "diagram", [](const MainDiagram& d) { return d.walk.diagram.get(); },
          py::return_value_policy::reference_internal, "The Diagram.")
      .def_property_readonly(
          "camera", [](const MainDiagram& d) { return d.camera; }, py::return_value_policy::reference_internal,
          "The camera.")
      .def_property_readonly(
          "stereo", [](const MainDiagram& d) { return d.stereo; }, py::return_value_policy::reference_internal,
          "StereoMatcher.")
      .def_property_readonly(
          "depth", [](const MainDiagram& d) { return d.depth; }, py::return_value_policy::reference_internal,
          "DisparityToDepth.")
      .def_property_readonly(
          "occupancy", [](const MainDiagram& d) { return d.occupancy; },
          py::return_value_policy::reference_internal, "ConfidenceToOccupancy.")
      .def_property_readonly(
          "friction", [](const MainDiagram& d) { return d.friction; }, py::return_value_policy::reference_internal,
          "FrictionEstimator.")
      .def_property_readonly(
          "terrain", [](const MainDiagram& d) { return d.terrain; }, py::return_value_policy::reference_internal,
          "TerrainAssembler.");
  m.def(
      "BuildMainDiagram",
      [](const WalkSetup& walk, const PerceptionSetup& perception, py::object camera) {
        py::object main = py::cast(
            BuildMainDiagram(walk, perception, ReleaseFromPython<systems::System>(camera, "BuildMainDiagram")),
            py::return_value_policy::move);
        TieToOwner(camera, main);  // the camera's Python object now views a block of the main diagram
        return main;
      },
      py::arg("walk"), py::arg("perception"), py::arg("camera"),
      "camera -> stereo -> occupancy and friction -> terrain assembler -> the walk diagram. Takes the camera "
      "(a system with outputs left, right, left_colour, X_WC) over.");

  py::class_<MainRecord>(m, "MainRecord", "What a main-diagram run produced.")
      .def_readonly("walk", &MainRecord::walk, "WalkRecord.")
      .def_property_readonly(
          "terrain",
          [](const MainRecord& r) -> py::object { return r.terrain ? py::cast(TerrainMap(*r.terrain)) : py::none(); },
          "The assembled TerrainMap the plan was made on (a copy), or None.")
      .def_property_readonly(
          "grid",
          [](const MainRecord& r) -> py::object {
            return r.grid ? py::cast(perception::OccupancyGrid(*r.grid)) : py::none();
          },
          "The OccupancyGrid the terrain was assembled from (a copy), or None.")
      .def_readonly("image", &MainRecord::image, "The camera's left colour image (BGR, H x W x 3).")
      .def_readonly("material_probabilities", &MainRecord::material_probabilities,
                    "P(x_k = l_i) per pixel, registry order (H x W x labels).")
      .def_readonly("friction_quantile", &MainRecord::friction_quantile, "Q_{1-eta} per pixel (H x W).")
      .def_readonly("perception_seconds", &MainRecord::perception_seconds, "Wall time of the first frame.");
  m.def("RunMainDiagram", &RunMainDiagram, py::arg("main"), py::arg("options") = WalkRunOptions(),
        py::call_guard<py::gil_scoped_release>(),
        "Perceives the first frame, plans on it (footsteps, whole body, stabiliser), then walks it in the plant.");
}

}  // namespace cairn::python
