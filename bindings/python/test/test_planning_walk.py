"""cairn.planning, walk: the walk diagram (footsteps -> whole body -> stabiliser -> player -> plant), its run, the
scenario's plant boxes, the reference player; cairn.visualization's HTML viewer."""

import math
import os

import numpy as np
import pytest

import cairn.multibody as mb
import cairn.planning as planning
import cairn.visualization as viz
from conftest import source_path

HUMANOID = source_path("data", "robots", "cairn_humanoid.urdf")
CONTROL = source_path("data", "robots", "cairn_humanoid_control.yaml")

SHORT_WALK = """name: short walk
terrain:
  min: [-0.5, -1.0]
  max: [1.5, 1.0]
  regions:
    - {name: floor, box: {min: [-0.5, -1.0], max: [1.5, 1.0]}, friction: 0.8}
start: {left: [0.0, 0.1, 0.0], right: [0.0, -0.1, 0.0]}
goal: {left: [0.3, 0.1, 0.0], right: [0.3, -0.1, 0.0], tolerance: 0.1}
planner: {time_limit: 600, max_expansions: 5000}
"""


@pytest.fixture(scope="module")
def robot():
    options = mb.UrdfOptions()
    options.floating_base = True
    return mb.ParseUrdfFile(HUMANOID, options)


@pytest.fixture(scope="module")
def scenario(tmp_path_factory):
    path = tmp_path_factory.mktemp("walk") / "short.yaml"
    path.write_text(SHORT_WALK)
    return planning.FootstepScenario.Load(str(path))


def setup_for(scenario, oracle, walking_model, robot):
    controller = mb.JointPdController.Load(robot, CONTROL)
    setup = planning.WalkSetupFromScenario(scenario, oracle, walking_model,
                                           planning.WalkingObjective.kComWorkPlusHeat, robot, controller)
    setup.stabilizer.control_period = 0.01
    return setup


def test_the_scenario_becomes_one_plant_box_with_its_friction(scenario):
    boxes = planning.ScenarioTerrainBoxes(scenario)
    assert len(boxes) == 1
    assert boxes[0].name == "floor" and boxes[0].friction == pytest.approx(0.8)
    # The box's top face is the ground, z = 0.
    assert boxes[0].X_WB.translation()[2] + 0.5 * boxes[0].size[2] == pytest.approx(0.0, abs=1e-12)


def test_the_walk_diagram_settles_and_the_plant_walks_the_reference(scenario, oracle, walking_model, robot):
    setup = setup_for(scenario, oracle, walking_model, robot)
    assert setup.stabilizer.contact_timing and setup.stabilizer.method == "fft"
    # The walking model's motors drive the plant, so it measures the heat the planner's steps predict.
    assert len(setup.plant.drives) == robot.nv()
    walk = planning.BuildWalkDiagram(setup)
    names = [s.get_name() for s in walk.diagram.GetSystems()]
    assert {"footsteps", "trajectory", "stabilizer", "player", "plant"} <= set(names)
    options = planning.WalkRunOptions()
    options.settle_time = 0.2
    record = planning.RunWalk(walk, options)
    assert record.start.ready, record.start.reason
    assert record.plan.found and record.trajectory.found and record.reference.report.success
    assert record.samples[0].time == 0.0
    assert np.allclose(record.samples[0].q, record.reference.q[0])
    assert record.fell == bool(record.fall_reason)
    assert record.duration <= record.reference.duration() + options.settle_time + 1e-9
    energies = [s.com_energy for s in record.samples]
    assert all(b >= a - 1e-12 for a, b in zip(energies, energies[1:]))
    assert record.samples[-1].heat > 0.0 and record.samples[-1].electrical_energy > record.samples[-1].heat
    # A sole's tangential force is recorded next to its normal force; an unloaded sole carries neither.
    assert any(s.left_tangential > 0.0 for s in record.samples)
    assert all(s.left_tangential == 0.0 for s in record.samples if s.left_force == 0.0)


