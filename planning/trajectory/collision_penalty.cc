#include <cairn/planning/trajectory/collision_penalty.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/geometry.h>
#include <cairn/multibody/joint.h>
#include <cairn/multibody/joint_motion.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/planning/trajectory/hessian_by_differences.h>

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
                                   double fraction, double ground_height, CollisionHessian hessian,
                                   std::shared_ptr<const TerrainMap> ground_terrain)
    : optimization::Evaluator(name, NumInputs(model, name, d_safe, self_margin, fraction), 1,
                              DensePattern(1, NumInputs(model, name, d_safe, self_margin, fraction)),
                              optimization::DerivativeSource::kAnalytic),
      model_(std::move(model)),
      chart_(*model_),
      ground_height_(ground_height),
      ground_terrain_(std::move(ground_terrain)),
      d_safe_(d_safe),
      self_margin_(self_margin),
      fraction_(fraction),
      sample_(fraction > 0.0),
      hessian_(hessian),
      world_(*model_) {
  std::vector<int> all(static_cast<std::size_t>(num_inputs()));
  for (int i = 0; i < num_inputs(); ++i) all[static_cast<std::size_t>(i)] = i;
  DeclareHessianPattern(LowerTrianglePattern(all));
  // Robot box pairs: their distance has no gradient where faces are parallel (and jumps between deepest
  // vertices when they overlap), which stalls a Newton-type solver; the boxes' other shapes and the capsules still
  // repel.
  // Robot geometries come first, body by body in each body's order of shapes (CollisionWorld's numbering).
  std::vector<int> robot_boxes;
  int index = 0;
  for (int b = 0; b < model_->num_bodies(); ++b) {
    for (const multibody::Geometry& g : model_->body(b).collisions) {
      if (g.type == multibody::GeometryType::kBox) robot_boxes.push_back(index);
      ++index;
    }
  }
  for (std::size_t a = 0; a < robot_boxes.size(); ++a) {
    for (std::size_t b = a + 1; b < robot_boxes.size(); ++b) self_box_pairs_.insert({robot_boxes[a], robot_boxes[b]});
  }
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
    if (!(box.probability > 0.0 && box.probability <= 1.0)) {
      throw std::invalid_argument(name + ": environment box '" + box.name + "' has probability " +
                                  FormatShort(box.probability) + "; give a probability in (0, 1]");
    }
    const int index = world_.AddBox(box.name, box.size, box.X_WB);
    if (static_cast<int>(geometry_weight_.size()) <= index) geometry_weight_.resize(static_cast<std::size_t>(index) + 1, 1.0);
    geometry_weight_[static_cast<std::size_t>(index)] = box.probability;
  }
  geometry_weight_.resize(static_cast<std::size_t>(world_.num_geometries()), 1.0);
  for (const std::string& body : contact_bodies) contact_bodies_.insert(model_->GetBodyIndex(body));
  if (std::isinf(ground_height_)) {
    throw std::invalid_argument(name + ": ground_height is infinite; give a height in metres or NaN for no ground");
  }
  if (!std::isnan(ground_height_) || ground_terrain_ != nullptr) {
    for (int b = 1; b < model_->num_bodies(); ++b) {
      if (contact_bodies_.count(b) != 0) continue;
      for (const multibody::Geometry& g : model_->body(b).collisions) {
        switch (g.type) {
          case multibody::GeometryType::kBox:
            for (int corner = 0; corner < 8; ++corner) {
              const Eigen::Vector3d sign((corner & 1) ? 0.5 : -0.5, (corner & 2) ? 0.5 : -0.5, (corner & 4) ? 0.5 : -0.5);
              ground_points_.push_back({b, g.X_BG * Eigen::Vector3d(sign.cwiseProduct(g.size)), 0.0, g.name});
            }
            break;
          case multibody::GeometryType::kSphere:
            ground_points_.push_back({b, g.X_BG.translation(), g.radius, g.name});
            break;
          case multibody::GeometryType::kCapsule:
          case multibody::GeometryType::kCylinder:  // bounded by the capsule of its radius (conservative)
            for (const double end : {-0.5, 0.5}) {
              ground_points_.push_back({b, g.X_BG * Eigen::Vector3d(0.0, 0.0, end * g.length), g.radius, g.name});
            }
            break;
          case multibody::GeometryType::kMesh:
            break;
        }
      }
    }
  }
}

