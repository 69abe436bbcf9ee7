// cairn.perception: images (numpy <-> cv::Mat), stereo cost volumes, confidence, winner-take-all, occupancy grids
// and their systems.

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/occupancy/confidence_to_occupancy.h"
#include "cairn/perception/occupancy/cost_curve_sensor_model.h"
#include "cairn/perception/occupancy/occupancy_grid.h"
#include "cairn/perception/occupancy/wta_range_sensor_model.h"
#include "cairn/perception/stereo/compute_confidence.h"
#include "cairn/perception/stereo/compute_cost_volume.h"
#include "cairn/perception/stereo/confidence_model.h"
#include "cairn/perception/stereo/cost_samples.h"
#include "cairn/perception/stereo/cost_volume_options.h"
#include "cairn/perception/stereo/disparity_to_depth.h"
#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/histogram_sensor_model.h"
#include "cairn/perception/stereo/stereo_calibration.h"
#include "cairn/perception/stereo/stereo_matcher.h"
#include "cairn/perception/stereo/stereo_source.h"
#include "cairn/perception/stereo/winner_take_all.h"
#include "cv_mat_caster.h"
#include "numpy_support.h"
#include "system_support.h"

namespace cairn::python {

using namespace cairn::perception;

namespace {

// "Image": cv::Mat values on ports and in state, numpy arrays in Python. Values that C++ keeps are always copies
// (the array's memory belongs to Python).
void RegisterImageType() {
  AbstractValueType type;
  type.name = "Image";
  type.type = std::type_index(typeid(cv::Mat));
  type.to_python = [](const systems::AbstractValue& value, bool copy, py::handle) -> py::object {
    const auto& image = value.get_value<cv::Mat>();
    return copy ? MatToArray(image.clone()) : MatToArray(image, false);
  };
  type.from_python = [](py::handle object) -> std::unique_ptr<systems::AbstractValue> {
    if (!py::isinstance<py::array>(object)) throw py::cast_error("not a numpy array");
    return std::make_unique<systems::Value<cv::Mat>>(ArrayToMat(object).clone());
  };
  type.make_constant_source = &internal::MakeConstantValueSource<cv::Mat>;
  RegisterAbstractValueType(std::move(type));
}

py::array_t<float> FloatArray(const std::vector<float>& values) {
  py::array_t<float> out(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// A read-only (H, W, D) view of a volume's values, kept alive by the volume's Python object.
py::array VolumeView(py::object self) {
  const auto& volume = self.cast<const DisparityVolume&>();
  const auto item = static_cast<py::ssize_t>(sizeof(float));
  const auto d = static_cast<py::ssize_t>(volume.num_disparities());
  const auto w = static_cast<py::ssize_t>(volume.width());
  return ArrayView<float>(volume.data().data(), {volume.height(), w, d}, {w * d * item, d * item, item}, self, false);
}

DisparityVolume VolumeFromArray(const py::array_t<float, py::array::forcecast | py::array::c_style>& values,
                                int min_disparity) {
  if (values.ndim() != 3) throw py::value_error("DisparityVolume.FromArray: expected an (H, W, D) array");
  const auto h = static_cast<int>(values.shape(0));
  const auto w = static_cast<int>(values.shape(1));
  const auto d = static_cast<int>(values.shape(2));
  DisparityVolume volume(h, w, min_disparity, min_disparity + d - 1);
  const float* in = values.data();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::copy(in, in + d, volume.mutable_curve(y, x));
      in += d;
    }
  }
  return volume;
}

std::size_t CheckCellIndex(const OccupancyGrid& grid, long long index) {
  if (index < 0 || static_cast<std::size_t>(index) >= grid.num_cells()) {
    throw py::index_error("cell index " + cairn::FormatShort(index) + " is out of range [0, " +
                          cairn::FormatShort(grid.num_cells()) + ")");
  }
  return static_cast<std::size_t>(index);
}

void CheckCell(const OccupancyGrid& grid, const Eigen::Vector3i& cell) {
  for (int i = 0; i < 3; ++i) {
    if (cell[i] < 0 || cell[i] >= grid.dims()[i]) {
      throw py::index_error("cell (" + cairn::FormatShort(cell.x()) + ", " + cairn::FormatShort(cell.y()) + ", " +
                            cairn::FormatShort(cell.z()) + ") is outside the grid's " + cairn::FormatShort(grid.dims().x()) +
                            " x " + cairn::FormatShort(grid.dims().y()) + " x " + cairn::FormatShort(grid.dims().z()) +
                            " cells");
    }
  }
}

// Per-cell values as a (nz, ny, nx) array (a copy: cell (x, y, z) is [z, y, x]).
template <typename Value>
py::array_t<double> GridArray(const OccupancyGrid& grid, Value value) {
  const Eigen::Vector3i& dims = grid.dims();
  py::array_t<double> out({static_cast<py::ssize_t>(dims.z()), static_cast<py::ssize_t>(dims.y()),
                           static_cast<py::ssize_t>(dims.x())});
  double* data = out.mutable_data();
  for (std::size_t i = 0; i < grid.num_cells(); ++i) data[i] = value(i);
  return out;
}

template <typename T>
py::cpp_function MatProperty(const cv::Mat T::*field) {
  return py::cpp_function([field](const T& self) { return MatToArray(self.*field, false); });
}

}  // namespace

void DefinePerceptionStereoOccupancy(py::module_ m) {
  RegisterImageType();

  // -------------------------------------------------------------------------------------------------------------
  // Stereo

  py::enum_<CostFunction>(m, "CostFunction", "Window cost functions.")
      .value("kSsd", CostFunction::kSsd, "Sum of squared differences.")
      .value("kBtSad", CostFunction::kBtSad, "Sum of Birchfield-Tomasi dissimilarities.");
  py::enum_<Prefilter>(m, "Prefilter", "Image prefilters.")
      .value("kNone", Prefilter::kNone, "Grey images as they are.")
      .value("kSobel", Prefilter::kSobel, "Clipped horizontal Sobel derivative.");
  m.def("ParseCostFunction", &ParseCostFunction, py::arg("name"), "\"ssd\" or \"btsad\".");
  m.def("CostFunctionName", &CostFunctionName, py::arg("cost"), "\"ssd\" or \"btsad\".");
  m.def("ParsePrefilter", &ParsePrefilter, py::arg("name"), "\"sobel\" or \"none\".");

  py::class_<CostVolumeOptions>(m, "CostVolumeOptions",
                                "Cost function, window, disparity range and prefilter (defaults: BTSAD, 9x9 window, "
                                "9x9 Sobel clipped at 31, disparities 0..63).")
      .def(py::init<>(), "The thesis' defaults.")
      .def_readwrite("cost", &CostVolumeOptions::cost, "Window cost function.")
      .def_readwrite("window", &CostVolumeOptions::window, "Odd window side.")
      .def_readwrite("min_disparity", &CostVolumeOptions::min_disparity, "Smallest disparity.")
      .def_readwrite("max_disparity", &CostVolumeOptions::max_disparity, "Largest disparity.")
      .def_readwrite("prefilter", &CostVolumeOptions::prefilter, "Prefilter.")
      .def_readwrite("prefilter_size", &CostVolumeOptions::prefilter_size, "Sobel aperture 3, 5, 7 or 9.")
      .def_readwrite("prefilter_cap", &CostVolumeOptions::prefilter_cap, "Clip 1..63.")
      .def_readwrite("num_threads", &CostVolumeOptions::num_threads, "Threads (0: one per core).")
      .def("Validate", &CostVolumeOptions::Validate,
           py::arg("image_width") = CostVolumeOptions::kUnknownImageSize,
           py::arg("image_height") = CostVolumeOptions::kUnknownImageSize,
           "ValueError naming a bad value for this image size (-1: a side not known yet).");

  py::class_<DisparityVolume>(m, "DisparityVolume",
                              "An H x W x D array of float32 (a cost or confidence curve per pixel over "
                              "[min_disparity, max_disparity]); array() is a read-only view of its values.")
      .def(py::init<>(), "Empty.")
      .def(py::init<int, int, int, int>(), py::arg("height"), py::arg("width"), py::arg("min_disparity"),
           py::arg("max_disparity"), "Zeros; ValueError for bad sizes.")
      .def_static("FromArray", &VolumeFromArray, py::arg("values"), py::arg("min_disparity") = 0,
                  "A volume holding a copy of an (H, W, D) array.")
      .def("height", &DisparityVolume::height, "Rows.")
      .def("width", &DisparityVolume::width, "Columns.")
      .def("min_disparity", &DisparityVolume::min_disparity, "Smallest disparity.")
      .def("max_disparity", &DisparityVolume::max_disparity, "Largest disparity.")
      .def("num_disparities", &DisparityVolume::num_disparities, "D.")
      .def(
          "at",
          [](const DisparityVolume& v, int y, int x, int k) {
            if (y < 0 || y >= v.height() || x < 0 || x >= v.width() || k < 0 || k >= v.num_disparities()) {
              throw py::index_error("DisparityVolume.at: (" + cairn::FormatShort(y) + ", " + cairn::FormatShort(x) + ", " +
                                    cairn::FormatShort(k) + ") is outside the volume");
            }
            return v.at(y, x, k);
          },
          py::arg("y"), py::arg("x"), py::arg("k"), "Value at pixel (x, y), disparity index k.")
      .def("array", &VolumeView, "The values as a read-only (H, W, D) float32 view (no copy) keeping this alive.")
      .def("__array__", [](py::object self) { return VolumeView(self); }, "numpy.asarray support (a view).");

  py::class_<WtaOptions>(m, "WtaOptions", "Winner-take-all settings.")
      .def(py::init<>(), "Sub-pixel refinement on, left-right tolerance 1.")
      .def_readwrite("subpixel", &WtaOptions::subpixel, "Parabola refinement.")
      .def_readwrite("lr_tolerance", &WtaOptions::lr_tolerance, "Left-right agreement tolerance.")
      .def_readwrite("num_threads", &WtaOptions::num_threads, "Threads (0: one per core).");
  py::class_<WtaResult>(m, "WtaResult",
                        "Per-pixel winner-take-all output; each field is a read-only array sharing the result's "
                        "buffer (no copy).")
      .def(py::init<>(), "Empty.")
      .def_property_readonly("disparity", MatProperty(&WtaResult::disparity), "float32 disparity, NaN if invalid.")
      .def_property_readonly("best_index", MatProperty(&WtaResult::best_index), "int32 index k of the minimum, -1.")
      .def_property_readonly("best_cost", MatProperty(&WtaResult::best_cost), "float32 minimum cost.")
      .def_property_readonly("peak_ratio", MatProperty(&WtaResult::peak_ratio), "float32 peak ratio (>= 1).")
      .def_property_readonly("right_best_index", MatProperty(&WtaResult::right_best_index), "int32 right winner.")
      .def_property_readonly("lr_consistent", MatProperty(&WtaResult::lr_consistent), "uint8, 255 where consistent.");

  m.def("ToGray8", [](const cv::Mat& image) { return ToGray8(image, "ToGray8: the"); }, py::arg("image"),
        "8-bit grey from 8-bit grey or BGR; ValueError for other types.");
  m.def("SobelPrefilter", &SobelPrefilter, py::arg("gray"), py::arg("size"), py::arg("cap"),
        "The clipped, shifted horizontal Sobel derivative of a uint8 grey image.");
  m.def(
      "ComputeCostVolume",
      [](const cv::Mat& left, const cv::Mat& right, const CostVolumeOptions& options) {
        DisparityVolume costs;
        py::gil_scoped_release release;
        ComputeCostVolume(left, right, options, &costs);
        return costs;
      },
      py::arg("left"), py::arg("right"), py::arg("options") = CostVolumeOptions(),
      "The cost volume of a rectified pair (uint8 grey or BGR arrays, no copy), without the GIL; +inf where x - d "
      "leaves the right image. ValueError for bad images or options.");
  m.def(
      "ComputeWinnerTakeAll",
      [](const DisparityVolume& costs, const WtaOptions& options) {
        WtaResult result;
        py::gil_scoped_release release;
        ComputeWinnerTakeAll(costs, options, &result);
        return result;
      },
      py::arg("costs"), py::arg("options") = WtaOptions(), "Winner-take-all disparities of a cost volume.");
  m.def(
      "ComputeCostVolumeAndWinnerTakeAll",
      [](const cv::Mat& left, const cv::Mat& right, const CostVolumeOptions& options, const WtaOptions& wta_options) {
        DisparityVolume costs;
        WtaResult wta;
        {
          py::gil_scoped_release release;
          ComputeCostVolumeAndWinnerTakeAll(left, right, options, wta_options, &costs, &wta);
        }
        return py::make_tuple(std::move(costs), std::move(wta));
      },
      py::arg("left"), py::arg("right"), py::arg("options") = CostVolumeOptions(),
      py::arg("wta_options") = WtaOptions(), "(costs, wta) in one pass, identical to the two calls.");

  py::enum_<ConfidenceModelType>(m, "ConfidenceModelType", "Likelihood families of thesis 4.3.")
      .value("kMatthies", ConfidenceModelType::kMatthies, "Gaussian (SSD) / Laplace (SAD) pixel differences.")
      .value("kMerrell", ConfidenceModelType::kMerrell, "Costs Gaussian around the minimum.")
      .value("kExponential", ConfidenceModelType::kExponential, "Exponentially distributed costs.")
      .value("kHistogram", ConfidenceModelType::kHistogram, "Histogram sensor model.");
  m.def("ParseConfidenceModelType", &ParseConfidenceModelType, py::arg("name"),
        "\"matthies\", \"merrell\", \"exp\" or \"hsm\".");
  m.def("ConfidenceModelTypeName", &ConfidenceModelTypeName, py::arg("type"), "The type's name.");

  py::class_<HistogramSensorModel>(m, "HistogramSensorModel", "A histogram of costs at trusted disparities.")
      .def_static("FromSamples", &HistogramSensorModel::FromSamples, py::arg("samples"), py::arg("pseudo_count") = 1.0,
                  "Trains from finite non-negative cost samples.")
      .def("LogDensity", &HistogramSensorModel::LogDensity, py::arg("cost"), "log p(E = cost) up to a constant.")
      .def("bin_width", &HistogramSensorModel::bin_width, "Bin width.")
      .def("counts", &HistogramSensorModel::counts, "Samples per bin.")
      .def("num_samples", &HistogramSensorModel::num_samples, "Training samples.");

  py::class_<ConfidenceModel>(m, "ConfidenceModel", "A likelihood model p(E_d | d) for ComputeConfidence.")
      .def_static("Matthies", &ConfidenceModel::Matthies, py::arg("cost"), py::arg("parameter"), "Matthies' model.")
      .def_static("Merrell", &ConfidenceModel::Merrell, py::arg("cost"), py::arg("sigma2"), "Merrell's model.")
      .def_static("Exponential", &ConfidenceModel::Exponential, py::arg("cost"), py::arg("mu"), "Exponential model.")
      .def_static("Histogram", &ConfidenceModel::Histogram, py::arg("cost"), py::arg("histogram"),
                  "Histogram sensor model.")
      .def_static("Parametric", &ConfidenceModel::Parametric, py::arg("type"), py::arg("cost"), py::arg("parameter"),
                  "A parametric model with a fixed parameter.")
      .def_static("FitMaximumLikelihood", &ConfidenceModel::FitMaximumLikelihood, py::arg("type"), py::arg("cost"),
                  py::arg("samples"), "The maximum-likelihood model from cost samples.")
      .def("type", &ConfidenceModel::type, "The family.")
      .def("cost_function", &ConfidenceModel::cost_function, "The cost function.")
      .def("parameter", &ConfidenceModel::parameter, "The parameter (NaN for histograms).")
      .def("LogLikelihood", &ConfidenceModel::LogLikelihood, py::arg("cost"), py::arg("min_cost"),
           "log p(E_d = cost | d) up to a constant.")
      .def("Describe", &ConfidenceModel::Describe, "E.g. \"merrell(sigma2=1.2e+04)\".");

  m.def(
      "ComputeConfidence",
      [](const DisparityVolume& costs, const ConfidenceModel& model, int num_threads) {
        DisparityVolume confidence;
        py::gil_scoped_release release;
        ComputeConfidence(costs, model, &confidence, num_threads);
        return confidence;
      },
      py::arg("costs"), py::arg("model"), py::arg("num_threads") = 0,
      "C(d) for every pixel and disparity (sums to one per pixel), without the GIL.");
  m.def(
      "CollectConsistentWtaCosts",
      [](const DisparityVolume& costs, const WtaResult& wta) {
        std::vector<float> samples;
        CollectConsistentWtaCosts(costs, wta, &samples);
        return FloatArray(samples);
      },
      py::arg("costs"), py::arg("wta"), "Minimum costs of left-right consistent pixels (float32 array).");
  m.def(
      "CollectGroundTruthCosts",
      [](const DisparityVolume& costs, const cv::Mat& ground_truth, const cv::Mat& mask) {
        std::vector<float> samples;
        CollectGroundTruthCosts(costs, ground_truth, mask, &samples);
        return FloatArray(samples);
      },
      py::arg("costs"), py::arg("ground_truth"), py::arg("mask") = cv::Mat(),
      "Costs at ground-truth disparities (float32 array).");

  py::class_<StereoCalibration>(m, "StereoCalibration", "Rectified pinhole intrinsics and baseline.")
      .def(py::init<>(), "fx = fy = 500, (cx, cy) = (320, 240), baseline 0.1 m.")
      .def(py::init([](double fx, double fy, double cx, double cy, double baseline) {
             return StereoCalibration{fx, fy, cx, cy, baseline};
           }),
           py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"), py::arg("baseline"), "From values.")
      .def_readwrite("fx", &StereoCalibration::fx, "Focal length x (pixels).")
      .def_readwrite("fy", &StereoCalibration::fy, "Focal length y (pixels).")
      .def_readwrite("cx", &StereoCalibration::cx, "Principal point x.")
      .def_readwrite("cy", &StereoCalibration::cy, "Principal point y.")
      .def_readwrite("baseline", &StereoCalibration::baseline, "Baseline (metres).")
      .def("Validate", &StereoCalibration::Validate, "ValueError naming a non-positive value.")
      .def("depth_times_disparity", &StereoCalibration::depth_times_disparity, "fx * baseline.");

  py::class_<StereoMatcher, systems::LeafSystem> matcher(
      m, "StereoMatcher",
      "System: inputs `left`, `right` (Image, uint8 grey); outputs `cost_volume`, `wta`, `confidence` "
      "(DisparityVolume, WtaResult, DisparityVolume) and `model` (ConfidenceModel).");
  py::class_<StereoMatcher::Options>(matcher, "Options", "How to match.")
      .def(py::init<>(), "Defaults; the model parameter is fitted per pair.")
      .def_readwrite("cost_volume", &StereoMatcher::Options::cost_volume, "CostVolumeOptions.")
      .def_readwrite("wta", &StereoMatcher::Options::wta, "WtaOptions.")
      .def_readwrite("model", &StereoMatcher::Options::model, "ConfidenceModelType.")
      .def_readwrite("parameter", &StereoMatcher::Options::parameter, "Fixed parameter, or NaN to fit.");
  matcher.def(py::init<const StereoMatcher::Options&>(), py::arg("options") = StereoMatcher::Options(),
              "ValueError for bad options.")
      .def("get_left_input_port", PortGetter(&StereoMatcher::get_left_input_port), "Input `left`.")
      .def("get_right_input_port", PortGetter(&StereoMatcher::get_right_input_port), "Input `right`.")
      .def("get_cost_volume_output_port", PortGetter(&StereoMatcher::get_cost_volume_output_port), "Output `cost_volume`.")
      .def("get_wta_output_port", PortGetter(&StereoMatcher::get_wta_output_port), "Output `wta`.")
      .def("get_confidence_output_port", PortGetter(&StereoMatcher::get_confidence_output_port), "Output `confidence`.")
      .def("get_model_output_port", PortGetter(&StereoMatcher::get_model_output_port), "Output `model`.");

  py::class_<DisparityToDepth, systems::LeafSystem> to_depth(
      m, "DisparityToDepth",
      "System: input `wta` (WtaResult), output `depth` (float32 image, fx * baseline / d where the winner is "
      "trusted, NaN elsewhere).");
  py::class_<DisparityToDepth::Options>(to_depth, "Options", "Which winners are trusted.")
      .def(py::init<>(), "Left-right check on, any peak ratio.")
      .def_readwrite("require_left_right", &DisparityToDepth::Options::require_left_right, "Left-right check.")
      .def_readwrite("min_peak_ratio", &DisparityToDepth::Options::min_peak_ratio, "Smallest peak ratio (>= 1).");
  to_depth
      .def(py::init<const StereoCalibration&, const DisparityToDepth::Options&>(), py::arg("calibration"),
           py::arg("options") = DisparityToDepth::Options(), "ValueError for a bad calibration or peak ratio.")
      .def("calibration", &DisparityToDepth::calibration, "The calibration.")
      .def("options", &DisparityToDepth::options, "The options.")
      .def(
          "Convert",
          [](const DisparityToDepth& self, const WtaResult& wta) {
            cv::Mat depth;
            self.Convert(wta, &depth);
            return depth;
          },
          py::arg("wta"), "The output's computation: depth image of a WtaResult; ValueError for mismatched images.")
      .def("get_wta_input_port", PortGetter(&DisparityToDepth::get_wta_input_port), "Input `wta`.")
      .def("get_depth_output_port", PortGetter(&DisparityToDepth::get_depth_output_port), "Output `depth`.");

  py::class_<StereoSource, systems::LeafSystem>(
      m, "StereoSource",
      "System playing back rectified pairs from a YAML sequence: outputs `left`, `right` (Image) and `X_WC` "
      "(4x4 pose); frame floor(t / period) at time t.")
      .def(py::init<const std::string&, double>(), py::arg("yaml_path"), py::arg("period"),
           "Reads and checks every image; RuntimeError naming the file and the problem.")
      .def("calibration", &StereoSource::calibration, "The calibration.")
      .def("num_frames", &StereoSource::num_frames, "Frames.")
      .def("period", &StereoSource::period, "Seconds per frame.")
      .def("FrameIndexAt", &StereoSource::FrameIndexAt, py::arg("t"), "The frame shown at time t.")
      .def("get_left_output_port", PortGetter(&StereoSource::get_left_output_port), "Output `left`.")
      .def("get_right_output_port", PortGetter(&StereoSource::get_right_output_port), "Output `right`.")
      .def("get_pose_output_port", PortGetter(&StereoSource::get_pose_output_port), "Output `X_WC`.");

  // -------------------------------------------------------------------------------------------------------------
  // Occupancy

  py::class_<OccupancyGrid> grid(m, "OccupancyGrid",
                                 "A dense 3-D grid of log-odds of occupancy (x fastest), updated by Bayes' rule and "
                                 "clamped (picklable).");
  py::class_<OccupancyGrid::Options>(grid, "Options", "Clamping of the stored log-odds.")
      .def(py::init<>(), "OctoMap's 0.12 / 0.97.")
      .def_readwrite("min_log_odds", &OccupancyGrid::Options::min_log_odds, "Lower clamp.")
      .def_readwrite("max_log_odds", &OccupancyGrid::Options::max_log_odds, "Upper clamp.");
  grid.def(py::init<const Eigen::Vector3d&, double, const Eigen::Vector3i&, const OccupancyGrid::Options&>(),
           py::arg("min_corner"), py::arg("resolution"), py::arg("dims"), py::arg("options") = OccupancyGrid::Options(),
           "Every cell at probability 0.5; ValueError for bad sizes.")
      .def("min_corner", [](const OccupancyGrid& g) { return Eigen::Vector3d(g.min_corner()); }, "Minimum corner.")
      .def("max_corner", &OccupancyGrid::max_corner, "Maximum corner.")
      .def("resolution", &OccupancyGrid::resolution, "Cell side (metres).")
      .def("dims", [](const OccupancyGrid& g) { return Eigen::Vector3i(g.dims()); }, "Cells per axis (x, y, z).")
      .def("num_cells", &OccupancyGrid::num_cells, "Number of cells.")
      .def("CellOf", &OccupancyGrid::CellOf, py::arg("p_W"), "The cell (x, y, z) containing p_W, or None.")
      .def(
          "Index",
          [](const OccupancyGrid& g, const Eigen::Vector3i& cell) {
            CheckCell(g, cell);
            return g.Index(cell);
          },
          py::arg("cell"), "Linear index of a cell; IndexError outside the grid.")
      .def(
          "Cell", [](const OccupancyGrid& g, long long index) { return g.Cell(CheckCellIndex(g, index)); },
          py::arg("index"), "The cell of a linear index.")
      .def(
          "CellCenter",
          [](const OccupancyGrid& g, const Eigen::Vector3i& cell) {
            CheckCell(g, cell);
            return g.CellCenter(cell);
          },
          py::arg("cell"), "Centre of a cell.")
      .def(
          "log_odds", [](const OccupancyGrid& g, long long index) { return g.log_odds(CheckCellIndex(g, index)); },
          py::arg("index"), "Stored log-odds of a cell.")
      .def(
          "probability", [](const OccupancyGrid& g, long long index) { return g.probability(CheckCellIndex(g, index)); },
          py::arg("index"), "Occupancy probability of a cell.")
      .def("Probability", &OccupancyGrid::Probability, py::arg("p_W"), "Probability at a point (0.5 outside).")
      .def(
          "Update",
          [](OccupancyGrid& g, long long index, float measurement) { g.Update(CheckCellIndex(g, index), measurement); },
          py::arg("index"), py::arg("measurement_log_odds"), "Bayes update of one cell, then clamping.")
      .def("Clear", &OccupancyGrid::Clear, "Every cell back to 0.5.")
      .def(
          "OccupiedCells",
          [](const OccupancyGrid& g, double threshold) {
            const std::vector<std::size_t> cells = g.OccupiedCells(threshold);
            py::array_t<std::uint64_t> out(static_cast<py::ssize_t>(cells.size()));
            std::copy(cells.begin(), cells.end(), out.mutable_data());
            return out;
          },
          py::arg("threshold") = 0.5, "Linear indices of cells above `threshold` (uint64 array, ascending).")
      .def(
          "OccupiedPoints", [](const OccupancyGrid& g, double threshold) { return StackRows(g.OccupiedPoints(threshold)); },
          py::arg("threshold") = 0.5, "Centres of the occupied cells, (n, 3).")
      .def("CastRay", &OccupancyGrid::CastRay, py::arg("origin"), py::arg("direction"), py::arg("max_range"),
           py::arg("threshold") = 0.5, "First occupied cell centre along a ray, or None.")
      .def("PlyText", &OccupancyGrid::PlyText, py::arg("threshold") = 0.5,
           "The occupied cells as the text of an ASCII PLY point cloud.")
      .def("WritePly", &OccupancyGrid::WritePly, py::arg("path"), py::arg("threshold") = 0.5,
           "Writes PlyText() to `path` atomically (an earlier file stays whole if the write fails).")
      .def(
          "log_odds_array",
          [](const OccupancyGrid& g) { return GridArray(g, [&g](std::size_t i) { return double(g.log_odds(i)); }); },
          "Every cell's log-odds as an (nz, ny, nx) float64 array: a copy (the grid stores float32 internally), "
          "cell (x, y, z) at [z, y, x].")
      .def(
          "probabilities", [](const OccupancyGrid& g) { return GridArray(g, [&g](std::size_t i) { return g.probability(i); }); },
          "Every cell's probability as an (nz, ny, nx) array (a copy).")
      .def(py::pickle(
               [](const OccupancyGrid& g) {
                 std::vector<float> values(g.num_cells());
                 for (std::size_t i = 0; i < values.size(); ++i) values[i] = g.log_odds(i);
                 return py::make_tuple(Eigen::Vector3d(g.min_corner()), g.resolution(), Eigen::Vector3i(g.dims()),
                                       FloatArray(values));
               },
               [](const py::tuple& t) {
                 OccupancyGrid g(t[0].cast<Eigen::Vector3d>(), t[1].cast<double>(), t[2].cast<Eigen::Vector3i>());
                 const auto values = t[3].cast<py::array_t<float>>();
                 if (static_cast<std::size_t>(values.size()) != g.num_cells()) {
                   throw std::runtime_error("OccupancyGrid: bad pickle state");
                 }
                 // Re-applying the stored log-odds to a 0.5 grid reproduces them (clamps only restrict the range).
                 for (std::size_t i = 0; i < g.num_cells(); ++i) g.Update(i, values.data()[i]);
                 return g;
               }),
           "Pickles extent, resolution and log-odds (default clamps).");

  py::class_<CostCurveSensorModel> cost_curve(m, "CostCurveSensorModel",
                                              "Occupancy from whole-range stereo confidence (thesis eqs. 4.13-4.17).");
  py::class_<CostCurveSensorModel::Options>(cost_curve, "Options", "Limits and threading.")
      .def(py::init<>(), "0.12 / 0.97, visibility 0.25.")
      .def_readwrite("min_probability", &CostCurveSensorModel::Options::min_probability, "Lower clamp.")
      .def_readwrite("max_probability", &CostCurveSensorModel::Options::max_probability, "Upper clamp.")
      .def_readwrite("min_visibility", &CostCurveSensorModel::Options::min_visibility, "Cells less visible are left.")
      .def_readwrite("num_threads", &CostCurveSensorModel::Options::num_threads, "Threads (0: one per core).");
  cost_curve.def(py::init<const CostCurveSensorModel::Options&>(), py::arg("options") = CostCurveSensorModel::Options(),
                 "ValueError for bad limits.")
      .def("Integrate", &CostCurveSensorModel::Integrate, py::arg("confidence"), py::arg("calibration"),
           py::arg("X_WC"), py::arg("grid"), py::call_guard<py::gil_scoped_release>(),
           "Integrates one frame of confidence into `grid` (changed in place) at camera pose X_WC (4x4), without "
           "the GIL.");

  py::class_<WtaRangeSensorModel> wta_model(m, "WtaRangeSensorModel",
                                            "The traditional range-sensor occupancy model on WTA disparities.");
  py::class_<WtaRangeSensorModel::Options>(wta_model, "Options", "Parameters.")
      .def(py::init<>(), "sigma 0.5 px.")
      .def_readwrite("sigma_disparity", &WtaRangeSensorModel::Options::sigma_disparity, "Range sigma (px).")
      .def_readwrite("min_peak_ratio", &WtaRangeSensorModel::Options::min_peak_ratio, "Peak-ratio filter.")
      .def_readwrite("require_lr_consistency", &WtaRangeSensorModel::Options::require_lr_consistency,
                     "Drop left-right inconsistent pixels.")
      .def_readwrite("min_probability", &WtaRangeSensorModel::Options::min_probability, "Lower clamp.")
      .def_readwrite("max_probability", &WtaRangeSensorModel::Options::max_probability, "Upper clamp.")
      .def_readwrite("min_visibility", &WtaRangeSensorModel::Options::min_visibility, "Visibility threshold.")
      .def_readwrite("num_threads", &WtaRangeSensorModel::Options::num_threads, "Threads.");
  wta_model.def(py::init<const WtaRangeSensorModel::Options&>(), py::arg("options") = WtaRangeSensorModel::Options(),
                "ValueError for bad parameters.")
      .def("Integrate", &WtaRangeSensorModel::Integrate, py::arg("wta"), py::arg("min_disparity"),
           py::arg("max_disparity"), py::arg("calibration"), py::arg("X_WC"), py::arg("grid"),
           py::call_guard<py::gil_scoped_release>(), "Integrates one frame of WTA disparities into `grid`.");

  py::class_<ConfidenceToOccupancy, systems::LeafSystem>(
      m, "ConfidenceToOccupancy",
      "System: every `period` from t = `offset`, and on ExecuteForcedEvents, integrates input `confidence` "
      "(DisparityVolume) at input `X_WC` (4x4 pose) into the OccupancyGrid it holds as state, output `grid`.")
      .def(py::init<const OccupancyGrid&, const StereoCalibration&, double, const CostCurveSensorModel::Options&,
                    double>(),
           py::arg("prototype"), py::arg("calibration"), py::arg("period"),
           py::arg("sensor_options") = CostCurveSensorModel::Options(), py::arg("offset") = 0.0,
           "ValueError for a bad period, offset or calibration.")
      .def("period", &ConfidenceToOccupancy::period, "Update period.")
      .def("offset", &ConfidenceToOccupancy::offset, "Time of the first periodic update.")
      .def("calibration", &ConfidenceToOccupancy::calibration, "The calibration.")
      .def("get_confidence_input_port", PortGetter(&ConfidenceToOccupancy::get_confidence_input_port), "Input `confidence`.")
      .def("get_pose_input_port", PortGetter(&ConfidenceToOccupancy::get_pose_input_port), "Input `X_WC`.")
      .def("get_grid_output_port", PortGetter(&ConfidenceToOccupancy::get_grid_output_port), "Output `grid`.");

  RegisterBoundAbstractValueType<DisparityVolume>("DisparityVolume");
  RegisterBoundAbstractValueType<WtaResult>("WtaResult");
  RegisterBoundAbstractValueType<ConfidenceModel>("ConfidenceModel");
  RegisterBoundAbstractValueType<OccupancyGrid>("OccupancyGrid");
  RegisterBoundAbstractValueType<StereoCalibration>("StereoCalibration");
}

}  // namespace cairn::python
