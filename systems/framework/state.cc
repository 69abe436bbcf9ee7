#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace cairn::systems {

State::State(Eigen::VectorXd continuous, DiscreteValues discrete,
             std::vector<std::unique_ptr<AbstractValue>> abstract)
    : continuous_(std::move(continuous)), discrete_(std::move(discrete)), abstract_(std::move(abstract)) {}

const AbstractValue& State::abstract_state_value(int index) const {
  if (index < 0 || index >= num_abstract_states()) {
    throw std::out_of_range("Abstract state " + cairn::FormatShort(index) + " does not exist; there are " +
                            cairn::FormatShort(num_abstract_states()) + ".");
  }
  return *abstract_[index];
}

AbstractValue& State::get_mutable_abstract_state_value(int index) {
  return const_cast<AbstractValue&>(static_cast<const State*>(this)->abstract_state_value(index));
}

}  // namespace cairn::systems
