#include <cairn/planning/trajectory/waypoint_spec.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
// The unit normal of the plane h = a + b dx + c dy fitted to the ground heights of the cells whose centres lie in
// the sole's rectangle, or nothing when the fit is not determined.
std::optional<Eigen::Vector3d> FootprintNormal(const FootPose& foot, const TerrainMap& terrain, double length,
                                               double width) {
  const Eigen::Vector2d centre(foot.x, foot.y), along(std::cos(foot.theta), std::sin(foot.theta));
  const Eigen::Vector2d across(-along.y(), along.x());
  const double reach = 0.5 * std::hypot(length, width);
  int col_lo = 0, row_lo = 0, col_hi = 0, row_hi = 0;
  const Eigen::Vector2d lo = (centre.array() - reach).max(terrain.min_corner().array());
  const Eigen::Vector2d hi = (centre.array() + reach).min(terrain.max_corner().array() - 1e-9);
  if (!(lo.array() <= hi.array()).all() || !terrain.CellAt(lo.x(), lo.y(), &col_lo, &row_lo) ||
      !terrain.CellAt(hi.x(), hi.y(), &col_hi, &row_hi)) {
    return std::nullopt;
  }
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  int count = 0;
  for (int row = row_lo; row <= row_hi; ++row) {
    for (int col = col_lo; col <= col_hi; ++col) {
      if (!terrain.has_ground(col, row)) continue;
      const Eigen::Vector2d d = terrain.CellCenter(col, row) - centre;
      if (std::abs(d.dot(along)) > 0.5 * length || std::abs(d.dot(across)) > 0.5 * width) continue;
      const Eigen::Vector3d a(1.0, d.x(), d.y());
      normal_matrix += a * a.transpose();
      rhs += a * terrain.height(col, row);
      ++count;
    }
  }
  if (count < 3) return std::nullopt;
  const Eigen::LDLT<Eigen::Matrix3d> solve(normal_matrix);
  // Cells on one line leave the slope across it undetermined.
  if (solve.info() != Eigen::Success || !(std::abs(solve.vectorD().minCoeff()) > 1e-9 * normal_matrix.trace())) {
    return std::nullopt;
  }
  const Eigen::Vector3d plane = solve.solve(rhs);
  return Eigen::Vector3d(-plane(1), -plane(2), 1.0).normalized();
}
}  // namespace

multibody::Pose SoleTargetPose(const FootPose& foot, const TerrainMap* terrain, double sole_length,
                               double sole_width) {
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(foot.theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Matrix3d tilt = Eigen::Matrix3d::Identity();
  if (terrain != nullptr) {
    if (const auto normal = FootprintNormal(foot, *terrain, sole_length, sole_width)) {
      tilt = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), *normal).toRotationMatrix();
    }
  }
  return multibody::Pose(tilt * yaw, Eigen::Vector3d(foot.x, foot.y, foot.z));
}

namespace {

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

WaypointContact Contact(FootSide side, const FootPose& foot, const TrajectoryOptimizerOptions& options,
                        const TerrainMap* terrain) {
  return {side == FootSide::kLeft ? options.left_sole_frame : options.right_sole_frame, side,
          SoleTargetPose(foot, terrain, options.sole_length, options.sole_width)};
}

const FootPose& Foot(const Stance& stance, FootSide side) {
  return side == FootSide::kLeft ? stance.left : stance.right;
}
}  // namespace

std::vector<WaypointSpec> MakeWaypointSpecs(const FootstepPlan& plan, const TrajectoryOptimizerOptions& options,
                                            const TerrainMap* terrain) {
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
    start.contacts = {Contact(FootSide::kLeft, stance.left, options, terrain),
                      Contact(FootSide::kRight, stance.right, options, terrain)};
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
    swing.contacts = {Contact(support, Foot(stance, support), options, terrain)};
    SetPolygon({Foot(stance, support)}, options, &swing);
    swing.supports = {{support_frame, 1.0}};
    specs.push_back(swing);
    t += t_ds + t_sw;
  }
  return specs;
}

}  // namespace cairn::planning
