#include "cairn/common/number_text.h"
#include "cairn/planning/locomotion/walking_pattern_generator.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

namespace cairn::planning {
namespace {

using Vector4d = Eigen::Vector4d;

// The ZMP interpolation 3s^2 - 2s^3 and its derivatives with respect to s.
double Blend(double s) { return s * s * (3.0 - 2.0 * s); }
double BlendRate(double s) { return 6.0 * s * (1.0 - s); }
double BlendCurvature(double s) { return 6.0 - 12.0 * s; }
constexpr double kBlendJerk = -12.0;

// Everything that defines the step's forcing; the flow of the COM state s = (x, y, vx, vy) is affine in s(0).
struct Step {
  double t_ds, t_sw, h, k;  // k: slope of the foothold plane z = k x
  double omega;             // sqrt(g / h)
  Eigen::Vector2d start;    // ZMP at t = 0: the previous sole centre
  Eigen::Vector2d delta;    // ZMP travel in double support (to the stance sole centre, the origin)
  int samples;              // per phase
};

// Records sample k of the pattern from the horizontal state and ZMP.
void Record(const Step& step, WalkingPattern& out, int k, double t, const Vector4d& s, const Eigen::Vector2d& zmp,
            double load, bool double_support) {
  const double w2 = step.omega * step.omega;
  const Eigen::Vector2d a = w2 * (s.head<2>() - zmp);
  out.time[k] = t;
  out.phase[static_cast<std::size_t>(k)] = double_support ? ContactPhase::kDoubleSupport : ContactPhase::kSingleSupport;
  out.com.col(k) << s[0], s[1], step.h + step.k * s[0];
  out.com_velocity.col(k) << s[2], s[3], step.k * s[2];
  out.com_acceleration.col(k) << a.x(), a.y(), step.k * a.x();
  out.zmp.col(k) << zmp.x(), zmp.y(), step.k * zmp.x();
  out.stance_load_fraction[k] = load;
}

// Double support: x = x_p + A cosh(wt) + B sinh(wt) with the particular solution x_p = p + p''/w^2 of the cubic
// ZMP p. Records samples 0 .. samples-1 if `out` is given; returns the state at t_ds.
Vector4d FlowDoubleSupport(const Step& step, const Vector4d& s0, WalkingPattern* out) {
  const double w = step.omega;
  const double T = step.t_ds;
  auto particular = [&](double t, Eigen::Vector2d* xp, Eigen::Vector2d* vp) {
    const double s = t / T;
    *xp = step.start + step.delta * (Blend(s) + BlendCurvature(s) / (T * T * w * w));
    *vp = step.delta * (BlendRate(s) / T + kBlendJerk / (T * T * T * w * w));
  };
  Eigen::Vector2d xp0, vp0;
  particular(0.0, &xp0, &vp0);
  const Eigen::Vector2d A = s0.head<2>() - xp0;
  const Eigen::Vector2d B = (s0.tail<2>() - vp0) / w;
  auto at = [&](double t) {
    Eigen::Vector2d xp, vp;
    particular(t, &xp, &vp);
    const double c = std::cosh(w * t), sh = std::sinh(w * t);
    Vector4d s;
    s.head<2>() = xp + A * c + B * sh;
    s.tail<2>() = vp + w * (A * sh + B * c);
    return s;
  };
  if (out != nullptr) {
    const int n = step.samples;
    for (int k = 0; k < n; ++k) {
      const double t = T * k / (n - 1);
      const double blend = Blend(t / T);
      Record(step, *out, k, t, at(t), step.start + step.delta * blend, blend, true);
    }
  }
  return at(T);
}

// Swing: ZMP fixed at the stance sole centre (the origin).
Vector4d FlowSwing(const Step& step, const Vector4d& s0, WalkingPattern* out) {
  const double w = step.omega;
  auto at = [&](double tau) {
    const double c = std::cosh(w * tau), sh = std::sinh(w * tau);
    Vector4d s;
    s.head<2>() = s0.head<2>() * c + s0.tail<2>() * (sh / w);
    s.tail<2>() = s0.head<2>() * (w * sh) + s0.tail<2>() * c;
    return s;
  };
  if (out != nullptr) {
    const int n = step.samples;
    for (int k = 0; k < n; ++k) {
      const double tau = step.t_sw * k / (n - 1);
      Record(step, *out, n + k, step.t_ds + tau, at(tau), Eigen::Vector2d::Zero(), 1.0, false);
    }
  }
  return at(step.t_sw);
}

Vector4d Flow(const Step& step, const Vector4d& s0, WalkingPattern* out) {
  return FlowSwing(step, FlowDoubleSupport(step, s0, out), out);
}

void CheckFinite(double value, const char* name) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string("GenerateWalkingPattern: ") + name + " is not finite.");
  }
}

}  // namespace

