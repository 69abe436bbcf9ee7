#include <cairn/planning/trajectory/hessian_by_differences.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace cairn::planning {

std::vector<optimization::SparsityEntry> LowerTrianglePattern(const std::vector<int>& columns) {
  std::vector<optimization::SparsityEntry> pattern;
  pattern.reserve(columns.size() * (columns.size() + 1) / 2);
  for (std::size_t i = 0; i < columns.size(); ++i) {
    for (std::size_t j = 0; j <= i; ++j) pattern.push_back({columns[i], columns[j]});
  }
  return pattern;
}

void HessianByDifferences(const optimization::Evaluator& f, const Eigen::Ref<const Eigen::VectorXd>& x,
                          const Eigen::Ref<const Eigen::VectorXd>& weights,
                          const std::vector<optimization::SparsityEntry>& pattern, Eigen::Ref<Eigen::VectorXd> values,
                          DifferenceScheme scheme) {
  // The columns that appear in the pattern, in order.
  std::vector<int> columns;
  for (const optimization::SparsityEntry& e : pattern) columns.push_back(e.col);
  std::sort(columns.begin(), columns.end());
  columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
  std::map<int, int> slot;
  for (std::size_t i = 0; i < columns.size(); ++i) slot[columns[i]] = static_cast<int>(i);

  const auto n = static_cast<Eigen::Index>(columns.size());
  Eigen::VectorXd y(f.num_outputs());
  Eigen::VectorXd jacobian(f.jacobian_nonzeros());
  // Each Jacobian entry's slot in the differenced columns (-1: not one of them), looked up once, not per evaluation.
  const std::vector<optimization::SparsityEntry>& jp = f.jacobian_pattern();
  std::vector<int> entry_slot(jp.size(), -1);
  for (std::size_t k = 0; k < jp.size(); ++k) {
    const auto it = slot.find(jp[k].col);
    if (it != slot.end()) entry_slot[k] = it->second;
  }
  const auto gradient = [&](const Eigen::VectorXd& at, Eigen::VectorXd* g) {
    f.EvalWithJacobian(at, y, jacobian);
    g->setZero(n);
    for (std::size_t k = 0; k < jp.size(); ++k) {
      if (entry_slot[k] >= 0) (*g)(entry_slot[k]) += weights(jp[k].row) * jacobian(static_cast<Eigen::Index>(k));
    }
  };
  const bool forward = scheme == DifferenceScheme::kForward;
  const double step = forward ? std::sqrt(std::numeric_limits<double>::epsilon())
                              : std::cbrt(std::numeric_limits<double>::epsilon());
  Eigen::MatrixXd H(n, n);
  Eigen::VectorXd point = x;
  Eigen::VectorXd g_zero(n), g_plus(n), g_minus(n);
  if (forward) gradient(point, &g_zero);
  for (Eigen::Index j = 0; j < n; ++j) {
    const int c = columns[static_cast<std::size_t>(j)];
    const double h = step * std::max(1.0, std::abs(x(c)));
    point(c) = x(c) + h;
    gradient(point, &g_plus);
    if (forward) {
      point(c) = x(c);
      H.col(j) = (g_plus - g_zero) / h;
    } else {
      point(c) = x(c) - h;
      gradient(point, &g_minus);
      point(c) = x(c);
      H.col(j) = (g_plus - g_minus) / (2.0 * h);
    }
  }
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    const int r = slot.at(pattern[k].row), c = slot.at(pattern[k].col);
    values(static_cast<Eigen::Index>(k)) = 0.5 * (H(r, c) + H(c, r));
  }
}

}  // namespace cairn::planning
