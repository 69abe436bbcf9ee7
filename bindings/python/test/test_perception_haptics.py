"""cairn.perception, haptics (seed 000): descriptor, memory, planning, change detection, calibration, systems."""

import numpy as np
import pytest

import cairn.perception as perception
from cairn.systems import Simulator


def one_line(n, s, d, m):
    return perception.AffordanceDescriptor.FromValues(np.array([n, s, d, m], dtype=float))


def test_descriptor_metrics_by_hand():
    histogram = np.array([[0, 2, 3, 0, 1, 0, 0, 4]], dtype=np.int32)
    d = perception.AffordanceDescriptor.FromHistogram(histogram)
    assert list(d.values) == [3.0, 2.0, 1.25, 5.0]
    grid = np.array([[0.02 * c, 0.02 * l, 0.5] for l in range(14) for c in range(16)]).T
    full = perception.AffordanceDescriptor.Compute(grid, perception.AffordanceDescriptor.Options())
    assert full.values.shape == (56,)
    assert list(full.values[:4]) == [1.0, 16.0, 1.0, 16.0]


def test_memory_recall_save_and_load(tmp_path):
    assert perception.TraversabilityMemory.Dissimilarity(
        one_line(2, 3, 1, 4), one_line(3, 1, 2, 3), perception.TraversabilityMemory.Options()) == pytest.approx(0.6)
    memory = perception.TraversabilityMemory(perception.TraversabilityMemory.Options(), 1)
    memory.Add(one_line(2, 3, 1, 4), True)
    memory.Add(one_line(3, 1, 2, 3), False)
    memory.Add(one_line(2, 3, 1, 3), True)
    memory.Add(one_line(4, 3, 1, 4), False)
    recall = memory.Recall(one_line(2, 3, 1, 4), 3)
    assert recall.traversable
    assert recall.confidence == pytest.approx(0.625)
    path = str(tmp_path / "memory.txt")
    memory.Save(path)
    assert perception.TraversabilityMemory.Load(path).ToText() == memory.ToText()
    with pytest.raises(RuntimeError, match="not a traversability memory"):
        perception.TraversabilityMemory.FromText("nope 1\n", "m.txt")
    with pytest.raises(ValueError, match="k is 0"):
        memory.Recall(one_line(1, 1, 1, 1), 0)


def test_planner_gist_and_rigid_fit():
    planner = perception.HapticInteractionPlanner()
    plan = planner.Plan(np.array([[0.01, 0.07], [-0.1, -0.1], [1.0, 1.0]]), 0.5)
    assert len(plan.selected) == 2
    assert plan.selected[0].p_C[0] == pytest.approx(0.07)
    assert plan.targets_C[0][2] == pytest.approx(1.05)
    points = np.array([[0.005, 0.006, 0.105], [0.005, 0.006, 0.005], [1.005, 1.006, 1.005]])
    assert perception.GistChangeDetector.Gist(points, 0.01) == pytest.approx(2.0 / 3.0)
    p_A = perception.CameraAntennaCalibrator.Table1Points()
    angle = 0.3
    R = np.array([[np.cos(angle), 0, np.sin(angle)], [0, 1, 0], [-np.sin(angle), 0, np.cos(angle)]])
    t = np.array([[0.1], [0.05], [-0.02]])
    p_C = R.T @ (p_A - t)
    fit = perception.FitRigidTransform(p_C, p_A)
    assert fit.rms_residual < 1e-12
    assert np.allclose(fit.X_AC[:3, :3], R)


def test_systems_between_python_and_cpp():
    descriptor = perception.ObjectDescriptor()
    context = descriptor.CreateDefaultContext()
    grid = np.array([[0.02 * c, 0.02 * l, 0.5] for l in range(14) for c in range(16)]).T
    descriptor.GetInputPort("points_C").FixValue(context, grid)
    d = descriptor.GetOutputPort("descriptor").Eval(context)
    assert d.values.shape == (56,)
    memory = perception.AffordanceMemory(perception.TraversabilityMemory(), 0.1)
    mcontext = memory.CreateDefaultContext()
    memory.GetInputPort("descriptor").FixValue(mcontext, d)
    outcome = perception.HapticOutcome()
    outcome.sequence = 0
    outcome.traversable = False
    outcome.descriptor = d
    memory.GetInputPort("outcome").FixValue(mcontext, outcome)
    simulator = Simulator(memory, mcontext)
    simulator.AdvanceTo(0.25)
    recall = memory.GetOutputPort("recall").Eval(simulator.get_context())
    assert not recall.traversable
    assert recall.confidence == pytest.approx(0.2)
    assert memory.GetOutputPort("memory").Eval(simulator.get_context()).size() == 1


def test_simulated_rock_blocks_the_antenna():
    experiment = perception.HapticAffordanceExperiment()
    points = experiment.Observe(perception.HapticObjectKind.kRock, 0)
    assert points.shape[0] == 3 and points.shape[1] > 100
    blocked, planned = experiment.Touch(perception.HapticObjectKind.kRock, 0, points, 0.0)
    assert blocked and planned > 0
    assert not perception.HapticObjectTraversable(perception.HapticObjectKind.kRock)
    assert perception.HapticObjectName(perception.DataSet1()[3]) == "(d) shrub"


def test_simulated_camera_and_antenna_systems():
    wall = perception.MakeHapticObject(perception.HapticObjectKind.kWall)
    assert not wall.traversable()
    X_WC = perception.SimulatedDepthSensor.LookingAlong(np.array([-1.2, 0.0, 0.35]), 0.0)
    np.testing.assert_allclose(X_WC[:3, 2], [1.0, 0.0, 0.0], atol=1e-12)  # looking along +x
    camera = perception.SimulatedDepthCamera(perception.SimulatedDepthSensor.Options(), [wall], 0.1, 7)
    simulator = Simulator(camera)
    camera.GetInputPort("X_WC").FixValue(simulator.get_mutable_context(), X_WC)
    simulator.AdvanceTo(0.15)
    points = camera.GetOutputPort("points_C").Eval(simulator.get_context())
    assert points.shape[0] == 3 and points.shape[1] > 100
    # The wall stands in front: every point lies ahead of the sensor, within its range.
    assert np.all(points[2] > 0.4) and np.all(points[2] < 4.0)
    probe = perception.AntennaProbe(perception.SimulatedAntenna.Options(), [wall], np.eye(4), 14, 0.1)
    assert probe.num_output_ports() == 2
    with pytest.raises(ValueError):
        perception.SimulatedDepthCamera(perception.SimulatedDepthSensor.Options(), [wall], 0.0, 7)
