// cairn.perception, terrain part (seed 001): GridMap, elevation and semantic fusion, slope and roughness,
// collapsibility, hierarchical traversability, registration, and the ElevationMapper, TraversabilityAnalyzer and
// ProbeController systems. Layers come out as numpy arrays indexed [i, j] (i along x, j along y).

#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "abstract_values.h"
#include "bindings.h"
#include "cv_mat_caster.h"
#include "numpy_support.h"
#include "system_support.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/terrain/collapsibility_estimator.h"
#include "cairn/perception/terrain/elevation_fusion.h"
#include "cairn/perception/terrain/elevation_mapper.h"
#include "cairn/perception/terrain/grid_map.h"
#include "cairn/perception/terrain/hierarchical_traversability.h"
#include "cairn/perception/terrain/kalman_cell_update.h"
#include "cairn/perception/terrain/map_registration.h"
#include "cairn/perception/terrain/probe_controller.h"
#include "cairn/perception/terrain/probed_region.h"
#include "cairn/perception/terrain/range_variance_model.h"
#include "cairn/perception/terrain/semantic_fusion.h"
#include "cairn/perception/terrain/slope_roughness_filter.h"
#include "cairn/perception/terrain/traversability_analyzer.h"
#include "cairn/perception/terrain/traversability_class.h"

