// Cairn::planning: loads the humanoid's walking model (data/robots) and evaluates one step in the middle of its
// reach and parameter ranges.
#include <cmath>
#include <cstdio>

#include <cairn/planning/locomotion/step_evaluator.h>
#include <cairn/planning/locomotion/walking_model.h>

int main() {
  using namespace cairn::planning;
  const WalkingModel model = WalkingModel::Load(CAIRN_HUMANOID_WALKING_YAML);
  const StepReach& reach = model.reach();
  StepDisplacement d;
  d.dx = 0.5 * (reach.dx_min + reach.dx_max);
  d.dy = 0.5 * (reach.dy_min + reach.dy_max);
  StepParameters p;
  p.t_ds = 0.5 * (model.parameter_lower().t_ds + model.parameter_upper().t_ds);
  p.t_sw = 0.5 * (model.parameter_lower().t_sw + model.parameter_upper().t_sw);
  p.com_height = 0.5 * (model.parameter_lower().com_height + model.parameter_upper().com_height);
  StepEvaluator evaluator(model);
  const StepEvaluation& step = evaluator.Evaluate(d, p);
  std::printf("consumer planning: %s, %.2f kg, step of %.3f m: %s, E_COM %.3f J, RCOF %.3f\n", model.name().c_str(),
              model.mass(), d.dx, to_string(step.infeasibility), step.com_work, step.rcof);
  const bool right = model.mass() > 0.0 && std::isfinite(step.com_work) && step.com_work >= 0.0 &&
                     std::abs(step.duration - (p.t_ds + p.t_sw)) < 1e-12;
  return right ? 0 : 1;
}
