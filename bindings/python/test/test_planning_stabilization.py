"""cairn.planning, stabilisation: preview control, the Riccati solver, the full model's ZMP and StabilizeTrajectory."""

import math

import numpy as np
import pytest

import cairn.multibody as mb
import cairn.planning as planning
from conftest import source_path

HUMANOID = source_path("data", "robots", "cairn_humanoid.urdf")


@pytest.fixture(scope="module")
def model():
    options = mb.UrdfOptions()
    options.floating_base = True
    return mb.ParseUrdfFile(HUMANOID, options)


def one_step_plan():
    plan = planning.FootstepPlan()
    plan.found = True
    plan.start = planning.Stance(planning.FootPose(x=0.0, y=0.1), planning.FootPose(x=0.0, y=-0.1))
    step = planning.PlannedStep()
    step.side = planning.FootSide.kRight
    step.pose = planning.FootPose(x=0.15, y=-0.1)
    transition = step.transition
    transition.feasible = True
    parameters = transition.parameters
    parameters.t_ds, parameters.t_sw = 0.2, 0.6
    transition.parameters = parameters
    step.transition = transition
    plan.steps = [step]
    return plan


def test_riccati_matches_the_scalar_closed_form():
    p = planning.SolveDiscreteAlgebraicRiccati(np.array([[2.0]]), np.array([[1.0]]), np.array([[1.0]]),
                                               np.array([[1.0]]))
    assert abs(p[0, 0] - (2.0 + math.sqrt(5.0))) < 1e-10


def test_preview_control_tracks_a_step_of_the_zmp():
    controller = planning.CartTablePreviewController(0.005, 0.8)
    reference = np.zeros(1200)
    reference[400:] = 0.1
    motion = controller.Track(reference)
    assert abs(motion.zmp[-1] - 0.1) < 1e-3
    assert motion.position[399] > 0.02  # the preview moves the COM before the step
    with pytest.raises(ValueError, match="dt 0 s must be in"):
        planning.CartTablePreviewController(0.0, 0.8)


def test_standing_still_puts_the_zmp_under_the_com(model):
    q = mb.NeutralConfiguration(model)
    q[2] = 0.9
    zmp = planning.ComputeMotionZmp(model, [q, q, q], 0.01)
    data = mb.Data(model)
    com = mb.CenterOfMass(model, data, q)
    assert np.allclose(zmp[1], com[:2], atol=1e-9)
    with pytest.raises(ValueError, match="at least 3 are needed"):
        planning.ComputeMotionZmp(model, [q, q], 0.01)


def test_stabilize_trajectory_reports_errors_before_and_after(model):
    trajectory = planning.OptimizeWholeBodyTrajectory(model, one_step_plan())
    assert trajectory.found, trajectory.report.message
    options = planning.StabilizerOptions()
    options.method = "none"
    reference = planning.StabilizeTrajectory(model, trajectory, options)
    assert reference.report.success, reference.report.message
    # One step of 0.8 s at 200 Hz.
    assert len(reference.q) == 161 and abs(reference.duration() - 0.8) < 1e-9
    assert reference.report.rms_error_after == reference.report.rms_error_before
    options.method = "fft"
    stabilised = planning.StabilizeTrajectory(model, trajectory, options)
    assert stabilised.report.success, stabilised.report.message
    assert stabilised.report.rms_error_after <= stabilised.report.rms_error_before
    options.method = "lqr"
    with pytest.raises(ValueError, match="method 'lqr' is unknown"):
        planning.StabilizeTrajectory(model, trajectory, options)


def test_the_system_stabilises_in_an_event(model):
    options = planning.StabilizerOptions()
    options.method = "none"
    system = planning.Stabilizer(model, options)
    context = system.CreateDefaultContext()
    system.get_trajectory_input_port().FixValue(context, planning.OptimizeWholeBodyTrajectory(model, one_step_plan()))
    assert not system.get_reference_output_port().Eval(context).report.success
    system.ExecuteForcedEvents(context)
    assert system.get_reference_output_port().Eval(context).report.success


def test_walking_options_are_validated(model):
    options = planning.StabilizerOptions()
    options.contact_timing = True
    options.cart_table_start = True
    options.crouch = 0.06
    assert options.cart_table_start and abs(options.crouch - 0.06) < 1e-12
    options.crouch = 0.5
    with pytest.raises(ValueError, match="crouch 0.5 m must be in"):
        planning.Stabilizer(model, options)


def test_the_walking_options_are_the_defaults_with_contact_timing_and_a_crouch(model):
    options = planning.WalkingStabilizerOptions("preview")
    assert options.method == "preview" and options.contact_timing and options.cart_table_start
    assert options.waist_orientation == "upright" and abs(options.crouch - 0.06) < 1e-12
    assert not planning.StabilizerOptions().contact_timing
    # and a landing phase of 1 cm over 0.15 s, which the thesis' defaults do not have
    assert options.landing_height == pytest.approx(0.01) and options.landing_time == pytest.approx(0.15)
    assert planning.StabilizerOptions().landing_height == 0.0
    options.landing_time = 0.0
    with pytest.raises(ValueError, match="must be both 0"):
        planning.Stabilizer(model, options)
