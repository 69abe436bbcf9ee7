"""cairn.multibody plant: BulletPlant agrees with ForwardDynamics, a block slides at g(sin - mu cos), and the
HumanoidPlant stands in a diagram and ends a simulation when it falls."""

import math

import numpy as np
import pytest

import cairn.multibody as mb
import cairn.systems as sy
from conftest import source_path

HUMANOID = source_path("data", "robots", "cairn_humanoid.urdf")
CONTROL = source_path("data", "robots", "cairn_humanoid_control.yaml")
WALKING = source_path("data", "robots", "cairn_humanoid_walking.yaml")


@pytest.fixture(scope="module")
def model():
    options = mb.UrdfOptions()
    options.floating_base = True
    return mb.ParseUrdfFile(HUMANOID, options)


def standing_q(model):
    q = mb.NeutralConfiguration(model)
    data = mb.Data(model)
    mb.ForwardKinematics(model, data, q)
    q[2] = -mb.FramePose(model, data, model.GetFrameIndex("l_sole")).translation()[2]
    return q


def ground(friction):
    return [mb.TerrainBox("ground", mb.Pose(np.eye(3), [0.0, 0.0, -0.5]), [20.0, 20.0, 1.0], friction)]


def test_accelerations_match_forward_dynamics(model):
    options = mb.BulletPlantOptions()
    options.time_step = 1e-8
    options.contacts = False
    plant = mb.BulletPlant(model, [], options)
    q = mb.RandomConfiguration(model, 5, 1.0)
    rng = np.random.default_rng(5)
    v = rng.uniform(-1.0, 1.0, model.nv())
    tau = rng.uniform(-10.0, 10.0, model.nv())
    expected = np.array(mb.ForwardDynamics(model, mb.Data(model), q, v, tau))
    plant.SetState(q, v)
    plant.Step(tau)
    actual = (plant.velocities() - v) / options.time_step
    assert np.max(np.abs(actual - expected)) <= 1e-7 * max(1.0, np.max(np.abs(expected)))


def test_block_slides_at_the_coulomb_acceleration():
    builder = mb.ModelBuilder("block")
    body = mb.Body()
    body.name = "block"
    body.inertia = mb.SpatialInertia.FromMassComInertia(1.0, np.zeros(3), np.eye(3) * 0.005)
    joint = mb.Joint()
    joint.name = "root_joint"
    joint.type = mb.JointType.kFloating
    index = builder.AddBody(0, body, joint)
    box = mb.Geometry()
    box.name = "box"
    box.type = mb.GeometryType.kBox
    box.size = np.array([0.2, 0.2, 0.1])
    builder.AddCollisionGeometry(index, box)
    block = builder.Build()
    theta, mu = math.radians(30.0), 0.2
    c, s = math.cos(theta), math.sin(theta)
    R = np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    incline = mb.TerrainBox("incline", mb.Pose(R, R @ np.array([0.0, 0.0, -0.5])), [40.0, 4.0, 1.0], mu)
    plant = mb.BulletPlant(block, [incline])
    w = math.cos(theta / 2.0)
    q0 = np.concatenate([R @ np.array([0.0, 0.0, 0.05]), [w, 0.0, math.sin(theta / 2.0), 0.0]])
    plant.SetState(q0, np.zeros(6))
    plant.Step(np.zeros(6), 500)
    v_half = plant.velocities()[3]
    plant.Step(np.zeros(6), 500)
    acceleration = (plant.velocities()[3] - v_half) / 0.5
    expected = 9.81 * (s - mu * c)
    assert acceleration == pytest.approx(expected, rel=0.01)
    assert plant.time() == pytest.approx(1.0)


