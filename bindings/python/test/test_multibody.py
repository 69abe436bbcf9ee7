"""cairn.multibody: the humanoid's URDF, Data views, every algorithm, configurations and the collision world."""

import os
import pickle

import numpy as np
import pytest

import cairn.multibody as mb
from conftest import source_path

HUMANOID = source_path("data", "robots", "cairn_humanoid.urdf")


@pytest.fixture(scope="module")
def model():
    options = mb.UrdfOptions()
    options.floating_base = True
    return mb.ParseUrdfFile(HUMANOID, options)


def random_state(model, seed):
    q = mb.RandomConfiguration(model, seed, 1.0)
    rng = np.random.default_rng(seed)
    return q, rng.standard_normal(model.nv()), rng.standard_normal(model.nv())


def test_model_from_urdf(model):
    assert model.nq() == model.nv() + 1  # floating base: quaternion
    assert model.joint(1).type == mb.JointType.kFloating
    assert model.num_bodies() == len(model.body_names())
    assert model.total_mass() > 10.0
    assert model.GetFrameIndex(model.frame_names()[3]) == 3
    with pytest.raises(ValueError, match="closest|did you mean|Did you mean"):
        model.GetBodyIndex("pelvis_typo")
    with pytest.raises(RuntimeError, match="missing.urdf"):
        mb.ParseUrdfFile(source_path("data", "robots", "missing.urdf"))


def test_model_pickles_as_its_file(model):
    copy = pickle.loads(pickle.dumps(model))
    assert (copy.nq(), copy.nv(), copy.body_names()) == (model.nq(), model.nv(), model.body_names())
    built = mb.ModelBuilder("one").Build()
    with pytest.raises(TypeError, match="cannot be pickled"):
        pickle.dumps(built)


def test_data_views_are_zero_copy_and_read_only(model):
    data = mb.Data(model)
    q, _, _ = random_state(model, 1)
    M = mb.MassMatrix(model, data, q)
    view = data.M
    assert M.__array_interface__["data"][0] == view.__array_interface__["data"][0]
    assert not M.flags.writeable
    with pytest.raises(ValueError):
        M[0, 0] = 1.0
    del data  # the view keeps the Data alive
    assert M.shape == (model.nv(), model.nv())
    np.testing.assert_allclose(M, M.T, atol=1e-12)
    assert np.all(np.linalg.eigvalsh(M) > 0)


def test_dynamics_are_consistent(model):
    data = mb.Data(model)
    q, v, a = random_state(model, 2)
    tau = np.array(mb.InverseDynamics(model, data, q, v, a))
    M = np.array(mb.MassMatrix(model, data, q))
    qdd = np.array(mb.ForwardDynamics(model, data, q, v, tau))
    np.testing.assert_allclose(qdd, a, atol=1e-8)
    gravity = np.array(mb.GravityTorques(model, data, q))
    np.testing.assert_allclose(gravity, mb.InverseDynamics(model, data, q, np.zeros(model.nv()), np.zeros(model.nv())),
                               atol=1e-9)
    assert mb.KineticEnergy(model, data, q, v) == pytest.approx(0.5 * v @ M @ v, rel=1e-10)
    h = np.array(data.nonlinear_effects)
    np.testing.assert_allclose(M @ a + h, tau, atol=1e-8)


def test_jacobians_match_finite_differences(model):
    data = mb.Data(model)
    q, v, _ = random_state(model, 3)
    frame = model.frame_names()[-1]
    eps = 1e-6
    mb.ForwardKinematics(model, data, q)
    J = mb.FrameJacobian(model, data, frame, mb.ReferenceFrame.kWorldAligned)
    p0 = mb.FramePose(model, data, frame).translation()
    q_plus = mb.Integrate(model, q, v, eps)
    mb.ForwardKinematics(model, data, q_plus)
    velocity_fd = (mb.FramePose(model, data, frame).translation() - p0) / eps
    np.testing.assert_allclose(J[3:] @ v, velocity_fd, atol=1e-4)
    com0 = np.array(mb.CenterOfMass(model, data, q))
    Jcom = np.array(mb.CenterOfMassJacobian(model, data, q))
    com1 = np.array(mb.CenterOfMass(model, data, q_plus))
    np.testing.assert_allclose(Jcom @ v, (com1 - com0) / eps, atol=1e-4)
    np.testing.assert_allclose(mb.Difference(model, q, q_plus), eps * v, atol=1e-12)


def test_algorithm_errors(model):
    data = mb.Data(model)
    with pytest.raises(ValueError, match="q"):
        mb.ForwardKinematics(model, data, np.zeros(3))
    other = mb.ParseUrdfFile(HUMANOID)  # welded root: another nq
    with pytest.raises(ValueError):
        mb.FramePose(other, data, 0)
    with pytest.raises(IndexError):
        mb.FramePose(model, data, 10_000)


def test_collision_world(model):
    world = mb.CollisionWorld(model)
    data = mb.Data(model)
    q = mb.NeutralConfiguration(model)
    mb.ForwardKinematics(model, data, q)
    world.UpdatePoses(model, data)
    sphere = world.AddSphere("ball", 0.05, np.array([0.0, 0.0, -5.0]))
    assert world.geometry_name(sphere) == "ball"
    assert world.geometry_body(sphere) == -1
    pair = world.ClosestPair()
    assert pair.geometry_a >= 0
    gradient = world.DistanceGradient(model, data, pair)
    assert gradient.shape == (model.nv(),)
    d = mb.SphereSphereDistance(np.zeros(3), 1.0, np.array([3.0, 0.0, 0.0]), 1.0)
    assert d.distance == pytest.approx(1.0)
    np.testing.assert_allclose(d.normal, [1.0, 0.0, 0.0])


def test_pose():
    rotation = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])  # C order: copied, right values
    pose = mb.Pose(rotation, np.array([1.0, 2.0, 3.0]))
    np.testing.assert_array_equal(pose.rotation(), rotation)
    np.testing.assert_allclose(pose * np.array([1.0, 0.0, 0.0]), [1.0, 3.0, 3.0])
    np.testing.assert_allclose((pose * pose.Inverse()).matrix(), np.eye(4), atol=1e-15)
    assert pickle.loads(pickle.dumps(pose)).IsApprox(pose, 0.0)
    with pytest.raises(ValueError, match="rigid"):
        mb.Pose.FromMatrix(np.diag([2.0, 1.0, 1.0, 1.0]))


@pytest.mark.skipif(not os.path.exists("/usr/share/doc/dart/data/sdf/atlas/atlas_v3_no_head.urdf"),
                    reason="dart-doc's Atlas model is not installed")
def test_atlas_mass():
    options = mb.UrdfOptions()
    options.check_mesh_files = False
    atlas = mb.ParseUrdfFile("/usr/share/doc/dart/data/sdf/atlas/atlas_v3_no_head.urdf", options)
    assert atlas.total_mass() == pytest.approx(146.554, abs=1e-3)
