#include <cairn/planning/trajectory/trajectory_problem.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <cairn/common/number_text.h>
#include <cairn/multibody/configuration.h>
#include <cairn/planning/trajectory/base_rotation_change.h>
#include <cairn/planning/trajectory/center_of_mass_projection.h>
#include <cairn/planning/trajectory/frame_pose_error.h>
#include <cairn/planning/trajectory/inverse_kinematics.h>
#include <cairn/planning/trajectory/quaternion_norm_error.h>
#include <cairn/planning/trajectory/scaled_evaluator.h>
#include <cairn/planning/trajectory/waist_roll_error.h>

namespace cairn::planning {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

CollisionHessian CollisionHessianOf(const TrajectoryOptimizerOptions& options) {
  return options.hessian == "gauss-newton" ? CollisionHessian::kGaussNewton : CollisionHessian::kDifferences;
}

// The bodies whose geometry touches the ground through a contact frame: the frame's body and the bodies welded
// to it on the way to the root (the sole frame sits on a massless body fixed to the foot).
std::vector<std::string> ContactBodies(const multibody::Model& model, const std::vector<WaypointContact>& contacts) {
  std::vector<std::string> bodies;
  for (const WaypointContact& contact : contacts) {
    int body = model.frame(model.GetFrameIndex(contact.frame)).body;
    while (body > 0) {
      bodies.push_back(model.body(body).name);
      if (model.joint(body).nq != 0) break;
      body = model.parent(body);
    }
  }
  return bodies;
}

std::vector<std::string> CommonContactBodies(const multibody::Model& model, const WaypointSpec& a,
                                             const WaypointSpec& b) {
  const std::vector<std::string> in_a = ContactBodies(model, a.contacts);
  const std::vector<std::string> in_b = ContactBodies(model, b.contacts);
  std::vector<std::string> common;
  for (const std::string& body : in_a) {
    if (std::find(in_b.begin(), in_b.end(), body) != in_b.end()) common.push_back(body);
  }
  return common;
}

double Yaw(const Eigen::Matrix3d& R) { return std::atan2(R(1, 0), R(0, 0)); }

void SetJoint(const multibody::Model& model, const std::string& name, double value, Eigen::VectorXd* q) {
  if (model.HasJoint(name)) (*q)(model.joint(model.GetJointIndex(name)).idx_q) = value;
}
}  // namespace

std::string RowViolation::ToString() const {
  return label + " off by " + FormatShort(amount) + (unit.empty() ? "" : " " + unit);
}

