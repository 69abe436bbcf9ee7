#include <cairn/planning/footstep/stance_graph.h>

#include <algorithm>
#include <limits>
#include <queue>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include <cairn/planning/footstep/internal/yaw_box.h>
#include <cairn/planning/footstep/time_limit_reached.h>

#include "cairn/common/number_text.h"

namespace cairn::planning {
namespace {

constexpr int kPositionBits = 12;
constexpr int kYawBits = 5;
constexpr int kFootBits = 2 * kPositionBits + kYawBits;
constexpr std::uint64_t kFootMask = (std::uint64_t{1} << kFootBits) - 1;
// Friction high enough to lift any friction limit of a step cost model.
constexpr double kUnlimitedFriction = 1e3;

double WrapAngle(double a) { return std::remainder(a, 2.0 * M_PI); }

std::uint32_t PackFoot(const StanceGraph::LatticeFoot& f) {
  return static_cast<std::uint32_t>(f.ix) | (static_cast<std::uint32_t>(f.iy) << kPositionBits) |
         (static_cast<std::uint32_t>(f.itheta) << (2 * kPositionBits));
}

StanceGraph::LatticeFoot UnpackFoot(std::uint64_t bits) {
  StanceGraph::LatticeFoot f;
  f.ix = static_cast<int>(bits & ((1u << kPositionBits) - 1));
  f.iy = static_cast<int>((bits >> kPositionBits) & ((1u << kPositionBits) - 1));
  f.itheta = static_cast<int>((bits >> (2 * kPositionBits)) & ((1u << kYawBits) - 1));
  return f;
}

}  // namespace

StanceGraph::StanceGraph(const TerrainMap& terrain, const StepCostModel& cost_model, const BipedGeometry& geometry,
                         const FootstepPlannerOptions& options, const StanceGoal& goal, Clock::time_point deadline)
    : terrain_(terrain),
      cost_model_(cost_model),
      geometry_(geometry),
      options_(options),
      goal_(goal),
      deadline_(deadline) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("StanceGraph: " + what); };
  if (!(options.lattice_resolution > 0.0) || !std::isfinite(options.lattice_resolution)) {
    fail("lattice_resolution must be a positive length, got " + cairn::FormatShort(options.lattice_resolution));
  }
  if (options.orientations < 1 || options.orientations > (1 << kYawBits)) {
    fail("orientations must be in [1, 32], got " + cairn::FormatShort(options.orientations));
  }
  if (!(options.max_slope > 0.0 && options.max_slope < M_PI / 2)) {
    fail("max_slope must be in (0, pi/2) rad, got " + cairn::FormatShort(options.max_slope));
  }
  if (!(options.support_tolerance >= 0.0)) {
    fail("support_tolerance must be >= 0 m, got " + cairn::FormatShort(options.support_tolerance));
  }
  if (!(options.level_step_tolerance >= 0.0 && options.level_step_tolerance <= 1.0)) {
    fail("level_step_tolerance must be in [0, 1] m, got " + cairn::FormatShort(options.level_step_tolerance));
  }
  if (!(options.min_body_free_probability > 0.0 && options.min_body_free_probability <= 1.0)) {
    fail("min_body_free_probability must be in (0, 1], got " + cairn::FormatShort(options.min_body_free_probability));
  }
  if (!(geometry.foot_length > 0.0 && geometry.foot_width > 0.0)) {
    fail("the sole must have a positive length and width");
  }
  if (!(goal.position_tolerance >= 0.0 && goal.yaw_tolerance >= 0.0)) {
    fail("goal tolerances must be >= 0");
  }
  const Eigen::Vector2d extent = terrain.max_corner() - terrain.min_corner();
  // Counted in double first: a tiny resolution must give this message, not an overflowing cast.
  const double cols = std::floor(extent.x() / options.lattice_resolution) + 1.0;
  const double rows = std::floor(extent.y() / options.lattice_resolution) + 1.0;
  if (!(cols <= (1 << kPositionBits) && rows <= (1 << kPositionBits))) {
    std::ostringstream message;
    message << "StanceGraph: the terrain (" << extent.x() << " x " << extent.y() << " m) needs a lattice of "
            << cols << " x " << rows << " footholds at " << options.lattice_resolution
            << " m; at most 4096 per axis are supported. Crop the terrain or coarsen the lattice.";
    throw std::invalid_argument(message.str());
  }
  // Every (position, yaw) foothold is evaluated and cached once for the heuristic; bound the memory it takes.
  constexpr double kMaxFootholds = 2e7;
  if (cols * rows * options.orientations > kMaxFootholds) {
    std::ostringstream message;
    message << "StanceGraph: " << cols << " x " << rows << " lattice positions x " << options.orientations
            << " yaws are " << cols * rows * options.orientations << " footholds; at most " << kMaxFootholds
            << " are supported. Crop the terrain to the region around start and goal or coarsen the lattice.";
    throw std::invalid_argument(message.str());
  }
  lattice_cols_ = static_cast<int>(cols);
  lattice_rows_ = static_cast<int>(rows);
  min_cost_per_metre_ = cost_model.min_cost_per_metre();
  min_cost_per_step_ = cost_model.min_cost_per_step();
  const StepReach& reach = cost_model.reach();
  max_step_length_ = std::hypot(std::max(std::abs(reach.dx_min), std::abs(reach.dx_max)),
                                std::max(std::abs(reach.dy_min), std::abs(reach.dy_max)));
  if (!(min_cost_per_step_ >= 0.0) || !std::isfinite(min_cost_per_step_) || !(max_step_length_ > 0.0)) {
    fail("the step cost model needs a finite min_cost_per_step() >= 0 and a reach box of positive size");
  }
  for (int k = 0; k < 2 * options.orientations; ++k) {
    const double yaw = M_PI * k / options.orientations;
    half_bin_cos_.push_back(std::cos(yaw));
    half_bin_sin_.push_back(std::sin(yaw));
  }
  const std::size_t num_footholds = static_cast<std::size_t>(lattice_cols_) * lattice_rows_ * options.orientations;
  footholds_.assign(num_footholds, Foothold{});
  foothold_evaluated_.assign(num_footholds, 0);
  BuildStepClasses();
  ComputeChainDistances();
  if (!(min_cost_per_metre_ >= 0.0) || !std::isfinite(min_cost_per_metre_)) {
    fail("the step cost model's min_cost_per_metre() must be finite and >= 0, got " +
         cairn::FormatShort(min_cost_per_metre_));
  }
}

