#include "cairn/systems/analysis/runge_kutta45_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::systems {
namespace {

// Dormand & Prince (1980) tableau.
constexpr double kC[7] = {0.0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1.0, 1.0};
constexpr double kA[7][6] = {
    {},
    {1.0 / 5},
    {3.0 / 40, 9.0 / 40},
    {44.0 / 45, -56.0 / 15, 32.0 / 9},
    {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
    {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
    {35.0 / 384, 0.0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
};
// Fifth-order weights (the last row of kA) minus the embedded fourth-order weights.
constexpr double kE[7] = {71.0 / 57600, 0.0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525, -1.0 / 40};

}  // namespace

RungeKutta45Integrator::RungeKutta45Integrator(double maximum_step_size, double target_accuracy)
    : IntegratorBase(maximum_step_size) {
  set_target_accuracy(target_accuracy);
}

void RungeKutta45Integrator::set_minimum_step_size(double h) {
  if (!(h > 0.0) || !std::isfinite(h)) {
    throw std::invalid_argument("The minimum step size must be finite and > 0; got " + FormatShort(h) + ".");
  }
  minimum_step_size_ = h;
}

double RungeKutta45Integrator::DoStep(const System& system, Context* context, double t_max) {
  const double t0 = context->get_time();
  x0_ = context->get_continuous_state_vector();
  if (next_step_ <= 0.0) next_step_ = 0.01 * maximum_step_size();
  const double accuracy = target_accuracy();
  while (true) {
    double h = std::min(next_step_, maximum_step_size());
    // A trial step too small to move time (late in a long simulation) is raised to the largest allowed;
    // Step() has checked that that one advances.
    if (!(t0 + h > t0)) h = maximum_step_size();
    // Land on t_max rather than leave a sliver for the next step.
    const bool reaches_end = t_max - t0 <= 1.01 * h;
    if (reaches_end) h = t_max - t0;
    for (int stage = 0; stage < 7; ++stage) {
      x5_ = x0_;
      for (int j = 0; j < stage; ++j) x5_ += h * kA[stage][j] * k_[j];
      EvalDerivatives(system, context, t0 + kC[stage] * h, x5_, &k_[stage]);
    }
    // The last stage was evaluated at the fifth-order solution itself (FSAL row), so x5_ holds it now.
    error_.setZero(x0_.size());
    for (int stage = 0; stage < 7; ++stage) error_ += h * kE[stage] * k_[stage];
    // A trial solution or error that overflowed counts as an infinite error (std::max would drop a NaN), so
    // the step is rejected and shrunk rather than accepted.
    double error_norm = x5_.allFinite() ? 0.0 : std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < x0_.size() && std::isfinite(error_norm); ++i) {
      const double scale = accuracy * (1.0 + std::max(std::abs(x0_[i]), std::abs(x5_[i])));
      const double e = std::abs(error_[i]) / scale;
      error_norm = std::isnan(e) ? std::numeric_limits<double>::infinity() : std::max(error_norm, e);
    }
    const bool finite = std::isfinite(error_norm);
    const double factor = !finite ? 0.2 : error_norm == 0.0 ? 5.0 : std::clamp(0.9 * std::pow(error_norm, -0.2), 0.2, 5.0);
    if (finite && error_norm <= 1.0) {
      const double t1 = reaches_end ? t_max : t0 + h;
      // A step shortened to land on t_max says little about the step size the dynamics allow.
      next_step_ = reaches_end ? std::max(next_step_, h * factor) : h * factor;
      context->SetTime(t1);
      WriteContinuousState(context, x5_);
      return t1;
    }
    count_rejection();
    next_step_ = h * factor;
    if (next_step_ < minimum_step_size_ || !(t0 + next_step_ > t0)) {
      throw std::runtime_error("RungeKutta45Integrator: at t = " + FormatShort(t0) + " the step size fell to " +
                               FormatShort(next_step_) + ", below the minimum " + FormatShort(minimum_step_size_) +
                               " (or too small to advance time there), without meeting the accuracy " +
                               FormatShort(accuracy) +
                               "; loosen the accuracy or check the system for discontinuities or a blow-up.");
    }
  }
}

}  // namespace cairn::systems