void GenerateWalkingPattern(const StepDisplacement& d, const StepParameters& p, double gravity,
                            const WalkingPatternOptions& options, WalkingPattern& pattern) {
  CheckFinite(d.dx, "dx");
  CheckFinite(d.dy, "dy");
  CheckFinite(d.dz, "dz");
  CheckFinite(d.dtheta, "dtheta");
  if (!(p.t_ds > 0.0) || !(p.t_sw > 0.0) || !(p.com_height > 0.0) || !std::isfinite(p.t_ds) ||
      !std::isfinite(p.t_sw) || !std::isfinite(p.com_height)) {
    throw std::invalid_argument("GenerateWalkingPattern: t_ds, t_sw and com_height must be positive and finite (got " +
                                cairn::FormatShort(p.t_ds) + ", " + cairn::FormatShort(p.t_sw) + ", " +
                                cairn::FormatShort(p.com_height) + ").");
  }
  if (!(gravity > 0.0) || !std::isfinite(gravity)) {
    throw std::invalid_argument("GenerateWalkingPattern: gravity must be positive and finite.");
  }
  if (options.samples_per_phase < 2) {
    throw std::invalid_argument("GenerateWalkingPattern: samples_per_phase must be >= 2 (got " +
                                cairn::FormatShort(options.samples_per_phase) + ").");
  }
  if (d.dz != 0.0 && d.dx == 0.0) {
    throw std::invalid_argument("GenerateWalkingPattern: dz = " + cairn::FormatShort(d.dz) +
                                " with dx = 0 has no periodic gait (each foot would land straight above its last "
                                "foothold); give the step a forward component.");
  }

  // Footholds. M maps f_j's frame to f_{j+1}'s frame mirrored in y, r' = S (r - c_next): the translation
  // part of the periodic gait (the yaw dtheta only turns the landing foot; see the header).
  Eigen::Matrix2d L;  // S = diag(1, -1)
  L << 1.0, 0.0, 0.0, -1.0;
  const Eigen::Vector2d c_next(d.dx, d.dy);
  const Eigen::Vector2d c_prev = L * (-c_next);  // the image of f_j's origin: (-dx, dy)
  pattern.displacement = d;
  pattern.parameters = p;
  pattern.stance_foot = Foothold{};
  pattern.next_foot = Foothold{Eigen::Vector3d(d.dx, d.dy, d.dz), d.dtheta};
  pattern.previous_foot = Foothold{Eigen::Vector3d(c_prev.x(), c_prev.y(), -d.dz), 0.0};

  const int n = options.samples_per_phase;
  const int total = 2 * n;
  if (pattern.time.size() != total) {
    pattern.time.resize(total);
    pattern.phase.resize(static_cast<std::size_t>(total));
    pattern.com.resize(3, total);
    pattern.com_velocity.resize(3, total);
    pattern.com_acceleration.resize(3, total);
    pattern.zmp.resize(3, total);
    pattern.stance_load_fraction.resize(total);
  }

  Step step;
  step.t_ds = p.t_ds;
  step.t_sw = p.t_sw;
  step.h = p.com_height;
  step.k = d.dz == 0.0 ? 0.0 : d.dz / d.dx;
  step.omega = std::sqrt(gravity / p.com_height);
  step.start = c_prev;
  step.delta = -c_prev;
  step.samples = n;
  pattern.slope = step.k;

  // Periodicity: with s(T) = Phi s(0) + s_p, require diag(L, L) s(T) + (-L c_next, 0) = s(0).
  const Vector4d s_p = Flow(step, Vector4d::Zero(), nullptr);
  Eigen::Matrix4d Phi;
  for (int i = 0; i < 4; ++i) Phi.col(i) = Flow(step, Vector4d::Unit(i), nullptr) - s_p;
  Eigen::Matrix4d L4 = Eigen::Matrix4d::Zero();
  L4.topLeftCorner<2, 2>() = L;
  L4.bottomRightCorner<2, 2>() = L;
  Vector4d b = Vector4d::Zero();
  b.head<2>() = -L * c_next;
  const Vector4d s0 = (Eigen::Matrix4d::Identity() - L4 * Phi).partialPivLu().solve(L4 * s_p + b);
  Flow(step, s0, &pattern);
}

WalkingPattern GenerateWalkingPattern(const StepDisplacement& d, const StepParameters& p, double gravity,
                                      const WalkingPatternOptions& options) {
  WalkingPattern pattern;
  GenerateWalkingPattern(d, p, gravity, options, pattern);
  return pattern;
}

}  // namespace cairn::planning