void StanceGraph::CheckDeadline(const char* what) const {
  if (deadline_ != Clock::time_point::max() && Clock::now() >= deadline_) {
    throw TimeLimitReached(std::string("the time limit ran out while ") + what + " (" +
                           cairn::FormatShort(lattice_cols_) + " x " + cairn::FormatShort(lattice_rows_) +
                           " lattice positions, " + cairn::FormatShort(terrain_.obstacles().size()) + " obstacles)");
  }
}

Eigen::Vector2d StanceGraph::Position(const LatticeFoot& foot) const {
  return terrain_.origin() + options_.lattice_resolution * Eigen::Vector2d(foot.ix, foot.iy);
}

double StanceGraph::Yaw(int itheta) const {
  const int d = options_.orientations;
  return 2.0 * M_PI * ((itheta + d / 2) % d - d / 2) / d;  // in [-pi, pi)
}

bool StanceGraph::Snap(const FootPose& pose, LatticeFoot* foot) const {
  const double fx = std::round((pose.x - terrain_.origin().x()) / options_.lattice_resolution);
  const double fy = std::round((pose.y - terrain_.origin().y()) / options_.lattice_resolution);
  if (!(fx >= 0 && fy >= 0 && fx < lattice_cols_ && fy < lattice_rows_)) return false;
  foot->ix = static_cast<int>(fx);
  foot->iy = static_cast<int>(fy);
  const int d = options_.orientations;
  foot->itheta = ((static_cast<int>(std::lround(pose.theta / (2.0 * M_PI) * d)) % d) + d) % d;
  return true;
}

FootPose StanceGraph::PoseOf(const LatticeFoot& foot) const {
  const Eigen::Vector2d p = Position(foot);
  FootPose pose;
  pose.x = p.x();
  pose.y = p.y();
  pose.theta = Yaw(foot.itheta);
  const std::size_t index = FootholdIndex(foot);
  pose.z = foothold_evaluated_[index] ? footholds_[index].z : 0.0;
  return pose;
}

const StanceGraph::Foothold& StanceGraph::EvaluateFoothold(const LatticeFoot& foot) {
  const std::size_t index = FootholdIndex(foot);
  Foothold& result = footholds_[index];
  if (foothold_evaluated_[index]) return result;
  foothold_evaluated_[index] = 1;
  const Eigen::Vector2d p = Position(foot);
  int col, row;
  if (!terrain_.CellAt(p.x(), p.y(), &col, &row) || !terrain_.walkable(col, row)) return result;
  const Eigen::Vector3d n = terrain_.normal(col, row);
  if (std::acos(std::min(1.0, n.z())) > options_.max_slope) return result;
  // The foothold's plane: through the centre cell's ground point, with its normal.
  const Eigen::Vector2d c = terrain_.CellCenter(col, row);
  const double hc = terrain_.height(col, row);
  auto plane = [&](const Eigen::Vector2d& q) { return hc - (n.x() * (q.x() - c.x()) + n.y() * (q.y() - c.y())) / n.z(); };
  const double yaw = Yaw(foot.itheta);
  const Eigen::Vector2d ax(std::cos(yaw), std::sin(yaw)), ay(-std::sin(yaw), std::cos(yaw));
  // 5 x 3 samples spread over the sole, just inside its edges.
  double friction = terrain_.friction(col, row);
  for (int i = -2; i <= 2; ++i) {
    for (int j = -1; j <= 1; ++j) {
      const Eigen::Vector2d q = p + (0.49 * geometry_.foot_length * i / 2.0) * ax + (0.49 * geometry_.foot_width * j) * ay;
      int qc, qr;
      if (!terrain_.CellAt(q.x(), q.y(), &qc, &qr) || !terrain_.walkable(qc, qr)) return result;
      if (std::abs(terrain_.height(qc, qr) - plane(terrain_.CellCenter(qc, qr))) > options_.support_tolerance) {
        return result;
      }
      friction = std::min(friction, terrain_.friction(qc, qr));
    }
  }
  result.supported = true;
  result.z = plane(p);
  result.friction = friction;
  result.normal = n;
  return result;
}