double CollisionPenalty::GroundPenalty(const multibody::Data& data, Eigen::VectorXd* gradient) const {
  double sum = 0.0;
  for (const GroundPoint& point : ground_points_) {
    const multibody::Pose& X_WB = data.X_world[static_cast<std::size_t>(point.body)];
    const Eigen::Vector3d p_W = X_WB * point.p_B;
    Eigen::Vector3d normal;
    const double h = d_safe_ - Clearance(p_W, point.radius, &normal);
    if (h <= 0.0) continue;
    sum += h * h;
    if (gradient == nullptr) continue;
    Eigen::VectorXd dd = Eigen::VectorXd::Zero(model_->nv());
    ClearanceGradient(data, point.body, p_W, normal, dd);
    *gradient -= 2.0 * h * dd;
  }
  return sum;
}

double CollisionPenalty::Clearance(const Eigen::Vector3d& p_W, double radius, Eigen::Vector3d* normal) const {
  int col = 0, row = 0;
  if (ground_terrain_ != nullptr && ground_terrain_->CellAt(p_W.x(), p_W.y(), &col, &row) &&
      ground_terrain_->has_ground(col, row)) {
    *normal = ground_terrain_->normal(col, row);
    const Eigen::Vector2d c = ground_terrain_->CellCenter(col, row);
    return normal->dot(p_W - Eigen::Vector3d(c.x(), c.y(), ground_terrain_->height(col, row))) - radius;
  }
  *normal = Eigen::Vector3d::UnitZ();
  if (std::isnan(ground_height_)) return std::numeric_limits<double>::infinity();
  return p_W.z() - radius - ground_height_;
}

void CollisionPenalty::ClearanceGradient(const multibody::Data& data, int body, const Eigen::Vector3d& p_W,
                                         const Eigen::Vector3d& normal, Eigen::Ref<Eigen::VectorXd> gradient) const {
  // Along every joint between the body and the root: the velocity of p along the normal under each motion column.
  for (int i = body; i > 0; i = model_->parent(i)) {
    const multibody::Joint& joint = model_->joint(i);
    const multibody::Pose& X = data.X_world[static_cast<std::size_t>(i)];
    for (int k = 0; k < joint.nv; ++k) {
      const multibody::Vector6d s = X.ActMotion(multibody::internal::MotionSubspaceColumn(joint, k));
      gradient(joint.idx_v + k) = normal.dot(s.tail<3>() + s.head<3>().cross(p_W));
    }
  }
}

Eigen::MatrixXd CollisionPenalty::GaussNewtonHessian(const Eigen::VectorXd& q_raw) const {
  const int nv = model_->nv();
  const Eigen::VectorXd q = chart_.Normalized(q_raw);
  multibody::Data data(*model_);
  // One row per pair or ground point within its margin: the tangent gradient of its distance.
  std::vector<Eigen::VectorXd> rows;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    Eigen::VectorXd pair_gradient(nv);
    for (const WeightedPair& p : Pairs(q, &data)) {
      world_.DistanceGradient(*model_, data, p.pair, pair_gradient);
      rows.push_back(std::sqrt(p.weight) * pair_gradient);
    }
  }
  for (const GroundPoint& point : ground_points_) {
    const Eigen::Vector3d p_W = data.X_world[static_cast<std::size_t>(point.body)] * point.p_B;
    Eigen::Vector3d normal;
    if (d_safe_ - Clearance(p_W, point.radius, &normal) <= 0.0) continue;
    Eigen::VectorXd dd = Eigen::VectorXd::Zero(nv);
    ClearanceGradient(data, point.body, p_W, normal, dd);
    rows.push_back(std::move(dd));
  }
  Eigen::MatrixXd G(static_cast<Eigen::Index>(rows.size()), nv);
  for (std::size_t r = 0; r < rows.size(); ++r) G.row(static_cast<Eigen::Index>(r)) = rows[r].transpose();
  const Eigen::MatrixXd J = chart_.TangentToCoordinates(q_raw, G);
  return 2.0 * J.transpose() * J;
}

double CollisionPenalty::GroundDistance(const multibody::Data& data, std::string* which) const {
  double best = std::numeric_limits<double>::infinity();
  for (const GroundPoint& point : ground_points_) {
    const Eigen::Vector3d p_W = data.X_world[static_cast<std::size_t>(point.body)] * point.p_B;
    Eigen::Vector3d normal;
    const double d = Clearance(p_W, point.radius, &normal);
    if (d < best) {
      best = d;
      if (which != nullptr) *which = point.name + " - ground";
    }
  }
  return best;
}

