#include "cairn/planning/locomotion/step_evaluator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cairn::planning {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Vector6d = Eigen::Matrix<double, 6, 1>;

double Blend(double s) { return s * s * (3.0 - 2.0 * s); }

Eigen::Matrix2d Rotation(double yaw) {
  Eigen::Matrix2d R;
  R << std::cos(yaw), -std::sin(yaw), std::sin(yaw), std::cos(yaw);
  return R;
}

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// A convex polygon (counter-clockwise) of at most 8 vertices: the hull of one or two sole rectangles.
struct Polygon {
  std::array<Eigen::Vector2d, 9> v;
  int size{0};

  // Distance of `p` outside the polygon (0 inside or on the boundary).
  double DistanceOutside(const Eigen::Vector2d& p) const {
    bool inside = true;
    double distance = std::numeric_limits<double>::infinity();
    for (int i = 0; i < size; ++i) {
      const Eigen::Vector2d& a = v[i];
      const Eigen::Vector2d& b = v[(i + 1) % size];
      if (Cross(a, b, p) < 0.0) inside = false;
      const Eigen::Vector2d ab = b - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      distance = std::min(distance, (a + t * ab - p).norm());
    }
    return inside ? 0.0 : distance;
  }
};

void SoleCorners(const Foothold& foot, double length, double width, std::array<Eigen::Vector2d, 8>& points, int offset) {
  const Eigen::Matrix2d R = Rotation(foot.yaw);
  const double hx = 0.5 * length, hy = 0.5 * width;
  const Eigen::Vector2d c = foot.position.head<2>();
  points[offset + 0] = c + R * Eigen::Vector2d(hx, hy);
  points[offset + 1] = c + R * Eigen::Vector2d(-hx, hy);
  points[offset + 2] = c + R * Eigen::Vector2d(-hx, -hy);
  points[offset + 3] = c + R * Eigen::Vector2d(hx, -hy);
}

