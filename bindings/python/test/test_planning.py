"""cairn.planning: scenarios, terrain, the oracle, PlanFootsteps, FootstepPlanner in a diagram, plans as values."""

import json
import pickle

import numpy as np
import pytest

import cairn.planning as planning
from cairn.systems import ConstantValueSource, DiagramBuilder
from conftest import source_path

ICE = source_path("examples", "scenarios", "ice_narrow_012.yaml")


def budgeted(options, expansions=20000):
    options.search.max_expansions = expansions
    options.search.time_limit = float("inf")
    return options


def test_scenario_and_terrain():
    scenario = planning.FootstepScenario.Load(ICE)
    assert scenario.name() == "narrow ice, mu 0.12"
    assert scenario.oracle() == "model"
    priced_by_plant = planning.FootstepScenario.Load(source_path("examples", "scenarios", "flat_plant_oracle.yaml"))
    assert priced_by_plant.oracle() == "plant"
    assert [r.name for r in scenario.regions()] == ["ground", "ice"]
    terrain = scenario.BuildTerrain()
    col, row = terrain.CellAt(1.5, 0.0)
    assert terrain.friction(col, row) == pytest.approx(0.12)
    assert terrain.friction(*terrain.CellAt(0.5, 1.0)) == pytest.approx(1.0)
    assert terrain.frictions().shape == (terrain.rows(), terrain.cols())
    assert terrain.CellAt(100.0, 0.0) is None
    with pytest.raises(IndexError):
        terrain.height(terrain.cols(), 0)
    with pytest.raises(ValueError, match="missing.yaml"):
        planning.FootstepScenario.Load(source_path("examples", "scenarios", "missing.yaml"))
    # A generous limit gives the same terrain; a non-positive one is refused with the range.
    limited = scenario.BuildTerrain(time_limit=600.0)
    assert (limited.frictions() == terrain.frictions()).all()
    with pytest.raises(ValueError, match=r"time_limit -1 s must be in \(0, 86400\]"):
        scenario.BuildTerrain(time_limit=-1.0)


def test_plan_footsteps_on_ice(walking_model, oracle):
    scenario = planning.FootstepScenario.Load(ICE)
    geometry = planning.BipedGeometry.FromWalkingModel(walking_model)
    plan = planning.PlanFootsteps(scenario.BuildTerrain(), scenario.start(), scenario.goal(), oracle, geometry,
                                  budgeted(scenario.planner()))
    assert plan.found, plan.reason
    assert len(plan.steps) > 5
    assert plan.max_rcof <= 1.0 and plan.min_friction_margin >= 0.0
    last = plan.StanceAfter(len(plan.steps) - 1)
    assert abs(last.left.x - 3.0) < 0.15 and abs(last.right.x - 3.0) < 0.15
    as_dict = plan.to_dict()
    json.dumps(as_dict)  # plain Python values
    assert as_dict["found"] and len(as_dict["steps"]) == len(plan.steps)
    assert as_dict["steps"][0]["side"] in ("left", "right")
    assert sum(s["energy"] for s in as_dict["steps"]) == pytest.approx(plan.energy, rel=1e-9)
    copy = pickle.loads(pickle.dumps(plan))
    assert copy.to_dict() == as_dict
    refined = planning.RefineFootstepPlan(walking_model, planning.WalkingObjective.kComWorkPlusHeat, copy)
    assert refined > 0 and copy.found


def test_footstep_planner_system_matches_the_function(walking_model, oracle):
    scenario = planning.FootstepScenario.Load(ICE)
    geometry = planning.BipedGeometry.FromWalkingModel(walking_model)
    options = budgeted(scenario.planner())
    terrain = scenario.BuildTerrain()
    builder = DiagramBuilder()
    planner = builder.AddSystem(planning.FootstepPlanner(oracle, geometry, options))
    for port, value in ((planner.get_terrain_input_port(), terrain), (planner.get_start_input_port(), scenario.start()),
                        (planner.get_goal_input_port(), scenario.goal())):
        source = builder.AddSystem(ConstantValueSource(value))
        builder.Connect(source.get_output_port(0), port)
    builder.ExportOutput(planner.get_plan_output_port(), "plan")
    diagram = builder.Build()
    context = diagram.CreateDefaultContext()
    assert not diagram.GetOutputPort("plan").Eval(context).found  # the search runs in an event
    diagram.ExecuteForcedEvents(context)
    plan = diagram.GetOutputPort("plan").Eval(context)
    direct = planning.PlanFootsteps(terrain, scenario.start(), scenario.goal(), oracle, geometry, options)
    assert plan.found
    ours = plan.to_dict()
    theirs = direct.to_dict()
    for d in (ours, theirs):
        d.pop("statistics")
    assert ours == theirs


