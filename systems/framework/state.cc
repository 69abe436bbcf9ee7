#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace cairn::systems {

State::State(Eigen::VectorXd continuous, DiscreteValues discrete,
             std::vector<std::shared_ptr<AbstractValue>> abstract)
    : continuous_(std::move(continuous)), discrete_(std::move(discrete)), abstract_(std::move(abstract)) {}

const AbstractValue& State::abstract_state_value(int index) const {
  if (index < 0 || index >= num_abstract_states()) {
    throw std::out_of_range("Abstract state " + cairn::FormatShort(index) + " does not exist; there are " +
                            cairn::FormatShort(num_abstract_states()) + ".");
  }
  return *abstract_[index];
}

AbstractValue& State::get_mutable_abstract_state_value(int index) {
  abstract_state_value(index);  // validates the index
  std::shared_ptr<AbstractValue>& value = abstract_[static_cast<std::size_t>(index)];
  if (value.use_count() > 1) value = value->Clone();
  return *value;
}

}  // namespace cairn::systems
