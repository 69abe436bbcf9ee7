#pragma once

/// @file
/// Frame Jacobians (6 x nv, angular rows first) mapping v to a frame's twist.

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// How a frame Jacobian expresses the frame's twist.
enum class ReferenceFrame {
  kLocal,         ///< Twist of the frame in the frame's own axes, linear part = velocity of the frame origin.
  kWorldAligned,  ///< Same twist in world axes: [ω_W; velocity of the frame origin in world axes].
  kWorld,         ///< Spatial twist in the world frame (linear part = velocity of the point at the world origin).
};

/// Fills J (6 x nv) with the Jacobian of frame `frame` from the poses of the last ForwardKinematics; columns
/// of joints that do not move the frame are zero. No allocation. Throws std::invalid_argument on a wrong J size
/// or frame index.
void FrameJacobian(const Model& model, const Data& data, int frame, ReferenceFrame reference,
                   Eigen::Ref<Eigen::MatrixXd> J);

/// Computes the poses of `frame`'s body and its ancestors only (data.X_world for those bodies; the others are
/// left as they were) from q, then fills J as above: the cheapest way to one Jacobian at a new configuration.
void FrameJacobian(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q, int frame,
                   ReferenceFrame reference, Eigen::Ref<Eigen::MatrixXd> J);

}  // namespace cairn::multibody