def test_footstep_replanner_matches_plan_footsteps(walking_model, oracle):
    scenario = planning.FootstepScenario.Load(ICE)
    terrain = scenario.BuildTerrain()
    geometry = planning.BipedGeometry()
    options = budgeted(scenario.planner())
    replanner = planning.FootstepReplanner(terrain, scenario.goal(), oracle, geometry, options)
    assert not replanner.prepared()
    first = replanner.Plan(scenario.start())
    assert first.found and replanner.prepared()
    start = first.StanceAfter(0)
    again = replanner.Plan(start)
    direct = planning.PlanFootsteps(terrain, start, scenario.goal(), oracle, geometry, options)
    assert again.found and again.cost == direct.cost
    assert len(again.steps) == len(first.steps) - 1
    # Less friction everywhere only raises costs: the precomputation is kept and the plan stays optimal.
    slippery = scenario.BuildTerrain()
    for row in range(slippery.rows()):
        for col in range(slippery.cols()):
            if slippery.walkable(col, row):
                slippery.SetCell(col, row, slippery.height(col, row), np.array([0.0, 0.0, 1.0]),  # level ground
                                 min(slippery.friction(col, row), 0.3))
    assert replanner.UpdateTerrain(slippery) and replanner.prepared()
    assert replanner.Plan(start).cost == pytest.approx(
        planning.PlanFootsteps(slippery, start, scenario.goal(), oracle, geometry, options).cost, abs=1e-6)
    with pytest.raises(ValueError, match="cost model is null"):
        planning.FootstepReplanner(terrain, scenario.goal(), None, geometry, options)


def test_level_step_tolerance_prices_millimetre_bumps_as_level_steps(walking_model, oracle):
    # The mock-up's wood and tiles with every cell's height off by up to 4 mm, as stereo leaves them. The oracle
    # knows heights every 5 cm, so priced as measured a step on wood (Q = 0.103, which a level step needs nearly
    # all of) is mostly refused; within level_step_tolerance the steps are level and the footholds keep their heights.
    scenario = planning.FootstepScenario.Load(source_path("examples", "scenarios", "mockup", "mockup.yaml"))
    terrain = scenario.BuildTerrain()
    for row in range(terrain.rows()):
        for col in range(terrain.cols()):
            terrain.SetCell(col, row, 0.001 * ((7 * col + 3 * row) % 5), np.array([0.0, 0.0, 1.0]),
                            terrain.friction(col, row))
    geometry = planning.BipedGeometry.FromWalkingModel(walking_model)
    options = budgeted(scenario.planner())
    assert options.level_step_tolerance == pytest.approx(0.01)  # mockup.yaml sets it
    level = planning.PlanFootsteps(terrain, scenario.start(), scenario.goal(), oracle, geometry, options)
    assert level.found, level.reason
    assert all(step.displacement.dz == 0.0 for step in level.steps)
    assert any(step.pose.z != 0.0 for step in level.steps)
    options.level_step_tolerance = 0.0
    measured = planning.PlanFootsteps(terrain, scenario.start(), scenario.goal(), oracle, geometry, options)
    assert not measured.found or measured.cost > level.cost


def test_min_cost_over_heights(oracle):
    d = planning.StepDisplacement(dx=0.25, dy=0.2)
    costs = []
    for dz in np.linspace(0.0, 0.04, 9):
        step = oracle.Evaluate(planning.StepDisplacement(dx=0.25, dy=0.2, dz=float(dz)), 1.0)
        assert step.feasible
        costs.append(step.cost)
    bound = oracle.MinCostOverHeights(d, 0.0, 0.04, 1.0)
    assert bound <= min(costs) * (1 + 1e-12)
    assert bound >= min(costs) * (1 - 1e-12)  # the oracle's bound is the exact minimum
    assert oracle.MinCostOverHeights(d, 1.0, 1.1, 1.0) == float("inf")  # beyond the reach


def test_values_and_errors(walking_model, oracle):
    pose = planning.FootPose(x=1.0, y=2.0, theta=0.5)
    assert pickle.loads(pickle.dumps(pose)).to_dict() == {"x": 1.0, "y": 2.0, "z": 0.0, "theta": 0.5}
    goal = pickle.loads(pickle.dumps(planning.StanceGoal(planning.Stance(pose, pose), 0.2)))
    assert goal.position_tolerance == 0.2 and goal.stance.left.y == 2.0
    assert planning.to_string(planning.ParseWalkingObjective("time")) == "time"
    with pytest.raises(ValueError, match="ecom"):
        planning.ParseWalkingObjective("ecmo")
    step = oracle.Evaluate(planning.StepDisplacement(dx=0.2, dy=0.2), 1.0)
    assert step.feasible and step.rcof <= 1.0
    assert pickle.loads(pickle.dumps(walking_model)).name() == walking_model.name()
    terrain = planning.TerrainMap(np.array([0.0, 0.0]), 4, 3, 0.5)
    with pytest.raises(ValueError):
        terrain.SetCell(0, 0, 0.0, np.array([0.0, 0.0, -1.0]), 1.0)
    stance = planning.Stance(planning.FootPose(x=0.5, y=0.6), planning.FootPose(x=0.5, y=0.4))
    options = planning.FootstepPlannerOptions()
    options.orientations = 64
    with pytest.raises(ValueError, match="orientations|32"):
        planning.PlanFootsteps(terrain, stance, planning.StanceGoal(stance, 0.2), oracle, planning.BipedGeometry(),
                               options)
    with pytest.raises(ValueError, match="both feet stand at one point"):
        planning.PlanFootsteps(terrain, planning.Stance(), planning.StanceGoal(stance, 0.2), oracle,
                               planning.BipedGeometry(), planning.FootstepPlannerOptions())