void StanceGraph::RefreshFootholds(int col0, int row0, int col1, int row1) {
  // A sole's samples lie within this distance of its centre; one terrain cell more covers the cell containing
  // the centre (the foothold's plane) and rounding.
  const double reach = std::hypot(0.49 * geometry_.foot_length, 0.49 * geometry_.foot_width) + terrain_.resolution();
  const Eigen::Vector2d lo = terrain_.origin() + terrain_.resolution() * Eigen::Vector2d(col0, row0) -
                             Eigen::Vector2d::Constant(reach);
  const Eigen::Vector2d hi = terrain_.origin() + terrain_.resolution() * Eigen::Vector2d(col1 + 1, row1 + 1) +
                             Eigen::Vector2d::Constant(reach);
  const double res = options_.lattice_resolution;
  const int ix0 = std::max(0, static_cast<int>(std::floor((lo.x() - terrain_.origin().x()) / res)));
  const int iy0 = std::max(0, static_cast<int>(std::floor((lo.y() - terrain_.origin().y()) / res)));
  const int ix1 = std::min(lattice_cols_ - 1, static_cast<int>(std::ceil((hi.x() - terrain_.origin().x()) / res)));
  const int iy1 = std::min(lattice_rows_ - 1, static_cast<int>(std::ceil((hi.y() - terrain_.origin().y()) / res)));
  for (int iy = iy0; iy <= iy1; ++iy) {
    for (int ix = ix0; ix <= ix1; ++ix) {
      for (int it = 0; it < options_.orientations; ++it) {
        const LatticeFoot foot{ix, iy, it};
        const std::size_t index = FootholdIndex(foot);
        if (!foothold_evaluated_[index]) continue;
        foothold_evaluated_[index] = 0;
        footholds_[index] = Foothold{};
        EvaluateFoothold(foot);
      }
    }
  }
}

StanceGraph::Key StanceGraph::MakeKey(const LatticeFoot& older, const LatticeFoot& newer, FootSide newer_side) const {
  return static_cast<Key>(PackFoot(older)) | (static_cast<Key>(PackFoot(newer)) << kFootBits) |
         (static_cast<Key>(newer_side == FootSide::kRight) << (2 * kFootBits));
}

void StanceGraph::Decode(Key key, LatticeFoot* older, LatticeFoot* newer, FootSide* newer_side) const {
  *older = UnpackFoot(key & kFootMask);
  *newer = UnpackFoot((key >> kFootBits) & kFootMask);
  *newer_side = ((key >> (2 * kFootBits)) & 1) ? FootSide::kRight : FootSide::kLeft;
}

double StanceGraph::Heuristic(Key key) const {
  LatticeFoot older, newer;
  FootSide side;
  Decode(key, &older, &newer, &side);
  if (IsGoal(key)) return 0.0;
  // Unless both feet are done, the older foot moves next (feet alternate), so every foot still to be placed
  // lies on the chain from the newer foot, and the chain must reach both goal footholds.
  const double chain = std::max(ChainDistance(newer, 0), ChainDistance(newer, 1));
  const double stride = stride_distance_[side == FootSide::kLeft ? 0 : 1]
                                        [static_cast<std::size_t>(newer.iy) * lattice_cols_ + newer.ix];
  return std::max({chain, stride, FootholdChainDistance(newer, side)});
}

double StanceGraph::FootholdChainDistance(const LatticeFoot& foot, FootSide side) const {
  if (foothold_distance_.empty()) return 0.0;
  // The margin covers rounding: the search sums the same step costs in another order, and its displacements
  // come from absolute lattice positions rather than offsets.
  constexpr double kRoundingMargin = 1.0 - 1e-9;
  return kRoundingMargin * foothold_distance_[FootholdIndex(foot) * 2 + (side == FootSide::kLeft ? 0 : 1)];
}

bool StanceGraph::IsGoal(Key key) const {
  LatticeFoot older, newer;
  FootSide side;
  Decode(key, &older, &newer, &side);
  const LatticeFoot& left = side == FootSide::kLeft ? newer : older;
  const LatticeFoot& right = side == FootSide::kLeft ? older : newer;
  auto near = [&](const LatticeFoot& f, const FootPose& g) {
    const Eigen::Vector2d p = Position(f);
    return std::hypot(p.x() - g.x, p.y() - g.y) <= goal_.position_tolerance &&
           std::abs(WrapAngle(Yaw(f.itheta) - g.theta)) <= goal_.yaw_tolerance;
  };
  return near(left, goal_.stance.left) && near(right, goal_.stance.right);
}

bool StanceGraph::BodyBlocked(const Eigen::Vector3d& center, double yaw) const {
  if (terrain_.BoxHitsObstacle(center, geometry_.body_half_extents, yaw)) return true;
  return !terrain_.occupied_voxels().empty() &&
         terrain_.BoxFreeProbability(center, geometry_.body_half_extents, yaw, options_.min_body_free_probability) <
             options_.min_body_free_probability;
}