namespace cairn::python {

using namespace cairn::perception;

namespace {

// A layer as a new (size x, size y) array in map-index order.
py::array_t<double> LayerArray(const GridMap& map, const std::string& name) {
  const int layer = map.LayerIndex(name);
  py::array_t<double> out({static_cast<py::ssize_t>(map.size().x()), static_cast<py::ssize_t>(map.size().y())});
  auto view = out.mutable_unchecked<2>();
  for (int i = 0; i < map.size().x(); ++i) {
    for (int j = 0; j < map.size().y(); ++j) view(i, j) = map.at(layer, i, j);
  }
  return out;
}

void SetLayerArray(GridMap& map, const std::string& name, const py::array_t<double>& values) {
  const int layer = map.LayerIndex(name);
  if (values.ndim() != 2 || values.shape(0) != map.size().x() || values.shape(1) != map.size().y()) {
    throw py::value_error("SetLayer: layer '" + name + "' needs a " + FormatShort(map.size().x()) + " x " +
                          FormatShort(map.size().y()) + " array");
  }
  auto view = values.unchecked<2>();
  for (int i = 0; i < map.size().x(); ++i) {
    for (int j = 0; j < map.size().y(); ++j) map.at(layer, i, j) = view(i, j);
  }
}

void CheckCell(const GridMap& map, int i, int j) {
  if (!map.Contains(Eigen::Vector2i(i, j))) {
    throw py::index_error("cell (" + FormatShort(i) + ", " + FormatShort(j) + ") is outside the " +
                          FormatShort(map.size().x()) + " x " + FormatShort(map.size().y()) + " map");
  }
}

}  // namespace

void DefinePerceptionTerrain(py::module_ m) {
  py::class_<GridMap>(m, "GridMap",
                      "A 2-D map of named layers over a circular buffer (NaN = unknown); Move shifts an index "
                      "offset and clears only the cells that leave.")
      .def(py::init<const Eigen::Vector2i&, double, const Eigen::Vector2d&>(), py::arg("size"), py::arg("resolution"),
           py::arg("center"), "size (cells x, y), resolution (m), centre (world x, y).")
      .def("AddLayer", &GridMap::AddLayer, py::arg("name"), py::arg("fill") = std::numeric_limits<double>::quiet_NaN(),
           "Adds a layer filled with `fill`; returns its index.")
      .def("HasLayer", &GridMap::HasLayer, py::arg("name"), "Whether the layer exists.")
      .def("LayerIndex", &GridMap::LayerIndex, py::arg("name"), "Index of a layer.")
      .def("layer_names", &GridMap::layer_names, "Layer names in order.")
      .def("size", &GridMap::size, "Cells (x, y).")
      .def("resolution", &GridMap::resolution, "Cell side, m.")
      .def("center", &GridMap::center, "Centre in the world.")
      .def("min_corner", &GridMap::min_corner, "Minimum corner in the world.")
      .def("start_index", &GridMap::start_index, "Storage offset of map cell (0, 0).")
      .def("Move", &GridMap::Move, py::arg("center"), "Moves the map by whole cells; returns the shift.")
      .def(
          "CellOf",
          [](const GridMap& map, const Eigen::Vector2d& p) -> py::object {
            Eigen::Vector2i cell;
            if (!map.CellOf(p, &cell)) return py::none();
            return py::make_tuple(cell.x(), cell.y());
          },
          py::arg("p"), "(i, j) of the cell containing p, or None outside.")
      .def("CellCenter", &GridMap::CellCenter, py::arg("cell"), "World centre of a cell.")
      .def("ValueAt", &GridMap::ValueAt, py::arg("name"), py::arg("p"), "Layer value at p (NaN outside).")
      .def(
          "at",
          [](const GridMap& map, const std::string& name, int i, int j) {
            CheckCell(map, i, j);
            return map.at(map.LayerIndex(name), i, j);
          },
          py::arg("name"), py::arg("i"), py::arg("j"), "Layer value of cell (i, j).")
      .def("Layer", &LayerArray, py::arg("name"), "A layer as a new array [i, j].")
      .def("SetLayer", &SetLayerArray, py::arg("name"), py::arg("values"), "Sets a layer from an array [i, j].")
      .def("__repr__", [](const GridMap& map) {
        return "GridMap(" + FormatShort(map.size().x()) + " x " + FormatShort(map.size().y()) + " at " +
               FormatShort(map.resolution()) + " m, " + FormatShort(map.num_layers()) + " layers)";
      });

  py::class_<RangeVarianceModel>(m, "RangeVarianceModel", "sigma(z) = a + b (z - c)^2 (RealSense D435 defaults).")
      .def(py::init<>(), "D435 defaults.")
      .def_readwrite("a", &RangeVarianceModel::a, "m.")
      .def_readwrite("b", &RangeVarianceModel::b, "1/m.")
      .def_readwrite("c", &RangeVarianceModel::c, "m.")
      .def("StdDev", &RangeVarianceModel::StdDev, py::arg("z"), "sigma at ray length z.")
      .def("Variance", &RangeVarianceModel::Variance, py::arg("z"), "sigma^2 at ray length z.");

  m.def(
      "KalmanCellUpdate",
      [](double z, double measurement_variance, double mean, double variance) {
        KalmanCellUpdate(z, measurement_variance, &mean, &variance);
        return py::make_tuple(mean, variance);
      },
      py::arg("z"), py::arg("measurement_variance"), py::arg("mean"), py::arg("variance"),
      "Eq. (1) of seed 001: returns the fused (mean, variance); a NaN mean is an unknown cell.");

  py::class_<ElevationFusion> fusion(m, "ElevationFusion", "Point clouds into layers elevation and elevation_variance.");
  py::class_<ElevationFusion::Options>(fusion, "Options", "Noise model, range window, threads.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("noise", &ElevationFusion::Options::noise, "RangeVarianceModel.")
      .def_readwrite("min_range", &ElevationFusion::Options::min_range, "m.")
      .def_readwrite("max_range", &ElevationFusion::Options::max_range, "m.")
      .def_readwrite("num_threads", &ElevationFusion::Options::num_threads, "0: one per core.");
  py::class_<ElevationFusion::Stats>(fusion, "Stats", "Counts of the last update.")
      .def_readonly("points", &ElevationFusion::Stats::points, "Points given.")
      .def_readonly("fused", &ElevationFusion::Stats::fused, "Points fused.")
      .def_readonly("outside_map", &ElevationFusion::Stats::outside_map, "Outside the map.")
      .def_readonly("rejected", &ElevationFusion::Stats::rejected, "Non-finite or out of range.");
  py::class_<ElevationFusion::Intrinsics>(fusion, "Intrinsics", "Pinhole intrinsics, pixels.")
      .def(py::init([](double fx, double fy, double cx, double cy) { return ElevationFusion::Intrinsics{fx, fy, cx, cy}; }),
           py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"), "From values.");
  fusion.def(py::init<const ElevationFusion::Options&>(), py::arg("options") = ElevationFusion::Options{}, "With options.")
      .def_static("AddLayers", &ElevationFusion::AddLayers, py::arg("map"), "Adds elevation and elevation_variance.")
      .def(
          "Integrate",
          [](ElevationFusion& self, const Eigen::Matrix3Xd& points, const Eigen::Vector3d& sensor, GridMap& map) {
            py::gil_scoped_release release;
            return self.Integrate(points, sensor, &map);
          },
          py::arg("points_W"), py::arg("sensor_W"), py::arg("map"), "Fuses a 3 x N cloud; returns Stats.")
      .def(
          "IntegrateDepth",
          [](ElevationFusion& self, const cv::Mat& depth, const ElevationFusion::Intrinsics& K,
             const Eigen::Isometry3d& X_WC, GridMap& map) { return self.IntegrateDepth(depth, K, X_WC, &map); },
          py::arg("depth"), py::arg("intrinsics"), py::arg("X_WC"), py::arg("map"),
          "Fuses a float32 depth image (m) from camera pose X_WC (4 x 4).");

  py::class_<SlopeRoughnessFilter> filter(m, "SlopeRoughnessFilter", "Slope and roughness from a plane fit per window.");
  py::class_<SlopeRoughnessFilter::Options>(filter, "Options", "Window and threads.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("window_radius", &SlopeRoughnessFilter::Options::window_radius, "Half-width, cells.")
      .def_readwrite("min_valid_cells", &SlopeRoughnessFilter::Options::min_valid_cells, "Fewest heights for a fit.")
      .def_readwrite("num_threads", &SlopeRoughnessFilter::Options::num_threads, "0: one per core.");
  filter.def(py::init<const SlopeRoughnessFilter::Options&>(), py::arg("options") = SlopeRoughnessFilter::Options{},
             "With options.")
      .def(
          "Compute", [](const SlopeRoughnessFilter& self, GridMap& map, const std::string& layer) { self.Compute(&map, layer); },
          py::arg("map"), py::arg("elevation_layer") = "elevation", "Writes layers slope and roughness.");

  py::class_<SemanticFusion> semantic(m, "SemanticFusion", "Per-point class probabilities into semantic_<class> layers.");
  py::class_<SemanticFusion::Options>(semantic, "Options", "Classes, variance, threads.")
      .def(py::init<>(), "Defaults (plants, water).")
      .def_readwrite("classes", &SemanticFusion::Options::classes, "Class names.")
      .def_readwrite("measurement_variance", &SemanticFusion::Options::measurement_variance, "Per update.")
      .def_readwrite("input_labels", &SemanticFusion::Options::input_labels,
                     "The segmenter's labels, when the rows come straight from it (else empty).")
      .def_readwrite("class_labels", &SemanticFusion::Options::class_labels,
                     "Dict: class -> its labels, e.g. {'plants': ['grass'], 'water': ['water']}.")
      .def_readwrite("num_threads", &SemanticFusion::Options::num_threads, "0: one per core.");
  semantic.def(py::init<const SemanticFusion::Options&>(), py::arg("options") = SemanticFusion::Options{}, "With options.")
      .def("AddLayers", [](const SemanticFusion& self, GridMap& map) { self.AddLayers(&map); }, py::arg("map"),
           "Adds the class layers.")
      .def(
          "Integrate",
          [](SemanticFusion& self, const Eigen::Matrix3Xd& points, const Eigen::MatrixXd& p, GridMap& map) {
            self.Integrate(points, p, &map);
          },
          py::arg("points_W"), py::arg("probabilities"), py::arg("map"), "Fuses classes x N probabilities.")
      .def("num_input_rows", &SemanticFusion::num_input_rows, "Rows Integrate() expects.")
      .def_static("LayerName", &SemanticFusion::LayerName, py::arg("class_name"), "\"semantic_<class>\".");

  py::class_<CollapsibilityEstimator> collapsibility(m, "CollapsibilityEstimator",
                                                     "Eq. (5): C = max(F_hard - F, 0) / F_hard over a sliding window.");
  py::class_<CollapsibilityEstimator::Options>(collapsibility, "Options", "Reference force and window.")
      .def(py::init<>(), "Defaults (100 N, 20 samples).")
      .def_readwrite("hard_force", &CollapsibilityEstimator::Options::hard_force, "N.")
      .def_readwrite("window", &CollapsibilityEstimator::Options::window, "Samples.");
  collapsibility
      .def(py::init<const CollapsibilityEstimator::Options&>(), py::arg("options") = CollapsibilityEstimator::Options{},
           "With options.")
      .def_static("FromForce", &CollapsibilityEstimator::FromForce, py::arg("force"), py::arg("hard_force"),
                  "Eq. (5) for one force.")
      .def("AddSample", &CollapsibilityEstimator::AddSample, py::arg("force"), "Adds a force sample, N.")
      .def("Reset", &CollapsibilityEstimator::Reset, "Forgets the samples.")
      .def("num_samples", &CollapsibilityEstimator::num_samples, "Samples in the window.")
      .def("AverageForce", &CollapsibilityEstimator::AverageForce, "Window average, N.")
      .def("Collapsibility", &CollapsibilityEstimator::Collapsibility, "C of the window average.");

  py::enum_<TraversabilityClass>(m, "TraversabilityClass", "Classes of a traversability value (seed 001 4.1).")
      .value("kUnknown", TraversabilityClass::kUnknown, "NaN.")
      .value("kUntraversable", TraversabilityClass::kUntraversable, "0.")
      .value("kSemiUntraversable", TraversabilityClass::kSemiUntraversable, "(0, 0.5].")
      .value("kSemiTraversable", TraversabilityClass::kSemiTraversable, "(0.5, 1).")
      .value("kTraversable", TraversabilityClass::kTraversable, "1.");
  m.def("ClassifyTraversability", &ClassifyTraversability, py::arg("t"), "The class of t.");

  py::class_<HierarchicalTraversability> rule(m, "HierarchicalTraversability",
                                              "Algorithm 1: collapsibility, else semantics, else slope/roughness.");
  py::class_<HierarchicalTraversability::SemanticValue>(rule, "SemanticValue", "A class and its fixed value.")
      .def(py::init([](std::string name, double t) { return HierarchicalTraversability::SemanticValue{std::move(name), t}; }),
           py::arg("name"), py::arg("traversability"), "From values.")
      .def_readwrite("name", &HierarchicalTraversability::SemanticValue::name, "Class.")
      .def_readwrite("traversability", &HierarchicalTraversability::SemanticValue::traversability, "Value.");
  py::class_<HierarchicalTraversability::Options>(rule, "Options", "Values, weights, critical values.")
      .def(py::init<>(), "Defaults (plants 0.8, water 0.3).")
      .def_readwrite("semantic_values", &HierarchicalTraversability::Options::semantic_values, "Classes.")
      .def_readwrite("semantic_threshold", &HierarchicalTraversability::Options::semantic_threshold, "Probability.")
      .def_readwrite("slope_weight", &HierarchicalTraversability::Options::slope_weight, "w1.")
      .def_readwrite("roughness_weight", &HierarchicalTraversability::Options::roughness_weight, "w2.")
      .def_readwrite("critical_slope", &HierarchicalTraversability::Options::critical_slope, "rad.")
      .def_readwrite("critical_roughness", &HierarchicalTraversability::Options::critical_roughness, "m.")
      .def_readwrite("probe_variance", &HierarchicalTraversability::Options::probe_variance,
                     "Variance of a probed cell's traversability.")
      .def_readwrite("semantic_variance", &HierarchicalTraversability::Options::semantic_variance,
                     "Variance of a cell set by its class.")
      .def_readwrite("geometry_variance", &HierarchicalTraversability::Options::geometry_variance,
                     "Variance of a geometric cell without elevation_variance.")
      .def_readwrite("num_threads", &HierarchicalTraversability::Options::num_threads, "0: one per core.");
  rule.def(py::init<const HierarchicalTraversability::Options&>(),
           py::arg("options") = HierarchicalTraversability::Options{}, "With options.")
      .def(
          "CellValue",
          [](const HierarchicalTraversability& self, double c, std::vector<double> semantic, double slope,
             double roughness) {
            if (!semantic.empty() && semantic.size() != self.options().semantic_values.size()) {
              throw py::value_error("CellValue: give one probability per semantic class, or none");
            }
            return self.CellValue(c, semantic.empty() ? nullptr : semantic.data(), slope, roughness);
          },
          py::arg("collapsibility"), py::arg("semantic"), py::arg("slope"), py::arg("roughness"),
          "The rule for one cell (NaN = unknown).")
      .def("options", &HierarchicalTraversability::options, py::return_value_policy::copy, "The options (a copy).")
      .def("Compute", [](const HierarchicalTraversability& self, GridMap& map) { self.Compute(&map); }, py::arg("map"),
           "Writes layers traversability and traversability_variance.");

  py::class_<MapRegistration> registration(m, "MapRegistration", "Local layers into a global map by eq. (1).");
  py::class_<MapRegistration::Layer>(registration, "Layer", "One layer to register.")
      .def(py::init([](std::string local, std::string global, double variance, std::string variance_layer) {
             return MapRegistration::Layer{std::move(local), std::move(global), variance, std::move(variance_layer)};
           }),
           py::arg("local_layer"), py::arg("global_layer"), py::arg("variance") = 0.01, py::arg("variance_layer") = "",
           "Constant variance, or a local variance layer.");
  registration.def(py::init<std::vector<MapRegistration::Layer>, int>(), py::arg("layers"), py::arg("num_threads") = 0,
                   "The layers to register.")
      .def("AddLayers", [](const MapRegistration& self, GridMap& g) { self.AddLayers(&g); }, py::arg("global_map"),
           "Adds the global layers.")
      .def("Register", [](const MapRegistration& self, const GridMap& l, GridMap& g) { self.Register(l, &g); },
           py::arg("local_map"), py::arg("global_map"), "Fuses the local map into the global one.");

  py::class_<ProbedRegion>(m, "ProbedRegion", "A probe's C and the cluster points (x, y) it was assigned to.")
      .def(py::init([](std::vector<Eigen::Vector2d> points, double c) { return ProbedRegion{std::move(points), c}; }),
           py::arg("points"), py::arg("collapsibility"), "From values.")
      .def_readwrite("points", &ProbedRegion::points, "List of 2-vectors.")
      .def_readwrite("collapsibility", &ProbedRegion::collapsibility, "C.");

  py::class_<ElevationMapper, systems::LeafSystem> mapper(
      m, "ElevationMapper",
      "System: inputs `points_W` (3 x N), `sensor_W` (3), `probabilities` (classes x N); output `map` (GridMap), "
      "updated every period.");
  py::class_<ElevationMapper::Options>(mapper, "Options", "The fusions' and the filter's options.")
      .def(py::init<>(), "Defaults.")
      .def_readwrite("elevation", &ElevationMapper::Options::elevation, "ElevationFusion.Options.")
      .def_readwrite("semantics", &ElevationMapper::Options::semantics, "SemanticFusion.Options.")
      .def_readwrite("geometry", &ElevationMapper::Options::geometry, "SlopeRoughnessFilter.Options.")
      .def_readwrite("follow_sensor", &ElevationMapper::Options::follow_sensor, "Robot-centred map.");
  mapper
      .def(py::init<const GridMap&, double, const ElevationMapper::Options&>(), py::arg("prototype"), py::arg("period"),
           py::arg("options") = ElevationMapper::Options{}, "Map geometry, update period, options.")
      .def("get_points_input_port", PortGetter(&ElevationMapper::get_points_input_port), "Input `points_W`.")
      .def("get_sensor_input_port", PortGetter(&ElevationMapper::get_sensor_input_port), "Input `sensor_W`.")
      .def("get_probabilities_input_port", PortGetter(&ElevationMapper::get_probabilities_input_port),
           "Input `probabilities`.")
      .def("get_map_output_port", PortGetter(&ElevationMapper::get_map_output_port), "Output `map`.");

  py::class_<TraversabilityAnalyzer, systems::LeafSystem>(
      m, "TraversabilityAnalyzer",
      "System: inputs `map` (GridMap), `probes` (list of ProbedRegion); outputs `map` (with collapsibility and "
      "traversability) and `traversability` (array [i, j]).")
      .def(py::init<const HierarchicalTraversability::Options&>(),
           py::arg("options") = HierarchicalTraversability::Options{}, "Algorithm 1's options.")
      .def("get_map_input_port", PortGetter(&TraversabilityAnalyzer::get_map_input_port), "Input `map`.")
      .def("get_probes_input_port", PortGetter(&TraversabilityAnalyzer::get_probes_input_port), "Input `probes`.")
      .def("get_map_output_port", PortGetter(&TraversabilityAnalyzer::get_map_output_port), "Output `map`.")
      .def("get_traversability_output_port", PortGetter(&TraversabilityAnalyzer::get_traversability_output_port),
           "Output `traversability`.");

  py::class_<ProbeController, systems::LeafSystem>(
      m, "ProbeController",
      "System: inputs `force` (1), `probing` (1); output `collapsibility` ([C, samples]), sampled every period.")
      .def(py::init<const CollapsibilityEstimator::Options&, double>(), py::arg("options"), py::arg("period"),
           "Estimator options and the sample period.")
      .def("get_force_input_port", PortGetter(&ProbeController::get_force_input_port), "Input `force`.")
      .def("get_probing_input_port", PortGetter(&ProbeController::get_probing_input_port), "Input `probing`.")
      .def("get_collapsibility_output_port", PortGetter(&ProbeController::get_collapsibility_output_port),
           "Output `collapsibility`.");

  RegisterBoundAbstractValueType<GridMap>("GridMap");
  RegisterConvertedAbstractValueType<Eigen::Matrix3Xd>("Matrix3Xd");
  RegisterConvertedAbstractValueType<Eigen::MatrixXd>("MatrixXd");
  RegisterConvertedAbstractValueType<std::vector<ProbedRegion>>("ProbedRegions");
}

}  // namespace cairn::python
