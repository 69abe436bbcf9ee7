#include <cairn/planning/stabilization/preview_zmp_stabilizer.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include <cairn/common/number_text.h>
#include <cairn/planning/stabilization/cart_table_preview_controller.h>

namespace cairn::planning {

PreviewZmpStabilizer::PreviewZmpStabilizer(double gravity, double preview, double q, double r)
    : gravity_(gravity), preview_(preview), q_(q), r_(r) {
  // Validates the parameters once, at construction.
  CartTablePreviewController(0.005, 0.8, gravity_, preview_, q_, r_);
}

Eigen::VectorXd PreviewZmpStabilizer::ComOffsets(const Eigen::VectorXd& error, double period,
                                                 double com_height) const {
  if (error.size() == 0 || !error.allFinite()) {
    throw std::invalid_argument("PreviewZmpStabilizer::ComOffsets: the ZMP error must be non-empty and finite");
  }
  const CartTablePreviewController controller(period, com_height, gravity_, preview_, q_, r_);
  return controller.Track(error).position;
}

}  // namespace cairn::planning