def test_humanoid_plant_stands_in_a_diagram(model):
    pd = mb.JointPdController.Load(model, CONTROL)
    options = mb.HumanoidPlantOptions()
    options.drives = mb.LoadJointDrives(model, WALKING)
    q0 = standing_q(model)
    builder = sy.DiagramBuilder()
    plant = builder.AddNamedSystem("plant", mb.HumanoidPlant(model, ground(0.8), pd, q0, options))
    reference = np.concatenate([q0, np.zeros(model.nv())])
    source = builder.AddNamedSystem("reference", sy.ConstantVectorSource(reference))
    builder.Connect(source.get_output_port(0), plant.GetInputPort("reference"))
    diagram = builder.Build()
    simulator = sy.Simulator(diagram)
    status = simulator.AdvanceTo(0.5)
    assert status.reached_boundary_time()
    context = diagram.GetSubsystemContext(plant, simulator.get_context())
    state = plant.GetOutputPort("state").Eval(context)
    assert abs(state[2] - q0[2]) < 1e-3
    soles = plant.GetOutputPort("contacts").Eval(context)
    assert len(soles) == 2 and soles[0].loaded and soles[1].loaded
    assert soles[0].normal_force + soles[1].normal_force == pytest.approx(model.total_mass() * 9.81, rel=0.02)
    assert plant.GetOutputPort("slips").Eval(context) == []
    assert plant.GetOutputPort("energy").Eval(context)[1] > 0.0
    # Standing still asks almost no friction of either sole or of their net force.
    stances = plant.GetOutputPort("stances").Eval(context)
    assert len(stances) == 2
    assert all(s.net_rcof < 0.05 and s.rcof < 0.05 for s in stances)


def test_contact_monitor_options_refuse_a_negative_stance_gap(model):
    options = mb.HumanoidPlantOptions()
    assert options.monitor.stance_gap == pytest.approx(0.03)
    options.monitor.stance_gap = -1.0
    pd = mb.JointPdController.Load(model, CONTROL)
    with pytest.raises(ValueError, match="stance_gap is -1"):
        mb.HumanoidPlant(model, ground(0.8), pd, standing_q(model), options)


def test_a_fall_ends_the_simulation(model):
    limp = mb.JointPdController(model, np.zeros(model.nv()), np.ones(model.nv()))
    q0 = standing_q(model)
    plant = mb.HumanoidPlant(model, ground(0.8), limp, q0)
    simulator = sy.Simulator(plant)
    plant.get_input_port(0).FixValue(simulator.get_mutable_context(), np.concatenate([q0, np.zeros(model.nv())]))
    status = simulator.AdvanceTo(5.0)
    assert status.reason == sy.SimulatorStatus.Reason.kReachedTerminationCondition
    assert "the robot fell at t = " in status.message
    assert status.time < 5.0


def test_bad_input_is_refused(model):
    with pytest.raises(ValueError, match="friction -1"):
        mb.BulletPlant(model, ground(-1.0))
    pd = mb.JointPdController.Load(model, CONTROL)
    with pytest.raises(ValueError, match="initial_q has size 3"):
        mb.HumanoidPlant(model, ground(0.8), pd, np.zeros(3))


def test_scenario_and_trajectory_files(model, tmp_path):
    scenario = mb.PlantScenario.Load(source_path("examples", "scenarios", "plant", "ice_and_carpet.yaml"))
    assert [box.name for box in scenario.terrain] == ["ice", "carpet"]
    assert scenario.terrain[0].friction == pytest.approx(0.1)
    path = tmp_path / "wave.csv"
    path.write_text("time,r_elbow\n0,0\n1,-1\n")
    trajectory = mb.JointTrajectory.LoadCsv(model, str(path))
    q, v = trajectory.Evaluate(0.5, mb.NeutralConfiguration(model))
    elbow = model.joint(model.GetJointIndex("r_elbow"))
    assert q[elbow.idx_q] == pytest.approx(-0.5)
    assert v[elbow.idx_v] == pytest.approx(-1.0)
    path.write_text("time,r_elbow\n0,5\n")
    with pytest.raises(ValueError, match="outside its limits"):
        mb.JointTrajectory.LoadCsv(model, str(path))
