// The extension module cairn._cairn; the package cairn (cairn/__init__.py) exposes its submodules as
// cairn.systems, cairn.optimization, cairn.multibody, cairn.perception, cairn.planning, cairn.visualization and
// cairn.examples.

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "ownership.h"

PYBIND11_MODULE(_cairn, m) {
  namespace py = pybind11;
  m.doc() = "Cairn's C++ libraries (the extension module behind the `cairn` package).";
  // Order matters: later submodules use the classes earlier ones bind (System, Context, cv::Mat values, ...).
  py::module_ systems = m.def_submodule("systems", "Block diagrams of typed systems: cairn::systems.");
  cairn::python::DefineSystemsFramework(systems);
  cairn::python::DefineSystemsLeafSystem(systems);
  cairn::python::DefineSystemsAnalysisAndPrimitives(systems);
  cairn::python::DefineOptimization(
      m.def_submodule("optimization", "Mathematical programs and their solvers: cairn::optimization."));
  py::module_ multibody = m.def_submodule("multibody", "Rigid-body models and algorithms: cairn::multibody.");
  cairn::python::DefineMultibody(multibody);
  cairn::python::DefineMultibodyPlant(multibody);
  py::module_ perception =
      m.def_submodule("perception", "Stereo, occupancy and friction perception: cairn::perception.");
  cairn::python::DefinePerceptionStereoOccupancy(perception);
  cairn::python::DefinePerceptionFriction(perception);
  cairn::python::DefinePerceptionSyntheticEvaluation(perception);
  cairn::python::DefinePerceptionTerrain(perception);
  cairn::python::DefinePerceptionHaptics(perception);
  py::module_ planning = m.def_submodule("planning", "Footstep planning and locomotion: cairn::planning.");
  cairn::python::DefinePlanning(planning);
  cairn::python::DefinePlanningTrajectory(planning);
  cairn::python::DefinePlanningTerrain(planning);
  cairn::python::DefinePlanningGrid(planning);
  cairn::python::DefinePlanningStabilization(planning);
  cairn::python::DefinePlanningWalk(planning);
  cairn::python::DefinePlanningRun(planning);
  cairn::python::DefineVisualization(m.def_submodule("visualization", "HTML viewers: cairn::visualization."));
  cairn::python::DefineExamples(m.def_submodule("examples", "The example systems of examples/systems."));
  cairn::python::FixDynamicAttributeTraversal(m);
}
