#pragma once

// The project's humanoid walking a stabilised reference in the Bullet plant under joint PD tracking, outside a
// diagram: flat ground of friction 0.8, the reference interpolated linearly between its samples, then one second
// holding its last sample. An optional correction sits between the reference and the drive, as BalanceFeedback
// does in the walk diagram.

#include <cmath>
#include <functional>
#include <string>

#include <Eigen/Core>

#include <cairn/multibody/plant/bullet_plant.h>
#include <cairn/multibody/plant/contact_monitor.h>
#include <cairn/multibody/plant/joint_pd_controller.h>
#include <cairn/planning/stabilization/stabilized_trajectory.h>

#include "../trajectory/test_robot.h"
#include "test_paths.h"

namespace cairn::planning::test {

struct PlantWalk {
  bool fell{false};
  double fall_time{0.0};
  Eigen::Vector3d left_sole, right_sole;  // where the soles ended
};

/// Maps the reference [q; v], the plant's [q; v] and whether the left and right soles are loaded to the [q; v] the
/// PD drive tracks.
using ReferenceCorrection = std::function<Eigen::VectorXd(const Eigen::VectorXd& reference, const Eigen::VectorXd& state,
                                                          bool left_loaded, bool right_loaded)>;

inline PlantWalk WalkInPlant(const StabilizedTrajectory& reference, const ReferenceCorrection& correction = {}) {
  const auto model = Humanoid();
  const multibody::JointPdController pd = multibody::JointPdController::Load(
      *model, std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid_control.yaml");
  multibody::TerrainBox ground;
  ground.name = "ground";
  ground.X_WB = multibody::Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, -0.5));
  ground.size = Eigen::Vector3d(20.0, 20.0, 1.0);
  ground.friction = 0.8;
  multibody::BulletPlant plant(*model, {ground});
  multibody::ContactMonitor monitor(plant, {"l_sole", "r_sole"}, "pelvis");
  plant.SetState(reference.q.front(), reference.v.front());
  const double dt = plant.options().time_step;
  const auto steps = static_cast<int>(std::ceil((reference.duration() + 1.0) / dt));
  const int nq = model->nq(), nv = model->nv();
  Eigen::VectorXd x_ref(nq + nv), x(nq + nv);
  for (int k = 0; k < steps && !monitor.fallen(); ++k) {
    const double u = k * dt / reference.period;
    const auto i = static_cast<std::size_t>(u);
    x_ref << reference.q.back(), Eigen::VectorXd::Zero(nv);
    if (i + 1 < reference.q.size()) {
      const double a = u - static_cast<double>(i);
      x_ref << (1.0 - a) * reference.q[i] + a * reference.q[i + 1], (1.0 - a) * reference.v[i] + a * reference.v[i + 1];
    }
    if (correction) {
      x << plant.positions(), plant.velocities();
      x_ref = correction(x_ref, x, monitor.soles()[0].loaded, monitor.soles()[1].loaded);
    }
    const Eigen::VectorXd tau = pd.Torques(plant.positions(), plant.velocities(), x_ref.head(nq), x_ref.tail(nv));
    plant.Step(tau);
    monitor.Update(plant, tau);
  }
  return {monitor.fallen(), monitor.fall_time(), monitor.soles()[0].position, monitor.soles()[1].position};
}

}  // namespace cairn::planning::test