// Andrew's monotone chain over the first `count` points.
Polygon ConvexHull(std::array<Eigen::Vector2d, 8> points, int count) {
  std::sort(points.begin(), points.begin() + count, [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::array<Eigen::Vector2d, 17> hull;
  int k = 0;
  for (int i = 0; i < count; ++i) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (int i = count - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  Polygon polygon;
  polygon.size = k - 1;
  for (int i = 0; i < polygon.size; ++i) polygon.v[i] = hull[i];
  return polygon;
}

}  // namespace

const char* to_string(StepInfeasibility reason) {
  switch (reason) {
    case StepInfeasibility::kNone:
      return "none";
    case StepInfeasibility::kOutOfReach:
      return "out of reach";
    case StepInfeasibility::kParametersOutOfBounds:
      return "parameters out of bounds";
    case StepInfeasibility::kSolesOverlap:
      return "soles overlap";
    case StepInfeasibility::kFootLifts:
      return "foot lifts";
    case StepInfeasibility::kLegTooLong:
      return "leg too long";
    case StepInfeasibility::kLegTooShort:
      return "leg too short";
    case StepInfeasibility::kLegPosture:
      return "leg posture";
    case StepInfeasibility::kZmpOutsideSupport:
      return "ZMP outside support";
  }
  return "unknown";
}

StepEvaluator::StepEvaluator(const WalkingModel& model, const WalkingPatternOptions& options)
    : model_(model), options_(options) {
  const int contacts = num_contact_samples();
  evaluation_.normal_force.resize(contacts);
  evaluation_.tangential_force.resize(contacts);
  evaluation_.leg_length.resize(contacts);
  evaluation_.leg_posture_excess.resize(contacts);
}

const StepEvaluation& StepEvaluator::Evaluate(const StepDisplacement& d, const StepParameters& p) {
  StepEvaluation& e = evaluation_;
  // Same-side footholds 2 dx apart at heights differing by 2 dz must not overlap in plan: the terrain has one
  // height per point. Such a step has no periodic gait to evaluate.
  if (d.dz != 0.0 && 2.0 * std::abs(d.dx) < model_.foot_length() && std::isfinite(d.dx)) {
    e = StepEvaluation{};
    e.normal_force.setZero(num_contact_samples());
    e.tangential_force.setZero(num_contact_samples());
    e.leg_length.setZero(num_contact_samples());
    e.leg_posture_excess.setZero(num_contact_samples());
    e.rcof = std::numeric_limits<double>::infinity();
    e.duration = p.t_ds + p.t_sw;
    e.infeasibility = model_.reach().Contains(d) ? StepInfeasibility::kSolesOverlap : StepInfeasibility::kOutOfReach;
    e.feasible = false;
    return e;
  }
  GenerateWalkingPattern(d, p, model_.gravity(), options_, pattern_);
  const int n = options_.samples_per_phase;
  const int total = 2 * n;
  const double m = model_.mass();
  const double g = model_.gravity();
  const LegGeometry& leg = model_.leg();
  const LegTorqueTable& table = model_.leg_torques();
  const LegTorqueGrid& grid = table.grid();
  std::array<double, WalkingModel::kLegJoints> heat_coefficient;  // R / (r K)^2: heat power per torque^2
  for (int j = 0; j < WalkingModel::kLegJoints; ++j) {
    const MotorConstants& motor = model_.motor(j);
    heat_coefficient[j] = motor.resistance / std::pow(motor.gear_ratio * motor.torque_constant, 2);
  }

  // Both contact surfaces lie on the plane through the footholds, z = k x.
  const Eigen::Vector3d surface_normal = Eigen::Vector3d(-pattern_.slope, 0.0, 1.0).normalized();
  const Eigen::Vector3d& n_stance = surface_normal;
  const Eigen::Vector3d& n_prev = surface_normal;

  // Pelvis upright with yaw halfway between the feet; the stance foot f_j is the right foot (mirrored frame).
  const double pelvis_yaw = 0.5 * d.dtheta;
  const Eigen::Matrix2d R_pelvis = Rotation(pelvis_yaw);
  auto hip_offset = [&](bool left) {
    const Eigen::Vector2d xy = R_pelvis * Eigen::Vector2d(leg.hip_from_com.x(), left ? leg.hip_from_com.y()
                                                                                      : -leg.hip_from_com.y());
    return Eigen::Vector3d(xy.x(), xy.y(), leg.hip_from_com.z());
  };
  const Eigen::Vector3d left_hip_offset = hip_offset(true);
  const Eigen::Vector3d right_hip_offset = hip_offset(false);
  auto ankle_of = [&](const Eigen::Vector3d& sole, double yaw) {
    const Eigen::Vector2d forward = Rotation(yaw) * Eigen::Vector2d(leg.ankle_forward, 0.0);
    return Eigen::Vector3d(sole.x() + forward.x(), sole.y() + forward.y(), sole.z() + leg.ankle_height);
  };
  const Eigen::Vector3d stance_ankle = ankle_of(pattern_.stance_foot.position, pattern_.stance_foot.yaw);
  const Eigen::Vector3d prev_ankle = ankle_of(pattern_.previous_foot.position, pattern_.previous_foot.yaw);
  const Eigen::Vector3d next_ankle = ankle_of(pattern_.next_foot.position, pattern_.next_foot.yaw);
  // Leg posture in the torque table's coordinates (left-leg pelvis axes).
  auto posture = [&](const Eigen::Vector3d& ankle_from_hip, bool left) {
    const Eigen::Vector2d xy = R_pelvis.transpose() * ankle_from_hip.head<2>();
    return Eigen::Vector3d(xy.x(), left ? xy.y() : -xy.y(), ankle_from_hip.z());
  };
  auto posture_excess = [&](const Eigen::Vector3d& e_leg) {
    const double down = std::max(-e_leg.z(), 1e-9);
    const double pitch = std::atan2(e_leg.x(), down);
    const double roll = std::atan2(e_leg.y(), down);
    const double above_hip = e_leg.z() < 0.0 ? -kPi : kPi;  // an ankle above the hip is never a stance posture
    return std::max({pitch - grid.pitch_max, grid.pitch_min - pitch, roll - grid.roll_max, grid.roll_min - roll,
                     above_hip, table.JointLimitExcess(e_leg)});
  };

  // Support polygons.
  std::array<Eigen::Vector2d, 8> corners;
  SoleCorners(pattern_.stance_foot, model_.foot_length(), model_.foot_width(), corners, 0);
  const Polygon single_support = ConvexHull(corners, 4);
  SoleCorners(pattern_.previous_foot, model_.foot_length(), model_.foot_width(), corners, 4);
  const Polygon double_support = ConvexHull(corners, 8);

  double rcof = 0.0;
  double min_normal = std::numeric_limits<double>::infinity();
  double zmp_outside = 0.0;
  double com_work = 0.0, heat = 0.0, squared_torque = 0.0;
  double previous_energy = 0.0, previous_power = 0.0, previous_square = 0.0;
  Vector6d tau;
  for (int k = 0; k < total; ++k) {
    const bool ds = pattern_.phase[static_cast<std::size_t>(k)] == ContactPhase::kDoubleSupport;
    const Eigen::Vector3d com = pattern_.com.col(k);
    const Eigen::Vector3d force = m * (pattern_.com_acceleration.col(k) + Eigen::Vector3d(0.0, 0.0, g));
    const double w = pattern_.stance_load_fraction[k];
    const Eigen::Vector2d cop_world = com.head<2>() - pattern_.zmp.col(k).head<2>();
    const Eigen::Vector2d cop = R_pelvis.transpose() * cop_world;  // COP offset from each sole centre, pelvis axes

    // Stance foot (right leg), every sample.
    const Eigen::Vector3d stance_leg = stance_ankle - (com + right_hip_offset);
    {
      const double normal = force.dot(n_stance);
      e.normal_force[k] = normal;
      e.tangential_force[k] = (force - normal * n_stance).norm();
      e.leg_length[k] = stance_leg.norm();
      e.leg_posture_excess[k] = posture_excess(posture(stance_leg, false));
    }
    double power = 0.0, square = 0.0;
    table.Torques(posture(stance_leg, false), w * m * g, Eigen::Vector2d(cop.x(), -cop.y()), tau);
    for (int j = 0; j < 6; ++j) {
      power += heat_coefficient[j] * tau[j] * tau[j];
      square += tau[j] * tau[j];
    }
    if (ds) {
      // Previous foot (left leg) in double support.
      const int c = total + k;
      const Eigen::Vector3d prev_leg = prev_ankle - (com + left_hip_offset);
      const double normal = force.dot(n_prev);
      e.normal_force[c] = normal;
      e.tangential_force[c] = (force - normal * n_prev).norm();
      e.leg_length[c] = prev_leg.norm();
      e.leg_posture_excess[c] = posture_excess(posture(prev_leg, true));
      table.Torques(posture(prev_leg, true), (1.0 - w) * m * g, cop, tau);
      zmp_outside = std::max(zmp_outside, double_support.DistanceOutside(pattern_.zmp.col(k).head<2>()));
    } else {
      // Swing leg (left) holding its own weight along the swing path.
      const double s = (pattern_.time[k] - p.t_ds) / p.t_sw;
      const double b = Blend(s);
      Eigen::Vector3d swing_ankle = (1.0 - b) * prev_ankle + b * next_ankle;
      swing_ankle.z() += model_.swing_height() * std::sin(kPi * s);
      table.Torques(posture(swing_ankle - (com + left_hip_offset), true), 0.0, Eigen::Vector2d::Zero(), tau);
      zmp_outside = std::max(zmp_outside, single_support.DistanceOutside(pattern_.zmp.col(k).head<2>()));
    }
    for (int j = 0; j < 6; ++j) {
      power += heat_coefficient[j] * tau[j] * tau[j];
      square += tau[j] * tau[j];
    }

    // Mechanical energy of the COM; v . F = dE/dt, so the integral of |v . F| is E's total variation.
    const double energy = 0.5 * m * pattern_.com_velocity.col(k).squaredNorm() + m * g * com.z();
    if (k > 0 && k != n) {
      const double dt = pattern_.time[k] - pattern_.time[k - 1];
      com_work += std::abs(energy - previous_energy);
      heat += 0.5 * dt * (power + previous_power);
      squared_torque += 0.5 * dt * (square + previous_square);
    }
    previous_energy = energy;
    previous_power = power;
    previous_square = square;
  }
  // The sample at the phase boundary appears twice (k = n-1 and k = n), so skipping k = n loses nothing; the
  // swing-leg term switches on at the boundary, and its jump is integrated from k = n on.
  for (int c = 0; c < num_contact_samples(); ++c) {
    min_normal = std::min(min_normal, e.normal_force[c]);
    const double ratio = e.normal_force[c] > 0.0 ? e.tangential_force[c] / e.normal_force[c]
                                                 : std::numeric_limits<double>::infinity();
    rcof = std::max(rcof, ratio);
  }

  e.com_work = com_work;
  e.heat = heat;
  e.squared_torque = squared_torque;
  e.rcof = rcof;
  e.duration = p.t_ds + p.t_sw;
  e.leg_length_min = e.leg_length.minCoeff();
  e.leg_length_max = e.leg_length.maxCoeff();
  e.zmp_outside_support = zmp_outside;

  const StepParameters& lo = model_.parameter_lower();
  const StepParameters& hi = model_.parameter_upper();
  constexpr double kSlack = 1e-9;
  e.infeasibility = StepInfeasibility::kNone;
  if (!model_.reach().Contains(d)) {
    e.infeasibility = StepInfeasibility::kOutOfReach;
  } else if (p.t_ds < lo.t_ds - kSlack || p.t_ds > hi.t_ds + kSlack || p.t_sw < lo.t_sw - kSlack ||
             p.t_sw > hi.t_sw + kSlack || p.com_height < lo.com_height - kSlack ||
             p.com_height > hi.com_height + kSlack) {
    e.infeasibility = StepInfeasibility::kParametersOutOfBounds;
  } else if (!(min_normal > 0.0)) {
    e.infeasibility = StepInfeasibility::kFootLifts;
  } else if (e.leg_length_max > leg.leg_length_max) {
    e.infeasibility = StepInfeasibility::kLegTooLong;
  } else if (e.leg_length_min < leg.leg_length_min) {
    e.infeasibility = StepInfeasibility::kLegTooShort;
  } else if (e.leg_posture_excess.maxCoeff() > 0.0) {
    e.infeasibility = StepInfeasibility::kLegPosture;
  } else if (zmp_outside > 1e-9) {
    e.infeasibility = StepInfeasibility::kZmpOutsideSupport;
  }
  e.feasible = e.infeasibility == StepInfeasibility::kNone;
  return e;
}

}  // namespace cairn::planning
