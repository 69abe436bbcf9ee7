#include "cairn/common/number_text.h"
#include "cairn/optimization/bounding_box_constraint.h"

#include <stdexcept>

namespace cairn::optimization {

namespace {

Eigen::SparseMatrix<double> Identity(const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                                     const Eigen::Ref<const Eigen::VectorXd>& upper_bound) {
  if (lower_bound.size() != upper_bound.size()) {
    throw std::invalid_argument("BoundingBoxConstraint: lower bound has size " + cairn::FormatShort(lower_bound.size()) +
                                " but upper bound has size " + cairn::FormatShort(upper_bound.size()) +
                                "; give one lower and one upper bound per variable.");
  }
  Eigen::SparseMatrix<double> identity(lower_bound.size(), lower_bound.size());
  identity.setIdentity();
  return identity;
}

}  // namespace

BoundingBoxConstraint::BoundingBoxConstraint(const Eigen::Ref<const Eigen::VectorXd>& lower_bound,
                                             const Eigen::Ref<const Eigen::VectorXd>& upper_bound)
    : LinearConstraint("BoundingBoxConstraint", Identity(lower_bound, upper_bound), lower_bound, upper_bound) {}

}  // namespace cairn::optimization
