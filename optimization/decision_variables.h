#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cairn::optimization {

/// An ordered list of a MathematicalProgram's decision variables, used to bind costs and constraints.
///
/// MathematicalProgram::NewContinuousVariables returns one for a contiguous block; Segment and Concatenate
/// build the lists a cost or constraint needs (e.g. two neighbours in a chain). A handle remembers which program
/// created it, so that binding it to another program is reported instead of silently indexing the wrong
/// variables. Handles are cheap values; they never own the program.
class DecisionVariables {
 public:
  /// An empty list that belongs to no program.
  DecisionVariables() = default;

  /// Number of variables in the list.
  int size() const { return static_cast<int>(indices_.size()); }

  /// True if the list is empty.
  bool empty() const { return indices_.empty(); }

  /// Index into the program's decision vector of the i-th variable of this list.
  int operator[](int i) const;

  /// All program indices, in list order.
  const std::vector<int>& indices() const { return indices_; }

  /// Human-readable description used in messages, e.g. "x" or "x[2:4]".
  const std::string& description() const { return description_; }

  /// Identifier of the program that created the variables (0 for an empty default list).
  std::int64_t program_id() const { return program_id_; }

  /// The `count` variables starting at list position `start`; throws std::invalid_argument if out of range.
  DecisionVariables Segment(int start, int count) const;

  /// The single variable at list position `i`, as a list (throws if out of range).
  DecisionVariables Element(int i) const { return Segment(i, 1); }

  /// The lists joined in order; all must belong to the same program (throws std::invalid_argument otherwise).
  static DecisionVariables Concatenate(const std::vector<DecisionVariables>& parts);

  /// Used by MathematicalProgram to create handles; users call NewContinuousVariables instead.
  static DecisionVariables FromIndices(std::int64_t program_id, std::vector<int> indices,
                                       std::string description);

 private:
  std::int64_t program_id_{0};
  std::vector<int> indices_;
  std::string description_;
};

}  // namespace cairn::optimization
