#include <cairn/planning/walk/walk_step_comparison.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>

#include <stdexcept>

#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/multibody/plant/stance_phase.h>

namespace cairn::planning {
namespace {

// The sample recorded nearest to time t (samples are in time order).
const WalkSample& SampleAt(const std::vector<WalkSample>& samples, double t) {
  const auto after = std::lower_bound(samples.begin(), samples.end(), t,
                                      [](const WalkSample& s, double time) { return s.time < time; });
  if (after == samples.begin()) return *after;
  if (after == samples.end()) return samples.back();
  return (after->time - t) < (t - std::prev(after)->time) ? *after : *std::prev(after);
}

}  // namespace

std::vector<WalkStepComparison> CompareWalkSteps(const WalkRecord& record) {
  std::vector<WalkStepComparison> steps;
  steps.reserve(record.plan.steps.size());
  double t = 0.0;
  const double nan = std::nan("");
  for (std::size_t k = 0; k < record.plan.steps.size(); ++k) {
    const PlannedStep& step = record.plan.steps[k];
    WalkStepComparison c;
    c.index = static_cast<int>(k) + 1;
    c.foot = FootSideName(step.side);
    c.start = t;
    c.end = t + step.transition.duration;
    t = c.end;
    c.predicted_rcof = step.transition.rcof;
    c.mu_allowed = step.mu_allowed;
    c.predicted_com_work = step.transition.com_work;
    c.predicted_heat = step.transition.heat;
    c.completed = !record.samples.empty() && c.end <= record.duration + 1e-9;
    c.measured_rcof = c.measured_rcof_after_touchdown = c.measured_net_rcof = nan;
    c.measured_com_energy = c.measured_electrical_energy = c.measured_heat = nan;
    if (!c.completed) {
      steps.push_back(c);
      continue;
    }
    // The support sole's stance is the one that holds the middle of the swing.
    const double swing_middle = c.start + step.transition.parameters.t_ds + 0.5 * step.transition.parameters.t_sw;
    const int support = step.side == FootSide::kLeft ? 1 : 0;
    for (const multibody::StancePhase& stance : record.stances) {
      if (stance.foot == support && stance.start <= swing_middle && swing_middle <= stance.end) {
        c.measured_rcof = stance.rcof;
        c.measured_rcof_after_touchdown = stance.rcof_after_touchdown;
        c.measured_net_rcof = stance.net_rcof;
      }
    }
    const WalkSample& a = SampleAt(record.samples, c.start);
    const WalkSample& b = SampleAt(record.samples, c.end);
    c.measured_com_energy = b.com_energy - a.com_energy;
    c.measured_electrical_energy = b.electrical_energy - a.electrical_energy;
    c.measured_heat = b.heat - a.heat;
    steps.push_back(c);
  }
  return steps;
}

double SoleDistance(const multibody::Model& robot, const std::vector<std::string>& soles, const WalkRecord& record,
                    const Stance& stance) {
  if (record.samples.empty()) throw std::invalid_argument("SoleDistance: the walk recorded no sample");
  if (soles.size() < 2) {
    throw std::invalid_argument("SoleDistance: give the left and the right sole body (got " +
                                std::to_string(soles.size()) + " names)");
  }
  multibody::Data data(robot);
  multibody::ForwardKinematics(robot, data, record.samples.back().q);
  const auto sole = [&](const std::string& name) {
    return data.X_world[static_cast<std::size_t>(robot.GetBodyIndex(name))].translation().head<2>().eval();
  };
  const double left = (sole(soles[0]) - Eigen::Vector2d(stance.left.x, stance.left.y)).norm();
  const double right = (sole(soles[1]) - Eigen::Vector2d(stance.right.x, stance.right.y)).norm();
  return std::max(left, right);
}

}  // namespace cairn::planning