bool StanceGraph::EvaluateStep(const LatticeFoot& older, const LatticeFoot& newer, FootSide newer_side,
                               const LatticeFoot& target, PlannedStep* step, bool count_rejections) {
  const FootSide moving = OtherSide(newer_side);
  const double sigma = moving == FootSide::kLeft ? 1.0 : -1.0;
  const Eigen::Vector2d pn = Position(newer), pt = Position(target);
  const double cn = half_bin_cos_[2 * newer.itheta], sn = half_bin_sin_[2 * newer.itheta];
  const int bins = BinDelta(newer.itheta, target.itheta);
  const double yaw_step = 2.0 * M_PI / options_.orientations;
  const Eigen::Vector2d delta = pt - pn;
  StepDisplacement d;
  d.dx = cn * delta.x() + sn * delta.y();
  d.dy = sigma * (-sn * delta.x() + cn * delta.y());
  d.dtheta = sigma * bins * yaw_step;
  const StepReach& reach = cost_model_.reach();
  if (d.dx < reach.dx_min || d.dx > reach.dx_max || d.dy < reach.dy_min || d.dy > reach.dy_max ||
      d.dtheta < reach.dtheta_min - 1e-9 || d.dtheta > reach.dtheta_max + 1e-9) {
    return false;
  }
  // The lateral spacing must also hold across the stance's mean heading (the pelvis'): measured only in the stance
  // foot's frame, splayed feet (one turned out, the other in) would stand closer than the legs allow.
  if (bins != 0) {
    const int half_bins = 2 * options_.orientations;
    const int mid = ((2 * newer.itheta + bins) % half_bins + half_bins) % half_bins;
    if (sigma * (-half_bin_sin_[mid] * delta.x() + half_bin_cos_[mid] * delta.y()) < reach.dy_min) return false;
  }
  const Foothold& ft = EvaluateFoothold(target);
  if (!ft.supported) {
    if (count_rejections) ++rejections_.rejected_support;
    return false;
  }
  const Foothold& fn = EvaluateFoothold(newer);
  const Foothold& fo = EvaluateFoothold(older);
  d.dz = StepHeight(fn.z, ft.z);
  if (d.dz < reach.dz_min || d.dz > reach.dz_max) return false;
  const Eigen::Vector3d sole(0.5 * geometry_.foot_length, 0.5 * geometry_.foot_width, 1.0);
  if (delta.squaredNorm() < sole.head<2>().squaredNorm() * 4.0 &&
      internal::YawBoxesOverlap(Eigen::Vector3d(pt.x(), pt.y(), 0.0), sole, Yaw(target.itheta),
                                Eigen::Vector3d(pn.x(), pn.y(), 0.0), sole, Yaw(newer.itheta))) {
    if (count_rejections) ++rejections_.rejected_collision;
    return false;
  }
  if (HasBodyChecks()) {
    const Eigen::Vector2d mid = 0.5 * (pn + pt);
    const double body_z = std::max(ft.z, fn.z) + geometry_.body_bottom + geometry_.body_half_extents.z();
    if (BodyBlocked(Eigen::Vector3d(mid.x(), mid.y(), body_z), Yaw(newer.itheta) + 0.5 * bins * yaw_step)) {
      if (count_rejections) ++rejections_.rejected_collision;
      return false;
    }
  }
  const double mu = ignore_friction_ ? kUnlimitedFriction : std::min({fo.friction, fn.friction, ft.friction});
  TransitionCost cost = cost_model_.Evaluate(d, mu);
  if (!cost.feasible) {
    if (count_rejections && cost_model_.Evaluate(d, kUnlimitedFriction).feasible) ++rejections_.rejected_friction;
    return false;
  }
  step->side = moving;
  step->pose = PoseOf(target);
  step->displacement = d;
  step->mu_allowed = mu;
  step->transition = cost;
  return true;
}

void StanceGraph::GenerateSuccessors(Key key, std::vector<std::pair<Key, double>>* out) {
  LatticeFoot older, newer;
  FootSide newer_side;
  Decode(key, &older, &newer, &newer_side);
  const FootSide moving = OtherSide(newer_side);
  const double sigma = moving == FootSide::kLeft ? 1.0 : -1.0;
  const StepReach& reach = cost_model_.reach();
  const Eigen::Vector2d pn = Position(newer);
  const double cn = half_bin_cos_[2 * newer.itheta], sn = half_bin_sin_[2 * newer.itheta];
  const Eigen::Vector2d ax(cn, sn), ay(-sn, cn);
  // Lattice positions in the bounding box of the reach rectangle.
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e30), hi = Eigen::Vector2d::Constant(-1e30);
  for (double dx : {reach.dx_min, reach.dx_max}) {
    for (double dy : {reach.dy_min, reach.dy_max}) {
      const Eigen::Vector2d corner = pn + dx * ax + sigma * dy * ay;
      lo = lo.cwiseMin(corner);
      hi = hi.cwiseMax(corner);
    }
  }
  const double res = options_.lattice_resolution;
  const int ix0 = std::max(0, static_cast<int>(std::ceil((lo.x() - terrain_.origin().x()) / res - 1e-9)));
  const int ix1 = std::min(lattice_cols_ - 1, static_cast<int>(std::floor((hi.x() - terrain_.origin().x()) / res + 1e-9)));
  const int iy0 = std::max(0, static_cast<int>(std::ceil((lo.y() - terrain_.origin().y()) / res - 1e-9)));
  const int iy1 = std::min(lattice_rows_ - 1, static_cast<int>(std::floor((hi.y() - terrain_.origin().y()) / res + 1e-9)));
  const int d = options_.orientations;
  const double yaw_step = 2.0 * M_PI / d;
  const int k0 = static_cast<int>(std::ceil(reach.dtheta_min / yaw_step - 1e-9));
  const int k1 = static_cast<int>(std::floor(reach.dtheta_max / yaw_step + 1e-9));
  PlannedStep step;
  for (int iy = iy0; iy <= iy1; ++iy) {
    for (int ix = ix0; ix <= ix1; ++ix) {
      LatticeFoot target{ix, iy, 0};
      const Eigen::Vector2d delta = Position(target) - pn;
      const double dx = delta.dot(ax), dy = sigma * delta.dot(ay);
      if (dx < reach.dx_min || dx > reach.dx_max || dy < reach.dy_min || dy > reach.dy_max) continue;
      if (!std::isfinite(ChainDistance(target, 0)) || !std::isfinite(ChainDistance(target, 1))) continue;
      for (int k = k0; k <= k1; ++k) {
        target.itheta = (((newer.itheta + static_cast<int>(sigma) * k) % d) + d) % d;
        if (EvaluateStep(older, newer, newer_side, target, &step, true)) {
          out->emplace_back(MakeKey(newer, target, moving), step.transition.cost);
        }
      }
    }
  }
}

