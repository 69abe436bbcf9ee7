#include "cairn/common/number_text.h"
#include "cairn/systems/framework/discrete_values.h"

#include <stdexcept>
#include <string>

namespace cairn::systems {

void DiscreteValues::CheckGroup(int group) const {
  if (group < 0 || group >= num_groups()) {
    throw std::out_of_range("Discrete state group " + cairn::FormatShort(group) + " does not exist; there are " +
                            cairn::FormatShort(num_groups()) + " group(s), indexed from 0.");
  }
}

const Eigen::VectorXd& DiscreteValues::value(int group) const {
  CheckGroup(group);
  return groups_[group];
}

Eigen::VectorXd& DiscreteValues::get_mutable_value(int group) {
  CheckGroup(group);
  return groups_[group];
}

void DiscreteValues::set_value(int group, const Eigen::Ref<const Eigen::VectorXd>& value) {
  CheckGroup(group);
  if (value.size() != groups_[group].size()) {
    throw std::invalid_argument("Discrete state group " + cairn::FormatShort(group) + " has size " +
                                cairn::FormatShort(groups_[group].size()) + " but was given a vector of size " +
                                cairn::FormatShort(value.size()) + ".");
  }
  groups_[group] = value;
}

void DiscreteValues::SetFrom(const DiscreteValues& other) {
  if (other.num_groups() != num_groups()) {
    throw std::invalid_argument("DiscreteValues::SetFrom: " + cairn::FormatShort(other.num_groups()) +
                                " groups given for " + cairn::FormatShort(num_groups()) + ".");
  }
  for (int i = 0; i < num_groups(); ++i) set_value(i, other.groups_[i]);
}

}  // namespace cairn::systems
