// BalanceFeedback: the capture-point error tilts the loaded legs so that the COM moves against it, in the base's
// heading frame, clamped; swing legs and a robot in the air are left alone; and in the plant it turns a slow plan
// that falls open loop into a walk.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cairn/multibody/configuration.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/urdf_parser.h>
#include <cairn/multibody/plant/sole_state.h>
#include <cairn/planning/stabilization/stabilize_trajectory.h>
#include <cairn/planning/trajectory/optimize_whole_body_trajectory.h>
#include <cairn/planning/walk/balance_feedback.h>
#include <cairn/systems/framework/diagram_builder.h>

#include "../support/plant_walk.h"
#include "../trajectory/test_robot.h"
#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

using multibody::Model;

// The humanoid standing: a valid [q; v] with the base 0.8 m up and every joint at zero.
Eigen::VectorXd Standing(const Model& model) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(model.nq() + model.nv());
  x.head(model.nq()) = multibody::NeutralConfiguration(model);
  x[2] = 0.8;
  return x;
}

// The sole's rotation about the world y axis (its pitch) at configuration x; the base is what it is in x.
double SolePitch(const Model& model, const Eigen::VectorXd& x, const std::string& sole) {
  multibody::Data data(model);
  multibody::ForwardKinematics(model, data, x.head(model.nq()));
  const Eigen::Matrix3d R = data.X_world[model.GetBodyIndex(sole)].rotation();
  return std::atan2(-R(2, 0), R(0, 0));
}

double SoleRoll(const Model& model, const Eigen::VectorXd& x, const std::string& sole) {
  multibody::Data data(model);
  multibody::ForwardKinematics(model, data, x.head(model.nq()));
  const Eigen::Matrix3d R = data.X_world[model.GetBodyIndex(sole)].rotation();
  return std::atan2(R(2, 1), R(2, 2));
}

TEST(BalanceFeedbackTest, NoErrorLeavesTheReferenceAsItIs) {
  const auto model = test::Humanoid();
  const BalanceFeedback feedback(model);
  const Eigen::VectorXd x = Standing(*model);
  EXPECT_TRUE(feedback.Correct(x, x, true, true).isApprox(x, 0.0));
}

// The measured COM 5 cm ahead of the planned one (the whole robot shifted forward): each loaded leg tilts back by
// pitch_gain * 5 cm. With the base held, that shows as the sole pitching toes-down by that angle, so once the sole
// is flat on the ground again the body leans back. (The soles moved with the robot; the foothold term, tested
// below, is off here.)
TEST(BalanceFeedbackTest, ACapturePointAheadTiltsTheLoadedLegsBack) {
  const auto model = test::Humanoid();
  BalanceFeedbackOptions options;
  options.foothold_gain = 0.0;
  const BalanceFeedback feedback(model, options);
  const Eigen::VectorXd planned = Standing(*model);
  Eigen::VectorXd measured = planned;
  measured[0] += 0.05;
  const Eigen::VectorXd corrected = feedback.Correct(planned, measured, true, true);
  const double expected = feedback.options().pitch_gain * 0.05;
  for (const char* sole : {"l_sole", "r_sole"}) {
    EXPECT_NEAR(SolePitch(*model, corrected, sole) - SolePitch(*model, planned, sole), expected, 1e-9) << sole;
    EXPECT_NEAR(SoleRoll(*model, corrected, sole) - SoleRoll(*model, planned, sole), 0.0, 1e-9) << sole;
  }
  // Only the ankles move.
  Eigen::VectorXd rest = corrected - planned;
  for (const char* joint : {"l_ankle_pitch", "r_ankle_pitch"}) rest[model->joint(model->GetJointIndex(joint)).idx_q] = 0;
  EXPECT_EQ(rest.norm(), 0.0);
}

