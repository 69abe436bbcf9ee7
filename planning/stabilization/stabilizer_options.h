#pragma once

#include <string>

namespace cairn::planning {

/// Most samples a stabilised trajectory may hold (duration / control_period), checked before allocating.
inline constexpr long long kMaxStabilizationSamples = 200000;

/// Parameters of interpolation and ZMP stabilisation (thesis 2.5.1c). Defaults: 200 Hz, Hermite, the thesis'
/// FFT compensation; the preview-control defaults are Kajita 2003's common values.
struct StabilizerOptions {
  /// "fft" (the thesis' iterative frequency-domain compensation), "preview" (Kajita's preview control on the
  /// cart-table model) or "none" (interpolation only).
  std::string method{"fft"};
  /// "hermite" (cubic with zero derivatives at the knots, the thesis) or "spline" (natural C2 cubic spline).
  std::string interpolation{"hermite"};
  /// Sampling period of the dense reference, s, in [1e-4, 0.05].
  double control_period{0.005};
  /// False (the thesis): the optimiser's waypoints are interpolated at their own times and the reference ZMP is
  /// their interpolated COM projection. True: the knots are re-timed to the plan's contact events (the swing foot
  /// leaves the ground at lift-off, not at the stance's start), the reference ZMP stays over the stance foot until
  /// touch-down (MakeInterpolationKnots), and every sample is rebuilt by PelvisPoseSolver: soles still on the
  /// ground in double support, the swing sole on a minimum-jerk path with the mid-swing waypoint's apex, the waist
  /// at its orientation (see waist_orientation) and `crouch` below the interpolated height. Without the thesis'
  /// timing the reference ZMP leaves the stance foot in the second half of every swing, and no walk in the plant
  /// survives it; with contact timing, crouch 0.06 m, an upright waist and cart_table_start the compensation
  /// converges to a ZMP inside the support polygons and the four-step test plan is walked (docs/stabilization.md).
  bool contact_timing{false};
  /// Start the compensation from the COM that the cart-table model (x - (z_c / g) x'' = p_ref) says realises the
  /// reference ZMP, applied in full, before the full-model passes.
  bool cart_table_start{false};
  /// With contact timing: lower the waist by this much below the interpolated postures' (m, in [0, 0.3]); bent
  /// knees keep the legs away from their stretched singularity while the COM moves between the feet.
  double crouch{0.0};
  /// With contact timing: the swing sole's last `landing_height` (m, in [0, 0.1]) is a straight descent at the
  /// constant speed landing_height / landing_time (landing_time in s, in [0, 1] and at most half of each swing,
  /// which StabilizeTrajectory checks): its horizontal motion, turn and the apex path end landing_time before
  /// touch-down at that height above the touch-down pose, at rest. A sole that runs a few millimetres below its reference touches the ground early;
  /// on the swing's quadratic approach (the default 0, 0) it then meets it at 15-20 cm/s, on this descent at
  /// landing_height / landing_time whatever the error below landing_height (docs/walk.md, "Touchdown and RCOF").
  double landing_height{0.0};
  double landing_time{0.0};
  /// Compensation passes (each: ZMP from the full model, COM offsets, leg IK), in [1, 100].
  int max_iterations{8};
  /// Fraction of each pass's COM offsets applied, in (0, 1]: the full model is far from the linear ZMP equation
  /// at walking speed (the swing leg, the arms, the waist), and full steps overshoot.
  double step_fraction{0.5};
  /// Stop when the RMS ZMP error falls below this, m (> 0).
  double tolerance{1e-3};
  /// Stop when a pass improves the RMS error by less than this fraction of it, in [0, 1).
  double min_improvement{0.02};
  /// Preview horizon, s, in (0, 5].
  double preview_time{1.6};
  /// Weight of the ZMP error (Q) and of the jerk increment (R) of the preview controller (> 0).
  double preview_q{1.0};
  double preview_r{1e-6};
  /// Zero-error padding on each side of the trajectory before the FFT, s, in [0, 10]: the periodic solution
  /// then wraps through a rest, not from the end to the start.
  double fft_padding{2.0};
  /// Sole rectangle (length, width), m, centred on the sole frames: the support polygons of the report.
  double sole_length{0.24};
  double sole_width{0.14};
  std::string left_sole_frame{"l_sole"};
  std::string right_sole_frame{"r_sole"};
  /// Orientation of the waist (floating base) in the compensated motion: "interpolated" keeps the optimiser's
  /// (interpolated on the sphere), "upright" turns it to zero roll and pitch with the yaw half-way between the
  /// soles' (the optimiser leaves the waist's pitch and yaw free, and its waypoints swing them by tens of degrees
  /// between consecutive waypoints; that swing's angular momentum moves the ZMP by decimetres, which no COM shift
  /// cancels, but turning it upright moves the whole upper body and, measured on the flat test trajectory, makes
  /// the compensation worse). The upper body keeps its joint angles relative to the waist either way.
  std::string waist_orientation{"interpolated"};
  /// Waist frame kept at zero roll by the leg inverse kinematics.
  std::string waist_frame{"pelvis"};
};

/// The defaults with the settings a walk in the plant needs (docs/stabilization.md, "Walking it in the plant"):
/// contact timing, an upright waist, the cart-table start, a 6 cm crouch and a landing phase of 1 cm over 0.15 s
/// (docs/walk.md, "Touchdown and RCOF"), with `method`. The defaults stay the thesis' procedure; these are the
/// ones measured to walk the plans in the plant with the balance feedback (the four-step test plan, open loop,
/// walks better without the landing phase: plant_walk_test.cc).
StabilizerOptions WalkingStabilizerOptions(const std::string& method = "fft");

/// Throws std::invalid_argument naming the first option out of range and its valid range.
void ValidateStabilizerOptions(const StabilizerOptions& options);

}  // namespace cairn::planning
