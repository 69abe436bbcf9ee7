#include <cairn/planning/trajectory/waypoint_evaluator.h>

#include <cairn/planning/trajectory/hessian_by_differences.h>

#include <stdexcept>
#include <utility>

namespace cairn::planning {

namespace {
std::shared_ptr<const multibody::Model> RequireModel(std::shared_ptr<const multibody::Model> model,
                                                     const std::string& name) {
  if (model == nullptr) throw std::invalid_argument(name + ": the robot model is null; pass a parsed Model");
  return model;
}
}  // namespace

WaypointEvaluator::~WaypointEvaluator() = default;

WaypointEvaluator::WaypointEvaluator(std::string name, std::shared_ptr<const multibody::Model> model,
                                     int num_outputs, const std::vector<int>& columns)
    : optimization::Evaluator(name, RequireModel(model, name)->nq(), num_outputs, BlockPattern(num_outputs, columns),
                              optimization::DerivativeSource::kAnalytic),
      model_(std::move(model)),
      chart_(*model_) {
  DeclareHessianPattern(LowerTrianglePattern(columns));
}

void WaypointEvaluator::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                      const Eigen::Ref<const Eigen::VectorXd>& weights,
                                      Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  HessianByDifferences(*this, x, weights, hessian_pattern(), hessian_values);
}

std::vector<optimization::SparsityEntry> WaypointEvaluator::BlockPattern(int rows, const std::vector<int>& columns) {
  std::vector<optimization::SparsityEntry> pattern;
  pattern.reserve(static_cast<std::size_t>(rows) * columns.size());
  for (int r = 0; r < rows; ++r) {
    for (int c : columns) pattern.push_back({r, c});
  }
  return pattern;
}

void WaypointEvaluator::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  EvalTangent(chart_.Normalized(x), y, nullptr);
}

void WaypointEvaluator::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                           Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  Eigen::MatrixXd J_v = Eigen::MatrixXd::Zero(num_outputs(), model_->nv());
  EvalTangent(chart_.Normalized(x), y, &J_v);
  const Eigen::MatrixXd J_q = chart_.TangentToCoordinates(x, J_v);
  const std::vector<optimization::SparsityEntry>& pattern = jacobian_pattern();
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    jacobian_values(static_cast<Eigen::Index>(k)) = J_q(pattern[k].row, pattern[k].col);
  }
}

}  // namespace cairn::planning