TrajectoryProblem::TrajectoryProblem(std::shared_ptr<const multibody::Model> model, std::vector<WaypointSpec> waypoints,
                                     const std::vector<EnvironmentBox>& environment,
                                     const TrajectoryOptimizerOptions& options, std::optional<FixedWaypoint> previous,
                                     std::shared_ptr<const TerrainMap> terrain)
    : model_(std::move(model)),
      chart_(model_ != nullptr ? *model_ : throw std::invalid_argument("TrajectoryProblem: the robot model is null")),
      specs_(std::move(waypoints)),
      previous_(std::move(previous)),
      options_(options) {
  ValidateTrajectoryOptimizerOptions(options_);
  const multibody::Model& model_ref = *model_;
  if (specs_.empty()) throw std::invalid_argument("TrajectoryProblem: no waypoints; give at least one");
  if (static_cast<int>(specs_.size()) > 2 * kMaxTrajectoryStances) {
    throw std::invalid_argument("TrajectoryProblem: " + FormatShort(static_cast<int>(specs_.size())) +
                                " waypoints exceed the limit of " + FormatShort(2 * kMaxTrajectoryStances));
  }
  model_ref.GetFrameIndex(options_.left_sole_frame);
  model_ref.GetFrameIndex(options_.right_sole_frame);
  model_ref.GetFrameIndex(options_.waist_frame);
  if (previous_ && previous_->q.size() != model_ref.nq()) {
    throw std::invalid_argument("TrajectoryProblem: the fixed waypoint has " +
                                FormatShort(static_cast<int>(previous_->q.size())) + " coordinates, expected nq = " +
                                FormatShort(model_ref.nq()));
  }

  // Coordinate names.
  coordinate_names_.assign(static_cast<std::size_t>(model_ref.nq()), "");
  if (chart_.has_floating_base()) {
    const char* base[] = {"base_x", "base_y", "base_z", "base_qw", "base_qx", "base_qy", "base_qz"};
    for (int i = 0; i < 7; ++i) coordinate_names_[static_cast<std::size_t>(i)] = base[i];
  }
  for (int j = 1; j < static_cast<int>(model_ref.joints().size()); ++j) {
    if (model_ref.joint(j).nq == 1) coordinate_names_[static_cast<std::size_t>(model_ref.joint(j).idx_q)] = model_ref.joint(j).name;
  }
  for (int i : chart_.joint_coordinates()) joint_names_.push_back(coordinate_names_[static_cast<std::size_t>(i)]);

  // The environment (the ground is a closed-form term of CollisionPenalty).
  std::vector<EnvironmentBox> boxes = environment;
  std::set<std::string> names;
  for (const EnvironmentBox& box : boxes) {
    if (!names.insert(box.name).second) {
      throw std::invalid_argument("TrajectoryProblem: two environment boxes are called '" + box.name +
                                  "'; give each a unique name");
    }
  }
  // Bounds: joint limits; the quaternion within [-1, 1] (its norm is a constraint), the base position free.
  Eigen::VectorXd lower = Eigen::VectorXd::Constant(model_ref.nq(), -kInf);
  Eigen::VectorXd upper = Eigen::VectorXd::Constant(model_ref.nq(), kInf);
  for (int i : chart_.joint_coordinates()) {
    lower(i) = model_ref.lower_position_limits()(i);
    upper(i) = model_ref.upper_position_limits()(i);
  }
  if (chart_.has_floating_base()) {
    lower.segment<4>(3).setConstant(-1.0);
    upper.segment<4>(3).setConstant(1.0);
  }
  Eigen::VectorXd torque_scale(static_cast<Eigen::Index>(chart_.joint_velocities().size()));
  for (std::size_t i = 0; i < chart_.joint_velocities().size(); ++i) {
    const double limit = model_ref.effort_limits()(chart_.joint_velocities()[i]);
    torque_scale(static_cast<Eigen::Index>(i)) = std::isfinite(limit) && limit > 0.0 ? 1.0 / limit : 1.0;
  }

  if (previous_) {
    fixed_vars_ = prog_.NewContinuousVariables(model_ref.nq(), "q_fixed");
    prog_.AddBoundingBoxConstraint(previous_->q, previous_->q, fixed_vars_);
    prog_.SetInitialGuess(fixed_vars_, previous_->q);
  }
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const WaypointSpec& spec = specs_[i];
    const auto& q = vars_.emplace_back(prog_.NewContinuousVariables(model_ref.nq(), "q" + FormatShort(static_cast<int>(i))));
    prog_.AddBoundingBoxConstraint(lower, upper, q);
    // Cost: static torques and collisions.
    auto torque = std::make_shared<StaticTorqueResidual>(model_, spec.supports, torque_scale);
    torques_.push_back(torque);
    prog_.AddLeastSquaresCost(std::make_shared<ScaledEvaluator>(torque, std::sqrt(2.0 * options_.torque_weight)), q);
    auto collision = std::make_shared<CollisionPenalty>("collision(" + spec.label + ")", model_, boxes,
                                                        ContactBodies(model_ref, spec.contacts), options_.d_safe,
                                                        options_.self_margin, 0.0, options_.ground_height,
                                                        CollisionHessianOf(options_), terrain);
    waypoint_collisions_.push_back(collision);
    if (options_.collision_weight > 0.0) {
      prog_.AddCost(std::make_shared<ScaledEvaluator>(collision, options_.collision_weight), q);
    }
    if (options_.posture_weight > 0.0) {
      std::vector<Eigen::Triplet<double>> diagonal;
      for (int k : chart_.joint_coordinates()) diagonal.emplace_back(k, k, 2.0 * options_.posture_weight);
      Eigen::SparseMatrix<double> Q(model_ref.nq(), model_ref.nq());
      Q.setFromTriplets(diagonal.begin(), diagonal.end());
      prog_.AddQuadraticCost(Q, Eigen::VectorXd::Zero(model_ref.nq()), 0.0, q);
    }
    // Contacts (2.9b).
    for (const WaypointContact& contact : spec.contacts) {
      auto error = std::make_shared<FramePoseError>(model_, contact.frame, contact.X_WF);
      std::vector<std::string> group(3, spec.label + ", " + contact.frame + " position");
      group.resize(6, spec.label + ", " + contact.frame + " rotation");
      std::vector<std::string> unit(3, "m");
      unit.resize(6, "rad");
      AddLabeledConstraint(error, q, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6), group, unit);
    }
    // COM in the support polygon (2.9c).
    const auto edges = spec.polygon_A.rows();
    AddLabeledConstraint(std::make_shared<CenterOfMassProjection>(model_, spec.polygon_A), q,
                         Eigen::VectorXd::Constant(edges, -kInf), spec.polygon_b,
                         std::vector<std::string>(static_cast<std::size_t>(edges), spec.label + ", COM outside support polygon"),
                         std::vector<std::string>(static_cast<std::size_t>(edges), "m"));
    // Waist roll (2.9d).
    AddLabeledConstraint(std::make_shared<WaistRollError>(model_, options_.waist_frame), q, Eigen::VectorXd::Zero(1),
                         Eigen::VectorXd::Zero(1), {spec.label + ", " + options_.waist_frame + " roll (sine)"}, {""});
    if (chart_.has_floating_base()) {
      AddLabeledConstraint(std::make_shared<QuaternionNormError>(), q.Segment(3, 4), Eigen::VectorXd::Zero(1),
                           Eigen::VectorXd::Zero(1), {spec.label + ", unit quaternion"}, {""});
    }
  }

  // Links between consecutive waypoints: speed limits (2.9e) and collision samples.
  const auto link = [&](const WaypointSpec& a, const optimization::DecisionVariables& qa, const WaypointSpec& b,
                        const optimization::DecisionVariables& qb) {
    const double dt = b.time - a.time;
    if (!(dt > 0.0)) {
      throw std::invalid_argument("TrajectoryProblem: waypoint '" + b.label + "' at " + FormatShort(b.time) +
                                  " s does not come after '" + a.label + "' at " + FormatShort(a.time) + " s");
    }
    std::vector<Eigen::Triplet<double>> triplets;
    std::vector<double> bound;
    std::vector<std::string> group, unit;
    for (std::size_t j = 0; j < chart_.joint_coordinates().size(); ++j) {
      const double v_max = model_ref.velocity_limits()(chart_.joint_velocities()[j]);
      if (!std::isfinite(v_max)) continue;
      const int row = static_cast<int>(bound.size());
      triplets.emplace_back(row, chart_.joint_coordinates()[j], -1.0);
      triplets.emplace_back(row, model_ref.nq() + chart_.joint_coordinates()[j], 1.0);
      bound.push_back(v_max * dt);
      group.push_back(a.label + " -> " + b.label + ", " + joint_names_[j] + " speed limit");
      unit.push_back("rad");
    }
    const optimization::DecisionVariables both = optimization::DecisionVariables::Concatenate({qa, qb});
    if (!bound.empty()) {
      Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(bound.size()), 2 * model_ref.nq());
      A.setFromTriplets(triplets.begin(), triplets.end());
      const Eigen::VectorXd ub = Eigen::Map<const Eigen::VectorXd>(bound.data(), static_cast<Eigen::Index>(bound.size()));
      const auto binding = prog_.AddLinearConstraint(A, -ub, ub, both);
      constraints_.push_back({binding.evaluator(), both, -ub, ub, group, unit});
    }
    if (options_.smoothness_weight > 0.0) {
      std::vector<Eigen::Triplet<double>> q_triplets;
      const double w = 2.0 * options_.smoothness_weight;
      for (int i : chart_.joint_coordinates()) {
        const int a_i = i, b_i = model_ref.nq() + i;
        q_triplets.emplace_back(a_i, a_i, w);
        q_triplets.emplace_back(b_i, b_i, w);
        q_triplets.emplace_back(a_i, b_i, -w);
        q_triplets.emplace_back(b_i, a_i, -w);
      }
      Eigen::SparseMatrix<double> Q(2 * model_ref.nq(), 2 * model_ref.nq());
      Q.setFromTriplets(q_triplets.begin(), q_triplets.end());
      prog_.AddQuadraticCost(Q, Eigen::VectorXd::Zero(2 * model_ref.nq()), 0.0, both);
    }
    if (options_.base_rotation_smoothness_weight > 0.0 && chart_.has_floating_base()) {
      prog_.AddLeastSquaresCost(std::make_shared<ScaledEvaluator>(std::make_shared<BaseRotationChange>(),
                                                                  std::sqrt(2.0 * options_.base_rotation_smoothness_weight)),
                                optimization::DecisionVariables::Concatenate({qa.Segment(3, 4), qb.Segment(3, 4)}));
    }
    for (int k = 1; k <= options_.samples_between; ++k) {
      const double fraction = static_cast<double>(k) / (options_.samples_between + 1);
      auto sample = std::make_shared<CollisionPenalty>("collision(" + a.label + " -> " + b.label + ")", model_, boxes,
                                                       CommonContactBodies(model_ref, a, b), options_.d_safe,
                                                       options_.self_margin, fraction, options_.ground_height,
                                                       CollisionHessianOf(options_), terrain);
      sample_collisions_.emplace_back(sample, both);
      if (options_.collision_weight > 0.0) {
        prog_.AddCost(std::make_shared<ScaledEvaluator>(sample, options_.collision_weight), both);
      }
    }
  };
  if (previous_) link(previous_->spec, fixed_vars_, specs_.front(), vars_.front());
  for (std::size_t i = 0; i + 1 < specs_.size(); ++i) link(specs_[i], vars_[i], specs_[i + 1], vars_[i + 1]);
}

