#pragma once

#include <memory>

#include <cairn/multibody/model.h>
#include <cairn/planning/stabilization/stabilized_trajectory.h>
#include <cairn/planning/stabilization/stabilizer_options.h>
#include <cairn/planning/trajectory/whole_body_trajectory.h>

namespace cairn::planning {

/// Interpolates and stabilises a whole-body trajectory (thesis 2.5.1c):
///  1. knots (MakeInterpolationKnots) interpolated (TrajectoryInterpolator) and sampled every control_period;
///     the reference ZMP p_ref is the interpolated COM projection of the knots (inside the support polygons at
///     the knots, as problem 2.9 constrains them);
///  2. the ZMP p of the sampled motion from the full model (ComputeMotionZmp, on the plane of the loaded soles);
///  3. unless the method is "none", passes i = 1..max_iterations of: e = p_ref - p; COM offsets
///     d_i = d_i-1 + ZmpStabilizer::ComOffsets(e) per horizontal axis (z_c the mean COM height above the soles);
///     every interpolated sample shifted by leg inverse kinematics (ComShiftSolver: both soles at their
///     interpolated poses, the waist orientation and the upper body as interpolated, the COM's projection at its
///     interpolated value + d_i); p recomputed from the full model. A pass is kept only if it
///     lowers the RMS error; the iteration stops below options.tolerance, when a pass gains less than
///     options.min_improvement of the error, or after max_iterations;
///  4. velocities by central differences of the kept samples.
///
/// Throws std::invalid_argument for a null model, options out of range, a trajectory MakeInterpolationKnots
/// rejects, or more than kMaxStabilizationSamples samples. Samples whose motion would need a pulling ground
/// (f_z <= 0) have no ZMP: they are counted in the report, left out of the error statistics, take the error of
/// the nearest earlier sample in the compensation, and a pass that leaves fewer of them is kept.
StabilizedTrajectory StabilizeTrajectory(std::shared_ptr<const multibody::Model> model,
                                         const WholeBodyTrajectory& trajectory,
                                         const StabilizerOptions& options = StabilizerOptions());

}  // namespace cairn::planning
