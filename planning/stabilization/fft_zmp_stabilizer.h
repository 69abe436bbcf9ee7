#pragma once

#include <string>

#include <Eigen/Core>

#include <cairn/planning/stabilization/zmp_stabilizer.h>

namespace cairn::planning {

/// The thesis' compensation (2.5.1c, the Takanishi lab's method of its reference [119]) in the frequency domain:
/// the error e_k is padded with `padding` s of zeros on both sides (the robot at rest: the periodic solution of
/// the DFT then wraps through a rest rather than from the end to the start) up to a power of two, N samples, and
/// transformed; with w_n = 2 pi n / (N dt) (n taken as the signed frequency index) the linearised ZMP equation
/// dp = dx - (z_c/g) dx'' becomes DP_n = (1 + (z_c/g) w_n^2) DX_n, so
///   DX_n = E_n / (1 + (z_c / g) w_n^2),
/// the inverse transform gives dx over the padded window and its middle part the offsets. Non-causal by design:
/// the COM starts moving before the error it cancels, as the whole trajectory is known. Every dx satisfies the
/// linear equation exactly on the padded periodic window, so the remaining error is the model's nonlinearity
/// (the multibody ZMP is not the cart-table's), which the outer iteration removes.
class FftZmpStabilizer final : public ZmpStabilizer {
 public:
  /// Largest padded transform, samples.
  static constexpr long long kMaxTransformSize = 1LL << 22;

  /// Throws std::invalid_argument unless gravity is positive and finite and padding in [0, 10] s.
  explicit FftZmpStabilizer(double gravity = 9.81, double padding = 2.0);

  std::string name() const override { return "fft"; }
  Eigen::VectorXd ComOffsets(const Eigen::VectorXd& error, double period, double com_height) const override;

 private:
  double gravity_;
  double padding_;
};

}  // namespace cairn::planning
