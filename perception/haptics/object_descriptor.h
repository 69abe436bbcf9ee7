#pragma once

/// @file
/// ObjectDescriptor: the §3.3 descriptor of the object in view, as a block-diagram system.

#include <Eigen/Core>

#include "cairn/perception/haptics/affordance_descriptor.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// Computes the object descriptor of the cloud on its input, and the object's points the descriptor was built
/// from (down-sampled and within the antenna's reach), which the interaction planner scores.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `points_C` | Eigen::Matrix3Xd | the depth sensor's points in its frame C |
/// | output `descriptor` | AffordanceDescriptor | eq. 6 |
/// | output `object_C` | Eigen::Matrix3Xd | the points after the 1 cm down-sampling and the reach cut |
///
/// Stateless; both outputs depend on the input only (direct feedthrough). (A point matrix is an abstract value:
/// fix the input with FixAbstractValue(context, systems::Value<Eigen::Matrix3Xd>(points)), since FixValue turns
/// Eigen objects into vector-port values.)
class ObjectDescriptor final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for invalid options.
  explicit ObjectDescriptor(const AffordanceDescriptor::Options& options);
  /// The paper's options.
  ObjectDescriptor();

  const AffordanceDescriptor::Options& options() const { return options_; }

  const systems::InputPort& get_points_input_port() const { return get_input_port(0); }
  const systems::OutputPort& get_descriptor_output_port() const { return get_output_port(0); }
  const systems::OutputPort& get_object_output_port() const { return get_output_port(1); }

 private:
  AffordanceDescriptor::Options options_;
};

}  // namespace cairn::perception
