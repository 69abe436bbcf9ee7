#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "cairn/systems/framework/discrete_values.h"
#include "cairn/systems/framework/value.h"

namespace cairn::systems {

/// The complete state of one leaf system (continuous, discrete and abstract), as handed to unrestricted update
/// events: initialised to the current state, and whatever the handler writes becomes the next state.
///
/// Abstract values are shared copy-on-write with the context they were cloned from: cloning a state copies
/// pointers, and the first mutable access to a shared value copies it. So an event that only reads a large
/// abstract state (a dense reference, a map) costs nothing per step, and Context::SetState() sees which values
/// the handler did not touch and leaves their dependents' caches valid.
class State {
 public:
  State() = default;
  State(Eigen::VectorXd continuous, DiscreteValues discrete, std::vector<std::shared_ptr<AbstractValue>> abstract);

  const Eigen::VectorXd& continuous_state() const { return continuous_; }
  Eigen::VectorXd& get_mutable_continuous_state() { return continuous_; }

  const DiscreteValues& discrete_state() const { return discrete_; }
  DiscreteValues& get_mutable_discrete_state() { return discrete_; }

  int num_abstract_states() const { return static_cast<int>(abstract_.size()); }
  const AbstractValue& abstract_state_value(int index) const;
  /// Copies the value first when it is still shared with the context it was cloned from.
  AbstractValue& get_mutable_abstract_state_value(int index);

  /// Abstract state `index` as a T (type-checked).
  template <typename T>
  const T& abstract_state(int index) const {
    return abstract_state_value(index).get_value<T>();
  }
  template <typename T>
  T& get_mutable_abstract_state(int index) {
    return get_mutable_abstract_state_value(index).get_mutable_value<T>();
  }

 private:
  friend class Context;  // shares and compares the abstract values' storage

  Eigen::VectorXd continuous_;
  DiscreteValues discrete_;
  std::vector<std::shared_ptr<AbstractValue>> abstract_;
};

}  // namespace cairn::systems