CollisionPenalty::~CollisionPenalty() = default;

void CollisionPenalty::DoEvalHessian(const Eigen::Ref<const Eigen::VectorXd>& x,
                                     const Eigen::Ref<const Eigen::VectorXd>& weights,
                                     Eigen::Ref<Eigen::VectorXd> hessian_values) const {
  if (hessian_ == CollisionHessian::kGaussNewton) {
    const int nq = model_->nq();
    const Eigen::VectorXd q_raw = sample_ ? Eigen::VectorXd((1.0 - fraction_) * x.head(nq) + fraction_ * x.tail(nq))
                                          : Eigen::VectorXd(x);
    const Eigen::MatrixXd H = weights(0) * GaussNewtonHessian(q_raw);
    const std::vector<optimization::SparsityEntry>& pattern = hessian_pattern();
    for (std::size_t k = 0; k < pattern.size(); ++k) {
      const int r = pattern[k].row, c = pattern[k].col;
      const double wr = !sample_ ? 1.0 : r < nq ? 1.0 - fraction_ : fraction_;
      const double wc = !sample_ ? 1.0 : c < nq ? 1.0 - fraction_ : fraction_;
      hessian_values(static_cast<Eigen::Index>(k)) = wr * wc * H(r % nq, c % nq);
    }
    return;
  }
  // Differences of the analytic gradient, over the columns that move a body of a pair or ground point within its
  // margin only: the other pairs are zero near x and every term depends on its bodies' poses alone, so the other
  // rows and columns of the Hessian are exactly zero (most waypoints have no active term at all, and a head near
  // a bar moves with the base and the spine, not the legs).
  const int nq = model_->nq();
  const Eigen::VectorXd q_raw = sample_ ? Eigen::VectorXd((1.0 - fraction_) * x.head(nq) + fraction_ * x.tail(nq))
                                        : Eigen::VectorXd(x);
  hessian_values.setZero();
  const std::vector<int> columns = ActiveColumns(chart_.Normalized(q_raw));
  if (columns.empty()) return;
  // f(q_a, q_b) = g((1 - s) q_a + s q_b): differentiate g once at the blended point and scale its blocks, half
  // the Jacobian evaluations of differencing over both waypoints. The gradient of f at (blended, blended) is
  // ((1 - s) grad g, s grad g), so differencing f along the first block only, with weights divided by (1 - s)^2,
  // gives Hessian(g) there.
  Eigen::VectorXd point(num_inputs());
  if (sample_) {
    point << q_raw, q_raw;
  } else {
    point = q_raw;
  }
  const double scale = sample_ ? 1.0 / ((1.0 - fraction_) * (1.0 - fraction_)) : 1.0;
  const std::vector<optimization::SparsityEntry> block = LowerTrianglePattern(columns);
  Eigen::VectorXd g_values(static_cast<Eigen::Index>(block.size()));
  HessianByDifferences(*this, point, scale * weights, block, g_values, DifferenceScheme::kCentral);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(nq, nq);
  for (std::size_t k = 0; k < block.size(); ++k) {
    H(block[k].row, block[k].col) = H(block[k].col, block[k].row) = g_values(static_cast<Eigen::Index>(k));
  }
  const std::vector<optimization::SparsityEntry>& pattern = hessian_pattern();
  for (std::size_t k = 0; k < pattern.size(); ++k) {
    const int r = pattern[k].row, c = pattern[k].col;
    const double wr = !sample_ ? 1.0 : r < nq ? 1.0 - fraction_ : fraction_;
    const double wc = !sample_ ? 1.0 : c < nq ? 1.0 - fraction_ : fraction_;
    hessian_values(static_cast<Eigen::Index>(k)) = wr * wc * H(r % nq, c % nq);
  }
}

