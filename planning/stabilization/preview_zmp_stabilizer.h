#pragma once

#include <string>

#include <Eigen/Core>

#include <cairn/planning/stabilization/zmp_stabilizer.h>

namespace cairn::planning {

/// Kajita's preview control as the offset solver (Kajita et al. 2003): the cart-table COM that a
/// CartTablePreviewController starting at rest drives along the ZMP error e_k (its "reference ZMP") is the
/// offset dx_k; its cart-table ZMP dx - (z_c/g) dx'' tracks e with the controller's preview. Causal: dx_0 = 0.
class PreviewZmpStabilizer final : public ZmpStabilizer {
 public:
  /// Throws std::invalid_argument as CartTablePreviewController does for the parameters.
  PreviewZmpStabilizer(double gravity = 9.81, double preview = 1.6, double q = 1.0, double r = 1e-6);

  std::string name() const override { return "preview"; }
  Eigen::VectorXd ComOffsets(const Eigen::VectorXd& error, double period, double com_height) const override;

 private:
  double gravity_, preview_, q_, r_;
};

}  // namespace cairn::planning
