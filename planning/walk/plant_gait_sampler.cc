#include <cairn/planning/walk/plant_gait_sampler.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/plant/joint_drive.h>
#include <cairn/planning/walk/walk_run.h>
#include <cairn/planning/walk/walk_step_comparison.h>

namespace cairn::planning {
namespace {

void Check(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("PlantGaitSampler: " + what);
}

}  // namespace

PlantGaitSampler::PlantGaitSampler(std::shared_ptr<const WalkingModel> walking_model,
                                   std::shared_ptr<const multibody::Model> robot,
                                   std::shared_ptr<const multibody::JointPdController> controller,
                                   WalkingObjective objective, PlantGaitOptions options)
    : walking_model_(std::move(walking_model)),
      robot_(std::move(robot)),
      controller_(std::move(controller)),
      objective_(objective),
      options_(std::move(options)) {
  Check(walking_model_ != nullptr, "the walking model is null");
  Check(robot_ != nullptr, "the robot model is null");
  Check(controller_ != nullptr, "the PD controller is null");
  Check(robot_->num_bodies() >= 2 && robot_->joint(1).type == multibody::JointType::kFloating,
        "the robot '" + robot_->name() + "' has no floating base; load its URDF with a floating base");
  const PlantGaitOptions& o = options_;
  Check(o.transient_steps >= 0 && o.transient_steps <= 10,
        "transient_steps " + FormatShort(o.transient_steps) + " must be in [0, 10]");
  Check(o.num_steps >= 2 * o.transient_steps + 1 && o.num_steps <= kMaxPeriodicGaitSteps,
        "num_steps " + FormatShort(o.num_steps) + " must be in [2 transient_steps + 1, " +
            FormatShort(kMaxPeriodicGaitSteps) + "] = [" + FormatShort(2 * o.transient_steps + 1) + ", " +
            FormatShort(kMaxPeriodicGaitSteps) + "] so that a step is measured");
  Check(std::isfinite(o.ground_friction) && o.ground_friction > 0.0 && o.ground_friction <= 10.0,
        "ground_friction " + FormatShort(o.ground_friction) + " must be in (0, 10]");
  Check(o.tracking_tolerance > 0.0 && o.tracking_tolerance <= 1.0,
        "tracking_tolerance " + FormatShort(o.tracking_tolerance) + " m must be in (0, 1]");
  Check(o.settle_time >= 0.0 && o.settle_time <= 60.0,
        "settle_time " + FormatShort(o.settle_time) + " s must be in [0, 60]");
  options_.plant.stop_on_fall = true;
  if (options_.plant.drives.empty()) {
    options_.plant.drives = multibody::LoadJointDrives(*robot_, walking_model_->yaml_path());
  }
}

WalkSetup PlantGaitSampler::Setup(const PeriodicGait& gait) const {
  PeriodicGait steps = gait;
  steps.num_steps = options_.num_steps;
  WalkSetup setup;
  setup.plan = std::make_shared<const FootstepPlan>(
      PeriodicGaitPlan(steps, *walking_model_, objective_, options_.ground_friction));
  setup.plant_terrain = PeriodicGaitTerrain(*setup.plan, walking_model_->foot_length(), walking_model_->foot_width(),
                                            options_.ground_friction);
  setup.objective = objective_;
  setup.trajectory = options_.trajectory;
  // The whole-body problem keeps links off a level ground plane; a staircase has no single one.
  if (gait.displacement.dz != 0.0) setup.trajectory.ground_height = std::nan("");
  setup.stabilizer = options_.stabilizer;
  setup.feedback = options_.feedback;
  setup.balance = options_.balance;
  setup.robot = robot_;
  setup.controller = controller_;
  setup.plant = options_.plant;
  return setup;
}

GaitMeasurement PlantGaitSampler::Measure(const PeriodicGait& gait) const {
  const double nan = std::nan("");
  GaitMeasurement m;
  m.gait = gait;
  m.gait.num_steps = options_.num_steps;
  m.com_work = m.electrical_energy = m.heat = m.rcof = m.sole_rcof = m.com_height = m.final_error = nan;
  // The plan first: a gait outside the model's reach or bounds is the caller's error and throws.
  const FootstepPlan plan = PeriodicGaitPlan(m.gait, *walking_model_, objective_, options_.ground_friction);
  m.predicted = plan.steps.front().transition;
  const int gait_steps = options_.num_steps;  // the plan's last step is the closing one
  WalkSetup setup;
  try {
    setup = Setup(m.gait);
  } catch (const std::invalid_argument& e) {
    // No staircase holds the footholds: the gait does not exist, which is a result.
    m.reason = std::string("no ground for this gait: ") + e.what();
    return m;
  }
  const WalkDiagram walk = BuildWalkDiagram(setup);
  WalkRunOptions run;
  run.settle_time = options_.settle_time;
  const WalkRecord record = RunWalk(walk, run);
  m.seconds = record.start.seconds;
  m.plant_seconds = record.plant_seconds;
  m.duration = record.duration;
  if (!record.start.ready) {
    m.reason = record.start.reason;
    return m;
  }
  m.simulated = true;
  m.slips = static_cast<int>(record.slips.size());

  const std::vector<WalkStepComparison> steps = CompareWalkSteps(record);
  const int first = options_.transient_steps, last = gait_steps - options_.transient_steps;
  double com_work = 0.0, electrical = 0.0, heat = 0.0, rcof = 0.0, sole_rcof = 0.0, height = 0.0;
  int height_samples = 0;
  for (int k = first; k < last; ++k) {
    const WalkStepComparison& step = steps[static_cast<std::size_t>(k)];
    if (!step.completed) break;
    ++m.measured_steps;
    com_work += step.measured_com_energy;
    electrical += step.measured_electrical_energy;
    heat += step.measured_heat;
    rcof = std::max(rcof, step.measured_net_rcof);
    sole_rcof = std::max(sole_rcof, step.measured_rcof_after_touchdown);
    const Stance stance = plan.StanceAfter(k - 1);
    const double ground = 0.5 * (stance.left.z + stance.right.z);
    for (const WalkSample& s : record.samples) {
      if (s.time < step.start || s.time > step.end) continue;
      height += s.com.z() - ground;
      ++height_samples;
    }
  }
  const bool all_measured = m.measured_steps == last - first;
  if (all_measured) {
    m.com_work = com_work / m.measured_steps;
    m.electrical_energy = electrical / m.measured_steps;
    m.heat = heat / m.measured_steps;
    m.rcof = rcof;
    m.sole_rcof = sole_rcof;
    m.com_height = height_samples > 0 ? height / height_samples : nan;
  }
  m.final_error = SoleDistance(*robot_, options_.plant.sole_bodies, record, plan.StanceAfter(gait_steps));
  if (record.fell) {
    m.reason = "fell at " + FormatShort(record.duration) + " s (" + record.fall_reason + ")";
  } else if (!steps.back().completed) {
    m.reason = "the walk ended at " + FormatShort(record.duration) + " s, before its last step";
  } else if (!(m.final_error <= options_.tracking_tolerance)) {
    m.reason = "the soles ended " + FormatShort(m.final_error) + " m from the plan's last stance (tolerance " +
               FormatShort(options_.tracking_tolerance) + " m)";
  } else {
    m.feasible = true;
  }
  return m;
}

}  // namespace cairn::planning
