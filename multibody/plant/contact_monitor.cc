#include <cairn/multibody/plant/contact_monitor.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <cairn/common/number_text.h>
#include <cairn/multibody/dynamics.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::multibody {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void CheckPositive(double value, const char* name) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument("ContactMonitor: option " + std::string(name) + " is " + FormatShort(value) +
                                "; it must be finite and > 0");
  }
}

void CheckNonNegative(double value, const char* name) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw std::invalid_argument("ContactMonitor: option " + std::string(name) + " is " + FormatShort(value) +
                                "; it must be finite and >= 0");
  }
}

}  // namespace

ContactMonitor::ContactMonitor(const BulletPlant& plant, const std::vector<std::string>& sole_bodies,
                               const std::string& base_body, std::vector<JointDrive> drives,
                               const ContactMonitorOptions& options)
    : options_(options), drives_(std::move(drives)), model_(plant.model()), data_(model_),
      net_force_(Eigen::Vector3d::Zero()), zmp_(Eigen::Vector3d::Constant(kNaN)), fall_time_(kNaN) {
  CheckPositive(options.loaded_force, "loaded_force");
  CheckPositive(options.slip_speed, "slip_speed");
  CheckPositive(options.slip_distance, "slip_distance");
  CheckNonNegative(options.stance_gap, "stance_gap");
  CheckNonNegative(options.touchdown_time, "touchdown_time");
  if (options.stance_gap > 1.0 || options.touchdown_time > 1.0) {
    throw std::invalid_argument("ContactMonitor: stance_gap " + FormatShort(options.stance_gap) +
                                " s and touchdown_time " + FormatShort(options.touchdown_time) +
                                " s must be at most 1 s (longer would merge or skip whole steps)");
  }
  CheckNonNegative(options.force_filter_time, "force_filter_time");
  CheckPositive(options.fall_base_height, "fall_base_height");
  CheckPositive(options.fall_tilt, "fall_tilt");
  CheckPositive(options.fall_contact_force, "fall_contact_force");
  if (sole_bodies.size() != 2) {
    throw std::invalid_argument("ContactMonitor: " + FormatShort(sole_bodies.size()) +
                                " sole bodies given; name the left and the right sole");
  }
  if (!drives_.empty() && drives_.size() != static_cast<std::size_t>(model_.nv())) {
    throw std::invalid_argument("ContactMonitor: " + FormatShort(drives_.size()) + " joint drives given, but '" +
                                model_.name() + "' has " + FormatShort(model_.nv()) + " velocity coordinates");
  }
  for (const std::string& name : sole_bodies) {
    const int body = model_.GetBodyIndex(name);
    sole_bodies_.push_back(body);
    foot_bodies_.push_back(plant.merged_body(body));
  }
  base_body_ = model_.GetBodyIndex(base_body);
  soles_.assign(2, SoleState());
  has_previous_.assign(2, false);
  slide_distance_.assign(2, 0.0);
  slide_reported_.assign(2, false);
  open_stance_.assign(2, -1);
}

void ContactMonitor::Fall(double time, const std::string& reason) {
  if (fallen_) return;
  fallen_ = true;
  fall_time_ = time;
  fall_reason_ = reason;
}

