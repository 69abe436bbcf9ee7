#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

#include <cairn/planning/stabilization/stabilizer_options.h>

namespace cairn::planning {

/// One way to turn a ZMP error into a horizontal COM correction, the step the two stabilisers of thesis 2.5.1c
/// differ in (the rest, leg inverse kinematics and the full model's ZMP, is shared by StabilizeTrajectory). Both
/// solve the linearised ZMP equation of a COM at height z_c,
///   dp = dx - (z_c / g) dx'',
/// for the offset dx(t) whose ZMP change dp is the error e = p_ref - p over the whole trajectory, per axis.
class ZmpStabilizer {
 public:
  virtual ~ZmpStabilizer() = default;

  /// "fft" or "preview".
  virtual std::string name() const = 0;

  /// The COM offsets dx_k (one per sample, `period` s apart) for the ZMP error e_k, with the COM `com_height`
  /// above the ground. Throws std::invalid_argument for an empty or non-finite error or a height that is not
  /// positive and finite.
  virtual Eigen::VectorXd ComOffsets(const Eigen::VectorXd& error, double period, double com_height) const = 0;
};

/// The stabiliser called `options.method` ("fft": FftZmpStabilizer, "preview": PreviewZmpStabilizer) with the
/// options' parameters and gravity `gravity` (m/s^2). Throws std::invalid_argument for another name (listing
/// the two) and for options out of range.
std::unique_ptr<ZmpStabilizer> MakeZmpStabilizer(const StabilizerOptions& options, double gravity = 9.81);

}  // namespace cairn::planning