void TrajectoryProblem::AddLabeledConstraint(std::shared_ptr<optimization::Evaluator> function,
                                             const optimization::DecisionVariables& vars, const Eigen::VectorXd& lower,
                                             const Eigen::VectorXd& upper, std::vector<std::string> group,
                                             std::vector<std::string> unit) {
  prog_.AddConstraint(function, lower, upper, vars);
  constraints_.push_back({std::move(function), vars, lower, upper, std::move(group), std::move(unit)});
}

Eigen::VectorXd TrajectoryProblem::Gather(const Eigen::Ref<const Eigen::VectorXd>& x,
                                          const optimization::DecisionVariables& vars) const {
  if (x.size() != prog_.num_vars()) {
    throw std::invalid_argument("TrajectoryProblem: x has " + FormatShort(static_cast<int>(x.size())) +
                                " entries, the program has " + FormatShort(prog_.num_vars()) + " variables");
  }
  Eigen::VectorXd out(vars.size());
  for (int i = 0; i < vars.size(); ++i) out(i) = x(vars[i]);
  return out;
}

Eigen::VectorXd TrajectoryProblem::WaypointConfiguration(const Eigen::Ref<const Eigen::VectorXd>& x, int i) const {
  return chart_.Normalized(Gather(x, vars_.at(static_cast<std::size_t>(i))));
}

