#include <cairn/planning/trajectory/trajectory_optimizer_options.h>

#include <cmath>
#include <stdexcept>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
void Require(bool ok, const char* name, double value, const char* range) {
  if (!ok) {
    throw std::invalid_argument(std::string("TrajectoryOptimizerOptions: ") + name + " is " + FormatShort(value) +
                                "; it must be " + range);
  }
}
}  // namespace

void ValidateTrajectoryOptimizerOptions(const TrajectoryOptimizerOptions& o) {
  Require(o.collision_weight >= 0.0 && std::isfinite(o.collision_weight), "collision_weight", o.collision_weight,
          "finite and >= 0");
  Require(o.d_safe > 0.0 && o.d_safe <= 1.0, "d_safe", o.d_safe, "in (0, 1] m");
  Require(o.self_margin >= 0.0 && o.self_margin <= 1.0, "self_margin", o.self_margin, "in [0, 1] m");
  Require(o.samples_between >= 0 && o.samples_between <= 10, "samples_between", o.samples_between, "in [0, 10]");
  Require(o.torque_weight > 0.0 && std::isfinite(o.torque_weight), "torque_weight", o.torque_weight,
          "finite and > 0");
  Require(o.smoothness_weight >= 0.0 && std::isfinite(o.smoothness_weight), "smoothness_weight",
          o.smoothness_weight, "finite and >= 0");
  Require(o.base_rotation_smoothness_weight >= 0.0 && std::isfinite(o.base_rotation_smoothness_weight),
          "base_rotation_smoothness_weight", o.base_rotation_smoothness_weight, "finite and >= 0");
  Require(o.posture_weight >= 0.0 && std::isfinite(o.posture_weight), "posture_weight", o.posture_weight,
          "finite and >= 0");
  Require(o.sole_length > 0.0 && o.sole_length <= 1.0, "sole_length", o.sole_length, "in (0, 1] m");
  Require(o.sole_width > 0.0 && o.sole_width <= 1.0, "sole_width", o.sole_width, "in (0, 1] m");
  Require(o.com_margin >= 0.0 && o.com_margin < 0.5 * std::min(o.sole_length, o.sole_width), "com_margin",
          o.com_margin, "in [0, half the sole's smaller side)");
  Require(!std::isinf(o.ground_height), "ground_height", o.ground_height, "finite, or NaN for no ground");
  if (o.hessian != "gauss-newton" && o.hessian != "exact" && o.hessian != "limited-memory") {
    throw std::invalid_argument("TrajectoryOptimizerOptions: hessian is '" + o.hessian +
                                "'; it must be 'gauss-newton', 'exact' or 'limited-memory'");
  }
  Require(o.max_iterations >= 1 && o.max_iterations <= 100000, "max_iterations", o.max_iterations,
          "in [1, 100000]");
  Require(o.tolerance > 0.0 && o.tolerance <= 1e-2, "tolerance", o.tolerance, "in (0, 0.01]");
  Require(o.window_stances >= 0 && o.window_stances <= kMaxTrajectoryStances, "window_stances", o.window_stances,
          "in [0, 200]");
  Require(o.nominal_pelvis_height > 0.0 && o.nominal_pelvis_height < 5.0, "nominal_pelvis_height",
          o.nominal_pelvis_height, "in (0, 5) m");
}

}  // namespace cairn::planning
