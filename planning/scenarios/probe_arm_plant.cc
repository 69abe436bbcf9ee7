#include "cairn/planning/scenarios/probe_arm_plant.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/gravity_torques.h"
#include "cairn/multibody/plant/bullet_plant.h"
#include "cairn/multibody/plant/joint_pd_controller.h"
#include "cairn/multibody/urdf_parser.h"

namespace cairn::planning {
namespace {

// Thickness of the ground patch's box, m: far more than any probe depth.
constexpr double kPatchThickness = 0.5;
constexpr int kMaxSamples = 100000;

void CheckPositive(double value, const char* name, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("ProbeArmPlant: ") + name + " is " + FormatShort(value) + unit +
                                "; it must be finite and > 0");
  }
}

}  // namespace

ProbeArmPlant::ProbeArmPlant(multibody::Model arm, const Options& options)
    : arm_(std::move(arm)), options_(options) {
  CheckPositive(options.mount_height, "mount_height", " m");
  CheckPositive(options.clearance, "clearance", " m");
  CheckPositive(options.depth, "depth", " m");
  CheckPositive(options.push_time, "push_time", " s");
  CheckPositive(options.hold_time, "hold_time", " s");
  CheckPositive(options.time_step, "time_step", " s");
  CheckPositive(options.kp_rotary, "kp_rotary", " N m/rad");
  CheckPositive(options.kd_rotary, "kd_rotary", " N m s/rad");
  CheckPositive(options.kp_push, "kp_push", " N/m");
  CheckPositive(options.kd_push, "kd_push", " N s/m");
  CheckPositive(options.patch_size, "patch_size", " m");
  if (!(std::isfinite(options.noise) && options.noise >= 0.0)) {
    throw std::invalid_argument("ProbeArmPlant: noise is " + FormatShort(options.noise) +
                                " N; it must be finite and >= 0");
  }
  if (options.samples < 1 || options.samples > kMaxSamples) {
    throw std::invalid_argument("ProbeArmPlant: samples is " + FormatShort(options.samples) + "; it must lie in [1, " +
                                FormatShort(kMaxSamples) + "]");
  }
  const double steps = (options.push_time + options.hold_time) / options.time_step;
  if (!(steps <= kMaxSteps)) {
    throw std::invalid_argument("ProbeArmPlant: (push_time + hold_time) / time_step is " + FormatShort(steps) +
                                " steps, more than the limit of " + FormatShort(kMaxSteps) +
                                "; use a shorter probe or a longer step");
  }
  if (options.samples > static_cast<int>(options.hold_time / options.time_step)) {
    throw std::invalid_argument("ProbeArmPlant: " + FormatShort(options.samples) + " samples do not fit in the " +
                                FormatShort(static_cast<int>(options.hold_time / options.time_step)) +
                                " steps of the hold; lengthen hold_time or take fewer samples");
  }
  const char* const joints[] = {"yaw", "pitch", "push"};
  for (int k = 0; k < 3; ++k) {
    if (!arm_.HasJoint(joints[k]) || arm_.joint(arm_.GetJointIndex(joints[k])).idx_v != k) {
      throw std::invalid_argument("ProbeArmPlant: model '" + arm_.name() + "' needs the joints yaw, pitch, push as " +
                                  "its velocity coordinates 0, 1, 2 (data/robots/cairn_probe_arm.urdf)");
    }
  }
  if (arm_.nv() != 3 || arm_.joint(1).type != multibody::JointType::kFixed) {
    throw std::invalid_argument("ProbeArmPlant: model '" + arm_.name() + "' has " + FormatShort(arm_.nv()) +
                                " velocity coordinates; the arm must be welded to the world with exactly yaw, pitch "
                                "and push");
  }
  if (!arm_.HasBody("tip") || arm_.body(arm_.GetBodyIndex("tip")).collisions.size() != 1 ||
      arm_.body(arm_.GetBodyIndex("tip")).collisions[0].type != multibody::GeometryType::kSphere) {
    throw std::invalid_argument("ProbeArmPlant: model '" + arm_.name() +
                                "' needs a body 'tip' with exactly one collision sphere");
  }
  tip_body_ = arm_.GetBodyIndex("tip");
  tip_radius_ = arm_.body(tip_body_).collisions[0].radius;
  const multibody::Joint& push = arm_.joint(arm_.GetJointIndex("push"));
  push_min_ = push.lower_limit;
  push_max_ = push.upper_limit;
  if (!(std::isfinite(push_min_) && std::isfinite(push_max_))) {
    throw std::invalid_argument("ProbeArmPlant: the push joint of '" + arm_.name() + "' needs finite limits");
  }
}

ProbeArmPlant ProbeArmPlant::Load(const std::string& urdf_path, const Options& options) {
  return ProbeArmPlant(multibody::ParseUrdfFile(urdf_path), options);
}

double ProbeArmPlant::reach() const {
  const double h = options_.mount_height;
  const double s = push_max_ * h / (h - tip_radius_ + options_.depth);
  return s > h ? std::sqrt(s * s - h * h) : 0.0;
}