def test_the_player_interpolates_between_samples_and_holds_the_last(robot, scenario, oracle, walking_model):
    walk = planning.BuildWalkDiagram(setup_for(scenario, oracle, walking_model, robot))
    record = planning.RunWalk(walk, planning.WalkRunOptions())
    reference = record.reference
    player = planning.StabilizedReferencePlayer(robot)
    nq = robot.nq()
    half = player.Sample(reference, 0.5 * reference.period)
    assert np.allclose(half[7:nq], 0.5 * (reference.q[0][7:] + reference.q[1][7:]))
    end = player.Sample(reference, reference.duration() + 1.0)
    assert np.allclose(end[:nq], reference.q[-1]) and np.all(end[nq:] == 0.0)
    with pytest.raises(RuntimeError):
        player.Sample(planning.StabilizedTrajectory(), 0.0)


def standing(robot):
    x = np.zeros(robot.nq() + robot.nv())
    x[:robot.nq()] = mb.NeutralConfiguration(robot)
    x[2] = 0.8
    return x


def test_balance_feedback_tilts_only_the_loaded_ankles_against_the_capture_point(robot):
    assert planning.BalanceFeedback(robot).options().pitch_gain == pytest.approx(0.8)
    options = planning.BalanceFeedbackOptions()
    options.foothold_gain = 0.0  # the soles moved with the robot: only the tilt here
    feedback = planning.BalanceFeedback(robot, options)
    planned = standing(robot)
    assert np.array_equal(feedback.Correct(planned, planned, True, True), planned)
    measured = planned.copy()
    measured[0] += 0.05  # the COM 5 cm ahead of the plan
    corrected = feedback.Correct(planned, measured, True, False)
    changed = np.flatnonzero(corrected != planned)
    left_pitch = robot.joint(robot.GetJointIndex("l_ankle_pitch")).idx_q
    assert list(changed) == [left_pitch]  # the right leg swings: untouched
    assert abs(corrected[left_pitch] - planned[left_pitch]) == pytest.approx(0.8 * 0.05)
    # In the air nothing changes.
    assert np.array_equal(feedback.Correct(planned, measured, False, False), planned)


def test_balance_feedback_writes_a_loaded_foots_placement_into_its_leg(robot):
    options = planning.BalanceFeedbackOptions()
    options.pitch_gain = options.roll_gain = 0.0
    assert options.foothold_gain == pytest.approx(0.5)
    feedback = planning.BalanceFeedback(robot, options)
    planned = standing(robot)
    measured = planned.copy()
    measured[0] += 0.04  # the loaded left foot stands 4 cm ahead of where the reference puts it
    corrected = feedback.Correct(planned, measured, True, False)
    before, after = mb.Data(robot), mb.Data(robot)
    mb.ForwardKinematics(robot, before, planned[:robot.nq()])
    mb.ForwardKinematics(robot, after, corrected[:robot.nq()])
    sole = robot.GetBodyIndex("l_sole")
    moved = after.X_world[sole].translation() - before.X_world[sole].translation()
    np.testing.assert_allclose(moved, [0.02, 0.0, 0.0], atol=5e-4)  # half of it, at the default gain
    assert np.array_equal(corrected[:7], planned[:7])  # the base keeps the plan


def test_balance_feedback_levels_a_swing_sole_against_the_bases_tilt(robot):
    options = planning.BalanceFeedbackOptions()
    options.pitch_gain = options.roll_gain = options.foothold_gain = 0.0
    assert options.swing_orientation_gain == 0.0 and options.swing_position_gain == 0.0
    options.swing_orientation_gain = 1.0
    feedback = planning.BalanceFeedback(robot, options)
    planned = standing(robot)
    measured = planned.copy()
    measured[3:7] = [np.cos(0.025), 0.0, np.sin(0.025), 0.0]  # the base pitched 0.05 rad
    corrected = feedback.Correct(planned, measured, True, False)
    on_base = corrected.copy()
    on_base[:7] = measured[:7]
    want, got = mb.Data(robot), mb.Data(robot)
    mb.ForwardKinematics(robot, want, planned[:robot.nq()])
    mb.ForwardKinematics(robot, got, on_base[:robot.nq()])
    sole = robot.GetBodyIndex("r_sole")
    tilt = got.X_world[sole].rotation().T @ want.X_world[sole].rotation()
    assert np.arccos(np.clip((np.trace(tilt) - 1.0) / 2.0, -1.0, 1.0)) < 3e-3  # level again, as planned


