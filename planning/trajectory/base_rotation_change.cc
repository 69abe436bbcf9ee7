#include <cairn/planning/trajectory/base_rotation_change.h>

#include <vector>

namespace cairn::planning {

namespace {
// Row k reads quat_a(k) (column k, -2) and quat_b(k) (column 4 + k, +2).
std::vector<optimization::SparsityEntry> Pattern() {
  std::vector<optimization::SparsityEntry> pattern;
  for (int k = 0; k < 4; ++k) {
    pattern.push_back({k, k});
    pattern.push_back({k, 4 + k});
  }
  return pattern;
}
}  // namespace

BaseRotationChange::BaseRotationChange()
    : optimization::Evaluator("base_rotation_change", 8, 4, Pattern(), optimization::DerivativeSource::kAnalytic) {
  DeclareHessianPattern({});
}

void BaseRotationChange::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  y = 2.0 * (x.tail<4>() - x.head<4>());
}

void BaseRotationChange::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                            Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  DoEval(x, y);
  for (int k = 0; k < 4; ++k) {
    jacobian_values(2 * k) = -2.0;
    jacobian_values(2 * k + 1) = 2.0;
  }
}

void BaseRotationChange::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>&,
                                       const Eigen::Ref<const Eigen::VectorXd>&, Eigen::Ref<Eigen::VectorXd>) const {}

}  // namespace cairn::planning