def test_oracle_built_in_shards_matches_one_build(walking_model, tmp_path):
    grid_file = tmp_path / "grid.yaml"
    grid_file.write_text("dx: [0.15, 0.25]\ndy: [0.18, 0.24]\ndz: [0.0]\ndtheta: [0.0]\nmu: {from: 0.5, to: 1.0, step: 0.5}\n")
    grid = planning.OracleGrid.Load(str(grid_file))
    assert grid.mu == [0.5, 1.0]
    options = planning.OracleBuildOptions()
    options.num_threads = 1
    objective = planning.WalkingObjective.kComWorkPlusHeat
    whole = planning.TransitionOracle.Build(walking_model, objective, grid, options)
    builder = planning.OracleShardBuilder(walking_model, objective, grid, str(tmp_path / "parts"), 1)
    assert builder.num_chunks() == 4 and builder.ChunksOfRank(1, 2) == [1, 3]
    assert builder.BuildShard(1, 2, options).computed == 2
    assert builder.MissingChunks() == [0, 2]
    with pytest.raises(RuntimeError, match="2 of 4 chunks are not ready"):
        builder.Merge()
    report = builder.BuildShard(0, 1, options)
    assert (report.computed, report.resumed) == (2, 2)
    assert builder.Merge().Serialize() == whole.Serialize()
    builder.RemoveCheckpoints()
    assert not (tmp_path / "parts").exists()


def test_a_grid_fingerprint_names_its_values():
    grid = planning.OracleGrid()
    grid.dx, grid.dy, grid.dz = [0.15, 0.25], [0.18, 0.24], [0.0, 0.05]
    grid.dtheta, grid.mu = [0.0, 0.5], [0.06, 0.12, 1.0]
    assert grid.Fingerprint() == "55ac21ae5066908c"  # the C++ test's known answer
    grid.mu = [0.06, 0.12]
    assert grid.Fingerprint() != "55ac21ae5066908c"


def test_an_oracle_names_its_source_and_the_model_source_is_the_default(walking_model, tmp_path):
    grid = planning.OracleGrid()
    grid.dx, grid.dy, grid.dz, grid.dtheta, grid.mu = [0.15], [0.2], [0.0], [0.0], [0.1, 1.0]
    objective = planning.WalkingObjective.kComWork
    source = planning.ModelTransitionSource()
    assert (source.name(), source.Describe(), source.concurrent()) == ("model", "model", True)
    options = planning.OracleBuildOptions()
    options.num_threads = 1
    assert options.source is None
    default = planning.TransitionOracle.Build(walking_model, objective, grid, options)
    options.source = source
    named = planning.TransitionOracle.Build(walking_model, objective, grid, options)
    assert named.source() == "model" and named.Serialize() == default.Serialize()
    cell = source.CellEntries(walking_model, objective, planning.StepDisplacement(0.15, 0.2, 0.0, 0.0), grid.mu)
    assert len(cell) == 2 and cell[1].feasible
    with pytest.raises(ValueError, match="larger than the one before it"):
        source.CellEntries(walking_model, objective, planning.StepDisplacement(0.15, 0.2, 0.0, 0.0), [1.0, 0.5])
    path = str(tmp_path / "model.oracle")
    named.Save(path)
    assert planning.TransitionOracle.Load(path, walking_model, objective, grid, source).Serialize() == named.Serialize()
    builder = planning.OracleShardBuilder(walking_model, objective, grid, str(tmp_path / "parts"), 1, source)
    builder.BuildShard(0, 1, options)
    assert builder.Merge().Serialize() == named.Serialize()

    held_out = planning.OracleHeldOutOptions()
    held_out.num_samples = 3
    error = planning.MeasureOracleHeldOutError(named, source, walking_model, held_out)
    assert len(error.samples) == 3
    assert error.both_feasible + error.only_predicted + error.only_measured + error.neither == 3
    assert all(s.mu in grid.mu for s in error.samples)
