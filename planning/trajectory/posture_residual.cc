#include <cairn/planning/trajectory/posture_residual.h>

#include <stdexcept>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
std::vector<optimization::SparsityEntry> Diagonal(int nq, const std::vector<int>& coordinates,
                                                  const Eigen::VectorXd& nominal) {
  if (nominal.size() != nq) {
    throw std::invalid_argument("PostureResidual: the nominal configuration has " +
                                FormatShort(static_cast<int>(nominal.size())) + " entries, expected nq = " +
                                FormatShort(nq));
  }
  std::vector<optimization::SparsityEntry> pattern;
  for (std::size_t i = 0; i < coordinates.size(); ++i) {
    if (coordinates[i] < 0 || coordinates[i] >= nq) {
      throw std::invalid_argument("PostureResidual: coordinate " + FormatShort(coordinates[i]) + " is outside [0, " +
                                  FormatShort(nq) + ")");
    }
    pattern.push_back({static_cast<int>(i), coordinates[i]});
  }
  return pattern;
}
}  // namespace

PostureResidual::PostureResidual(int nq, const std::vector<int>& coordinates, const Eigen::VectorXd& nominal)
    : optimization::Evaluator("posture", nq, static_cast<int>(coordinates.size()), Diagonal(nq, coordinates, nominal),
                              optimization::DerivativeSource::kAnalytic),
      coordinates_(coordinates),
      nominal_(nominal) {
  DeclareHessianPattern({});
}

void PostureResidual::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  for (std::size_t i = 0; i < coordinates_.size(); ++i) {
    y(static_cast<Eigen::Index>(i)) = x(coordinates_[i]) - nominal_(coordinates_[i]);
  }
}

void PostureResidual::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                         Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  DoEval(x, y);
  jacobian_values.setOnes();
}

void PostureResidual::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>&, const Eigen::Ref<const Eigen::VectorXd>&,
                                    Eigen::Ref<Eigen::VectorXd>) const {}

}  // namespace cairn::planning
