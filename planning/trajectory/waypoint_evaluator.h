#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/optimization/evaluator.h>
#include <cairn/planning/trajectory/configuration_chart.h>

namespace cairn::planning {

/// Base of the whole-body evaluators: a function of one waypoint's configuration q (size nq, quaternion read
/// normalised, see ConfigurationChart) whose analytic Jacobian is computed in tangent space and mapped to q.
///
/// Subclasses implement EvalTangent (value and rows x nv tangent Jacobian at the normalised q); this class
/// evaluates it, maps the Jacobian through the chart and writes the declared pattern's entries. The Hessian
/// (lower triangle over the same columns) comes from forward differences of that analytic Jacobian
/// (HessianByDifferences), for Ipopt's exact-Hessian mode. Each call makes
/// its own multibody::Data, so the evaluators hold no mutable state and are safe to share between threads.
class WaypointEvaluator : public optimization::Evaluator {
 public:
  ~WaypointEvaluator() override;

  /// The robot model.
  const multibody::Model& model() const { return *model_; }

  /// The chart from q to tangent space.
  const ConfigurationChart& chart() const { return chart_; }

 protected:
  /// `columns` are the q coordinates the function depends on (the pattern is rows x columns, dense).
  WaypointEvaluator(std::string name, std::shared_ptr<const multibody::Model> model, int num_outputs,
                    const std::vector<int>& columns);

  /// Value y (num_outputs) and, if J_v is not null, the tangent Jacobian (num_outputs x nv) at normalised q.
  virtual void EvalTangent(const Eigen::VectorXd& q, Eigen::Ref<Eigen::VectorXd> y, Eigen::MatrixXd* J_v) const = 0;

  void DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const override;
  void DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const override;
  void DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& weights,
                     Eigen::Ref<Eigen::VectorXd> hessian_values) const override;

  /// The dense pattern rows x columns.
  static std::vector<optimization::SparsityEntry> BlockPattern(int rows, const std::vector<int>& columns);

 private:
  std::shared_ptr<const multibody::Model> model_;
  ConfigurationChart chart_;
};

}  // namespace cairn::planning
