#include "cairn/common/number_text.h"
#include "cairn/optimization/decision_variables.h"

#include <stdexcept>

namespace cairn::optimization {

int DecisionVariables::operator[](int i) const {
  if (i < 0 || i >= size()) {
    throw std::invalid_argument("DecisionVariables '" + description_ + "': position " + cairn::FormatShort(i) +
                                " is out of range; valid positions are 0.." + cairn::FormatShort(size() - 1) + ".");
  }
  return indices_[static_cast<std::size_t>(i)];
}

DecisionVariables DecisionVariables::Segment(int start, int count) const {
  if (start < 0 || count < 0 || start + count > size()) {
    throw std::invalid_argument("DecisionVariables '" + description_ + "'.Segment(" + cairn::FormatShort(start) +
                                ", " + cairn::FormatShort(count) + ") is out of range: the list has " +
                                cairn::FormatShort(size()) + " variables; pass start >= 0 and start + count <= " +
                                cairn::FormatShort(size()) + ".");
  }
  std::vector<int> indices(indices_.begin() + start, indices_.begin() + start + count);
  return FromIndices(program_id_, std::move(indices),
                     description_ + "[" + cairn::FormatShort(start) + ":" + cairn::FormatShort(start + count) + "]");
}

DecisionVariables DecisionVariables::Concatenate(const std::vector<DecisionVariables>& parts) {
  std::vector<int> indices;
  std::string description;
  std::int64_t program_id = 0;
  for (const DecisionVariables& part : parts) {
    if (part.empty()) continue;
    if (program_id != 0 && part.program_id_ != program_id) {
      throw std::invalid_argument("DecisionVariables::Concatenate: '" + part.description_ +
                                  "' belongs to a different MathematicalProgram than '" + description +
                                  "'; concatenate only variables created by the same program.");
    }
    program_id = part.program_id_;
    indices.insert(indices.end(), part.indices_.begin(), part.indices_.end());
    description += (description.empty() ? "" : ", ") + part.description_;
  }
  return FromIndices(program_id, std::move(indices), "(" + description + ")");
}

DecisionVariables DecisionVariables::FromIndices(std::int64_t program_id, std::vector<int> indices,
                                                 std::string description) {
  DecisionVariables result;
  result.program_id_ = program_id;
  result.indices_ = std::move(indices);
  result.description_ = std::move(description);
  return result;
}

}  // namespace cairn::optimization