Eigen::VectorXd TrajectoryProblem::DecisionVector(const std::vector<Eigen::VectorXd>& configurations) const {
  if (configurations.size() != specs_.size()) {
    throw std::invalid_argument("TrajectoryProblem::DecisionVector: " + FormatShort(static_cast<int>(configurations.size())) +
                                " configurations for " + FormatShort(num_waypoints()) + " waypoints");
  }
  Eigen::VectorXd x = Eigen::VectorXd::Zero(prog_.num_vars());
  if (previous_) {
    for (int k = 0; k < fixed_vars_.size(); ++k) x(fixed_vars_[k]) = previous_->q(k);
  }
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    if (configurations[i].size() != model_->nq()) {
      throw std::invalid_argument("TrajectoryProblem::DecisionVector: configuration " + FormatShort(static_cast<int>(i)) +
                                  " has " + FormatShort(static_cast<int>(configurations[i].size())) + " entries");
    }
    for (int k = 0; k < vars_[i].size(); ++k) x(vars_[i][k]) = configurations[i](k);
  }
  return x;
}

std::vector<Eigen::VectorXd> TrajectoryProblem::WarmStart() const {
  const multibody::Model& model = *model_;
  std::vector<Eigen::VectorXd> out;
  Eigen::VectorXd posture = multibody::NeutralConfiguration(model);
  for (const char* side : {"l_", "r_"}) {
    SetJoint(model, std::string(side) + "hip_pitch", -0.3, &posture);
    SetJoint(model, std::string(side) + "knee", 0.6, &posture);
    SetJoint(model, std::string(side) + "ankle_pitch", -0.3, &posture);
  }
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const WaypointSpec& spec = specs_[i];
    InverseKinematics ik(model_);
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& v : spec.polygon_vertices) centroid += v;
    centroid /= static_cast<double>(std::max<std::size_t>(1, spec.polygon_vertices.size()));
    double z = 0.0;
    Eigen::Vector2d heading = Eigen::Vector2d::Zero();
    for (const WaypointContact& c : spec.contacts) {
      ik.AddFramePoseTarget(c.frame, c.X_WF);
      z += c.X_WF.translation().z() / static_cast<double>(spec.contacts.size());
      const double yaw = Yaw(c.X_WF.rotation());
      heading += Eigen::Vector2d(std::cos(yaw), std::sin(yaw));
    }
    // The swing foot of a mid-swing waypoint: softly between its lift-off and landing poses, raised.
    if (spec.single_support && i + 1 < specs_.size()) {
      const WaypointSpec* before = i > 0 ? &specs_[i - 1] : (previous_ ? &previous_->spec : nullptr);
      const WaypointSpec& after = specs_[i + 1];
      const std::string& support = spec.contacts.front().frame;
      for (const WaypointContact& landing : after.contacts) {
        if (landing.frame == support || before == nullptr) continue;
        for (const WaypointContact& liftoff : before->contacts) {
          if (liftoff.frame != landing.frame) continue;
          const Eigen::Vector3d p = 0.5 * (liftoff.X_WF.translation() + landing.X_WF.translation()) +
                                    Eigen::Vector3d(0.0, 0.0, 0.06);
          const double yaw = 0.5 * (Yaw(liftoff.X_WF.rotation()) + Yaw(landing.X_WF.rotation()));
          ik.AddFramePoseTarget(landing.frame,
                                multibody::Pose(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(), p),
                                1.0);
        }
      }
    }
    ik.AddCenterOfMassTarget(centroid);
    ik.AddZeroRollTarget(options_.waist_frame);
    Eigen::VectorXd guess = posture;
    if (chart_.has_floating_base()) {
      const double yaw = std::atan2(heading.y(), heading.x());
      guess.head<3>() = Eigen::Vector3d(centroid.x(), centroid.y(), z + options_.nominal_pelvis_height);
      guess.segment<4>(3) << std::cos(0.5 * yaw), 0.0, 0.0, std::sin(0.5 * yaw);
    }
    ik.SetPosture(guess);
    out.push_back(ik.Solve(guess).q);
    // q and -q are the same pose; keep consecutive quaternions in one hemisphere so that the orientation
    // smoothness term (BaseRotationChange, linear in the quaternions) measures the rotation between them.
    if (chart_.has_floating_base()) {
      const Eigen::VectorXd* before = out.size() > 1 ? &out[out.size() - 2] : (previous_ ? &previous_->q : nullptr);
      if (before != nullptr && out.back().segment<4>(3).dot(before->segment<4>(3)) < 0.0) {
        out.back().segment<4>(3) *= -1.0;
      }
    }
  }
  return out;
}