void ContactMonitor::Update(const BulletPlant& plant, const Eigen::Ref<const Eigen::VectorXd>& tau) {
  if (tau.size() != model_.nv()) {
    throw std::invalid_argument("ContactMonitor: tau has size " + FormatShort(tau.size()) + ", but the model needs " +
                                FormatShort(model_.nv()));
  }
  const double time = plant.time();
  const double dt = plant.options().time_step;
  const Eigen::VectorXd q = plant.positions();
  const Eigen::VectorXd v = plant.velocities();
  ForwardKinematics(model_, data_, q);

  // Per-sole wrenches and the ZMP.
  std::vector<Eigen::Vector3d> normal_sum(2, Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> weighted_points(2, Eigen::Vector3d::Zero());
  std::vector<double> normal_total(2, 0.0);
  Eigen::Vector3d total_force = Eigen::Vector3d::Zero();
  for (int f = 0; f < 2; ++f) soles_[static_cast<std::size_t>(f)].force.setZero();
  for (const ContactPoint& contact : plant.contacts()) {
    const Eigen::Vector3d force = contact.normal_force * contact.normal + contact.tangential_force;
    total_force += force;
    int foot = -1;
    for (int f = 0; f < 2; ++f) {
      if (contact.body == foot_bodies_[static_cast<std::size_t>(f)]) foot = f;
    }
    if (foot < 0) {
      if (contact.normal_force > options_.fall_contact_force) {
        Fall(time, "body '" + model_.body(contact.body).name + "' pressed on terrain box " +
                       FormatShort(contact.terrain) + " with " + FormatShort(contact.normal_force) + " N");
      }
      continue;
    }
    const std::size_t uf = static_cast<std::size_t>(foot);
    soles_[uf].force += force;
    normal_sum[uf] += contact.normal_force * contact.normal;
    weighted_points[uf] += contact.normal_force * contact.position;
    normal_total[uf] += contact.normal_force;
  }
  // The soles' net force, low-passed (first order, exact for a constant input over the step), and its ratio.
  const Eigen::Vector3d feet_force = soles_[0].force + soles_[1].force;
  const double blend = options_.force_filter_time > 0.0 ? 1.0 - std::exp(-dt / options_.force_filter_time) : 1.0;
  net_force_ += blend * (feet_force - net_force_);
  const Eigen::Vector3d feet_normal_sum = normal_sum[0] + normal_sum[1];
  const Eigen::Vector3d feet_normal =
      feet_normal_sum.norm() > 0.0 ? Eigen::Vector3d(feet_normal_sum.normalized()) : Eigen::Vector3d::UnitZ();
  const double net_normal = net_force_.dot(feet_normal);
  const double net_force_ratio =
      net_normal > options_.loaded_force ? (net_force_ - net_normal * feet_normal).norm() / net_normal : 0.0;
  double zmp_weight = 0.0;
  Eigen::Vector3d zmp_sum = Eigen::Vector3d::Zero();
  double lowest_sole = std::numeric_limits<double>::infinity();
  for (int f = 0; f < 2; ++f) {
    const std::size_t uf = static_cast<std::size_t>(f);
    SoleState& sole = soles_[uf];
    const Eigen::Vector3d position = data_.X_world[static_cast<std::size_t>(sole_bodies_[uf])].translation();
    lowest_sole = std::min(lowest_sole, position.z());
    const Eigen::Vector3d normal =
        normal_sum[uf].norm() > 0.0 ? Eigen::Vector3d(normal_sum[uf].normalized()) : Eigen::Vector3d::UnitZ();
    sole.normal_force = sole.force.dot(normal);
    sole.tangential_force = (sole.force - sole.normal_force * normal).norm();
    sole.cop = normal_total[uf] > 0.0 ? Eigen::Vector3d(weighted_points[uf] / normal_total[uf]) : position;
    sole.loaded = sole.normal_force > options_.loaded_force;
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
    if (has_previous_[uf]) velocity = (position - sole.position) / dt;
    has_previous_[uf] = true;
    sole.position = position;
    sole.tangential_speed = (velocity - velocity.dot(normal) * normal).norm();
    const double ratio = sole.loaded ? sole.tangential_force / sole.normal_force : 0.0;

    // Slips: a continuous slide of a loaded sole, reported once it exceeds slip_distance.
    if (sole.loaded && sole.tangential_speed > options_.slip_speed) {
      slide_distance_[uf] += sole.tangential_speed * dt;
      if (!slide_reported_[uf] && slide_distance_[uf] > options_.slip_distance) {
        slips_.push_back(SlipEvent{time, f, position, ratio});
        slide_reported_[uf] = true;
      }
    } else {
      slide_distance_[uf] = 0.0;
      slide_reported_[uf] = false;
    }

    // Stances and their RCOF (eq. 2.2); an unloaded spell up to stance_gap long does not end a stance.
    if (sole.loaded) {
      if (open_stance_[uf] < 0) {
        open_stance_[uf] = static_cast<int>(stances_.size());
        StancePhase stance;
        stance.foot = f;
        stance.start = time;
        stances_.push_back(stance);
      }
      StancePhase& stance = stances_[static_cast<std::size_t>(open_stance_[uf])];
      stance.end = time;
      stance.rcof = std::max(stance.rcof, ratio);
      if (time - stance.start >= options_.touchdown_time) {
        stance.rcof_after_touchdown = std::max(stance.rcof_after_touchdown, ratio);
      }
      stance.net_rcof = std::max(stance.net_rcof, net_force_ratio);
    } else if (open_stance_[uf] >= 0) {
      StancePhase& stance = stances_[static_cast<std::size_t>(open_stance_[uf])];
      if (time - stance.end > options_.stance_gap) {
        stance.finished = true;
        open_stance_[uf] = -1;
      }
    }
    if (normal_total[uf] > 0.0) {
      zmp_sum += weighted_points[uf];
      zmp_weight += normal_total[uf];
    }
  }
  zmp_ = zmp_weight > 0.0 ? Eigen::Vector3d(zmp_sum / zmp_weight) : Eigen::Vector3d::Constant(kNaN);

  // Falls.
  const Pose& X_base = data_.X_world[static_cast<std::size_t>(base_body_)];
  base_height_ = X_base.translation().z() - lowest_sole;
  if (base_height_ < options_.fall_base_height) {
    Fall(time, "base '" + model_.body(base_body_).name + "' " + FormatShort(base_height_) +
                   " m above the lower sole, below " + FormatShort(options_.fall_base_height) + " m");
  }
  const double tilt = std::acos(std::clamp(X_base.rotation()(2, 2), -1.0, 1.0));
  if (tilt > options_.fall_tilt) {
    Fall(time, "base '" + model_.body(base_body_).name + "' tilted " + FormatShort(tilt) + " rad, beyond " +
                   FormatShort(options_.fall_tilt) + " rad");
  }

  // Energies.
  const double mass = model_.total_mass();
  const Eigen::Vector3d v_com = CentroidalMomentum(model_, data_, q, v).tail<3>() / mass;
  const Eigen::Vector3d external = total_force + mass * model_.gravity();
  com_energy_ += std::abs(v_com.dot(external)) * dt;
  for (std::size_t i = 0; i < drives_.size(); ++i) {
    const JointDrive& drive = drives_[i];
    if (drive.torque_constant <= 0.0) continue;
    const Eigen::Index iv = static_cast<Eigen::Index>(i);
    const double current = tau[iv] / (drive.gear_ratio * drive.torque_constant);
    const double joule = drive.resistance * current * current * dt;
    electrical_energy_ += std::abs(tau[iv] * v[iv]) * dt + joule;
    heat_ += joule;
  }
}

}  // namespace cairn::multibody