// A capture point to the left (here from a velocity: xi = c + c_dot / omega) rolls the legs to the right: the sole
// rolls by -roll_gain * e_left about x with the base held, so the body leans right once the sole is flat. Both legs
// are checked, since the right ankle's roll axis points the other way (-x).
TEST(BalanceFeedbackTest, ACapturePointToTheLeftRollsTheLoadedLegsRightByTheVelocityTerm) {
  const auto model = test::Humanoid();
  BalanceFeedbackOptions options;
  options.max_roll = 0.5;
  const BalanceFeedback feedback(model, options);
  const Eigen::VectorXd planned = Standing(*model);
  Eigen::VectorXd measured = planned;
  // The base's linear velocity is in its own frame; the base is level, so 0.1 m/s to the left.
  measured[model->nq() + 4] = 0.1;
  const double omega = std::sqrt(9.81 / options.com_height);
  const double e_left = 0.1 / omega;
  const Eigen::VectorXd both = feedback.Correct(planned, measured, true, true);
  for (const char* sole : {"l_sole", "r_sole"}) {
    EXPECT_NEAR(SoleRoll(*model, both, sole) - SoleRoll(*model, planned, sole), -options.roll_gain * e_left,
                1e-3 * options.roll_gain * e_left) << sole;
  }
  const Eigen::VectorXd corrected = feedback.Correct(planned, measured, true, false);
  EXPECT_NEAR(SoleRoll(*model, corrected, "l_sole") - SoleRoll(*model, planned, "l_sole"), -options.roll_gain * e_left,
              1e-3 * options.roll_gain * e_left);
  // The right leg swings: untouched.
  EXPECT_NEAR(SoleRoll(*model, corrected, "r_sole"), SoleRoll(*model, planned, "r_sole"), 1e-12);
  EXPECT_NEAR(SolePitch(*model, corrected, "r_sole"), SolePitch(*model, planned, "r_sole"), 1e-12);
}

// The error is read in the base's heading frame: a robot facing +y whose COM is ahead along +y tilts back as above.
TEST(BalanceFeedbackTest, TheErrorIsReadInTheBasesHeadingFrame) {
  const auto model = test::Humanoid();
  const BalanceFeedback feedback(model);
  Eigen::VectorXd planned = Standing(*model);
  const Eigen::Quaterniond yaw(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  planned.segment<4>(3) << yaw.w(), yaw.x(), yaw.y(), yaw.z();
  Eigen::VectorXd measured = planned;
  measured[1] += 0.05;
  const Eigen::VectorXd corrected = feedback.Correct(planned, measured, true, true);
  const Eigen::VectorXd straight_planned = Standing(*model);
  Eigen::VectorXd straight_measured = straight_planned;
  straight_measured[0] += 0.05;
  const Eigen::VectorXd straight = feedback.Correct(straight_planned, straight_measured, true, true);
  // The same joint offsets as for the robot facing +x with its COM ahead along +x.
  EXPECT_TRUE((corrected - planned).isApprox(straight - straight_planned, 1e-9));
  EXPECT_GT((corrected - planned).norm(), 0.0);
}

// The swing leg's reference poses its sole relative to the planned base; with the measured base pitched 3 degrees
// and 2 cm off, the corrected leg angles put on the measured base give the sole the reference's pose in the world
// (level, where planned), to first order. The standing leg is left alone.
TEST(BalanceFeedbackTest, ASwingSoleIsPosedAgainstTheBasesError) {
  const auto model = test::Humanoid();
  BalanceFeedbackOptions options;
  options.pitch_gain = 0.0;
  options.roll_gain = 0.0;
  options.foothold_gain = 0.0;
  options.swing_orientation_gain = 1.0;
  options.swing_position_gain = 1.0;
  const BalanceFeedback feedback(model, options);
  Eigen::VectorXd planned = Standing(*model);
  planned[2] = 0.75;  // knees bent enough for the leg to move its sole every way
  planned[model->joint(model->GetJointIndex("r_knee")).idx_q] = 0.6;
  planned[model->joint(model->GetJointIndex("r_hip_pitch")).idx_q] = -0.3;
  planned[model->joint(model->GetJointIndex("r_ankle_pitch")).idx_q] = -0.3;
  Eigen::VectorXd measured = planned;
  const Eigen::Quaterniond pitched(Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitY()));
  measured.segment<4>(3) << pitched.w(), pitched.x(), pitched.y(), pitched.z();
  measured[0] += 0.02;
  const Eigen::VectorXd corrected = feedback.Correct(planned, measured, true, false);
  Eigen::VectorXd on_measured_base = corrected;
  on_measured_base.head(7) = measured.head(7);
  multibody::Data want(*model), got(*model), uncorrected(*model);
  multibody::ForwardKinematics(*model, want, planned.head(model->nq()));
  multibody::ForwardKinematics(*model, got, on_measured_base.head(model->nq()));
  multibody::ForwardKinematics(*model, uncorrected, measured.head(model->nq()));
  const int sole = model->GetBodyIndex("r_sole");
  const auto angle = [](const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
    return Eigen::AngleAxisd(a.transpose() * b).angle();
  };
  EXPECT_NEAR(angle(uncorrected.X_world[sole].rotation(), want.X_world[sole].rotation()), 0.05, 1e-9);
  EXPECT_LT(angle(got.X_world[sole].rotation(), want.X_world[sole].rotation()), 3e-3);
  EXPECT_GT((uncorrected.X_world[sole].translation() - want.X_world[sole].translation()).norm(), 0.02);
  EXPECT_LT((got.X_world[sole].translation() - want.X_world[sole].translation()).norm(), 3e-3);
  // The standing (left) leg and the base keep the plan.
  for (const char* joint : {"l_hip_yaw", "l_hip_roll", "l_hip_pitch", "l_knee", "l_ankle_pitch", "l_ankle_roll"}) {
    const int q = model->joint(model->GetJointIndex(joint)).idx_q;
    EXPECT_EQ(corrected[q], planned[q]) << joint;
  }
  EXPECT_EQ((corrected - planned).head(7).norm(), 0.0);
  // Nothing to correct against with both feet down or none.
  EXPECT_EQ(feedback.Correct(planned, measured, true, true), planned);
  EXPECT_EQ(feedback.Correct(planned, measured, false, false), planned);

  options.swing_orientation_gain = -0.1;
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument,
                           "swing_orientation_gain -0.1 must be in [0, 1]");
}