std::vector<RowViolation> TrajectoryProblem::Violations(const Eigen::Ref<const Eigen::VectorXd>& x,
                                                        double threshold) const {
  std::vector<RowViolation> groups;
  std::map<std::string, std::size_t> index;
  const auto add = [&](const std::string& label, const std::string& unit, double violation) {
    if (!(violation > 0.0) && !std::isnan(violation)) return;
    auto [it, inserted] = index.emplace(label, groups.size());
    if (inserted) groups.push_back({label, 0.0, unit});
    RowViolation& g = groups[it->second];
    g.amount = std::isnan(violation) ? violation : std::hypot(g.amount, violation);
  };
  for (const LabeledConstraint& c : constraints_) {
    const Eigen::VectorXd y = c.function->Eval(Gather(x, c.vars));
    for (Eigen::Index r = 0; r < y.size(); ++r) {
      const double v = std::isnan(y(r)) ? y(r) : std::max({c.lower(r) - y(r), y(r) - c.upper(r), 0.0});
      add(c.group[static_cast<std::size_t>(r)], c.unit[static_cast<std::size_t>(r)], v);
    }
  }
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const Eigen::VectorXd q = Gather(x, vars_[i]);
    for (std::size_t j = 0; j < chart_.joint_coordinates().size(); ++j) {
      const int k = chart_.joint_coordinates()[j];
      const double v = std::max({model_->lower_position_limits()(k) - q(k), q(k) - model_->upper_position_limits()(k), 0.0});
      add(specs_[i].label + ", " + joint_names_[j] + " joint limit", "rad", v);
    }
  }
  std::vector<RowViolation> out;
  for (const RowViolation& g : groups) {
    if (std::isnan(g.amount) || g.amount > threshold) out.push_back(g);
  }
  std::stable_sort(out.begin(), out.end(), [](const RowViolation& a, const RowViolation& b) {
    return std::isnan(a.amount) ? !std::isnan(b.amount) : a.amount > b.amount;
  });
  return out;
}