void StanceGraph::ComputeChainDistances() {
  const std::size_t n = static_cast<std::size_t>(lattice_cols_) * lattice_rows_;
  // Positions where a sole fits in at least one orientation, with the most friction any such sole finds.
  std::vector<char> usable(n, 0);
  std::vector<double> ground(n, 0.0);  // a foothold's height does not depend on its yaw
  std::vector<float> friction(n, 0.0f);
  for (int iy = 0; iy < lattice_rows_; ++iy) {
    CheckDeadline("evaluating the footholds of the heuristic");
    for (int ix = 0; ix < lattice_cols_; ++ix) {
      const std::size_t i = static_cast<std::size_t>(iy) * lattice_cols_ + ix;
      for (int it = 0; it < options_.orientations; ++it) {
        const Foothold& foothold = EvaluateFoothold(LatticeFoot{ix, iy, it});
        if (!foothold.supported) continue;
        usable[i] = 1;
        ground[i] = foothold.z;
        friction[i] = std::max(friction[i], static_cast<float>(foothold.friction));
      }
    }
  }
  // Two consecutive footholds form a stance whose body box contains the disc of radius min(half x, half y)
  // around the point above their midpoint, whatever its yaw: if an obstacle reaches into that disc at every
  // height the body can have there, no real step exists.
  const double body_height = 2.0 * geometry_.body_half_extents.z();
  const double body_radius = std::min(geometry_.body_half_extents.x(), geometry_.body_half_extents.y());
  auto midpoint_blocked = [&](const Eigen::Vector2d& m, double feet_top) {
    const double bottom = feet_top + geometry_.body_bottom;
    for (const TerrainMap::Obstacle& o : terrain_.obstacles()) {
      if (!(o.center.z() - o.half_extents.z() < bottom + body_height && o.center.z() + o.half_extents.z() > bottom)) {
        continue;
      }
      const Eigen::Vector2d d = m - o.center.head<2>();
      const double c = std::cos(o.yaw), s = std::sin(o.yaw);
      const double gx = std::max(0.0, std::abs(c * d.x() + s * d.y()) - o.half_extents.x());
      const double gy = std::max(0.0, std::abs(-s * d.x() + c * d.y()) - o.half_extents.y());
      if (gx * gx + gy * gy < body_radius * body_radius) return true;
    }
    // A voxel that alone makes the body's free probability too small blocks as surely as a box.
    return terrain_.DiscMeetsVoxel(m, body_radius, bottom, bottom + body_height, options_.min_body_free_probability);
  };
  // Where the exact foothold-chain bound exists, the stride bound (a valid but looser bound on the same strides)
  // is not worth its Dijkstra with links of two steps' length; 0 is a valid bound in its place.
  if (static_cast<double>(footholds_.size()) > kMaxExactFootholds) {
    ComputeStrideDistances(usable, friction);
  } else {
    for (std::vector<double>& distance : stride_distance_) distance.assign(usable.size(), 0.0);
  }
  const bool has_obstacles = HasBodyChecks();
  // A real step between footholds at p and q uses at most the friction both offer, and its cost is at least the
  // model's bound there (friction values are few: one per region, so the bounds are memoised).
  std::unordered_map<float, StepCostLowerBound> bounds;
  auto bound_at = [&](float mu) -> const StepCostLowerBound& {
    auto it = bounds.find(mu);
    if (it == bounds.end()) it = bounds.emplace(mu, cost_model_.cost_lower_bound(ignore_friction_ ? kUnlimitedFriction : mu)).first;
    return it->second;
  };
  RelaxedDistances(usable, max_step_length_,
                   [&](std::size_t i, std::size_t j, const Eigen::Vector2d& pi, const Eigen::Vector2d& pj, double length) {
                     const StepCostLowerBound& b = bound_at(std::min(friction[i], friction[j]));
                     if (!b.any_feasible) return std::numeric_limits<double>::infinity();
                     if (has_obstacles && midpoint_blocked(0.5 * (pi + pj), std::max(ground[i], ground[j]))) {
                       return std::numeric_limits<double>::infinity();
                     }
                     return b.per_step + b.per_metre * length;
                   },
                   chain_distance_);
  ComputeFootholdChainDistances();
}

