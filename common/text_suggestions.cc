#include "cairn/common/text_suggestions.h"

#include <algorithm>
#include <numeric>

namespace cairn {

int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> previous(b.size() + 1);
  std::vector<int> current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::vector<std::string> ClosestNames(const std::string& name, const std::vector<std::string>& candidates,
                                      int max_count) {
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<int> distance(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) distance[i] = EditDistance(name, candidates[i]);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return distance[a] < distance[b]; });
  std::vector<std::string> result;
  for (std::size_t i = 0; i < order.size() && static_cast<int>(result.size()) < max_count; ++i) {
    result.push_back(candidates[order[i]]);
  }
  return result;
}

std::string QuotedList(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ", ";
    out += "'" + items[i] + "'";
  }
  return out;
}

}  // namespace cairn
