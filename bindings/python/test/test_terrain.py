"""cairn.perception terrain (seed 001) and cairn.planning grid: maps, Algorithm 1, searches, probing, systems."""

import math

import numpy as np
import pytest

import cairn.perception as perception
import cairn.planning as planning
from cairn.systems import Simulator
from conftest import source_path

SCENARIO = source_path("examples", "scenarios", "traverse", "plants_and_water.yaml")
ARM = source_path("data", "robots", "cairn_probe_arm.urdf")


def test_grid_map_moves_without_copying():
    grid = perception.GridMap([8, 6], 1.0, [0.0, 0.0])
    grid.AddLayer("id")
    values = np.arange(48, dtype=float).reshape(8, 6)
    grid.SetLayer("id", values)
    assert grid.CellOf([-3.5, -2.5]) == (0, 0)
    assert grid.CellOf([10.0, 0.0]) is None
    shift = grid.Move([2.0, 0.0])
    assert list(shift) == [2, 0]
    moved = grid.Layer("id")
    np.testing.assert_array_equal(moved[:6], values[2:])  # kept cells at their world positions
    assert np.isnan(moved[6:]).all()  # entering cells cleared
    with pytest.raises(ValueError, match="no layer named 'slope'"):
        grid.Layer("slope")


def test_kalman_plane_and_algorithm_one():
    mean, var = float("nan"), float("nan")
    for z in [0.1, 0.3]:
        mean, var = perception.KalmanCellUpdate(z, 0.04, mean, var)
    assert mean == pytest.approx(0.2) and var == pytest.approx(0.02)
    grid = perception.GridMap([20, 20], 0.05, [0.0, 0.0])
    perception.ElevationFusion.AddLayers(grid)
    xs = np.array([grid.CellCenter([i, j]) for i in range(20) for j in range(20)])
    points = np.vstack([xs.T, 0.2 * xs[:, 0]])
    stats = perception.ElevationFusion().Integrate(points, [0.0, 0.0, 1.0], grid)
    assert stats.fused == 400
    perception.SlopeRoughnessFilter().Compute(grid)
    assert grid.at("slope", 10, 10) == pytest.approx(math.atan(0.2))
    assert grid.at("roughness", 10, 10) == pytest.approx(0.0, abs=1e-9)
    rule = perception.HierarchicalTraversability()
    assert rule.CellValue(0.9, [1.0, 0.0], 0.0, 0.0) == pytest.approx(0.1)  # collapsibility first
    assert rule.CellValue(float("nan"), [0.9, 0.6], 0.0, 0.0) == 0.8  # then plants
    assert rule.CellValue(float("nan"), [0.1, 0.7], 0.0, 0.0) == 0.3  # water
    assert rule.CellValue(float("nan"), [], 0.6, 0.0) == 0.0  # too steep
    assert perception.ClassifyTraversability(0.8) == perception.TraversabilityClass.kSemiTraversable
    assert perception.CollapsibilityEstimator.FromForce(30.0, 100.0) == pytest.approx(0.7)


def test_grid_search_and_probing_planner():
    values = np.ones((5, 3))
    values[2, 1] = 0.0
    grid = planning.TraversabilityGrid(values, 1.0, [0.0, 0.0])
    for algorithm in (planning.GridSearch.Algorithm.kDijkstra, planning.GridSearch.Algorithm.kAStar):
        options = planning.GridSearch.Options()
        options.algorithm = algorithm
        path = planning.GridSearch(options).Plan(grid, [0, 1], [4, 1])
        assert path.found and all(list(c) != [2, 1] for c in path.cells)
        assert path.cost == pytest.approx(2.0 + 2.0 * math.sqrt(2.0))
    points = np.array([[1.0 + 0.05 * k for k in range(10)], [0.0] * 10])
    prober = planning.ProbingPlanner()
    clusters = prober.FindClusters(points, [0] * 10)
    assert len(clusters) == 1
    decision = prober.Decide(clusters, points, [0.5, 0.0])
    assert decision.action == planning.ProbingPlanner.Decision.Action.kProbe


