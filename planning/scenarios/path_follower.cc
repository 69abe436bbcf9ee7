#include "cairn/planning/scenarios/path_follower.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/discrete_values.h"

namespace cairn::planning {

PathFollower::PathFollower(const Eigen::Vector2d& start, double step, double period) : step_(step) {
  if (!(step > 0.0) || !(period > 0.0) || !std::isfinite(step) || !std::isfinite(period)) {
    throw std::invalid_argument("PathFollower: step " + FormatShort(step) + " m and period " + FormatShort(period) +
                                " s must be positive and finite");
  }
  DeclareAbstractInputPort("path", systems::Value<Eigen::Matrix2Xd>(Eigen::Matrix2Xd()));
  DeclareVectorInputPort("pause", 1);
  const int state = DeclareDiscreteState(start);
  DeclareStateOutputPort("position", state);
  DeclarePeriodicDiscreteUpdateEvent(period, 0.0, [this](const systems::Context& c, systems::DiscreteValues* next) {
    if (get_pause_input_port().Eval<Eigen::VectorXd>(c)[0] >= 0.5) return;
    const auto& path = get_path_input_port().Eval<Eigen::Matrix2Xd>(c);
    Eigen::Vector2d p = next->value(0);
    double left = step_;
    for (Eigen::Index k = 1; k < path.cols() && left > 1e-12; ++k) {
      const Eigen::Vector2d d = path.col(k) - p;
      const double n = d.norm();
      if (n <= left) {
        p = path.col(k);
        left -= n;
      } else {
        p += d * (left / n);
        left = 0.0;
      }
    }
    next->set_value(0, p);
  });
}

}  // namespace cairn::planning
