#include <cairn/planning/stabilization/interpolation_knots.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include <cairn/common/number_text.h>
#include <cairn/multibody/center_of_mass.h>
#include <cairn/multibody/configuration.h>
#include <cairn/multibody/data.h>
#include <cairn/multibody/kinematics.h>

namespace cairn::planning {

namespace {

int ContactBits(const WholeBodyWaypoint& waypoint, const StabilizerOptions& options) {
  int bits = 0;
  for (const std::string& frame : waypoint.contacts) {
    if (frame == options.left_sole_frame) bits |= kLeftSoleContact;
    if (frame == options.right_sole_frame) bits |= kRightSoleContact;
  }
  return bits;
}

InterpolationKnot Knot(const multibody::Model& model, multibody::Data& data, double time, const Eigen::VectorXd& q,
                       int contacts, std::string label) {
  InterpolationKnot knot;
  knot.time = time;
  knot.q = q;
  multibody::NormalizeConfiguration(model, knot.q);
  knot.com = multibody::CenterOfMass(model, data, knot.q).head<2>();
  knot.contacts = contacts;
  knot.label = std::move(label);
  return knot;
}

}  // namespace

std::vector<InterpolationKnot> MakeInterpolationKnots(std::shared_ptr<const multibody::Model> model,
                                                      const WholeBodyTrajectory& trajectory,
                                                      const StabilizerOptions& options) {
  if (model == nullptr) throw std::invalid_argument("MakeInterpolationKnots: the robot model is null");
  ValidateStabilizerOptions(options);
  for (const std::string* frame : {&options.left_sole_frame, &options.right_sole_frame, &options.waist_frame}) {
    if (!model->HasFrame(*frame)) {
      throw std::invalid_argument("MakeInterpolationKnots: the model '" + model->name() + "' has no frame '" + *frame +
                                  "'; set the StabilizerOptions frame names to frames of the robot");
    }
  }
  if (!trajectory.found) {
    throw std::invalid_argument("MakeInterpolationKnots: the whole-body trajectory was not found (" +
                                trajectory.report.message + "); stabilise only a found trajectory");
  }
  const auto& w = trajectory.waypoints;
  if (w.empty()) throw std::invalid_argument("MakeInterpolationKnots: the whole-body trajectory has no waypoints");
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w[i].q.size() != model->nq()) {
      throw std::invalid_argument("MakeInterpolationKnots: waypoint " + std::to_string(i) + " has " +
                                  std::to_string(w[i].q.size()) + " coordinates, the model '" + model->name() +
                                  "' has " + std::to_string(model->nq()));
    }
    if (!w[i].q.allFinite() || !std::isfinite(w[i].time)) {
      throw std::invalid_argument("MakeInterpolationKnots: waypoint " + std::to_string(i) +
                                  " has a time or coordinate that is not finite");
    }
    if (i > 0 && !(w[i].time > w[i - 1].time)) {
      throw std::invalid_argument("MakeInterpolationKnots: waypoint " + std::to_string(i) + " at " +
                                  FormatShort(w[i].time) + " s does not come after waypoint " + std::to_string(i - 1) +
                                  " at " + FormatShort(w[i - 1].time) + " s; times must increase");
    }
  }
  multibody::Data data(*model);
  std::vector<InterpolationKnot> knots;
  if (!options.contact_timing) {
    for (const WholeBodyWaypoint& waypoint : w) {
      knots.push_back(Knot(*model, data, waypoint.time, waypoint.q, ContactBits(waypoint, options), waypoint.label));
    }
    return knots;
  }
  // Stance starts at even indices, mid-swing postures at odd ones (MakeWaypointSpecs).
  if (w.size() % 2 == 0) {
    throw std::invalid_argument("MakeInterpolationKnots: " + std::to_string(w.size()) +
                                " waypoints cannot alternate stance start / mid-swing (an odd count is needed); "
                                "use contact_timing = false for other trajectories");
  }
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w[i].single_support != (i % 2 == 1)) {
      throw std::invalid_argument("MakeInterpolationKnots: waypoint " + std::to_string(i) + " ('" + w[i].label +
                                  "') breaks the stance start / mid-swing alternation; use contact_timing = false "
                                  "for other trajectories");
    }
  }
  const int both = kLeftSoleContact | kRightSoleContact;
  Eigen::VectorXd landing = w[0].q;
  Eigen::Vector2d landing_zmp = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  double t_ds_last = 0.0;
  for (std::size_t j = 0; j + 2 < w.size(); j += 2) {
    const double t_start = w[j].time, t_mid = w[j + 1].time, t_next = w[j + 2].time;
    const double t_sw = 2.0 * (t_next - t_mid);
    const double t_ds = (t_mid - t_start) - 0.5 * t_sw;
    if (t_ds < -1e-9) {
      throw std::invalid_argument("MakeInterpolationKnots: the step after '" + w[j].label + "' has a negative double "
                                  "support (" + FormatShort(t_ds) + " s) from its waypoint times; use "
                                  "contact_timing = false for trajectories not timed by MakeWaypointSpecs");
    }
    t_ds_last = std::max(t_ds, 0.0);
    const std::string stance = "stance " + std::to_string(w[j].stance);
    knots.push_back(Knot(*model, data, t_start, landing, both, j == 0 ? "start" : stance + " touch-down"));
    if (j > 0) knots.back().com = landing_zmp;
    if (t_ds > 1e-9) knots.push_back(Knot(*model, data, t_start + t_ds, w[j].q, both, stance + " lift-off"));
    else knots.back() = Knot(*model, data, t_start, w[j].q, both, stance + " lift-off");
    knots.push_back(Knot(*model, data, t_mid, w[j + 1].q, ContactBits(w[j + 1], options), stance + " mid-swing"));
    // At touch-down the posture is the next stance's start (feet in place, held through the double support);
    // the reference ZMP stays over the old stance foot until then and crosses during the double support.
    landing = w[j + 2].q;
    landing_zmp = knots.back().com;
  }
  const WholeBodyWaypoint& last = w.back();
  const std::string stance = "stance " + std::to_string(last.stance);
  if (w.size() == 1) {
    knots.push_back(Knot(*model, data, last.time, last.q, both, stance + " start"));
    return knots;
  }
  knots.push_back(Knot(*model, data, last.time, landing, both, stance + " touch-down"));
  knots.back().com = landing_zmp;
  if (t_ds_last > 1e-9) knots.push_back(Knot(*model, data, last.time + t_ds_last, last.q, both, stance + " end"));
  else knots.back() = Knot(*model, data, last.time, last.q, both, stance + " end");
  return knots;
}

}  // namespace cairn::planning
