#include <cairn/planning/trajectory/waypoint_spec.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
multibody::Pose SolePose(const FootPose& foot) {
  return multibody::Pose(Eigen::AngleAxisd(foot.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                         Eigen::Vector3d(foot.x, foot.y, foot.z));
}

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Eigen::Vector2d> Hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && Cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

void SetPolygon(const std::vector<FootPose>& feet, const TrajectoryOptimizerOptions& options, WaypointSpec* spec) {
  std::vector<Eigen::Vector2d> corners;
  for (const FootPose& foot : feet) {
    const Eigen::Rotation2Dd R(foot.theta);
    for (const double sx : {-0.5, 0.5}) {
      for (const double sy : {-0.5, 0.5}) {
        corners.push_back(Eigen::Vector2d(foot.x, foot.y) +
                          R * Eigen::Vector2d(sx * options.sole_length, sy * options.sole_width));
      }
    }
  }
  spec->polygon_vertices = Hull(corners);
  const auto n = static_cast<Eigen::Index>(spec->polygon_vertices.size());
  spec->polygon_A.resize(n, 2);
  spec->polygon_b.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = spec->polygon_vertices[static_cast<std::size_t>(i)];
    const Eigen::Vector2d& b = spec->polygon_vertices[static_cast<std::size_t>((i + 1) % n)];
    const Eigen::Vector2d edge = b - a;
    const Eigen::Vector2d outward = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    spec->polygon_A.row(i) = outward.transpose();
    spec->polygon_b(i) = outward.dot(a) - options.com_margin;
  }
}

WaypointContact Contact(FootSide side, const FootPose& foot, const TrajectoryOptimizerOptions& options) {
  return {side == FootSide::kLeft ? options.left_sole_frame : options.right_sole_frame, side, SolePose(foot)};
}

const FootPose& Foot(const Stance& stance, FootSide side) {
  return side == FootSide::kLeft ? stance.left : stance.right;
}
}  // namespace

std::vector<WaypointSpec> MakeWaypointSpecs(const FootstepPlan& plan, const TrajectoryOptimizerOptions& options) {
  ValidateTrajectoryOptimizerOptions(options);
  if (!plan.found) {
    throw std::invalid_argument("MakeWaypointSpecs: the footstep plan was not found (" + plan.reason +
                                "); plan footsteps first");
  }
  const int num_steps = static_cast<int>(plan.steps.size());
  if (num_steps + 1 > kMaxTrajectoryStances) {
    throw std::invalid_argument("MakeWaypointSpecs: the plan has " + FormatShort(num_steps + 1) +
                                " stances, more than the limit of " + FormatShort(kMaxTrajectoryStances) +
                                "; split it into windows or plan a shorter route");
  }
  std::vector<WaypointSpec> specs;
  double t = 0.0;
  for (int j = 0; j <= num_steps; ++j) {
    const Stance stance = plan.StanceAfter(j - 1);
    WaypointSpec start;
    start.time = t;
    start.stance = j;
    start.label = "stance " + FormatShort(j) + " start";
    start.contacts = {Contact(FootSide::kLeft, stance.left, options), Contact(FootSide::kRight, stance.right, options)};
    if (j == num_steps) {
      SetPolygon({stance.left, stance.right}, options, &start);
      start.supports = {{options.left_sole_frame, 0.5}, {options.right_sole_frame, 0.5}};
      specs.push_back(start);
      break;
    }
    const PlannedStep& step = plan.steps[static_cast<std::size_t>(j)];
    const double t_ds = step.transition.parameters.t_ds, t_sw = step.transition.parameters.t_sw;
    if (!(t_ds >= 0.0) || !(t_sw > 0.0) || !std::isfinite(t_ds + t_sw)) {
      throw std::invalid_argument("MakeWaypointSpecs: step " + FormatShort(j + 1) + " has t_ds = " + FormatShort(t_ds) +
                                  " s and t_sw = " + FormatShort(t_sw) +
                                  " s; the whole-body problem needs a finite swing time > 0 (refine the plan's timing)");
    }
    const FootSide support = OtherSide(step.side);
    const std::string support_frame = support == FootSide::kLeft ? options.left_sole_frame : options.right_sole_frame;
    SetPolygon({Foot(stance, support)}, options, &start);
    start.supports = {{support_frame, 1.0}};
    specs.push_back(start);

    WaypointSpec swing;
    swing.time = t + t_ds + 0.5 * t_sw;
    swing.stance = j;
    swing.single_support = true;
    swing.label = "stance " + FormatShort(j) + " mid-swing";
    swing.contacts = {Contact(support, Foot(stance, support), options)};
    SetPolygon({Foot(stance, support)}, options, &swing);
    swing.supports = {{support_frame, 1.0}};
    specs.push_back(swing);
    t += t_ds + t_sw;
  }
  return specs;
}

}  // namespace cairn::planning