// A loaded foot that stands 4 cm ahead and 2 cm left of where the reference puts it (here: the whole robot shifted,
// the base held at the plan in the reference): its leg's reference moves the sole by foothold_gain times that
// offset relative to the planned base, keeping the sole's orientation and height, so the legs agree with where
// the feet are. A swing leg keeps its reference.
TEST(BalanceFeedbackTest, ALoadedFootsPlacementErrorIsWrittenIntoItsLeg) {
  const auto model = test::Humanoid();
  BalanceFeedbackOptions options;
  options.pitch_gain = 0.0;
  options.roll_gain = 0.0;
  options.foothold_gain = 0.5;
  const BalanceFeedback feedback(model, options);
  const Eigen::VectorXd planned = Standing(*model);
  Eigen::VectorXd measured = planned;
  measured[0] += 0.04;
  measured[1] += 0.02;
  const Eigen::VectorXd corrected = feedback.Correct(planned, measured, true, false);
  multibody::Data before(*model), after(*model);
  multibody::ForwardKinematics(*model, before, planned.head(model->nq()));
  multibody::ForwardKinematics(*model, after, corrected.head(model->nq()));
  const auto sole = [&](const multibody::Data& data, const char* name) {
    return data.X_world[model->GetBodyIndex(name)];
  };
  const Eigen::Vector3d moved = sole(after, "l_sole").translation() - sole(before, "l_sole").translation();
  // One linear step of the leg's inverse kinematics: exact to first order in the 4.5 cm offset.
  EXPECT_NEAR(moved.x(), 0.02, 5e-4);
  EXPECT_NEAR(moved.y(), 0.01, 5e-4);
  EXPECT_NEAR(moved.z(), 0.0, 5e-4);
  EXPECT_TRUE(sole(after, "l_sole").rotation().isApprox(sole(before, "l_sole").rotation(), 1e-3));
  EXPECT_TRUE(sole(after, "r_sole").translation().isApprox(sole(before, "r_sole").translation(), 1e-12));
  // Only the left leg's joints changed; the base and the rest of the robot keep the plan.
  EXPECT_EQ((corrected - planned).head(7).norm(), 0.0);
  EXPECT_EQ(feedback.Correct(planned, planned, true, true), planned);

  options.foothold_gain = 1.5;
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument, "foothold_gain 1.5 must be in [0, 1]");
  options.foothold_gain = 0.5;
  options.left_sole = "l_foot_plate";
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument, "no frame 'l_foot_plate'",
                           "name the sole frames", "or set foothold_gain and the swing gains 0");
  options.left_sole = "head";  // a frame, but not at the end of a leg
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument,
                           "'head' is not on a leg of six one-axis joints");
  options.foothold_gain = 0.0;  // the sole frames are needed only with the foothold term
  options.left_sole = "l_foot_plate";
  EXPECT_NO_THROW(BalanceFeedback(model, options));
}