void StanceGraph::BuildStepClasses() {
  // Tolerances make the classes a superset of the steps the search takes: its displacements come from absolute
  // positions and differ from these by rounding, and a bound must not miss a step.
  constexpr double kTolerance = 1e-9;
  const StepReach& reach = cost_model_.reach();
  const int d = options_.orientations;
  const double res = options_.lattice_resolution;
  const double yaw_step = 2.0 * M_PI / d;
  const int k0 = static_cast<int>(std::ceil(reach.dtheta_min / yaw_step - 1e-9));
  const int k1 = static_cast<int>(std::floor(reach.dtheta_max / yaw_step + 1e-9));
  const int radius = static_cast<int>(std::ceil(max_step_length_ / res)) + 1;
  const Eigen::Vector3d sole(0.5 * geometry_.foot_length - kTolerance, 0.5 * geometry_.foot_width - kTolerance, 1.0);
  forward_classes_.assign(2 * d, {});
  incoming_.assign(2 * d, {});
  class_offset_.assign(2 * d + 1, 0);
  for (int itheta = 0; itheta < d; ++itheta) {
    const double cn = half_bin_cos_[2 * itheta], sn = half_bin_sin_[2 * itheta];
    for (int moving = 0; moving < 2; ++moving) {
      const int sigma = moving == 0 ? 1 : -1;
      std::vector<StepClass>& classes = forward_classes_[2 * itheta + moving];
      for (int diy = -radius; diy <= radius; ++diy) {
        for (int dix = -radius; dix <= radius; ++dix) {
          const Eigen::Vector2d delta = res * Eigen::Vector2d(dix, diy);
          const double dx = cn * delta.x() + sn * delta.y();
          const double dy = sigma * (-sn * delta.x() + cn * delta.y());
          if (dx < reach.dx_min - kTolerance || dx > reach.dx_max + kTolerance || dy < reach.dy_min - kTolerance ||
              dy > reach.dy_max + kTolerance) {
            continue;
          }
          for (int k = k0; k <= k1; ++k) {
            const int target_itheta = ((itheta + sigma * k) % d + d) % d;
            const int bins = BinDelta(itheta, target_itheta);
            if (bins != 0) {
              const int half_bins = 2 * d;
              const int mid = ((2 * itheta + bins) % half_bins + half_bins) % half_bins;
              if (sigma * (-half_bin_sin_[mid] * delta.x() + half_bin_cos_[mid] * delta.y()) <
                  reach.dy_min - kTolerance) {
                continue;
              }
            }
            if (delta.squaredNorm() < sole.head<2>().squaredNorm() * 4.0 &&
                internal::YawBoxesOverlap(Eigen::Vector3d(delta.x(), delta.y(), 0.0), sole, Yaw(target_itheta),
                                          Eigen::Vector3d::Zero(), sole, Yaw(itheta))) {
              continue;
            }
            StepClass step;
            step.dix = dix;
            step.diy = diy;
            step.k = k;
            step.d.dx = dx;
            step.d.dy = dy;
            step.d.dtheta = sigma * bins * yaw_step;
            incoming_[2 * target_itheta + moving].push_back(
                IncomingStep{itheta, static_cast<int>(classes.size())});
            classes.push_back(step);
          }
        }
      }
    }
  }
  for (int i = 0; i < 2 * d; ++i) class_offset_[i + 1] = class_offset_[i] + forward_classes_[i].size();
}

double StanceGraph::RelaxedStepCost(const LatticeFoot& from, int moving, int class_index, const StepClass& step) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kTolerance = 1e-9;
  const int d = options_.orientations;
  const int sigma = moving == 0 ? 1 : -1;
  const LatticeFoot target{from.ix + step.dix, from.iy + step.diy, ((from.itheta + sigma * step.k) % d + d) % d};
  if (target.ix < 0 || target.iy < 0 || target.ix >= lattice_cols_ || target.iy >= lattice_rows_) return kInf;
  const Foothold& ft = EvaluateFoothold(target);
  if (!ft.supported) return kInf;
  const Foothold& fn = EvaluateFoothold(from);
  const StepReach& reach = cost_model_.reach();
  const double dz = StepHeight(fn.z, ft.z);
  if (dz < reach.dz_min - kTolerance || dz > reach.dz_max + kTolerance) return kInf;
  if (HasBodyChecks()) {
    // As the search checks it, from the same absolute positions.
    const Eigen::Vector2d pn = Position(from), pt = Position(target);
    const Eigen::Vector2d mid = 0.5 * (pn + pt);
    const double body_z = std::max(ft.z, fn.z) + geometry_.body_bottom + geometry_.body_half_extents.z();
    if (BodyBlocked(Eigen::Vector3d(mid.x(), mid.y(), body_z),
                    Yaw(from.itheta) + 0.5 * BinDelta(from.itheta, target.itheta) * (2.0 * M_PI / d))) {
      return kInf;
    }
  }
  const double mu = ignore_friction_ ? kUnlimitedFriction : std::min(fn.friction, ft.friction);
  StepDisplacement displacement = step.d;
  displacement.dz = dz;
  // The cost of this step for a height in [dz_lo, dz_hi] (a lower bound over the range when it is one).
  auto evaluate = [&](double dz_lo, double dz_hi) {
    auto at = [&](const StepDisplacement& s) {
      if (dz_lo == dz_hi) {
        const TransitionCost cost = cost_model_.Evaluate(s, mu);
        return cost.feasible ? cost.cost : kInf;
      }
      return cost_model_.MinCostOverHeights(s, dz_lo, dz_hi, mu);
    };
    const double cost = at(displacement);
    if (cost < kInf) return cost;
    // The search's displacement of this step differs from ours by rounding; where the model's feasibility
    // changes within that distance (an interpolating model next to an infeasible entry), the step may exist
    // for the search, so try displacements just beside ours too.
    constexpr double kNudge = 1e-12;
    double best = kInf;
    for (int a = -1; a <= 1; ++a) {
      for (int b = -1; b <= 1; ++b) {
        if (a == 0 && b == 0) continue;
        StepDisplacement nudged = displacement;
        nudged.dx += a * kNudge;
        nudged.dy += b * kNudge;
        best = std::min(best, at(nudged));
      }
    }
    return best;
  };
  // Steps repeat all over the lattice: memoise their cost per friction value (the values are few, one per
  // region; beyond kMaxMemoFrictions of them, evaluate every time). Level steps are memoised exactly; the
  // heights of other steps differ by the rounding of the terrain's heights, so they are priced once per
  // kHeightBucket of height by the model's lower bound over it.
  constexpr std::size_t kMaxMemoFrictions = 16;
  constexpr double kHeightBucket = 1e-4;  // m: costs about 0.06 J per step of tightness on this robot
  std::size_t slot = 0;
  while (slot < memo_friction_.size() && memo_friction_[slot] != mu) ++slot;
  if (slot == memo_friction_.size()) {
    if (memo_friction_.size() >= kMaxMemoFrictions) return evaluate(dz, dz);
    memo_friction_.push_back(mu);
    memo_cost_.emplace_back(class_offset_.back(), std::numeric_limits<double>::quiet_NaN());
    memo_last_height_.emplace_back(class_offset_.back(), std::make_pair(std::numeric_limits<double>::quiet_NaN(), 0.0));
  }
  const std::size_t global_class = class_offset_[2 * from.itheta + moving] + class_index;
  if (dz != 0.0) {
    const double bucket = std::floor(dz / kHeightBucket);
    const std::uint64_t key = (static_cast<std::uint64_t>(global_class) * kMaxMemoFrictions + slot) * 65536 +
                              static_cast<std::uint64_t>(static_cast<std::int64_t>(bucket) + 32768);
    // On a plane a class's height is nearly the same everywhere: remember its last bucket before hashing.
    std::pair<double, double>& last = memo_last_height_[slot][global_class];
    if (last.first == bucket) return last.second;
    const auto [it, inserted] = memo_height_cost_.try_emplace(key, 0.0);
    if (inserted) it->second = evaluate(bucket * kHeightBucket, (bucket + 1.0) * kHeightBucket);
    last = {bucket, it->second};
    return it->second;
  }
  double& memo = memo_cost_[slot][global_class];
  if (std::isnan(memo)) memo = evaluate(0.0, 0.0);
  return memo;
}

