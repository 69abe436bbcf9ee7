#include <cairn/planning/trajectory/center_of_mass_projection.h>

#include <numeric>
#include <stdexcept>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/data.h>

namespace cairn::planning {

namespace {
int CheckedRows(const std::shared_ptr<const multibody::Model>& model, const Eigen::MatrixXd& A) {
  if (model == nullptr) throw std::invalid_argument("CenterOfMassProjection: the robot model is null");
  if (A.cols() != 2 || A.rows() < 1 || !A.allFinite()) {
    throw std::invalid_argument("CenterOfMassProjection: A is " + FormatShort(static_cast<int>(A.rows())) + " x " +
                                FormatShort(static_cast<int>(A.cols())) +
                                "; it needs at least one row, 2 columns and finite entries");
  }
  return static_cast<int>(A.rows());
}

std::vector<int> AllColumns(const std::shared_ptr<const multibody::Model>& model) {
  std::vector<int> columns(static_cast<std::size_t>(model->nq()));
  std::iota(columns.begin(), columns.end(), 0);
  return columns;
}
}  // namespace

CenterOfMassProjection::CenterOfMassProjection(std::shared_ptr<const multibody::Model> model, const Eigen::MatrixXd& A,
                                               const Eigen::VectorXd& offset)
    : WaypointEvaluator("com_projection", model, CheckedRows(model, A), AllColumns(model)),
      A_(A),
      offset_(offset.size() == 0 ? Eigen::VectorXd::Zero(A.rows()) : offset) {
  if (offset_.size() != A_.rows() || !offset_.allFinite()) {
    throw std::invalid_argument("CenterOfMassProjection: the offset has " +
                                FormatShort(static_cast<int>(offset.size())) + " entries; give one finite entry per "
                                "row of A (" + FormatShort(static_cast<int>(A_.rows())) + ")");
  }
}

void CenterOfMassProjection::EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y,
                                         Eigen::MatrixXd* J_v) const {
  multibody::Data data(model());
  if (J_v == nullptr) {
    const Eigen::Vector3d& com = multibody::CenterOfMass(model(), data, q);
    y = A_ * com.head<2>() - offset_;
    return;
  }
  const auto& J_com = multibody::CenterOfMassJacobian(model(), data, q);
  y = A_ * data.com.head<2>() - offset_;
  *J_v = A_ * J_com.topRows<2>();
}

}  // namespace cairn::planning