TEST(BalanceFeedbackTest, ALargeErrorIsClampedAndARobotInTheAirIsLeftAlone) {
  const auto model = test::Humanoid();
  BalanceFeedbackOptions options;
  options.foothold_gain = 0.0;
  const BalanceFeedback feedback(model, options);
  const Eigen::VectorXd planned = Standing(*model);
  Eigen::VectorXd measured = planned;
  measured[0] += 3.0;
  measured[1] -= 3.0;
  const Eigen::VectorXd corrected = feedback.Correct(planned, measured, true, true);
  EXPECT_NEAR(SolePitch(*model, corrected, "l_sole") - SolePitch(*model, planned, "l_sole"),
              feedback.options().max_pitch, 1e-9);
  // The capture point is far to the right: the legs roll left (the soles by +max_roll with the base held).
  for (const char* sole : {"l_sole", "r_sole"}) {
    EXPECT_NEAR(SoleRoll(*model, corrected, sole) - SoleRoll(*model, planned, sole), feedback.options().max_roll, 1e-9)
        << sole;
  }
  EXPECT_TRUE(feedback.Correct(planned, measured, false, false).isApprox(planned, 0.0));
}

TEST(BalanceFeedbackTest, TheSystemsOutputIsTheCorrectionOfItsInputs) {
  const auto model = test::Humanoid();
  systems::DiagramBuilder builder;
  auto* feedback = builder.AddSystem<BalanceFeedback>(model);
  builder.ExportInput(feedback->get_reference_input_port(), "reference");
  builder.ExportInput(feedback->get_state_input_port(), "state");
  builder.ExportInput(feedback->get_contacts_input_port(), "contacts");
  builder.ExportOutput(feedback->get_reference_output_port(), "reference");
  const auto diagram = builder.Build();
  auto context = diagram->CreateDefaultContext();
  const Eigen::VectorXd planned = Standing(*model);
  Eigen::VectorXd measured = planned;
  measured[0] -= 0.04;
  std::vector<multibody::SoleState> soles(2);
  soles[0].loaded = true;
  diagram->GetInputPort("reference").FixValue(context.get(), planned);
  diagram->GetInputPort("state").FixValue(context.get(), measured);
  diagram->GetInputPort("contacts").FixValue(context.get(), soles);
  const Eigen::VectorXd& y = diagram->GetOutputPort("reference").Eval<Eigen::VectorXd>(*context);
  EXPECT_TRUE(y.isApprox(feedback->Correct(planned, measured, true, false), 0.0));
  EXPECT_FALSE(y.isApprox(planned, 1e-9));

  soles.resize(1);
  diagram->GetInputPort("contacts").FixValue(context.get(), soles);
  CAIRN_EXPECT_THROWS_WITH(diagram->GetOutputPort("reference").Eval<Eigen::VectorXd>(*context), std::invalid_argument,
                           "the contacts input has 1 soles");
}

