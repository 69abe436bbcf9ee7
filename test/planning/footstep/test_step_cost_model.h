#pragma once

#include <cmath>
#include <string>

#include <cairn/planning/locomotion/step_cost_model.h>

namespace cairn::planning::test {

/// An analytic step cost model for planner tests: cost = per_metre * hypot(dx, dy) + per_step + climb * |dz|,
/// RCOF = 0.05 + rcof_per_metre * dx (longer steps need more friction), so the heuristic bound is exactly
/// `per_metre` and friction limits act through the step length as in the thesis' RCOF model.
class TestStepCostModel final : public StepCostModel {
 public:
  TestStepCostModel() {
    reach_.dx_min = 0.0;
    reach_.dx_max = 0.38;
    reach_.dy_min = 0.17;
    reach_.dy_max = 0.30;
    reach_.dz_min = -0.15;
    reach_.dz_max = 0.15;
    reach_.dtheta_min = 0.0;
    reach_.dtheta_max = 30.0 * M_PI / 180.0;
  }
  double per_metre{100.0};
  double per_step{20.0};
  double climb{300.0};
  double rcof_per_metre{0.5};
  mutable long evaluations{0};

 protected:
  TransitionCost DoEvaluate(const StepDisplacement& d, double mu_allowed) const override {
    ++evaluations;
    TransitionCost c;
    if (!reach_.Contains(d)) return c;
    c.rcof = 0.05 + rcof_per_metre * d.dx;
    if (c.rcof > mu_allowed) return c;
    c.feasible = true;
    c.cost = per_metre * std::hypot(d.dx, d.dy) + per_step + climb * std::abs(d.dz);
    c.com_work = c.cost;
    c.parameters = StepParameters{0.2, 0.9, 0.8};
    c.duration = 1.1;
    return c;
  }
  double do_min_cost_per_metre() const override { return per_metre; }
  double do_min_cost_per_step() const override { return per_step; }
  StepCostLowerBound do_cost_lower_bound(double mu_allowed) const override {
    return StepCostLowerBound{mu_allowed >= 0.05, per_step, per_metre};
  }
  const StepReach& do_reach() const override { return reach_; }
  std::string do_description() const override { return "test cost model"; }

 private:
  StepReach reach_;
};

}  // namespace cairn::planning::test