def test_systems_in_a_simulator():
    mapper = perception.ElevationMapper(perception.GridMap([10, 10], 0.1, [0.0, 0.0]), 0.1)
    context = mapper.CreateDefaultContext()
    xs = np.array([[x, y, 0.0] for x in np.arange(-0.45, 0.5, 0.05) for y in np.arange(-0.45, 0.5, 0.05)]).T
    mapper.get_points_input_port().FixValue(context, xs)
    mapper.get_sensor_input_port().FixValue(context, np.array([0.0, 0.0, 1.0]))
    mapper.get_probabilities_input_port().FixValue(context, np.zeros((2, 0)))
    simulator = Simulator(mapper, context)
    simulator.AdvanceTo(0.05)
    grid = mapper.get_map_output_port().Eval(simulator.get_context())
    assert grid.at("elevation", 5, 5) == pytest.approx(0.0)
    analyzer = perception.TraversabilityAnalyzer()
    ac = analyzer.CreateDefaultContext()
    analyzer.get_map_input_port().FixValue(ac, grid)
    analyzer.get_probes_input_port().FixValue(ac, [perception.ProbedRegion([np.array([0.05, 0.05])], 0.75)])
    raster = analyzer.get_traversability_output_port().Eval(ac)
    assert raster.shape == (10, 10) and raster[5, 5] == pytest.approx(0.25) and raster[2, 2] == 1.0
    probe = perception.ProbeController(perception.CollapsibilityEstimator.Options(), 0.01)
    pc = probe.CreateDefaultContext()
    probe.get_force_input_port().FixValue(pc, np.array([20.0]))
    probe.get_probing_input_port().FixValue(pc, np.array([1.0]))
    sim = Simulator(probe, pc)
    sim.AdvanceTo(0.035)
    np.testing.assert_allclose(probe.get_collapsibility_output_port().Eval(sim.get_context()), [0.8, 4.0])


def test_traverse_scenario_probes_and_avoids_soft_soil():
    scenario = planning.TraverseScenario.Load(SCENARIO)
    with_arm = planning.TraverseSimulation.Options()
    with_arm.probe_arm_urdf = ARM
    result = planning.TraverseSimulation(scenario, with_arm).Run()
    assert result.reached_goal, result.failure
    assert result.collapsible_steps == 0
    assert [p.region for p in result.probes][:1] == ["soft plants"]
    assert "hard plants" in result.regions_entered
    assert all(p.simulated_time > 0 for p in result.probes)
    options = planning.TraverseSimulation.Options()
    options.probing = False
    blind = planning.TraverseSimulation(scenario, options).Run()
    assert blind.collapsible_steps > 0 and "soft plants" in blind.regions_entered
    assert blind.map.Layer("traversability").shape == (100, 100)


def test_probe_arm_plant_measures_hard_soft_and_no_ground():
    arm = planning.ProbeArmPlant.Load(ARM)
    assert arm.reach() > 0.8
    ground = planning.ProbeArmPlant.Ground
    hard = arm.Run([0.0, 0.0], [0.6, 0.2], ground(0.0, 8000.0, 50.0), seed=2)
    soft = arm.Run([0.0, 0.0], [0.6, 0.2], ground(0.0, 750.0, 50.0), seed=2)
    water = arm.Run([0.0, 0.0], [0.6, 0.2], ground(0.0, 0.0, 0.0), seed=2)
    assert len(hard.forces) == 20 and hard.simulated_time > 0.2
    assert hard.true_forces[-1] == pytest.approx(8000.0 * hard.final_depth, rel=0.05)
    assert np.mean(hard.forces) > 100.0  # C = 0
    assert 10.0 < np.mean(soft.forces) < 20.0  # about 750 N/m x 2 cm: C about 0.85
    assert max(water.true_forces) == 0.0
    with pytest.raises(ValueError, match="beyond the arm's reach"):
        arm.Run([0.0, 0.0], [3.0, 0.0], ground(0.0, 8000.0, 50.0))


