#pragma once

/// @file
/// Forward kinematics: body poses, twists and accelerations, and frame poses.

#include <Eigen/Core>

#include <cairn/multibody/data.h>
#include <cairn/multibody/model.h>
#include <cairn/multibody/pose.h>

namespace cairn::multibody {

/// Computes every body's pose (data.X_parent, data.X_world) at configuration q.
/// Throws std::invalid_argument if q has the wrong size or a floating joint's quaternion is not unit length.
void ForwardKinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q);

/// Also computes every body's twist (data.v, body frame).
void ForwardKinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                       const Eigen::Ref<const Eigen::VectorXd>& v);

/// Also computes every body's spatial acceleration (data.a, body frame, without gravity).
void ForwardKinematics(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q,
                       const Eigen::Ref<const Eigen::VectorXd>& v, const Eigen::Ref<const Eigen::VectorXd>& a);

/// Pose X_WF of frame `frame` in the world, from the poses of the last ForwardKinematics.
Pose FramePose(const Model& model, const Data& data, int frame);

/// Twist of frame `frame` expressed in the frame itself (needs ForwardKinematics with velocities).
Vector6d FrameVelocity(const Model& model, const Data& data, int frame);

/// Throws std::invalid_argument unless `data` was made for `model` and q, v (when given) have its sizes.
/// `caller` names the algorithm in the message.
void CheckSizes(const Model& model, const Data& data, const char* caller, Eigen::Index q_size, Eigen::Index v_size = -1,
                Eigen::Index a_size = -1);

}  // namespace cairn::multibody
