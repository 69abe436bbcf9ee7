// cairn.planning (terrain from perception): TerrainAssemblyOptions, AssembleTerrain and the TerrainAssembler system.

#include <memory>
#include <utility>

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "cairn/planning/terrain/assemble_terrain.h"
#include "cairn/planning/terrain/terrain_assembler.h"

namespace cairn::python {

using namespace cairn::planning;

void DefinePlanningTerrain(py::module_ m) {
  py::enum_<MaterialFusion>(m, "MaterialFusion", "How a cell's points' material mixtures are fused.")
      .value("kAverage", MaterialFusion::kAverage, "The mean of the mixtures (linear opinion pool).")
      .value("kIndependent", MaterialFusion::kIndependent,
             "Normalised product: each point an independent observation of the cell's material.");
  py::class_<TerrainAssemblyOptions>(m, "TerrainAssemblyOptions", "How AssembleTerrain reads grid and points.")
      .def(py::init<>(), "Threshold 0.5, ground below 0.3 m, eta 0.95, exact quantiles, unseen material not walkable.")
      .def_readwrite("occupied_threshold", &TerrainAssemblyOptions::occupied_threshold, "Occupied above this.")
      .def_readwrite("max_ground_height", &TerrainAssemblyOptions::max_ground_height, "Highest foothold z, m.")
      .def_readwrite("eta", &TerrainAssemblyOptions::eta, "Confidence of the friction quantile.")
      .def_readwrite("quantile_method", &TerrainAssemblyOptions::quantile_method, "QuantileMethod.")
      .def_readwrite("fusion", &TerrainAssemblyOptions::fusion, "MaterialFusion of the points' mixtures.")
      .def_readwrite("outlier_height", &TerrainAssemblyOptions::outlier_height,
                     "A cell this far (m) from its window's median height loses its ground (0: keep all).")
      .def_readwrite("outlier_radius", &TerrainAssemblyOptions::outlier_radius, "Half-side of that window, m.")
      .def_readwrite("median_heights", &TerrainAssemblyOptions::median_heights,
                     "Each kept cell takes the median height within outlier_radius.")
      .def_readwrite("max_gap", &TerrainAssemblyOptions::max_gap,
                     "Widest gap (m) between level ground to bridge (0: none).")
      .def_readwrite("max_gap_step", &TerrainAssemblyOptions::max_gap_step,
                     "Largest height difference (m) across a bridged gap.")
      .def_readwrite("min_points", &TerrainAssemblyOptions::min_points, "Points a cell needs for a friction.")
      .def_readwrite("unknown_friction", &TerrainAssemblyOptions::unknown_friction,
                     "Friction of ground whose material was not seen (0: not walkable).");
  m.def("AssembleTerrain", &AssembleTerrain, py::arg("grid"), py::arg("points"), py::arg("registry"),
        py::arg("options") = TerrainAssemblyOptions(), py::call_guard<py::gil_scoped_release>(),
        "TerrainMap from an OccupancyGrid and a FrictionPointCloud (ground, fused friction quantiles, voxels).");
  py::class_<TerrainAssembler, systems::LeafSystem>(
      m, "TerrainAssembler",
      "System: inputs `grid` (OccupancyGrid), `friction_points` (FrictionPointCloud); output `terrain` (TerrainMap); "
      "abstract parameter: the MaterialRegistry.")
      .def(py::init([](perception::MaterialRegistry registry, const TerrainAssemblyOptions& options) {
             return std::make_unique<TerrainAssembler>(std::move(registry), options);
           }),
           py::arg("registry"), py::arg("options") = TerrainAssemblyOptions(), "ValueError for bad options.")
      .def("registry_parameter", &TerrainAssembler::registry_parameter, "Index of the registry parameter.");
}

}  // namespace cairn::python
