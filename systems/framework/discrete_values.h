#pragma once

#include <vector>

#include <Eigen/Core>

namespace cairn::systems {

/// The discrete state of one leaf system: a list of groups, each a vector of fixed size. Discrete update events
/// receive a DiscreteValues initialised to the current values and write the next ones into it.
class DiscreteValues {
 public:
  DiscreteValues() = default;
  explicit DiscreteValues(std::vector<Eigen::VectorXd> groups) : groups_(std::move(groups)) {}

  int num_groups() const { return static_cast<int>(groups_.size()); }

  /// Group `group`; throws std::out_of_range naming the valid range.
  const Eigen::VectorXd& value(int group = 0) const;
  Eigen::VectorXd& get_mutable_value(int group = 0);

  /// Sets group `group`; throws std::invalid_argument if the size differs from the group's.
  void set_value(int group, const Eigen::Ref<const Eigen::VectorXd>& value);

  /// Copies every group from `other`, which must have the same structure.
  void SetFrom(const DiscreteValues& other);

 private:
  void CheckGroup(int group) const;
  std::vector<Eigen::VectorXd> groups_;
};

}  // namespace cairn::systems