std::vector<int> CollisionPenalty::ActiveColumns(const Eigen::VectorXd& q) const {
  multibody::Data data(*model_);
  std::set<int> bodies;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (const WeightedPair& p : Pairs(q, &data)) {
      for (const int geometry : {p.pair.geometry_a, p.pair.geometry_b}) {
        const int body = world_.geometry_body(geometry);
        if (body >= 0) bodies.insert(body);
      }
    }
  }
  for (const GroundPoint& point : ground_points_) {
    const Eigen::Vector3d p_W = data.X_world[static_cast<std::size_t>(point.body)] * point.p_B;
    Eigen::Vector3d normal;
    if (d_safe_ - Clearance(p_W, point.radius, &normal) > 0.0) bodies.insert(point.body);
  }
  std::set<int> columns;
  for (const int body : bodies) {
    for (const int c : chart_.CoordinatesMovingBody(*model_, body)) columns.insert(c);
  }
  return {columns.begin(), columns.end()};
}

Eigen::VectorXd CollisionPenalty::Configuration(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const int nq = model_->nq();
  if (!sample_) return chart_.Normalized(x);
  const Eigen::VectorXd q = (1.0 - fraction_) * x.head(nq) + fraction_ * x.tail(nq);
  return chart_.Normalized(q);
}

std::vector<CollisionPenalty::WeightedPair> CollisionPenalty::Pairs(const Eigen::VectorXd& q, multibody::Data* data,
                                                                   double scale) const {
  multibody::ForwardKinematics(*model_, *data, q);
  world_.UpdatePoses(*model_, *data);
  std::vector<WeightedPair> kept;
  for (const multibody::CollisionPair& pair : world_.PairsWithin(scale * std::max(d_safe_, self_margin_))) {
    const bool a_env = world_.geometry_body(pair.geometry_a) < 0, b_env = world_.geometry_body(pair.geometry_b) < 0;
    double margin = self_margin_;
    double weight = 1.0;
    if (a_env != b_env) {
      const int robot = world_.geometry_body(a_env ? pair.geometry_b : pair.geometry_a);
      if (contact_bodies_.count(robot) != 0) continue;
      margin = d_safe_;
      weight = geometry_weight_[static_cast<std::size_t>(a_env ? pair.geometry_a : pair.geometry_b)];
    } else if (self_margin_ <= 0.0 || self_box_pairs_.count({pair.geometry_a, pair.geometry_b}) != 0) {
      continue;
    }
    if (pair.result.distance < scale * margin) kept.push_back({pair, margin, weight});
  }
  return kept;
}

std::vector<multibody::CollisionPair> CollisionPenalty::PairsWithinMargin(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const Eigen::VectorXd q = Configuration(x);
  multibody::Data data(*model_);
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<multibody::CollisionPair> out;
  for (const WeightedPair& p : Pairs(q, &data)) out.push_back(p.pair);
  return out;
}

double CollisionPenalty::MinimumEnvironmentDistance(const Eigen::Ref<const Eigen::VectorXd>& x,
                                                    std::string* which) const {
  const Eigen::VectorXd q = Configuration(x);
  multibody::Data data(*model_);
  const std::lock_guard<std::mutex> lock(mutex_);
  double best = std::numeric_limits<double>::infinity();
  if (which != nullptr) which->clear();
  for (const WeightedPair& p : Pairs(q, &data, 10.0)) {
    const multibody::CollisionPair& pair = p.pair;
    const bool a_env = world_.geometry_body(pair.geometry_a) < 0, b_env = world_.geometry_body(pair.geometry_b) < 0;
    if (a_env == b_env || pair.result.distance >= best) continue;
    best = pair.result.distance;
    if (which != nullptr) *which = world_.geometry_name(pair.geometry_a) + " - " + world_.geometry_name(pair.geometry_b);
  }
  std::string ground;
  const double d = GroundDistance(data, &ground);
  if (d < best && d < 10.0 * d_safe_) {
    best = d;
    if (which != nullptr) *which = ground;
  }
  return best;
}

void CollisionPenalty::DoEval(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
  const Eigen::VectorXd q = Configuration(x);
  multibody::Data data(*model_);
  const std::lock_guard<std::mutex> lock(mutex_);
  double sum = 0.0;
  for (const WeightedPair& p : Pairs(q, &data)) {
    const double h = p.margin - p.pair.result.distance;
    sum += p.weight * h * h;
  }
  y(0) = sum + GroundPenalty(data, nullptr);
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
    for (const WeightedPair& p : Pairs(q, &data)) {
      const double h = p.margin - p.pair.result.distance;
      sum += p.weight * h * h;
      world_.DistanceGradient(*model_, data, p.pair, pair_gradient);
      gradient_v -= 2.0 * p.weight * h * pair_gradient;
    }
  }
  sum += GroundPenalty(data, &gradient_v);
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