double TrajectoryProblem::MinimumClearance(const Eigen::Ref<const Eigen::VectorXd>& x, int i, std::string* which) const {
  return waypoint_collisions_.at(static_cast<std::size_t>(i))->MinimumEnvironmentDistance(Gather(x, vars_[static_cast<std::size_t>(i)]), which);
}

double TrajectoryProblem::MinimumSampleClearance(const Eigen::Ref<const Eigen::VectorXd>& x, std::string* which) const {
  double best = kInf;
  for (const auto& [penalty, vars] : sample_collisions_) {
    std::string name;
    const double d = penalty->MinimumEnvironmentDistance(Gather(x, vars), &name);
    if (d < best) {
      best = d;
      if (which != nullptr) *which = penalty->name() + ": " + name;
    }
  }
  return best;
}

Eigen::VectorXd TrajectoryProblem::JointTorques(const Eigen::Ref<const Eigen::VectorXd>& x, int i) const {
  return torques_.at(static_cast<std::size_t>(i))->JointTorques(Gather(x, vars_[static_cast<std::size_t>(i)]));
}

double TrajectoryProblem::TorqueCost(const Eigen::Ref<const Eigen::VectorXd>& x, int i) const {
  const std::size_t k = static_cast<std::size_t>(i);
  return options_.torque_weight * torques_.at(k)->Eval(Gather(x, vars_.at(k))).squaredNorm();
}

}  // namespace cairn::planning
