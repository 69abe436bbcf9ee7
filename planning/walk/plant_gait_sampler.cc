#include <cairn/planning/walk/plant_gait_sampler.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/plant/joint_drive.h>
#include <cairn/systems/analysis/simulator.h>
#include <cairn/planning/walk/walk_run.h>
#include <cairn/planning/walk/walk_step_comparison.h>

namespace cairn::planning {
namespace {

void Check(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("PlantGaitSampler: " + what);
}

// Mean over steps [first, last) of the torque terms of each step's waypoints (step k leaves stance k: its start and
// its mid-swing); NaN when the trajectory does not reach that far.
double MeanStepTorqueCost(const WholeBodyTrajectory& trajectory, int first, int last) {
  double sum = 0.0;
  int last_stance = -1;
  for (const WholeBodyWaypoint& w : trajectory.waypoints) {
    last_stance = std::max(last_stance, w.stance);
    if (w.stance >= first && w.stance < last) sum += w.torque_cost;
  }
  return trajectory.found && last_stance >= last ? sum / (last - first) : std::nan("");
}

// What both measurements start from: the gait with the options' number of steps, every measured quantity NaN, the
// analytic model's prediction, the gait's plan and its walk setup. A gait no staircase holds does not exist, which
// is a result: its `reason` says so and the setup is left empty.
struct Prepared {
  GaitMeasurement measurement;
  FootstepPlan plan;
  WalkSetup setup;
};

Prepared Prepare(const PlantGaitSampler& sampler, const PeriodicGait& gait) {
  const double nan = std::nan("");
  Prepared out;
  GaitMeasurement& m = out.measurement;
  m.gait = gait;
  m.gait.num_steps = sampler.options().num_steps;
  m.com_work = m.electrical_energy = m.heat = m.rcof = m.sole_rcof = m.com_height = m.final_error = nan;
  m.torque_cost = m.support_margin = nan;
  // The plan first: a gait outside the model's reach or bounds is the caller's error and throws.
  out.plan = PeriodicGaitPlan(m.gait, sampler.walking_model(), sampler.objective(), sampler.options().ground_friction);
  m.predicted = out.plan.steps.front().transition;
  try {
    out.setup = sampler.Setup(m.gait);
  } catch (const std::invalid_argument& e) {
    m.reason = std::string("no ground for this gait: ") + e.what();
  }
  return out;
}

// Start time of each of the plan's steps and the end of the last, s.
std::vector<double> StepTimes(const FootstepPlan& plan) {
  std::vector<double> t{0.0};
  for (const PlannedStep& step : plan.steps) t.push_back(t.back() + step.transition.duration);
  return t;
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
  Check(o.min_support_margin >= -0.1 && o.min_support_margin <= 0.1,
        "min_support_margin " + FormatShort(o.min_support_margin) + " m must be in [-0.1, 0.1]");
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
  Prepared prepared = Prepare(*this, gait);
  GaitMeasurement& m = prepared.measurement;
  if (!m.reason.empty()) return prepared.measurement;
  const FootstepPlan& plan = prepared.plan;
  const int gait_steps = options_.num_steps;  // the plan's last step is the closing one
  const WalkDiagram walk = BuildWalkDiagram(prepared.setup);
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
  const int first = options_.transient_steps, last = gait_steps - options_.transient_steps;
  m.torque_cost = MeanStepTorqueCost(record.trajectory, first, last);
  m.support_margin = record.reference.report.min_support_margin_after;
  m.slips = static_cast<int>(record.slips.size());

  const std::vector<WalkStepComparison> steps = CompareWalkSteps(record);
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

GaitMeasurement PlantGaitSampler::MeasurePlanned(const PeriodicGait& gait) const {
  Prepared prepared = Prepare(*this, gait);
  GaitMeasurement& m = prepared.measurement;
  if (!m.reason.empty()) return prepared.measurement;
  const FootstepPlan& plan = prepared.plan;
  // The walk diagram settled as for a walk, but never stepped: the chain's outputs are the measurement.
  const WalkDiagram walk = BuildWalkDiagram(prepared.setup);
  systems::Simulator simulator(*walk.diagram);
  const WalkStart start = InitializeWalk(walk, &simulator);
  m.seconds = start.seconds;
  if (!start.ready) {
    m.reason = start.reason;
    return m;
  }
  const systems::Context& root = simulator.get_context();
  const WholeBodyTrajectory& trajectory = walk.trajectory->get_trajectory_output_port().Eval<WholeBodyTrajectory>(
      walk.diagram->GetSubsystemContext(*walk.trajectory, root));
  const StabilizedTrajectory& reference = walk.stabilizer->get_reference_output_port().Eval<StabilizedTrajectory>(
      walk.diagram->GetSubsystemContext(*walk.stabilizer, root));
  const int first = options_.transient_steps, last = options_.num_steps - options_.transient_steps;
  m.torque_cost = MeanStepTorqueCost(trajectory, first, last);
  m.support_margin = reference.report.min_support_margin_after;
  m.duration = reference.duration();

  // The reference's COM and its net external force m (a - g), by central differences at the reference's period.
  multibody::Data data(*robot_);
  std::vector<Eigen::Vector3d> com;
  com.reserve(reference.q.size());
  for (const Eigen::VectorXd& q : reference.q) com.push_back(multibody::CenterOfMass(*robot_, data, q));
  const double h = reference.period, mass = robot_->total_mass();
  const std::vector<double> t = StepTimes(plan);
  double com_work = 0.0, rcof = 0.0, height = 0.0;
  int height_samples = 0;
  for (int k = first; k < last; ++k) {
    const Stance stance = plan.StanceAfter(k - 1);
    const double ground = 0.5 * (stance.left.z + stance.right.z);
    const auto begin = static_cast<std::size_t>(std::max(1.0, std::ceil(t[static_cast<std::size_t>(k)] / h)));
    const auto end = static_cast<std::size_t>(std::floor(t[static_cast<std::size_t>(k) + 1] / h));
    for (std::size_t i = begin; i <= end && i + 1 < com.size(); ++i) {
      const Eigen::Vector3d v = (com[i + 1] - com[i - 1]) / (2.0 * h);
      const Eigen::Vector3d a = (com[i + 1] - 2.0 * com[i] + com[i - 1]) / (h * h);
      const Eigen::Vector3d force = mass * (a - robot_->gravity());
      com_work += std::abs(v.dot(force)) * h;
      if (force.z() > 0.0) rcof = std::max(rcof, force.head<2>().norm() / force.z());
      height += com[i].z() - ground;
      ++height_samples;
    }
  }
  const double measured_end = t[static_cast<std::size_t>(last)];
  if (m.duration + 1e-9 >= measured_end && height_samples > 0) {
    m.measured_steps = last - first;
    m.com_work = com_work / m.measured_steps;
    m.rcof = rcof;
    m.com_height = height / height_samples;
  }
  if (!trajectory.found) {
    m.reason = "the whole-body trajectory was not found: " + trajectory.report.message;
  } else if (!(m.support_margin >= options_.min_support_margin)) {
    m.reason = "the stabilised ZMP's least margin inside its support polygon is " + FormatShort(m.support_margin) +
               " m, below the " + FormatShort(options_.min_support_margin) + " m allowed (min_support_margin)";
  } else if (m.measured_steps == 0) {
    m.reason = "the reference ends at " + FormatShort(m.duration) + " s, before the measured steps";
  } else {
    m.feasible = true;
  }
  return m;
}

}  // namespace cairn::planning