def test_probing_systems_in_a_diagram():
    scenario = planning.TraverseScenario.Load(SCENARIO)
    arm = planning.ProbeArm(scenario, ARM, 0.005)
    context = arm.CreateDefaultContext()
    arm.get_command_input_port().FixValue(context, np.array([3.5, 5.0, 1.0]))  # soft plants
    arm.get_robot_input_port().FixValue(context, np.array([2.9, 5.0]))
    sim = Simulator(arm, context)
    sim.AdvanceTo(0.05)
    assert arm.get_probing_output_port().Eval(sim.get_context())[0] == 1.0
    assert 5.0 < arm.get_force_output_port().Eval(sim.get_context())[0] < 25.0
    assert arm.simulated_time(sim.get_context()) > 0.0
    walker = planning.PathFollower([0.0, 0.0], 0.1, 0.1)
    wc = walker.CreateDefaultContext()
    walker.get_path_input_port().FixValue(wc, np.array([[0.0, 1.0], [0.0, 0.0]]))
    walker.get_pause_input_port().FixValue(wc, np.array([0.0]))
    ws = Simulator(walker, wc)
    ws.AdvanceTo(0.25)
    np.testing.assert_allclose(walker.get_position_output_port().Eval(ws.get_context()), [0.3, 0.0])
    sensor = planning.ScenarioSensor(scenario)
    sc = sensor.CreateDefaultContext()
    sensor.get_robot_input_port().FixValue(sc, np.array([3.5, 5.0]))
    assert sensor.GetOutputPort("points_W").Eval(sc).shape[0] == 3
    supervisor = planning.ProbeSupervisor(planning.ProbingPlanner.Options())
    assert supervisor.get_pause_output_port().Eval(supervisor.CreateDefaultContext())[0] == 0.0
    diagram = planning.BuildProbingDiagram(scenario, ARM)
    assert diagram.GetSubsystemByName("arm") is not None


