#include <cairn/planning/walk/periodic_gait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/planning/locomotion/step_evaluator.h>

namespace cairn::planning {
namespace {

// Where `side` lands when it steps by `d` from `support` (StepDisplacement's mirrored convention).
FootPose Place(const FootPose& support, FootSide side, const StepDisplacement& d) {
  const double sigma = side == FootSide::kLeft ? 1.0 : -1.0;
  const double c = std::cos(support.theta), s = std::sin(support.theta);
  FootPose pose;
  pose.x = support.x + c * d.dx - s * sigma * d.dy;
  pose.y = support.y + s * d.dx + c * sigma * d.dy;
  pose.z = support.z + d.dz;
  pose.theta = support.theta + sigma * d.dtheta;
  return pose;
}

// `range` names what the model's interval is ("reach", "parameter bounds").
void CheckWithin(const char* name, double value, double lo, double hi, const char* unit, const char* range) {
  if (!(value >= lo && value <= hi)) {
    throw std::invalid_argument(std::string("PeriodicGaitPlan: ") + name + " " + FormatShort(value) + unit +
                                " is outside the walking model's " + range + " [" + FormatShort(lo) + ", " +
                                FormatShort(hi) + "]" + unit);
  }
}

// A foothold's tread: the corners of its rectangle in the plane.
std::array<Eigen::Vector2d, 4> Corners(const FootPose& foot, double half_length, double half_width) {
  const Eigen::Rotation2Dd r(foot.theta);
  const Eigen::Vector2d c(foot.x, foot.y);
  return {c + r * Eigen::Vector2d(half_length, half_width), c + r * Eigen::Vector2d(-half_length, half_width),
          c + r * Eigen::Vector2d(-half_length, -half_width), c + r * Eigen::Vector2d(half_length, -half_width)};
}

// Separating axes: two convex rectangles overlap unless an edge normal of one separates them (touching counts as
// apart, so treads that only share an edge are a valid staircase).
bool Overlap(const std::array<Eigen::Vector2d, 4>& a, const std::array<Eigen::Vector2d, 4>& b) {
  for (const auto* shape : {&a, &b}) {
    for (int i = 0; i < 2; ++i) {
      const Eigen::Vector2d edge = (*shape)[static_cast<std::size_t>(i + 1)] - (*shape)[static_cast<std::size_t>(i)];
      const Eigen::Vector2d axis(-edge.y(), edge.x());
      double a_lo = std::numeric_limits<double>::infinity(), a_hi = -a_lo, b_lo = a_lo, b_hi = -a_lo;
      for (const Eigen::Vector2d& p : a) a_lo = std::min(a_lo, axis.dot(p)), a_hi = std::max(a_hi, axis.dot(p));
      for (const Eigen::Vector2d& p : b) b_lo = std::min(b_lo, axis.dot(p)), b_hi = std::max(b_hi, axis.dot(p));
      const double tolerance = 1e-9 * axis.norm();
      if (a_hi <= b_lo + tolerance || b_hi <= a_lo + tolerance) return false;
    }
  }
  return true;
}

}  // namespace

FootstepPlan PeriodicGaitPlan(const PeriodicGait& gait, const WalkingModel& model, WalkingObjective objective,
                              double mu_allowed) {
  if (gait.num_steps < 1 || gait.num_steps > kMaxPeriodicGaitSteps) {
    throw std::invalid_argument("PeriodicGaitPlan: num_steps " + FormatShort(gait.num_steps) + " must be in [1, " +
                                FormatShort(kMaxPeriodicGaitSteps) + "]");
  }
  if (!(std::isfinite(mu_allowed) && mu_allowed > 0.0 && mu_allowed <= 10.0)) {
    throw std::invalid_argument("PeriodicGaitPlan: mu_allowed " + FormatShort(mu_allowed) + " must be in (0, 10]");
  }
  const StepDisplacement& d = gait.displacement;
  const StepReach& reach = model.reach();
  CheckWithin("dx", d.dx, reach.dx_min, reach.dx_max, " m", "reach");
  CheckWithin("dy", d.dy, reach.dy_min, reach.dy_max, " m", "reach");
  CheckWithin("dz", d.dz, reach.dz_min, reach.dz_max, " m", "reach");
  CheckWithin("dtheta", d.dtheta, reach.dtheta_min, reach.dtheta_max, " rad", "reach");
  const StepParameters& p = gait.parameters;
  CheckWithin("t_ds", p.t_ds, model.parameter_lower().t_ds, model.parameter_upper().t_ds, " s", "parameter bounds");
  CheckWithin("t_sw", p.t_sw, model.parameter_lower().t_sw, model.parameter_upper().t_sw, " s", "parameter bounds");
  CheckWithin("com_height", p.com_height, model.parameter_lower().com_height, model.parameter_upper().com_height,
              " m", "parameter bounds");

  StepEvaluator evaluator(model);
  const auto predict = [&](const StepDisplacement& step) {
    const StepEvaluation& e = evaluator.Evaluate(step, p);
    TransitionCost predicted;
    predicted.feasible = e.feasible;
    predicted.cost = ObjectiveValue(objective, e);
    predicted.parameters = p;
    predicted.com_work = e.com_work;
    predicted.heat = e.heat;
    predicted.rcof = e.rcof;
    predicted.duration = p.t_ds + p.t_sw;
    return predicted;
  };
  const TransitionCost predicted = predict(d);
  const StepDisplacement closing{0.0, d.dy, 0.0, 0.0};

  FootstepPlan plan;
  plan.found = true;
  plan.start.right = FootPose{0.0, -0.5 * d.dy, 0.0, 0.0};
  plan.start.left = Place(plan.start.right, FootSide::kLeft, d);
  plan.first_side = FootSide::kRight;
  Stance stance = plan.start;
  FootSide side = plan.first_side;
  for (int k = 0; k <= gait.num_steps; ++k) {
    const bool close = k == gait.num_steps;
    PlannedStep step;
    step.side = side;
    const FootPose& support = side == FootSide::kLeft ? stance.right : stance.left;
    step.displacement = close ? closing : d;
    step.pose = Place(support, side, step.displacement);
    step.mu_allowed = mu_allowed;
    step.transition = close ? predict(closing) : predicted;
    (side == FootSide::kLeft ? stance.left : stance.right) = step.pose;
    plan.steps.push_back(step);
    side = OtherSide(side);
  }
  plan.cost_model = "periodic gait of " + model.name() + " (" + std::string(to_string(objective)) +
                    " predicted by the analytic model)";
  plan.UpdateTotals();
  return plan;
}

std::vector<multibody::TerrainBox> PeriodicGaitTerrain(const FootstepPlan& plan, double foot_length,
                                                       double foot_width, double friction, double margin) {
  if (!(foot_length > 0.0 && foot_width > 0.0 && std::isfinite(foot_length + foot_width))) {
    throw std::invalid_argument("PeriodicGaitTerrain: the sole " + FormatShort(foot_length) + " x " +
                                FormatShort(foot_width) + " m must have finite sides > 0");
  }
  if (!(margin >= 0.0 && margin <= 0.1)) {
    throw std::invalid_argument("PeriodicGaitTerrain: margin " + FormatShort(margin) + " m must be in [0, 0.1]");
  }
  if (!(friction >= 0.0 && friction <= 10.0)) {
    throw std::invalid_argument("PeriodicGaitTerrain: friction " + FormatShort(friction) + " must be in [0, 10]");
  }
  if (!plan.found || plan.steps.empty()) {
    throw std::invalid_argument("PeriodicGaitTerrain: the plan has no steps; give a found plan");
  }
  std::vector<FootPose> footholds = {plan.start.left, plan.start.right};
  for (const PlannedStep& step : plan.steps) footholds.push_back(step.pose);
  constexpr double kThickness = 1.0;
  const bool level = std::all_of(footholds.begin(), footholds.end(),
                                 [&](const FootPose& f) { return std::abs(f.z - footholds[0].z) <= 1e-9; });
  std::vector<multibody::TerrainBox> boxes;
  if (level) {
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const FootPose& f : footholds) {
      lo = lo.cwiseMin(Eigen::Vector2d(f.x, f.y));
      hi = hi.cwiseMax(Eigen::Vector2d(f.x, f.y));
    }
    lo.array() -= 1.0;
    hi.array() += 1.0;
    multibody::TerrainBox floor;
    floor.name = "floor";
    floor.size = Eigen::Vector3d(hi.x() - lo.x(), hi.y() - lo.y(), kThickness);
    const Eigen::Vector2d centre = 0.5 * (lo + hi);
    floor.X_WB = multibody::Pose(Eigen::Matrix3d::Identity(),
                                 Eigen::Vector3d(centre.x(), centre.y(), footholds[0].z - 0.5 * kThickness));
    floor.friction = friction;
    boxes.push_back(floor);
    return boxes;
  }
  const double half_length = 0.5 * foot_length + margin, half_width = 0.5 * foot_width + margin;
  std::vector<std::array<Eigen::Vector2d, 4>> treads;
  for (const FootPose& f : footholds) treads.push_back(Corners(f, half_length, half_width));
  // Footholds 0 and 1 are the start stance's left and right; k >= 2 is step k - 1's.
  const auto name = [&](std::size_t k) {
    return k < 2 ? std::string(k == 0 ? "the start's left foot" : "the start's right foot")
                 : "step " + FormatShort(static_cast<int>(k) - 1);
  };
  for (std::size_t i = 0; i < footholds.size(); ++i) {
    for (std::size_t j = i + 1; j < footholds.size(); ++j) {
      if (std::abs(footholds[i].z - footholds[j].z) > 1e-9 && Overlap(treads[i], treads[j])) {
        throw std::invalid_argument("PeriodicGaitTerrain: the treads of " + name(i) + " and " + name(j) +
                                    " overlap at heights " + FormatShort(footholds[i].z) + " and " +
                                    FormatShort(footholds[j].z) +
                                    " m; no staircase holds both: footholds at different heights must stand apart by the sole's "
                                    "size and twice the margin (a periodic gait with dz != 0 needs 2|dx| >= the foot's "
                                    "length)");
      }
    }
  }
  for (std::size_t k = 0; k < footholds.size(); ++k) {
    const FootPose& f = footholds[k];
    multibody::TerrainBox tread;
    tread.name = "tread of " + name(k);
    tread.size = Eigen::Vector3d(2.0 * half_length, 2.0 * half_width, kThickness);
    tread.X_WB = multibody::Pose(Eigen::AngleAxisd(f.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                                 Eigen::Vector3d(f.x, f.y, f.z - 0.5 * kThickness));
    tread.friction = friction;
    boxes.push_back(tread);
  }
  return boxes;
}

}  // namespace cairn::planning