TEST(BalanceFeedbackTest, RefusesBadModelsOptionsAndSizes) {
  const auto model = test::Humanoid();
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(nullptr), std::invalid_argument, "the robot model is null");
  multibody::UrdfOptions fixed;
  const auto welded = std::make_shared<const Model>(
      multibody::ParseUrdfFile(std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf", fixed));
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback{welded}, std::invalid_argument, "has no floating base");
  const auto weightless = std::make_shared<const Model>(model->WithGravity(Eigen::Vector3d::Zero()));
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback{weightless}, std::invalid_argument, "has gravity z 0 m/s^2",
                           "gravity pointing down");
  BalanceFeedbackOptions options;
  options.pitch_gain = -1.0;
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument, "pitch_gain -1 must be in [0, 1000]");
  options = {};
  options.max_roll = std::nan("");
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument, "max_roll nan must be in [0, 0.5]");
  options = {};
  options.com_height = 0.1;
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument, "com_height 0.1 must be in (0.1, 3]");
  options = {};
  options.left_ankle_roll = "l_ankel_roll";
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument, "has no joint 'l_ankel_roll'");
  options = {};
  options.left_ankle_roll = "l_ankle_pitch";
  CAIRN_EXPECT_THROWS_WITH(BalanceFeedback(model, options), std::invalid_argument,
                           "joint 'l_ankle_pitch' must be revolute about its x axis");
  const BalanceFeedback feedback(model);
  CAIRN_EXPECT_THROWS_WITH(feedback.Correct(Eigen::VectorXd::Zero(3), Standing(*model), true, true),
                           std::invalid_argument, "got 3 and");
}

// Four straight 0.2 m steps at the slow timing the footstep planner chooses for energy (0.35 s double support,
// 0.9 s swing): open loop the drift grows through each long single support and the robot falls; with the
// capture-point feedback it walks to the footholds. (Measured 2026-12-04 over the tilt gains, before the foothold
// term existed: every pitch gain in [0.6, 1] with a roll gain in [0.5, 2] walks it, 0.3 or less falls; the soles
// ended 3-4 cm ahead and 2-6 cm to the right of their footholds.)
TEST(BalanceFeedbackTest, TheFeedbackWalksASlowPlanThatFallsOpenLoop) {
  const auto model = test::Humanoid();
  FootstepPlan plan = test::StraightPlan(4, 0.2);
  for (PlannedStep& step : plan.steps) {
    step.transition.parameters = {0.35, 0.9, 0.8};
    step.transition.duration = 1.25;
  }
  plan.UpdateTotals();
  const WholeBodyTrajectory trajectory =
      OptimizeWholeBodyTrajectory(model, plan, {}, TrajectoryOptimizerOptions());
  ASSERT_TRUE(trajectory.found) << trajectory.report.message;
  const StabilizedTrajectory reference = StabilizeTrajectory(model, trajectory, WalkingStabilizerOptions("fft"));
  ASSERT_TRUE(reference.report.success) << reference.report.message;

  EXPECT_TRUE(test::WalkInPlant(reference).fell) << "the slow plan was walked open loop";
  const BalanceFeedback feedback(model);
  const test::PlantWalk closed_loop = test::WalkInPlant(
      reference, [&](const Eigen::VectorXd& x_ref, const Eigen::VectorXd& x, bool left_loaded, bool right_loaded) {
        return feedback.Correct(x_ref, x, left_loaded, right_loaded);
      });
  EXPECT_FALSE(closed_loop.fell) << "fell at " << closed_loop.fall_time << " s";
  EXPECT_LT((closed_loop.left_sole.head<2>() - Eigen::Vector2d(0.6, 0.1)).norm(), 0.1)
      << closed_loop.left_sole.transpose();
  EXPECT_LT((closed_loop.right_sole.head<2>() - Eigen::Vector2d(0.6, -0.1)).norm(), 0.1)
      << closed_loop.right_sole.transpose();
}

}  // namespace
}  // namespace cairn::planning
