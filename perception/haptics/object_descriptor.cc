#include "cairn/perception/haptics/object_descriptor.h"

#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception {

ObjectDescriptor::ObjectDescriptor() : ObjectDescriptor(AffordanceDescriptor::Options{}) {}

ObjectDescriptor::ObjectDescriptor(const AffordanceDescriptor::Options& options) : options_(options) {
  AffordanceDescriptor::Validate(options);
  DeclareAbstractInputPort("points_C", systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd(3, 0)));
  const AffordanceDescriptor::Options o = options;
  DeclareAbstractOutputPort(
      "descriptor", systems::Value<AffordanceDescriptor>(AffordanceDescriptor(options.lines)),
      [this, o](const systems::Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<AffordanceDescriptor>() =
            AffordanceDescriptor::Compute(get_points_input_port().Eval<Eigen::Matrix3Xd>(c), o);
      });
  DeclareAbstractOutputPort(
      "object_C", systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd(3, 0)),
      [this, o](const systems::Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<Eigen::Matrix3Xd>() =
            KeepWithinReach(DownsampleByMinDistance(get_points_input_port().Eval<Eigen::Matrix3Xd>(c),
                                                    o.min_point_distance),
                            o.reach_center_C, o.reach_radius);
      });
}

}  // namespace cairn::perception
