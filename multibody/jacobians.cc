#include <cairn/common/number_text.h>
#include <cairn/multibody/jacobians.h>

#include <stdexcept>
#include <string>

#include <cairn/multibody/joint_motion.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::multibody {

void FrameJacobian(const Model& model, const Data& data, int frame, ReferenceFrame reference,
                   Eigen::Ref<Eigen::MatrixXd> J) {
  if (J.rows() != 6 || J.cols() != model.nv()) {
    throw std::invalid_argument("FrameJacobian: J is " + cairn::FormatShort(J.rows()) + " x " + cairn::FormatShort(J.cols()) +
                                " but must be 6 x nv = 6 x " + cairn::FormatShort(model.nv()));
  }
  const Pose X_WF = FramePose(model, data, frame);
  const Eigen::Vector3d& p = X_WF.translation();
  const Eigen::Matrix3d R_FW = X_WF.rotation().transpose();
  J.setZero();
  for (int i = model.frames()[static_cast<std::size_t>(frame)].body; i > 0; i = model.parent(i)) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(i)];
    const Pose& X_WB = data.X_world[static_cast<std::size_t>(i)];
    for (int k = 0; k < joint.nv; ++k) {
      const Vector6d s = X_WB.ActMotion(internal::MotionSubspaceColumn(joint, k));
      auto column = J.col(joint.idx_v + k);
      switch (reference) {
        case ReferenceFrame::kWorld:
          column = s;
          break;
        case ReferenceFrame::kWorldAligned:
          column.head<3>() = s.head<3>();
          column.tail<3>() = s.tail<3>() + s.head<3>().cross(p);
          break;
        case ReferenceFrame::kLocal:
          column.head<3>() = R_FW * s.head<3>();
          column.tail<3>() = R_FW * (s.tail<3>() + s.head<3>().cross(p));
          break;
      }
    }
  }
}

void FrameJacobian(const Model& model, Data& data, const Eigen::Ref<const Eigen::VectorXd>& q, int frame,
                   ReferenceFrame reference, Eigen::Ref<Eigen::MatrixXd> J) {
  CheckSizes(model, data, "FrameJacobian", q.size());
  if (frame < 0 || frame >= model.num_frames()) {
    throw std::invalid_argument("FrameJacobian: frame index " + cairn::FormatShort(frame) + " is out of range [0, " +
                                cairn::FormatShort(model.num_frames()) + "); look frames up with Model::GetFrameIndex");
  }
  std::size_t depth = 0;
  for (int i = model.frames()[static_cast<std::size_t>(frame)].body; i > 0; i = model.parent(i)) {
    data.body_path[depth++] = i;
  }
  data.X_world[0] = Pose();
  while (depth > 0) {
    const int i = data.body_path[--depth];
    const std::size_t ui = static_cast<std::size_t>(i);
    const Joint& joint = model.joints()[ui];
    data.X_parent[ui] = internal::JointTransform(joint, q.data() + joint.idx_q);
    data.X_world[ui] = data.X_world[static_cast<std::size_t>(joint.parent)] * data.X_parent[ui];
  }
  FrameJacobian(model, data, frame, reference, J);
}

}  // namespace cairn::multibody