def test_semantic_fusion_maps_segmenter_labels_to_classes():
    options = perception.SemanticFusion.Options()
    options.input_labels = ["asphalt", "grass", "moss", "water"]
    options.class_labels = {"plants": ["grass", "moss"], "water": ["water"]}
    fusion = perception.SemanticFusion(options)
    assert fusion.num_input_rows() == 4
    grid = perception.GridMap([2, 1], 1.0, [0.0, 0.0])
    fusion.AddLayers(grid)
    points = np.array([[-0.5, -0.5, 0.5], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    rows = np.array([[0.1, 0.0, 0.1], [0.5, 0.6, 0.0], [0.3, 0.2, 0.0], [0.1, 0.2, 0.9]])
    fusion.Integrate(points, rows, grid)
    assert grid.at("semantic_plants", 0, 0) == pytest.approx(0.8)  # grass + moss, averaged over the cell's points
    assert grid.at("semantic_water", 0, 0) == pytest.approx(0.15)
    assert grid.at("semantic_water", 1, 0) == pytest.approx(0.9)
    options.class_labels = {"plants": ["grass"], "water": ["lake"]}
    with pytest.raises(ValueError, match="label 'lake'.*not an input label"):
        perception.SemanticFusion(options)


def test_registration_weighs_probes_above_semantics():
    rule = perception.HierarchicalTraversability()
    registration = perception.MapRegistration(
        [perception.MapRegistration.Layer("traversability", "traversability", variance_layer="traversability_variance")])
    world = perception.GridMap([1, 1], 0.1, [0.0, 0.0])
    registration.AddLayers(world)

    def local(collapsibility):
        grid = perception.GridMap([1, 1], 0.1, [0.0, 0.0])
        grid.AddLayer("semantic_plants", 0.9)
        grid.AddLayer("collapsibility", collapsibility)
        rule.Compute(grid)
        return grid

    for _ in range(3):
        registration.Register(local(float("nan")), world)
    assert world.at("traversability", 0, 0) == pytest.approx(0.8)
    registration.Register(local(0.85), world)
    vs, vp = rule.options().semantic_variance, rule.options().probe_variance
    expected = (vp * 0.8 + vs / 3 * 0.15) / (vs / 3 + vp)
    assert world.at("traversability", 0, 0) == pytest.approx(expected)
    assert world.at("traversability", 0, 0) < 0.5


def test_grid_path_planner_plans_around_a_wall_in_an_event():
    values = np.ones((10, 10))
    values[5, :8] = 0.0  # a wall at x = 0.55 with a gap at its top
    planner = planning.GridPathPlanner(0.1, np.array([0.0, 0.0]), planning.GridSearch.Options(), 0.1)
    context = planner.CreateDefaultContext()
    planner.get_traversability_input_port().FixValue(context, values)
    planner.get_start_input_port().FixValue(context, np.array([0.15, 0.15]))
    planner.get_goal_input_port().FixValue(context, np.array([0.85, 0.15]))
    assert planner.get_path_output_port().Eval(context).shape[1] == 0  # nothing planned before the first event
    simulator = Simulator(planner, context)
    simulator.AdvanceTo(0.05)
    path = planner.get_path_output_port().Eval(simulator.get_context())
    status = planner.get_status_output_port().Eval(simulator.get_context())
    assert status[0] == 1.0
    np.testing.assert_allclose(path[:, 0], [0.15, 0.15])
    np.testing.assert_allclose(path[:, -1], [0.85, 0.15])
    crossings = path[:, np.abs(path[0] - 0.55) < 1e-9]
    assert crossings.shape[1] >= 1 and (crossings[1] > 0.8).all()  # through the gap only


def test_probe_supervisor_pauses_probes_and_assigns_the_cluster():
    grid = perception.GridMap([20, 20], 0.1, [0.0, 0.0])
    grid.AddLayer("semantic_plants", 0.0)
    grid.AddLayer("semantic_water", 0.0)
    plants = grid.Layer("semantic_plants")
    for x in (0.55, 0.65, 0.75):
        for y in (-0.05, 0.05):
            i, j = grid.CellOf([x, y])
            plants[i, j] = 0.9
    grid.SetLayer("semantic_plants", plants)
    options = planning.ProbingPlanner.Options()
    options.reach = 1.0
    supervisor = planning.ProbeSupervisor(options, 0.5, 3, 0.1)
    context = supervisor.CreateDefaultContext()
    supervisor.GetInputPort("map").FixValue(context, grid)
    supervisor.GetInputPort("robot").FixValue(context, np.array([0.0, 0.0]))
    supervisor.GetInputPort("collapsibility").FixValue(context, np.array([float("nan"), 0.0]))
    simulator = Simulator(supervisor, context)
    simulator.AdvanceTo(0.05)
    command = supervisor.get_probe_command_output_port().Eval(simulator.get_context())
    assert supervisor.get_pause_output_port().Eval(simulator.get_context())[0] == 1.0
    assert command[2] == 1.0 and 0.5 <= command[0] < 0.8
    supervisor.GetInputPort("collapsibility").FixValue(simulator.get_mutable_context(), np.array([0.85, 20.0]))
    simulator.AdvanceTo(0.35)
    assert supervisor.get_pause_output_port().Eval(simulator.get_context())[0] == 0.0
    probes = supervisor.GetOutputPort("probes").Eval(simulator.get_context())
    assert len(probes) == 1 and probes[0].collapsibility == 0.85 and len(probes[0].points) == 6
    assert supervisor.probes_made(simulator.get_context()) == 1


def test_run_probing_diagram_probes_soft_plants_and_reaches_the_goal():
    scenario = planning.TraverseScenario.Load(SCENARIO)
    run = planning.RunProbingDiagram(scenario, ARM, 300.0)
    assert run.reached_goal, run.failure
    assert run.probes_made == 3 and run.probes[0].region == "soft plants"
    assert 0.75 < run.collapsibilities[0] < 0.95
    assert run.collapsible_steps == 0 and "soft plants" not in run.regions_entered
    blind = planning.RunProbingDiagram(scenario, ARM, 300.0, probing=False)
    assert blind.collapsible_steps > 0
