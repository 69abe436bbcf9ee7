#include "cairn/common/number_text.h"
#include "cairn/optimization/constraint.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cairn::optimization {

Constraint::Constraint(std::string name, int num_inputs, int num_outputs,
                       std::vector<SparsityEntry> jacobian_pattern, DerivativeSource jacobian_source,
                       const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                       const Eigen::Ref<const Eigen::VectorXd>& upper_bound)
    : Evaluator(std::move(name), num_inputs, num_outputs, std::move(jacobian_pattern), jacobian_source),
      lower_bound_(lower_bound),
      upper_bound_(upper_bound) {
  if (lower_bound_.size() != num_outputs || upper_bound_.size() != num_outputs) {
    throw std::invalid_argument("Constraint '" + this->name() + "': lower bound has size " +
                                cairn::FormatShort(lower_bound_.size()) + " and upper bound " +
                                cairn::FormatShort(upper_bound_.size()) + "; both need one entry per output (" +
                                cairn::FormatShort(num_outputs) + ").");
  }
  for (int i = 0; i < num_outputs; ++i) {
    if (std::isnan(lower_bound_[i]) || std::isnan(upper_bound_[i]) || lower_bound_[i] > upper_bound_[i]) {
      throw std::invalid_argument("Constraint '" + this->name() + "': row " + cairn::FormatShort(i) + " has bounds [" +
                                  cairn::FormatShort(lower_bound_[i]) + ", " + cairn::FormatShort(upper_bound_[i]) +
                                  "]; bounds must not be NaN and need lower <= upper (use +/-infinity for a "
                                  "one-sided row).");
    }
  }
}

Constraint::~Constraint() = default;

double Constraint::Violation(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const Eigen::VectorXd y = Eval(x);
  double violation = 0.0;
  for (int i = 0; i < num_outputs(); ++i) {
    violation = std::max({violation, lower_bound_[i] - y[i], y[i] - upper_bound_[i]});
  }
  return violation;
}

}  // namespace cairn::optimization
