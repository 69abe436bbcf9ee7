// cairn.perception: synthetic scenes and their renderer and source system (Cairn::perception_synthetic); data-set
// loaders and scores (Cairn::perception_evaluation).

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cairn/perception/evaluation/material_segmentation_score.h"
#include "cairn/perception/evaluation/middlebury_pair.h"
#include "cairn/perception/evaluation/occupancy_score.h"
#include "cairn/perception/evaluation/stereo_evaluation.h"
#include "cairn/perception/synthetic/bars_scenario.h"
#include "cairn/perception/synthetic/occupancy_scenario.h"
#include "cairn/perception/synthetic/procedural_texture.h"
#include "cairn/perception/synthetic/synthetic_stereo_renderer.h"
#include "cairn/perception/synthetic/synthetic_stereo_scene.h"
#include "cairn/perception/synthetic/synthetic_stereo_source.h"
#include "cv_mat_caster.h"
#include "numpy_support.h"
#include "system_support.h"

namespace cairn::python {

using namespace cairn::perception;

namespace {

template <typename T>
py::cpp_function MatField(cv::Mat T::*field) {
  return py::cpp_function([field](const T& self) { return MatToArray(self.*field, false); });
}

py::array_t<std::uint8_t> Bytes(const std::vector<std::uint8_t>& values) {
  py::array_t<std::uint8_t> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

}  // namespace

void DefinePerceptionSyntheticEvaluation(py::module_ m) {
  // -------------------------------------------------------------------------------------------------------------
  // Synthetic scenes

  py::class_<ProceduralTexture> texture(m, "ProceduralTexture", "A deterministic intensity pattern over a surface.");
  py::enum_<ProceduralTexture::Kind>(texture, "Kind", "Pattern families.")
      .value("kNoise", ProceduralTexture::Kind::kNoise, "Multi-octave value noise.")
      .value("kChecker", ProceduralTexture::Kind::kChecker, "Checkerboard.")
      .value("kUniform", ProceduralTexture::Kind::kUniform, "Constant (textureless).");
  texture.def(py::init<>(), "Noise, 5 cm features, mean 128, contrast 90, seed 1.")
      .def_readwrite("kind", &ProceduralTexture::kind, "Pattern family.")
      .def_readwrite("scale", &ProceduralTexture::scale, "Feature size (m).")
      .def_readwrite("mean", &ProceduralTexture::mean, "Mean intensity.")
      .def_readwrite("contrast", &ProceduralTexture::contrast, "Peak deviation.")
      .def_readwrite("seed", &ProceduralTexture::seed, "Seed.")
      .def("Evaluate", &ProceduralTexture::Evaluate, py::arg("u"), py::arg("v"), "Intensity at (u, v).");

  py::class_<SyntheticStereoScene>(m, "SyntheticStereoScene", "Textured, labelled planes and boxes.")
      .def(py::init<>(), "Empty.")
      .def("AddPlane", &SyntheticStereoScene::AddPlane, py::arg("point"), py::arg("normal"), py::arg("texture"),
           py::arg("label"), "Adds an infinite plane; returns its index.")
      .def("AddBox", &SyntheticStereoScene::AddBox, py::arg("X_WB"), py::arg("half_extents"), py::arg("texture"),
           py::arg("label"), "Adds a box at pose X_WB (4x4); returns its index.")
      .def("Occupies", &SyntheticStereoScene::Occupies, py::arg("p_W"), py::arg("tolerance") = 0.0,
           "Ground-truth occupancy of a point.")
      .def("OccupiesCube", &SyntheticStereoScene::OccupiesCube, py::arg("center"), py::arg("size"),
           "Whether an axis-aligned cube overlaps any object.")
      .def("num_objects", &SyntheticStereoScene::num_objects, "Number of objects.");

  py::class_<SyntheticStereoFrame>(m, "SyntheticStereoFrame", "One rendered frame (read-only arrays, no copy).")
      .def_property_readonly("left", MatField(&SyntheticStereoFrame::left), "uint8 left image.")
      .def_property_readonly("right", MatField(&SyntheticStereoFrame::right), "uint8 right image.")
      .def_property_readonly("depth", MatField(&SyntheticStereoFrame::depth), "float32 depth (inf: sky).")
      .def_property_readonly("labels", MatField(&SyntheticStereoFrame::labels), "int32 labels (-1: sky).")
      .def_readonly("X_WC", &SyntheticStereoFrame::X_WC, "Left camera pose (4x4).");

  py::class_<SyntheticStereoRenderer>(m, "SyntheticStereoRenderer", "A deterministic stereo ray-caster.")
      .def(py::init<const StereoCalibration&, int, int, double, std::uint32_t>(), py::arg("calibration"),
           py::arg("width"), py::arg("height"), py::arg("noise_variance") = 0.0, py::arg("seed") = 1,
           "ValueError for a bad calibration or size.")
      .def("Render", &SyntheticStereoRenderer::Render, py::arg("scene"), py::arg("X_WC"), py::arg("frame_index") = 0,
           py::call_guard<py::gil_scoped_release>(), "Renders the pair seen from X_WC (4x4).")
      .def("calibration", &SyntheticStereoRenderer::calibration, "The calibration.")
      .def("width", &SyntheticStereoRenderer::width, "Image width.")
      .def("height", &SyntheticStereoRenderer::height, "Image height.");

  py::class_<SyntheticStereoSource, systems::LeafSystem>(
      m, "SyntheticStereoSource",
      "System rendering a scene along a camera trajectory: outputs `left`, `right`, `depth`, `labels` (Images), "
      "`X_WC` (4x4), `left_colour`, `right_colour`.")
      .def(py::init<SyntheticStereoScene, SyntheticStereoRenderer, std::vector<Eigen::Isometry3d>, double>(),
           py::arg("scene"), py::arg("renderer"), py::arg("trajectory"), py::arg("period"),
           "`trajectory`: a list of 4x4 camera poses; frame floor(t / period) at time t.")
      .def("FrameIndexAt", &SyntheticStereoSource::FrameIndexAt, py::arg("t"), "The frame shown at time t.")
      .def("num_frames", &SyntheticStereoSource::num_frames, "Frames.")
      .def("period", &SyntheticStereoSource::period, "Seconds per frame.")
      .def("get_left_output_port", PortGetter(&SyntheticStereoSource::get_left_output_port), "Output `left`.")
      .def("get_right_output_port", PortGetter(&SyntheticStereoSource::get_right_output_port), "Output `right`.")
      .def("get_depth_output_port", PortGetter(&SyntheticStereoSource::get_depth_output_port), "Output `depth`.")
      .def("get_pose_output_port", PortGetter(&SyntheticStereoSource::get_pose_output_port), "Output `X_WC`.");

  py::class_<OccupancyScenario>(m, "OccupancyScenario", "A synthetic occupancy experiment.")
      .def_static("FromYaml", &OccupancyScenario::FromYaml, py::arg("path"), "Reads a scenario file.")
      .def_static("LookAt", &OccupancyScenario::LookAt, py::arg("position"), py::arg("target"),
                  "The camera pose at `position` looking at `target`, +z up in the image (4x4).")
      .def_readonly("scene", &OccupancyScenario::scene, "The scene.")
      .def_readonly("calibration", &OccupancyScenario::calibration, "The camera.")
      .def_readonly("width", &OccupancyScenario::width, "Image width.")
      .def_readonly("height", &OccupancyScenario::height, "Image height.")
      .def_readonly("min_disparity", &OccupancyScenario::min_disparity, "Smallest disparity matched.")
      .def_readonly("max_disparity", &OccupancyScenario::max_disparity, "Largest disparity matched.")
      .def_readonly("noise_variance", &OccupancyScenario::noise_variance, "Image noise variance.")
      .def_readonly("trajectory", &OccupancyScenario::trajectory, "Camera poses (4x4).")
      .def_readonly("grid_min_corner", &OccupancyScenario::grid_min_corner, "Grid corner.")
      .def_readonly("grid_resolution", &OccupancyScenario::grid_resolution, "Cell side.")
      .def_readonly("grid_dims", &OccupancyScenario::grid_dims, "Cells per axis.");
  py::class_<BarsScenario>(m, "BarsScenario", "The repetitive-bars scene of thesis Figs. 4.7/4.8.")
      .def_static("Make", &BarsScenario::Make, py::arg("frames") = 20, "Builds it with `frames` camera poses.")
      .def("ToOccupancyScenario", &BarsScenario::ToOccupancyScenario, "As a generic OccupancyScenario.");

  // -------------------------------------------------------------------------------------------------------------
  // Evaluation

  m.def("LoadGrayImage", &LoadGrayImage, py::arg("path"), "Reads an image as uint8 grey; RuntimeError naming it.");
  m.def("LoadDisparityImage", py::overload_cast<const std::string&, double>(&LoadDisparityImage), py::arg("path"),
        py::arg("scale"), "A ground-truth disparity PNG (8- or 16-bit) divided by `scale` (float32, 0 = unknown).");
  m.def("LoadDisparityImage", py::overload_cast<const std::string&>(&LoadDisparityImage), py::arg("path"),
        "A 16-bit ground-truth disparity PNG at the KITTI scale (256 per pixel); an 8-bit file needs a scale.");
  m.def("OcclusionFromGroundTruth", &OcclusionFromGroundTruth, py::arg("left_disparity"), py::arg("right_disparity"),
        py::arg("tolerance") = 1.0, "uint8 occlusion mask (255 = occluded) from two ground truths.");
  py::class_<MiddleburyPair>(m, "MiddleburyPair", "A Middlebury-2001-style pair with ground truth.")
      .def_static("Load", &MiddleburyPair::Load, py::arg("folder"), py::arg("scale"),
                  "Loads im2/im6/disp2[/disp6].png; RuntimeError naming a missing file.")
      .def_property_readonly("left", MatField(&MiddleburyPair::left), "uint8 left image.")
      .def_property_readonly("right", MatField(&MiddleburyPair::right), "uint8 right image.")
      .def_property_readonly("gt_left", MatField(&MiddleburyPair::gt_left), "float32 left ground truth.")
      .def_property_readonly("gt_right", MatField(&MiddleburyPair::gt_right), "float32 right ground truth or empty.")
      .def_property_readonly("occluded", MatField(&MiddleburyPair::occluded), "uint8 occlusion mask or empty.");

  py::class_<StereoEvaluationOptions>(m, "StereoEvaluationOptions", "Which pixels count, what is an error.")
      .def(py::init<>(), "Threshold 1 px, border 10, interval 1.")
      .def_readwrite("bad_threshold", &StereoEvaluationOptions::bad_threshold, "Bad-pixel threshold (px).")
      .def_readwrite("border", &StereoEvaluationOptions::border, "Ignored border (px).")
      .def_readwrite("gt_interval", &StereoEvaluationOptions::gt_interval, "C(d in GT) interval.");
  py::class_<StereoEvaluation>(m, "StereoEvaluation", "The thesis' criteria for one pair.")
      .def_readonly("bad_pixel_rate", &StereoEvaluation::bad_pixel_rate, "Integer WTA bad-pixel rate.")
      .def_readonly("bad_pixel_rate_subpixel", &StereoEvaluation::bad_pixel_rate_subpixel, "Sub-pixel rate.")
      .def_readonly("auc", &StereoEvaluation::auc, "ROC AUC of the confidence ranking (lower is better).")
      .def_readonly("auc_optimal", &StereoEvaluation::auc_optimal, "AUC of a perfect ranking.")
      .def_readonly("c_gt_badpx", &StereoEvaluation::c_gt_badpx, "Mean C(d in GT) over bad pixels.")
      .def_readonly("num_pixels", &StereoEvaluation::num_pixels, "Evaluated pixels.")
      .def_readonly("num_bad", &StereoEvaluation::num_bad, "Bad pixels.");
  m.def("RocAuc", &RocAuc, py::arg("confidence"), py::arg("is_error"), "Area under the ROC curve of a ranking.");
  m.def("OptimalAuc", &OptimalAuc, py::arg("error_rate"), "The AUC of a perfect ranking.");
  m.def("EvaluateStereo", &EvaluateStereo, py::arg("confidence"), py::arg("wta"), py::arg("ground_truth"),
        py::arg("occluded") = cv::Mat(), py::arg("options") = StereoEvaluationOptions(),
        py::call_guard<py::gil_scoped_release>(), "Evaluates a confidence volume and its WTA against ground truth.");

  py::class_<OccupancyScore>(m, "OccupancyScore", "Precision and recall of a grid.")
      .def_readonly("precision", &OccupancyScore::precision, "tp / (tp + fp).")
      .def_readonly("recall", &OccupancyScore::recall, "tp / n.")
      .def_readonly("true_positives", &OccupancyScore::true_positives, "tp.")
      .def_readonly("false_positives", &OccupancyScore::false_positives, "fp.")
      .def_readonly("num_occupied", &OccupancyScore::num_occupied, "n.");
  m.def(
      "ScoreOccupancy",
      [](const OccupancyGrid& grid, const py::array_t<std::uint8_t, py::array::forcecast>& truth, double threshold) {
        const std::vector<std::uint8_t> flags(truth.data(), truth.data() + truth.size());
        return ScoreOccupancy(grid, flags, threshold);
      },
      py::arg("grid"), py::arg("truth"), py::arg("threshold") = 0.5,
      "Scores `grid` against one truth flag per cell (any shape, cell order).");
  m.def(
      "RasterizeScene", [](const SyntheticStereoScene& scene, const OccupancyGrid& grid) { return Bytes(RasterizeScene(scene, grid)); },
      py::arg("scene"), py::arg("grid"), "Ground-truth occupancy per cell (uint8 array, cell order).");

  py::class_<MaterialSegmentationScore>(m, "MaterialSegmentationScore",
                                        "Accuracy and calibration of material probabilities over images.")
      .def(py::init<int, int>(), py::arg("num_labels"), py::arg("num_bins") = 10, "ValueError for num_labels <= 0.")
      .def("Add", &MaterialSegmentationScore::Add, py::arg("probabilities"), py::arg("truth"), py::arg("ignore") = 255,
           "Adds one image.")
      .def("num_pixels", &MaterialSegmentationScore::num_pixels, "Pixels scored.")
      .def("pixel_accuracy", &MaterialSegmentationScore::pixel_accuracy, "Global pixel accuracy.")
      .def("class_average_accuracy", &MaterialSegmentationScore::class_average_accuracy, "Mean per-class recall.")
      .def("expected_calibration_error", &MaterialSegmentationScore::expected_calibration_error, "ECE.")
      .def("mean_negative_log_likelihood", &MaterialSegmentationScore::mean_negative_log_likelihood, "Mean NLL.");
}

}  // namespace cairn::python
