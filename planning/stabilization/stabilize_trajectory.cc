#include <cairn/planning/stabilization/stabilize_trajectory.h>

#include <algorithm>
#include <chrono>
#include <utility>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>
#include <cairn/planning/stabilization/com_shift_solver.h>
#include <cairn/planning/stabilization/interpolation_knots.h>
#include <cairn/planning/stabilization/motion_zmp.h>
#include <cairn/planning/stabilization/pelvis_pose_solver.h>
#include <cairn/planning/stabilization/support_polygon.h>
#include <cairn/planning/stabilization/trajectory_interpolator.h>
#include <cairn/planning/stabilization/zmp_stabilizer.h>

namespace cairn::planning {

namespace {

struct ErrorStats {
  double rms{0.0};
  double max{0.0};
};

int Unsupported(const std::vector<Eigen::Vector2d>& zmp) {
  int count = 0;
  for (const Eigen::Vector2d& p : zmp) count += p.allFinite() ? 0 : 1;
  return count;
}

// RMS and maximum of |zmp - reference|; a sample without a ZMP (no support force) counts with the error of the
// nearest earlier sample that has one (or the next one, at the start).
ErrorStats Errors(const std::vector<Eigen::Vector2d>& zmp, const std::vector<Eigen::Vector2d>& reference) {
  ErrorStats stats;
  const std::size_t n = zmp.size();
  std::size_t last = n;
  for (std::size_t k = 0; k < n; ++k) {
    if (zmp[k].allFinite()) last = k;
    std::size_t use = last;
    if (use == n) {
      use = k;
      while (use < n && !zmp[use].allFinite()) ++use;
    }
    const double e = use < n ? (zmp[use] - reference[use]).norm() : 0.0;
    stats.rms += e * e;
    stats.max = std::max(stats.max, e);
  }
  stats.rms = n == 0 ? 0.0 : std::sqrt(stats.rms / static_cast<double>(n));
  return stats;
}

double MinMargin(const std::vector<std::vector<Eigen::Vector2d>>& polygons, const std::vector<Eigen::Vector2d>& zmp) {
  double margin = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < zmp.size(); ++k) {
    if (zmp[k].allFinite()) margin = std::min(margin, SupportMargin(polygons[k], zmp[k]));
  }
  return margin;
}

std::string Millimetres(double metres) { return FormatShort(1000.0 * metres) + " mm"; }

// The soles' poses over one knot segment under contact timing: both on the ground (start == end), or one
// swinging from its lift-off pose to its touch-down pose over [t0, t1] with the apex height `lift` above the
// straight line at mid-swing.
struct SolePath {
  double t0{0.0}, t1{0.0};
  multibody::Pose left0, right0, left1, right1;
  int swing{0};  // 0: none, else kLeftSoleContact or kRightSoleContact
  double lift{0.0};
};

std::vector<SolePath> MakeSolePaths(const multibody::Model& model, const std::vector<InterpolationKnot>& knots,
                                    const StabilizerOptions& options) {
  multibody::Data data(model);
  const int left = model.GetFrameIndex(options.left_sole_frame), right = model.GetFrameIndex(options.right_sole_frame);
  std::vector<multibody::Pose> L(knots.size()), R(knots.size());
  for (std::size_t i = 0; i < knots.size(); ++i) {
    multibody::ForwardKinematics(model, data, knots[i].q);
    L[i] = multibody::FramePose(model, data, left);
    R[i] = multibody::FramePose(model, data, right);
  }
  const int both = kLeftSoleContact | kRightSoleContact;
  std::vector<SolePath> paths;
  for (std::size_t i = 0; i + 1 < knots.size(); ++i) {
    SolePath path;
    if (knots[i].contacts == both && knots[i + 1].contacts == both) {
      path = {knots[i].time, knots[i + 1].time, L[i], R[i], L[i], R[i], 0, 0.0};
    } else if (knots[i + 1].contacts != both && i + 2 < knots.size()) {
      // lift-off (i) -> mid-swing (i + 1) -> touch-down (i + 2): one path over both segments.
      const int swing = both & ~knots[i + 1].contacts;
      const multibody::Pose& mid = swing == kLeftSoleContact ? L[i + 1] : R[i + 1];
      const multibody::Pose& from = swing == kLeftSoleContact ? L[i] : R[i];
      const multibody::Pose& to = swing == kLeftSoleContact ? L[i + 2] : R[i + 2];
      const double lift = mid.translation().z() - 0.5 * (from.translation().z() + to.translation().z());
      path = {knots[i].time, knots[i + 2].time, L[i], R[i], L[i + 2], R[i + 2], swing, std::max(lift, 0.0)};
      if (options.landing_time > 0.5 * (path.t1 - path.t0)) {
        throw std::invalid_argument("StabilizeTrajectory: landing_time " + FormatShort(options.landing_time) +
                                    " s is more than half of the swing from " + FormatShort(path.t0) + " s to " +
                                    FormatShort(path.t1) + " s; choose a shorter landing_time");
      }
      ++i;
    } else {
      path = {knots[i].time, knots[i + 1].time, L[i], R[i], L[i + 1], R[i + 1], 0, 0.0};
    }
    paths.push_back(path);
  }
  return paths;
}

multibody::Pose Blend(const multibody::Pose& a, const multibody::Pose& b, double s) {
  const Eigen::Quaterniond qa(a.rotation()), qb(b.rotation());
  Eigen::Vector3d p = a.translation() + s * (b.translation() - a.translation());
  return multibody::Pose(qa.slerp(s, qb).toRotationMatrix(), p);
}

// Soles at time t: the swing sole's horizontal motion and turn follow the minimum-jerk profile
// 10 u^3 - 15 u^4 + 6 u^5 (zero velocity and acceleration at lift-off and touch-down), its height the straight
// line plus lift * 16 u^2 (1 - u)^2 (zero vertical velocity at both ends, the apex at mid-swing). With a landing
// phase (landing_height h, landing_time d) that profile runs over [t0, t1 - d] towards the touch-down pose raised by
// h (the raise blended in by the same minimum-jerk profile), and the sole then descends h at the constant speed h / d.
std::pair<multibody::Pose, multibody::Pose> SolePosesAt(const std::vector<SolePath>& paths, double t,
                                                        double landing_height, double landing_time) {
  std::size_t i = 0;
  while (i + 1 < paths.size() && t > paths[i].t1) ++i;
  const SolePath& path = paths[i];
  if (path.swing == 0) return {path.left0, path.right0};
  // landing_time is at most half the swing (MakeSolePaths).
  const double u = std::clamp((t - path.t0) / (path.t1 - path.t0 - landing_time), 0.0, 1.0);
  const double s = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
  multibody::Pose moved = path.swing == kLeftSoleContact ? Blend(path.left0, path.left1, s)
                                                         : Blend(path.right0, path.right1, s);
  double raise = path.lift * 16.0 * u * u * (1 - u) * (1 - u);
  if (landing_time > 0.0) {
    const double descent = std::clamp((t - (path.t1 - landing_time)) / landing_time, 0.0, 1.0);
    raise += landing_height * (s - descent);
  }
  const Eigen::Vector3d lifted = moved.translation() + Eigen::Vector3d(0, 0, raise);
  moved = multibody::Pose(moved.rotation(), lifted);
  if (path.swing == kLeftSoleContact) return {moved, path.right0};
  return {path.left0, moved};
}

}  // namespace