def test_gravity_feedforward_holds_the_swing_leg_but_not_the_stance_leg(robot):
    feedforward = planning.GravityFeedforward(robot, ["l_sole", "r_sole"])
    q = standing(robot)[:robot.nq()]
    knee = robot.joint(robot.GetJointIndex("r_knee")).idx_q
    q[knee] = 0.6
    g = np.array(mb.GravityTorques(robot, mb.Data(robot), q)).copy()
    torque = feedforward.Torques(q, True, False)
    r_knee = robot.joint(robot.GetJointIndex("r_knee")).idx_v
    l_knee = robot.joint(robot.GetJointIndex("l_knee")).idx_v
    assert torque[r_knee] == pytest.approx(g[r_knee]) and g[r_knee] != 0.0
    assert torque[l_knee] == 0.0 and np.all(torque[:6] == 0.0)
    with pytest.raises(ValueError, match="gain 2 must be in"):
        planning.GravityFeedforward(robot, ["l_sole", "r_sole"], 2.0)


def test_balance_feedback_refuses_bad_options_and_sizes(robot):
    options = planning.BalanceFeedbackOptions()
    options.max_pitch = 0.7
    with pytest.raises(ValueError, match="max_pitch 0.7 must be in"):
        planning.BalanceFeedback(robot, options)
    options = planning.BalanceFeedbackOptions()
    options.right_ankle_pitch = "r_ankle"
    with pytest.raises(ValueError, match="no joint 'r_ankle'"):
        planning.BalanceFeedback(robot, options)
    with pytest.raises(ValueError, match="nq \\+ nv"):
        planning.BalanceFeedback(robot).Correct(np.zeros(3), np.zeros(3), True, True)


def test_the_walk_diagram_closes_the_loop_unless_told_to_play_open_loop(scenario, oracle, walking_model, robot):
    setup = setup_for(scenario, oracle, walking_model, robot)
    assert setup.feedback
    assert setup.gravity_feedforward == 0.0 and planning.BuildWalkDiagram(setup).feedforward is None
    setup.gravity_feedforward = 1.0
    walk = planning.BuildWalkDiagram(setup)
    assert walk.feedforward is not None and walk.feedforward.gain() == 1.0
    setup.gravity_feedforward = -0.5
    with pytest.raises(ValueError, match="gravity_feedforward -0.5 must be in"):
        planning.BuildWalkDiagram(setup)
    setup.gravity_feedforward = 0.0
    walk = planning.BuildWalkDiagram(setup)
    assert walk.balance is not None and walk.balance.get_name() == "balance"
    setup.feedback = False
    open_loop = planning.BuildWalkDiagram(setup)
    assert open_loop.balance is None
    assert "balance" not in [s.get_name() for s in open_loop.diagram.GetSystems()]


def test_the_viewer_page_inlines_three_js_and_refuses_a_bad_scene(robot, tmp_path):
    if not os.path.exists(viz.DefaultThreeJsPath()):
        pytest.skip("libjs-three is not installed")
    scene = viz.MotionScene()
    scene.title = "standing"
    box = viz.SceneBox()
    box.name, box.size, box.friction = "floor", np.array([2.0, 2.0, 0.1]), 0.8
    scene.boxes = [box]
    stance = planning.Stance()
    stance.left, stance.right = planning.FootPose(0.5, 0.1, 0.0, 0.0), planning.FootPose(0.5, -0.1, 0.0, 0.0)
    q = planning.StandingAtStart(robot, ["l_sole", "r_sole"], stance)
    assert q[0] == pytest.approx(0.5) and q[1] == pytest.approx(0.0) and q[2] > 0.5
    with pytest.raises(ValueError, match="unknown body 'left_foot_sole'"):
        planning.StandingAtStart(robot, ["left_foot_sole"], stance)
    fixed = mb.ParseUrdfFile(HUMANOID)  # no floating base: nothing to place over the feet
    with pytest.raises(ValueError, match="has no floating base; load the URDF with a floating base"):
        planning.StandingAtStart(fixed, ["l_sole", "r_sole"], stance)
    scene.times, scene.q = [0.0, 0.5], [q, q]
    cell = viz.SceneBox()
    cell.name, cell.size, cell.occupancy = "occupied", np.array([0.05, 0.05, 0.05]), 0.7
    scene.boxes = [box, cell]
    page = viz.MotionHtml(robot, scene)
    assert page.startswith("<!DOCTYPE html>") and "standing" in page and "THREE" in page
    assert '"occupancy": 0.7000' in page
    scene.times = [0.5, 0.0]
    with pytest.raises(ValueError, match="comes before the previous frame"):
        viz.MotionHtml(robot, scene)