void StanceGraph::ComputeFootholdChainDistances() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int d = options_.orientations;
  const std::size_t num_footholds = footholds_.size();
  memo_friction_.clear();
  memo_cost_.clear();
  memo_height_cost_.clear();
  memo_last_height_.clear();
  if (static_cast<double>(num_footholds) > kMaxExactFootholds) {
    foothold_distance_.clear();
    return;
  }
  std::vector<double>& dist = foothold_distance_;
  dist.assign(2 * num_footholds, kInf);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  auto near_goal = [&](const LatticeFoot& f, int side) {
    const FootPose& g = side == 0 ? goal_.stance.left : goal_.stance.right;
    const Eigen::Vector2d p = Position(f);
    return std::hypot(p.x() - g.x, p.y() - g.y) <= goal_.position_tolerance &&
           std::abs(WrapAngle(Yaw(f.itheta) - g.theta)) <= goal_.yaw_tolerance;
  };
  // Seeds: a newer foot at its goal foothold whose next step puts the other foot on its own ends the plan.
  for (int iy = 0; iy < lattice_rows_; ++iy) {
    CheckDeadline("finding the goal footholds of the heuristic");
    for (int ix = 0; ix < lattice_cols_; ++ix) {
      for (int it = 0; it < d; ++it) {
        const LatticeFoot f{ix, iy, it};
        if (!EvaluateFoothold(f).supported) continue;
        for (int side = 0; side < 2; ++side) {
          if (!near_goal(f, side)) continue;
          const int moving = 1 - side;
          const std::vector<StepClass>& classes = forward_classes_[2 * it + moving];
          double best = kInf;
          for (std::size_t c = 0; c < classes.size(); ++c) {
            const StepClass& step = classes[c];
            const int sigma = moving == 0 ? 1 : -1;
            const LatticeFoot t{ix + step.dix, iy + step.diy, ((it + sigma * step.k) % d + d) % d};
            if (t.ix < 0 || t.iy < 0 || t.ix >= lattice_cols_ || t.iy >= lattice_rows_ || !near_goal(t, moving)) {
              continue;
            }
            best = std::min(best, RelaxedStepCost(f, moving, static_cast<int>(c), step));
          }
          const std::size_t i = FootholdIndex(f) * 2 + side;
          if (best < dist[i]) {
            dist[i] = best;
            queue.emplace(best, i);
          }
        }
      }
    }
  }
  // Compact copies of what the relaxation reads of every foothold (all are evaluated by now).
  std::vector<double> height(num_footholds), friction(num_footholds);
  std::vector<char> supported(num_footholds);
  for (std::size_t f = 0; f < num_footholds; ++f) {
    const Foothold& foothold = footholds_[f];
    supported[f] = foothold.supported && foothold_evaluated_[f];
    height[f] = foothold.z;
    friction[f] = ignore_friction_ ? kUnlimitedFriction : foothold.friction;
  }
  const bool has_obstacles = !terrain_.obstacles().empty();
  const StepReach& reach = cost_model_.reach();
  constexpr double kTolerance = 1e-9;
  std::size_t pops = 0;
  while (!queue.empty()) {
    const auto [value, i] = queue.top();
    queue.pop();
    if (value > dist[i]) continue;
    if ((++pops & 1023) == 0) CheckDeadline("computing the heuristic's foothold chains to the goal");
    // Node i is a foothold t (the newer foot, of side i % 2); its predecessors are the footholds f of the other
    // side from which a step moves this side's foot onto t.
    const int moving = static_cast<int>(i % 2);
    const std::size_t t = i / 2;
    const int it = static_cast<int>(t % d);
    const std::size_t cell = t / d;
    const int tx = static_cast<int>(cell % lattice_cols_), ty = static_cast<int>(cell / lattice_cols_);
    for (const IncomingStep& in : incoming_[2 * it + moving]) {
      const StepClass& step = forward_classes_[2 * in.stance_itheta + moving][in.index];
      const int fx = tx - step.dix, fy = ty - step.diy;
      if (fx < 0 || fy < 0 || fx >= lattice_cols_ || fy >= lattice_rows_) continue;
      const std::size_t f = (static_cast<std::size_t>(fy) * lattice_cols_ + fx) * d + in.stance_itheta;
      const std::size_t j = f * 2 + (1 - moving);
      if (dist[j] <= value || !supported[f]) continue;
      double cost;
      const double dz = StepHeight(height[f], height[t]);
      if (dz == 0.0 && !has_obstacles) {
        // The common case, inlined: a level step whose cost is memoised for this friction.
        const double mu = std::min(friction[f], friction[t]);
        std::size_t slot = 0;
        while (slot < memo_friction_.size() && memo_friction_[slot] != mu) ++slot;
        const double memo = slot < memo_friction_.size()
                                ? memo_cost_[slot][class_offset_[2 * in.stance_itheta + moving] + in.index]
                                : std::numeric_limits<double>::quiet_NaN();
        cost = std::isnan(memo) ? RelaxedStepCost(LatticeFoot{fx, fy, in.stance_itheta}, moving, in.index, step) : memo;
      } else if (dz < reach.dz_min - kTolerance || dz > reach.dz_max + kTolerance) {
        continue;
      } else {
        cost = RelaxedStepCost(LatticeFoot{fx, fy, in.stance_itheta}, moving, in.index, step);
      }
      const double candidate = value + cost;
      if (candidate < dist[j]) {
        dist[j] = candidate;
        queue.emplace(candidate, j);
      }
    }
  }
}