StabilizedTrajectory StabilizeTrajectory(std::shared_ptr<const multibody::Model> model,
                                         const WholeBodyTrajectory& trajectory, const StabilizerOptions& options) {
  const auto clock_start = std::chrono::steady_clock::now();
  if (model == nullptr) throw std::invalid_argument("StabilizeTrajectory: the robot model is null");
  ValidateStabilizerOptions(options);
  // Checks the sample count from the waypoint times before building anything.
  if (!trajectory.waypoints.empty()) {
    const double span = trajectory.waypoints.back().time - trajectory.waypoints.front().time;
    const double samples = 2.0 * span / options.control_period;  // contact timing may add one double support
    if (!std::isfinite(span) || samples > static_cast<double>(kMaxStabilizationSamples)) {
      throw std::invalid_argument("StabilizeTrajectory: " + FormatShort(span) + " s at a control period of " +
                                  FormatShort(options.control_period) + " s may need " + FormatShort(samples) +
                                  " samples, more than the limit of " + std::to_string(kMaxStabilizationSamples) +
                                  "; lengthen control_period");
    }
  }
  std::vector<InterpolationKnot> knots = MakeInterpolationKnots(model, trajectory, options);
  const std::vector<SolePath> sole_paths = options.contact_timing ? MakeSolePaths(*model, knots, options)
                                                                  : std::vector<SolePath>();
  const TrajectoryInterpolator interpolator(model, std::move(knots), options.interpolation);
  const double duration = interpolator.end_time() - interpolator.start_time();
  const auto n = static_cast<std::size_t>(std::ceil(duration / options.control_period - 1e-9)) + 1;
  if (n > static_cast<std::size_t>(kMaxStabilizationSamples)) {
    throw std::invalid_argument("StabilizeTrajectory: " + std::to_string(n) + " samples, more than the limit of " +
                                std::to_string(kMaxStabilizationSamples) + "; lengthen control_period");
  }
  const double dt = options.control_period;
  const multibody::Model& m = *model;
  multibody::Data data(m);
  const int left = m.GetFrameIndex(options.left_sole_frame), right = m.GetFrameIndex(options.right_sole_frame);

  const PelvisPoseSolver placement(model, options.left_sole_frame, options.right_sole_frame);
  const Eigen::Index leg_count = m.nq() - 7;  // the seed's joints from the previous sample (legs' branch)
  struct Placement {
    Eigen::Matrix3d R_base;
    multibody::Pose left, right;
    double base_height{0.0};
  };
  std::vector<Placement> placed(sole_paths.empty() ? 0 : n);
  StabilizedTrajectory out;
  out.period = dt;
  out.report.method = options.method;
  std::vector<Eigen::VectorXd> q(n), v(n);
  std::vector<multibody::Pose> left_pose(n), right_pose(n);
  std::vector<std::vector<Eigen::Vector2d>> polygons(n);
  std::vector<double> ground(n);
  std::vector<Eigen::Vector2d> com_start(n);
  out.zmp_reference.resize(n);
  out.contacts.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = interpolator.start_time() + std::min(duration, dt * static_cast<double>(k));
    interpolator.Evaluate(t, &q[k], &v[k]);
    out.zmp_reference[k] = interpolator.ReferenceZmp(t);
    out.contacts[k] = interpolator.Contacts(t);
    if (!sole_paths.empty()) {
      // With contact timing the soles follow the plan's contacts exactly: still on the ground from touch-down to
      // lift-off, the swing sole on a smooth path (SolePosesAt) instead of wherever the interpolated postures
      // put it; the posture's COM is kept.
      const auto [X_left, X_right] = SolePosesAt(sole_paths, t, options.landing_height, options.landing_time);
      const Eigen::Vector3d heading = X_left.rotation().col(0) + X_right.rotation().col(0);
      const Eigen::Matrix3d R_base =
          options.waist_orientation == "upright"
              ? Eigen::AngleAxisd(std::atan2(heading.y(), heading.x()), Eigen::Vector3d::UnitZ()).toRotationMatrix()
              : Eigen::Quaterniond(q[k](3), q[k](4), q[k](5), q[k](6)).normalized().toRotationMatrix();
      const Eigen::Vector2d com = multibody::CenterOfMass(m, data, q[k]).head<2>();
      placed[k] = {R_base, X_left, X_right, q[k](2) - options.crouch};
      Eigen::VectorXd seed = q[k];
      if (k > 0) seed.segment(7, leg_count) = q[k - 1].segment(7, leg_count);
      q[k] = placement.Solve(seed, com, R_base, placed[k].base_height, X_left, X_right).q;
    }
    com_start[k] = multibody::CenterOfMass(m, data, q[k]).head<2>();  // also runs the kinematics
    left_pose[k] = multibody::FramePose(m, data, left);
    right_pose[k] = multibody::FramePose(m, data, right);
    std::vector<multibody::Pose> loaded;
    if (out.contacts[k] & kLeftSoleContact) loaded.push_back(left_pose[k]);
    if (out.contacts[k] & kRightSoleContact) loaded.push_back(right_pose[k]);
    if (loaded.empty()) loaded = {left_pose[k], right_pose[k]};
    double z = 0.0;
    for (const multibody::Pose& X : loaded) z += X.translation().z() / static_cast<double>(loaded.size());
    ground[k] = z;
    polygons[k] = SupportPolygon(loaded, options.sole_length, options.sole_width);
  }
  if (!sole_paths.empty()) v = SampleVelocities(m, q, dt);
  out.zmp_before = ComputeMotionZmp(m, q, dt, ground);
  out.report.unsupported_samples_before = Unsupported(out.zmp_before);
  const ErrorStats before = Errors(out.zmp_before, out.zmp_reference);
  out.report.rms_error_before = before.rms;
  out.report.max_error_before = before.max;
  out.report.min_support_margin_before = MinMargin(polygons, out.zmp_before);

  std::vector<Eigen::Vector2d> zmp = out.zmp_before;
  out.report.unsupported_samples_after = out.report.unsupported_samples_before;
  ErrorStats best = before;
  std::string ending = "interpolation only";
  if (options.method != "none") {
    const std::unique_ptr<ZmpStabilizer> stabilizer = MakeZmpStabilizer(options, -m.gravity().z());
    double com_height = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      com_height += (multibody::CenterOfMass(m, data, q[k]).z() - ground[k]) / static_cast<double>(n);
    }
    const auto rows = static_cast<Eigen::Index>(n);
    Eigen::MatrixXd offsets = Eigen::MatrixXd::Zero(rows, 2);
    const std::vector<Eigen::VectorXd> interpolated = q;
    const ComShiftSolver shift(model, options.left_sole_frame, options.right_sole_frame);
    const bool upright = options.waist_orientation == "upright";
    std::vector<Eigen::Matrix3d> waist(n);
    for (std::size_t k = 0; k < n; ++k) {
      // Yaw half-way between the soles' (through the mean of their heading vectors).
      const Eigen::Vector3d heading = left_pose[k].rotation().col(0) + right_pose[k].rotation().col(0);
      waist[k] = Eigen::AngleAxisd(std::atan2(heading.y(), heading.x()), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    }
    // Moves sample k's COM to `target`: with contact timing the soles, base orientation and height of its
    // placement, else the interpolated posture's soles and orientation (or the upright waist).
    const auto Shift = [&](std::size_t k, const Eigen::Vector2d& target) {
      if (!placed.empty()) {
        const Placement& p = placed[k];
        const PelvisPoseResult r = placement.Solve(q[k], target, p.R_base, p.base_height, p.left, p.right);
        return ComShiftResult{r.q, r.sole_error, r.com_error};
      }
      return upright ? shift.Solve(interpolated[k], target, waist[k]) : shift.Solve(interpolated[k], target);
    };
    // Every sample moved by its row of `offsets` into `moved`; returns the largest sole error.
    const auto ShiftAll = [&](const Eigen::MatrixXd& offsets_xy, std::vector<Eigen::VectorXd>* moved) {
      double ik_error = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        const ComShiftResult shifted =
            Shift(k, com_start[k] + offsets_xy.row(static_cast<Eigen::Index>(k)).transpose());
        (*moved)[k] = shifted.q;
        ik_error = std::max(ik_error, shifted.sole_error);
      }
      return ik_error;
    };
    ending = "stopped after max_iterations = " + std::to_string(options.max_iterations);
    if (options.cart_table_start) {
      // Pass 0: the offsets that make the cart-table ZMP of the posture's COM, x - (z_c / g) x'', equal the
      // reference, applied in full. The interpolated postures' static COM can be far from any COM that realises
      // the reference (with contact timing it crosses to the next foot during the swing), and the full-model
      // passes below, with their step fraction, start from there instead of walking that distance in halves.
      const double g = -m.gravity().z();
      Eigen::MatrixXd error(rows, 2);
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(n - 1, k + 1);
        Eigen::Vector2d acceleration = Eigen::Vector2d::Zero();
        if (b - a == 2) acceleration = (com_start[b] - 2.0 * com_start[k] + com_start[a]) / (dt * dt);
        const Eigen::Vector2d cart_table_zmp = com_start[k] - (com_height / g) * acceleration;
        error.row(static_cast<Eigen::Index>(k)) = (out.zmp_reference[k] - cart_table_zmp).transpose();
      }
      offsets.col(0) = stabilizer->ComOffsets(error.col(0), dt, com_height);
      offsets.col(1) = stabilizer->ComOffsets(error.col(1), dt, com_height);
      const double ik_error = ShiftAll(offsets, &q);
      zmp = ComputeMotionZmp(m, q, dt, ground);
      out.report.unsupported_samples_after = Unsupported(zmp);
      best = Errors(zmp, out.zmp_reference);
      out.report.max_ik_error = ik_error;
    }
    for (int pass = 1; pass <= options.max_iterations; ++pass) {
      if (best.rms < options.tolerance) {
        ending = "converged below " + Millimetres(options.tolerance);
        break;
      }
      // The error; a sample without a ZMP takes the error of the nearest sample before it that has one (or
      // after it, at the start), so the offsets see no jump there.
      Eigen::MatrixXd error(rows, 2);
      std::size_t last = n;
      for (std::size_t k = 0; k < n; ++k) {
        if (zmp[k].allFinite()) last = k;
        std::size_t use = last;
        if (use == n) {
          use = k;
          while (use < n && !zmp[use].allFinite()) ++use;
        }
        error.row(static_cast<Eigen::Index>(k)) =
            use < n ? Eigen::RowVector2d((out.zmp_reference[use] - zmp[use]).transpose()) : Eigen::RowVector2d::Zero();
      }
      Eigen::MatrixXd trial = offsets;
      const double fraction = options.step_fraction;
      trial.col(0) += fraction * stabilizer->ComOffsets(error.col(0), dt, com_height);
      trial.col(1) += fraction * stabilizer->ComOffsets(error.col(1), dt, com_height);
      std::vector<Eigen::VectorXd> q_trial(n);
      const double ik_error = ShiftAll(trial, &q_trial);
      const std::vector<Eigen::Vector2d> zmp_trial = ComputeMotionZmp(m, q_trial, dt, ground);
      const int unsupported = Unsupported(zmp_trial);
      const ErrorStats stats = Errors(zmp_trial, out.zmp_reference);
      const bool better = stats.rms < best.rms;
      if (!better) {
        ending = "pass " + std::to_string(pass) + " did not lower the error (" + Millimetres(stats.rms) + ")";
        break;
      }
      const double gain = (best.rms - stats.rms) / best.rms;
      out.report.unsupported_samples_after = unsupported;
      q = std::move(q_trial);
      zmp = zmp_trial;
      offsets = trial;
      best = stats;
      out.report.iterations = pass;
      out.report.max_ik_error = ik_error;
      if (best.rms < options.tolerance && unsupported == 0) {
        ending = "converged below " + Millimetres(options.tolerance);
        break;
      }
      if (gain < options.min_improvement) {
        ending = "pass " + std::to_string(pass) + " gained less than " + FormatShort(100.0 * options.min_improvement) +
                 " %";
        break;
      }
    }
    v = SampleVelocities(m, q, dt);
  }
  out.report.rms_error_after = best.rms;
  out.report.max_error_after = best.max;
  out.report.min_support_margin_after = MinMargin(polygons, zmp);
  out.report.joint_limits_held = true;
  for (const Eigen::VectorXd& sample : q) {
    out.report.joint_limits_held = out.report.joint_limits_held && multibody::IsWithinPositionLimits(m, sample, 1e-9);
  }
  out.com.resize(n);
  for (std::size_t k = 0; k < n; ++k) out.com[k] = multibody::CenterOfMass(m, data, q[k]).head<2>();
  out.zmp = std::move(zmp);
  out.q = std::move(q);
  out.v = std::move(v);
  out.report.success = true;
  out.report.message = options.method + ": ZMP error RMS " + Millimetres(before.rms) + " -> " +
                       Millimetres(best.rms) + " (max " + Millimetres(before.max) + " -> " + Millimetres(best.max) +
                       ") in " + std::to_string(out.report.iterations) + " pass(es), " + ending +
                       (out.report.joint_limits_held ? "" : "; joint limits violated") +
                       (out.report.unsupported_samples_after == 0
                            ? ""
                            : "; " + std::to_string(out.report.unsupported_samples_after) +
                                  " sample(s) without support force");
  out.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return out;
}

}  // namespace cairn::planning
