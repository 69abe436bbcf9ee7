#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/optimization/decision_variables.h"

namespace cairn::optimization {

/// An evaluator (cost or constraint) bound to an ordered list of a program's decision variables: input i of the
/// evaluator is the program variable variables()[i].
template <typename E>
class Binding {
 public:
  /// Throws std::invalid_argument if the evaluator is null or its input count differs from the variable count.
  Binding(std::shared_ptr<E> evaluator, DecisionVariables variables)
      : evaluator_(std::move(evaluator)), variables_(std::move(variables)) {
    if (evaluator_ == nullptr) {
      throw std::invalid_argument("Binding to '" + variables_.description() +
                                  "': the evaluator is null; pass a constructed cost or constraint.");
    }
    if (evaluator_->num_inputs() != variables_.size()) {
      throw std::invalid_argument("Binding '" + evaluator_->name() + "' to '" + variables_.description() +
                                  "': the evaluator takes " + cairn::FormatShort(evaluator_->num_inputs()) +
                                  " inputs but " + cairn::FormatShort(variables_.size()) +
                                  " variables were given; bind exactly one variable per input.");
    }
  }

  /// Converts a binding of a derived evaluator type (e.g. Binding<LinearCost> to Binding<Evaluator>).
  template <typename U, typename = std::enable_if_t<std::is_convertible_v<U*, E*>>>
  Binding(const Binding<U>& other)  // NOLINT(runtime/explicit): the conversion is meant to be implicit.
      : evaluator_(other.evaluator()), variables_(other.variables()) {}

  /// The bound evaluator.
  const std::shared_ptr<E>& evaluator() const { return evaluator_; }
  /// The variables, one per evaluator input.
  const DecisionVariables& variables() const { return variables_; }
  /// "name(variables)", the label used in solver and gradient-check messages.
  std::string ToString() const { return evaluator_->name() + "(" + variables_.description() + ")"; }

 private:
  std::shared_ptr<E> evaluator_;
  DecisionVariables variables_;
};

}  // namespace cairn::optimization