def gait(dx, dz, steps=6):
    return planning.PeriodicGait(planning.StepDisplacement(dx, 0.2, dz, 0.0), planning.StepParameters(0.5, 1.2, 0.7),
                                 steps)


def test_a_periodic_gait_repeats_its_step_and_closes_side_by_side(walking_model):
    plan = planning.PeriodicGaitPlan(gait(0.2, 0.0, 4), walking_model, planning.WalkingObjective.kComWork, 0.9)
    assert [str(s.side).endswith("kRight") for s in plan.steps] == [True, False, True, False, True]
    assert [s.displacement.dx for s in plan.steps] == [0.2, 0.2, 0.2, 0.2, 0.0]
    assert all(s.mu_allowed == 0.9 for s in plan.steps)
    assert plan.steps[-1].pose.x == pytest.approx(plan.steps[-2].pose.x)
    floor = planning.PeriodicGaitTerrain(plan, 0.24, 0.14, 1.0)
    assert len(floor) == 1 and floor[0].friction == 1.0
    stairs = planning.PeriodicGaitPlan(gait(0.3, 0.1, 4), walking_model, planning.WalkingObjective.kComWork, 0.9)
    assert len(planning.PeriodicGaitTerrain(stairs, 0.24, 0.14, 1.0)) == 2 + len(stairs.steps)
    steep = planning.PeriodicGaitPlan(gait(0.15, 0.1, 4), walking_model, planning.WalkingObjective.kComWork, 0.9)
    with pytest.raises(ValueError, match="overlap"):
        planning.PeriodicGaitTerrain(steep, 0.24, 0.14, 1.0)
    with pytest.raises(ValueError, match="dx 0.5 m"):
        planning.PeriodicGaitPlan(gait(0.5, 0.0), walking_model, planning.WalkingObjective.kComWork, 0.9)


def test_the_gait_sampler_walks_a_fixed_plan_and_reports_a_gait_without_ground(walking_model, robot):
    controller = mb.JointPdController.Load(robot, CONTROL)
    options = planning.PlantGaitOptions()
    options.num_steps = 1
    options.transient_steps = 0
    sampler = planning.PlantGaitSampler(walking_model, robot, controller, planning.WalkingObjective.kComWorkPlusHeat,
                                        options)
    assert sampler.options().num_steps == 1
    setup = sampler.Setup(gait(0.1, 0.0))
    assert len(setup.plan.steps) == 2
    walk = planning.BuildWalkDiagram(setup)
    assert walk.footsteps is None and walk.plan is not None
    run = planning.WalkRunOptions()
    run.settle_time = 0.2
    record = planning.RunWalk(walk, run)
    assert record.start.ready, record.start.reason
    assert [s.displacement.dx for s in record.plan.steps] == [0.1, 0.0]
    steps = planning.CompareWalkSteps(record)
    assert [s.index for s in steps] == [1, 2]
    assert not record.fell, record.fall_reason
    assert all(s.completed for s in steps)
    assert steps[0].measured_com_energy > 0.0
    assert planning.SoleDistance(robot, setup.plant.sole_bodies, record, record.plan.StanceAfter(1)) < 0.05

    no_ground = sampler.Measure(gait(0.15, 0.1))
    assert not no_ground.simulated and not no_ground.feasible
    assert "no ground for this gait" in no_ground.reason
    assert np.isnan(no_ground.com_work)
    setup.plan = None
    assert setup.plan is None


