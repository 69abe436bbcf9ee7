#pragma once

/// @file
/// The parts of the `cairn` Python module, one translation unit each (compile time: each is a few seconds of
/// pybind11 templates, and they build in parallel).

#include <pybind11/pybind11.h>

namespace cairn::python {

namespace py = pybind11;

/// cairn.systems: the framework (System, Context, ports, values, LeafSystem for Python subclasses, Diagram,
/// DiagramBuilder).
void DefineSystemsFramework(py::module_ m);
/// cairn.systems: LeafSystem, subclassable from Python.
void DefineSystemsLeafSystem(py::module_ m);
/// cairn.systems: Simulator, integrators and the primitives.
void DefineSystemsAnalysisAndPrimitives(py::module_ m);
/// cairn.optimization.
void DefineOptimization(py::module_ m);
/// cairn.multibody.
void DefineMultibody(py::module_ m);
/// cairn.multibody: the Bullet plant, PD controller and HumanoidPlant (after DefineMultibody: it uses Model, Pose).
void DefineMultibodyPlant(py::module_ m);
/// cairn.perception: stereo and occupancy.
void DefinePerceptionStereoOccupancy(py::module_ m);
/// cairn.perception: friction.
void DefinePerceptionFriction(py::module_ m);
/// cairn.perception: synthetic scenes and evaluation (Middlebury, scores).
void DefinePerceptionSyntheticEvaluation(py::module_ m);
/// cairn.perception: terrain (seed 001) maps, fusion, traversability and their systems.
void DefinePerceptionTerrain(py::module_ m);
/// cairn.perception, haptics part (seed 000) and its simulated world.
void DefinePerceptionHaptics(py::module_ m);
/// cairn.planning.
void DefinePlanning(py::module_ m);
/// cairn.planning, grid part: grid search, probing planner, GridPathPlanner, traverse scenario (after
/// DefinePerceptionTerrain: results hold a GridMap).
void DefinePlanningGrid(py::module_ m);
/// cairn.planning, whole-body part: TrajectoryOptimizer and OptimizeWholeBodyTrajectory (after DefinePlanning).
void DefinePlanningTrajectory(py::module_ m);
void DefinePlanningTerrain(py::module_ m);
/// cairn.planning, stabilisation part: Stabilizer, StabilizeTrajectory, preview control (after DefinePlanningTrajectory).
void DefinePlanningStabilization(py::module_ m);
/// cairn.planning, walk part: the walk diagram, its run and the reference player (after DefinePlanningStabilization).
void DefinePlanningWalk(py::module_ m);
/// cairn.planning, the main diagram: perception in front of the walk (after DefinePlanningWalk).
void DefinePlanningRun(py::module_ m);
/// cairn.visualization: the HTML motion viewer.
void DefineVisualization(py::module_ m);
/// cairn.examples: the example systems the C++ examples are built from.
void DefineExamples(py::module_ m);

}  // namespace cairn::python
