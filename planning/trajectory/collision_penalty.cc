#include <cairn/planning/trajectory/collision_penalty.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::planning {

namespace {
const multibody::Model& Checked(const std::shared_ptr<const multibody::Model>& model, const std::string& name,
                                double d_safe, double self_margin, double fraction) {
  if (model == nullptr) throw std::invalid_argument(name + ": the robot model is null");
  if (!(d_safe > 0.0) || !std::isfinite(d_safe)) {
    throw std::invalid_argument(name + ": d_safe is " + FormatShort(d_safe) + "; give a positive distance in metres");
  }
  if (!(self_margin >= 0.0) || !std::isfinite(self_margin)) {
    throw std::invalid_argument(name + ": self_margin is " + FormatShort(self_margin) +
                                "; give a distance >= 0 in metres (0 disables self-collision)");
  }
  if (!(fraction >= 0.0 && fraction < 1.0)) {
    throw std::invalid_argument(name + ": fraction is " + FormatShort(fraction) + "; it lies in [0, 1)");
  }
  return *model;
}

int NumInputs(const std::shared_ptr<const multibody::Model>& model, const std::string& name, double d_safe,
              double self_margin, double fraction) {
  const multibody::Model& m = Checked(model, name, d_safe, self_margin, fraction);
  return fraction > 0.0 ? 2 * m.nq() : m.nq();
}
}  // namespace

CollisionPenalty::CollisionPenalty(const std::string& name, std::shared_ptr<const multibody::Model> model,
                                   const std::vector<EnvironmentBox>& environment,
                                   const std::vector<std::string>& contact_bodies, double d_safe, double self_margin,
                                   double fraction)
    : optimization::Evaluator(name, NumInputs(model, name, d_safe, self_margin, fraction), 1,
                              DensePattern(1, NumInputs(model, name, d_safe, self_margin, fraction)),
                              optimization::DerivativeSource::kAnalytic),
      model_(std::move(model)),
      chart_(*model_),
      d_safe_(d_safe),
      self_margin_(self_margin),
      fraction_(fraction),
      sample_(fraction > 0.0),
      world_(*model_) {
  if (self_margin_ > 0.0) {
    multibody::Data data(*model_);
    multibody::ForwardKinematics(*model_, data, multibody::NeutralConfiguration(*model_));
    world_.UpdatePoses(*model_, data);
    for (const multibody::CollisionPair& pair : world_.PairsWithin(self_margin_)) {
      world_.ExcludeGeometryPair(world_.geometry_name(pair.geometry_a), world_.geometry_name(pair.geometry_b));
    }
  }
  for (const EnvironmentBox& box : environment) {
    if (!(box.size.minCoeff() > 0.0) || !box.size.allFinite()) {
      throw std::invalid_argument(name + ": environment box '" + box.name + "' has size (" + FormatShort(box.size.x()) +
                                  ", " + FormatShort(box.size.y()) + ", " + FormatShort(box.size.z()) +
                                  "); every side must be positive and finite");
    }
    world_.AddBox(box.name, box.size, box.X_WB);
  }
  for (const std::string& body : contact_bodies) contact_bodies_.insert(model_->GetBodyIndex(body));
}

CollisionPenalty::~CollisionPenalty() = default;

Eigen::VectorXd CollisionPenalty::Configuration(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const int nq = model_->nq();
  if (!sample_) return chart_.Normalized(x);
  const Eigen::VectorXd q = (1.0 - fraction_) * x.head(nq) + fraction_ * x.tail(nq);
  return chart_.Normalized(q);
}

std::vector<std::pair<multibody::CollisionPair, double>> CollisionPenalty::Pairs(const Eigen::VectorXd& q,
                                                                                 multibody::Data* data,
                                                                                 double scale) const {
  multibody::ForwardKinematics(*model_, *data, q);
  world_.UpdatePoses(*model_, *data);
  std::vector<std::pair<multibody::CollisionPair, double>> kept;
  for (const multibody::CollisionPair& pair : world_.PairsWithin(scale * std::max(d_safe_, self_margin_))) {
    const bool a_env = world_.geometry_body(pair.geometry_a) < 0, b_env = world_.geometry_body(pair.geometry_b) < 0;
    double margin = self_margin_;
    if (a_env != b_env) {
      const int robot = world_.geometry_body(a_env ? pair.geometry_b : pair.geometry_a);
      if (contact_bodies_.count(robot) != 0) continue;
      margin = d_safe_;
    }
    if (pair.result.distance < scale * margin) kept.emplace_back(pair, margin);
  }
  return kept;
}

std::vector<multibody::CollisionPair> CollisionPenalty::PairsWithinMargin(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const Eigen::VectorXd q = Configuration(x);
  multibody::Data data(*model_);
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<multibody::CollisionPair> out;
  for (const auto& [pair, margin] : Pairs(q, &data)) out.push_back(pair);
  return out;
}

double CollisionPenalty::MinimumEnvironmentDistance(const Eigen::Ref<const Eigen::VectorXd>& x,
                                                    std::string* which) const {
  const Eigen::VectorXd q = Configuration(x);
  multibody::Data data(*model_);
  const std::lock_guard<std::mutex> lock(mutex_);
  double best = std::numeric_limits<double>::infinity();
  if (which != nullptr) which->clear();
  for (const auto& [pair, margin] : Pairs(q, &data, 10.0)) {
    const bool a_env = world_.geometry_body(pair.geometry_a) < 0, b_env = world_.geometry_body(pair.geometry_b) < 0;
    if (a_env == b_env || pair.result.distance >= best) continue;
    best = pair.result.distance;
    if (which != nullptr) *which = world_.geometry_name(pair.geometry_a) + " - " + world_.geometry_name(pair.geometry_b);
  }
  return best;
}

void CollisionPenalty::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  const Eigen::VectorXd q = Configuration(x);
  multibody::Data data(*model_);
  const std::lock_guard<std::mutex> lock(mutex_);
  double sum = 0.0;
  for (const auto& [pair, margin] : Pairs(q, &data)) {
    const double h = margin - pair.result.distance;
    sum += h * h;
  }
  y(0) = sum;
}

void CollisionPenalty::DoEvalWithJacobian(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                                          Eigen::Ref<Eigen::VectorXd> jacobian_values) const {
  const int nq = model_->nq();
  const int nv = model_->nv();
  const Eigen::VectorXd q = Configuration(x);
  multibody::Data data(*model_);
  Eigen::VectorXd gradient_v = Eigen::VectorXd::Zero(nv);
  Eigen::VectorXd pair_gradient(nv);
  double sum = 0.0;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [pair, margin] : Pairs(q, &data)) {
      const double h = margin - pair.result.distance;
      sum += h * h;
      world_.DistanceGradient(*model_, data, pair, pair_gradient);
      gradient_v -= 2.0 * h * pair_gradient;
    }
  }
  y(0) = sum;
  if (!sample_) {
    jacobian_values = chart_.TangentToCoordinates(x, gradient_v.transpose()).row(0).transpose();
    return;
  }
  // The sample reads normalise((1 - s) q_a + s q_b): the chart at the blended raw point, times the blend weights.
  const Eigen::VectorXd blended = (1.0 - fraction_) * x.head(nq) + fraction_ * x.tail(nq);
  const Eigen::VectorXd g_q = chart_.TangentToCoordinates(blended, gradient_v.transpose()).row(0).transpose();
  jacobian_values.head(nq) = (1.0 - fraction_) * g_q;
  jacobian_values.tail(nq) = fraction_ * g_q;
}

}  // namespace cairn::planning