def test_the_plant_source_keeps_the_cheapest_measured_gait_within_each_limit(walking_model, robot):
    controller = mb.JointPdController.Load(robot, CONTROL)
    sampler = planning.PlantGaitSampler(walking_model, robot, controller, planning.WalkingObjective.kComWork)
    source = planning.PlantTransitionSource(sampler, [0.5], [1.2])
    assert source.name() == "plant" and not source.concurrent()
    assert source.Describe().startswith("plant t_ds 0.5 t_sw 1.2 steps 6 ")
    assert source.t_ds() == [0.5] and source.t_sw() == [1.2]
    grid = planning.PlantTransitionSource.DefaultGrid(walking_model)
    assert grid.dz == [0.0] and len(grid.dx) == 4
    assert planning.PlantTransitionSource.DefaultSwingTimes(walking_model) == [0.9, 1.2]
    with pytest.raises(ValueError, match="t_ds value 9 s is outside"):
        planning.PlantTransitionSource(sampler, [9.0], [1.2])

    def measured(t_ds, com_work, rcof):
        m = planning.GaitMeasurement()
        m.gait.parameters = planning.StepParameters(t_ds, 1.2, 0.7)
        m.simulated, m.feasible, m.com_work, m.heat, m.rcof = True, True, com_work, 0.0, rcof
        return m

    entries = planning.PlantTransitionSource.EntriesFrom([measured(0.2, 5.0, 0.3), measured(0.9, 9.0, 0.1)],
                                                         planning.WalkingObjective.kComWork, [0.05, 0.2, 1.0])
    assert [e.feasible for e in entries] == [False, True, True]
    assert [e.cost for e in entries[1:]] == [9.0, 5.0]
    with pytest.raises(ValueError, match="no squared static torques"):
        planning.PlantTransitionSource.EntriesFrom([], planning.WalkingObjective.kSquaredTorque, [1.0])

    # The pipeline mode prices the whole-body torque cost and refuses heat, which it does not measure.
    pipeline = planning.PlantTransitionSource(sampler, [0.5], [1.2], planning.PlantTransitionSource.Mode.kPipeline)
    assert pipeline.name() == "pipeline" and pipeline.mode() == planning.PlantTransitionSource.Mode.kPipeline
    cheap, dear = measured(0.2, 5.0, 0.3), measured(0.9, 9.0, 0.1)
    cheap.torque_cost, dear.torque_cost = 0.2, 0.1
    entries = planning.PlantTransitionSource.EntriesFrom([cheap, dear], planning.WalkingObjective.kSquaredTorque,
                                                         [1.0], planning.PlantTransitionSource.Mode.kPipeline)
    assert entries[0].cost == 0.1 and entries[0].parameters.t_ds == 0.9
    with pytest.raises(ValueError, match="measures no heat"):
        planning.PlantTransitionSource.EntriesFrom([], planning.WalkingObjective.kComWorkPlusHeat, [1.0],
                                                   planning.PlantTransitionSource.Mode.kPipeline)


def test_the_pipeline_measurement_plans_and_stabilises_a_gait_without_walking_it(walking_model, robot):
    controller = mb.JointPdController.Load(robot, CONTROL)
    sampler = planning.PlantGaitSampler(walking_model, robot, controller, planning.WalkingObjective.kSquaredTorque)
    m = sampler.MeasurePlanned(gait(0.1, 0.0))
    assert m.feasible and not m.simulated, m.reason
    assert m.measured_steps == 2
    assert m.torque_cost > 0.0 and m.com_work > 0.0 and 0.0 < m.rcof < 0.5
    assert m.support_margin >= sampler.options().min_support_margin
    assert 0.6 < m.com_height < 0.85
    assert math.isnan(m.heat) and math.isnan(m.electrical_energy)
