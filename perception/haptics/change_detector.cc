#include "cairn/perception/haptics/change_detector.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::perception {

ChangeDetector::ChangeDetector(const GistChangeDetector::Options& options, double period) : period_(period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ChangeDetector: period " + FormatShort(period) +
                                " s must be positive and finite (one progression step, e.g. 0.5)");
  }
  DeclareAbstractInputPort("points_C", systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd(3, 0)));
  detector_state_ = DeclareAbstractState(systems::Value<GistChangeDetector>(GistChangeDetector(options)));
  result_state_ = DeclareDiscreteState(Eigen::Vector3d::Zero());
  DeclareStateOutputPort("change", result_state_);
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &ChangeDetector::Update);
}

void ChangeDetector::Update(const systems::Context& context, systems::State* next) const {
  const Eigen::Matrix3Xd& points = get_points_input_port().Eval<Eigen::Matrix3Xd>(context);
  GistChangeDetector& detector = next->get_mutable_abstract_state<GistChangeDetector>(detector_state_);
  Eigen::VectorXd& result = next->get_mutable_discrete_state().get_mutable_value(result_state_);
  if (!detector.has_reference()) {
    detector.SetReference(points);
    result << detector.reference_gist(), 0.0, 0.0;
    return;
  }
  const GistChangeDetector::Result r = detector.Compare(points);
  result << r.gist, r.difference, r.changed ? 1.0 : 0.0;
}

}  // namespace cairn::perception