template <class LinkCost>
void StanceGraph::RelaxedDistances(const std::vector<char>& usable, double max_link, LinkCost&& link_cost,
                                   std::vector<double> distances[2]) const {
  const std::size_t n = usable.size();
  const double res = options_.lattice_resolution;
  const int radius = static_cast<int>(std::floor(max_link / res + 1e-9));
  std::vector<std::pair<int, int>> offsets;
  std::vector<double> lengths;
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const double length = res * std::hypot(dx, dy);
      if ((dx != 0 || dy != 0) && length <= max_link + 1e-9) {
        offsets.emplace_back(dx, dy);
        lengths.push_back(length);
      }
    }
  }
  const FootPose* goals[2] = {&goal_.stance.left, &goal_.stance.right};
  for (int side = 0; side < 2; ++side) {
    std::vector<double>& dist = distances[side];
    dist.assign(n, std::numeric_limits<double>::infinity());
    using Item = std::pair<double, std::size_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (int iy = 0; iy < lattice_rows_; ++iy) {
      for (int ix = 0; ix < lattice_cols_; ++ix) {
        const std::size_t i = static_cast<std::size_t>(iy) * lattice_cols_ + ix;
        const Eigen::Vector2d p = Position(LatticeFoot{ix, iy, 0});
        if (usable[i] && std::hypot(p.x() - goals[side]->x, p.y() - goals[side]->y) <= goal_.position_tolerance) {
          dist[i] = 0.0;
          queue.emplace(0.0, i);
        }
      }
    }
    std::size_t pops = 0;
    while (!queue.empty()) {
      const auto [d, i] = queue.top();
      queue.pop();
      if (d > dist[i]) continue;
      if ((++pops & 255) == 0) CheckDeadline("computing the heuristic's distances to the goal");
      const int ix = static_cast<int>(i % lattice_cols_), iy = static_cast<int>(i / lattice_cols_);
      const Eigen::Vector2d pi = Position(LatticeFoot{ix, iy, 0});
      for (std::size_t k = 0; k < offsets.size(); ++k) {
        const int jx = ix + offsets[k].first, jy = iy + offsets[k].second;
        if (jx < 0 || jy < 0 || jx >= lattice_cols_ || jy >= lattice_rows_) continue;
        const std::size_t j = static_cast<std::size_t>(jy) * lattice_cols_ + jx;
        if (!usable[j] || d >= dist[j]) continue;
        const double candidate = d + link_cost(i, j, pi, Position(LatticeFoot{jx, jy, 0}), lengths[k]);
        if (candidate < dist[j]) {
          dist[j] = candidate;
          queue.emplace(candidate, j);
        }
      }
    }
  }
}

void StanceGraph::ComputeStrideDistances(const std::vector<char>& usable, const std::vector<float>& friction) {
  const std::size_t n = usable.size();
  // A stride of this foot from p to q is two steps: the other foot lands beside p, then this foot lands at q
  // beside it. Both steps have p among their feet, so both use at most the friction at p (its best orientation);
  // the search runs from the goal backwards, so the link j -> i of the relaxation is the stride from p = j.
  std::unordered_map<float, StrideCostLowerBound> bounds;
  double longest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable[i] || bounds.count(friction[i])) continue;
    StrideCostLowerBound b = cost_model_.stride_cost_lower_bound(ignore_friction_ ? kUnlimitedFriction : friction[i]);
    if (b.any_feasible && !b.stride.empty()) longest = std::max(longest, b.stride.back());
    bounds.emplace(friction[i], std::move(b));
  }
  // Link costs per friction value and link length, computed on first use.
  std::unordered_map<float, StrideCostLowerBound>::const_iterator last = bounds.end();
  RelaxedDistances(usable, longest,
                   [&](std::size_t /*i*/, std::size_t j, const Eigen::Vector2d&, const Eigen::Vector2d&, double length) {
                     const float mu = friction[j];
                     if (last == bounds.end() || last->first != mu) last = bounds.find(mu);
                     return last->second(length);
                   },
                   stride_distance_);
}

double StanceGraph::ChainDistanceToGoal(const LatticeFoot& foot, FootSide side) {
  return ChainDistance(foot, side == FootSide::kLeft ? 0 : 1);
}

PlannedStep StanceGraph::Transition(Key from, Key to) {
  LatticeFoot older, newer, to_older, to_newer;
  FootSide newer_side, to_side;
  Decode(from, &older, &newer, &newer_side);
  Decode(to, &to_older, &to_newer, &to_side);
  PlannedStep step;
  if (!EvaluateStep(older, newer, newer_side, to_newer, &step, false)) {
    throw std::logic_error("StanceGraph::Transition: the two stances are not connected");
  }
  return step;
}

}  // namespace cairn::planning