ProbeArmPlant::Probe ProbeArmPlant::Run(const Eigen::Vector2d& base, const Eigen::Vector2d& target,
                                        const Ground& ground, std::mt19937* rng) const {
  if (!(ground.stiffness >= 0.0)) {
    throw std::invalid_argument("ProbeArmPlant: ground stiffness " + FormatShort(ground.stiffness) +
                                " N/m must be >= 0 (0: no support, infinity: rigid)");
  }
  if (!(std::isfinite(ground.damping) && ground.damping >= 0.0)) {
    throw std::invalid_argument("ProbeArmPlant: ground damping " + FormatShort(ground.damping) +
                                " N s/m must be finite and >= 0");
  }
  if (!std::isfinite(ground.height) || !base.allFinite() || !target.allFinite()) {
    throw std::invalid_argument("ProbeArmPlant: the base, target and ground height must be finite");
  }
  const Options& o = options_;
  // The plant's world is the robot's base frame, translated: the base is welded at its origin.
  const Eigen::Vector2d d_xy = target - base;
  const double d = d_xy.norm();
  const double drop = o.mount_height - ground.height;
  if (!(drop > tip_radius_ + o.clearance)) {
    throw std::invalid_argument("ProbeArmPlant: the ground at the target is " + FormatShort(ground.height) +
                                " m high, too close to the arm's base at " + FormatShort(o.mount_height) + " m");
  }
  const double yaw = std::atan2(d_xy.y(), d_xy.x());
  const double pitch = std::atan2(drop, d);
  const double sin_pitch = std::sin(pitch);
  const double s_touch = (drop - tip_radius_) / sin_pitch;
  const double s_start = s_touch - o.clearance;
  const double s_push = (drop - tip_radius_ + o.depth) / sin_pitch;
  if (s_push > push_max_ || s_start < push_min_) {
    throw std::invalid_argument("ProbeArmPlant: the target is " + FormatShort(d) +
                                " m from the base, beyond the arm's reach of " + FormatShort(reach()) +
                                " m; move the robot closer");
  }

  std::vector<multibody::TerrainBox> terrain;
  if (ground.stiffness > 0.0) {
    multibody::TerrainBox box;
    box.name = "probed ground";
    box.size = Eigen::Vector3d(o.patch_size, o.patch_size, kPatchThickness);
    // The patch's centre is a quarter side off the target: with the tip straight above the box's centre, Bullet's
    // soft contact pushed back with twice k x depth (measured: 29.6 N instead of 14.9 N at 750 N/m and 2 cm).
    const double off = 0.25 * o.patch_size;
    box.X_WB = multibody::Pose(Eigen::Matrix3d::Identity(),
                               Eigen::Vector3d(d_xy.x() + off, d_xy.y() + off, -drop - 0.5 * kPatchThickness));
    if (std::isfinite(ground.stiffness)) {
      box.contact_stiffness = ground.stiffness;
      box.contact_damping = ground.damping;
    }
    terrain.push_back(box);
  }
  multibody::BulletPlantOptions plant_options;
  plant_options.time_step = o.time_step;
  multibody::BulletPlant plant(arm_, terrain, plant_options);
  const Eigen::Vector3d kp(o.kp_rotary, o.kp_rotary, o.kp_push);
  const Eigen::Vector3d kd(o.kd_rotary, o.kd_rotary, o.kd_push);
  const multibody::JointPdController pd(arm_, kp, kd);
  multibody::Data data(arm_);

  Eigen::VectorXd q(3), v = Eigen::VectorXd::Zero(3);
  q << yaw, pitch, s_start;
  plant.SetState(q, v);
  const int push_steps = static_cast<int>(std::ceil(o.push_time / o.time_step));
  const int hold_steps = static_cast<int>(std::ceil(o.hold_time / o.time_step));
  const double rate = (s_push - s_start) / (push_steps * o.time_step);
  std::normal_distribution<double> unit(0.0, 1.0);
  Probe probe;
  Eigen::VectorXd q_ref = q, v_ref = v;
  int next_sample = 1;
  for (int step = 1; step <= push_steps + hold_steps; ++step) {
    if (step <= push_steps) {
      q_ref[2] = s_start + rate * step * o.time_step;
      v_ref[2] = rate;
    } else {
      q_ref[2] = s_push;
      v_ref[2] = 0.0;
    }
    q = plant.positions();
    v = plant.velocities();
    plant.Step(pd.Torques(q, v, q_ref, v_ref, multibody::GravityTorques(arm_, data, q)));
    // Readings at equal intervals through the hold, the last at its end.
    const int hold_step = step - push_steps;
    if (hold_step > 0 && static_cast<std::int64_t>(hold_step) * o.samples >=
                             static_cast<std::int64_t>(next_sample) * hold_steps) {
      double force = 0.0;
      int points = 0;
      for (const multibody::ContactPoint& c : plant.contacts()) {
        if (c.body != tip_body_) continue;
        force += c.normal_force;
        ++points;
      }
      probe.max_contact_points = std::max(probe.max_contact_points, points);
      probe.true_forces.push_back(force);
      probe.forces.push_back(force + o.noise * unit(*rng));
      ++next_sample;
    }
  }
  q = plant.positions();
  probe.final_depth = q[2] * std::sin(q[1]) + tip_radius_ - drop;
  probe.steps = push_steps + hold_steps;
  probe.simulated_time = plant.time();
  return probe;
}

}  // namespace cairn::planning
