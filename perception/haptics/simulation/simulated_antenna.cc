#include "cairn/perception/haptics/simulation/simulated_antenna.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::perception {

SimulatedAntenna::SimulatedAntenna() : SimulatedAntenna(Options{}) {}

SimulatedAntenna::SimulatedAntenna(const Options& options) : options_(options) {
  const auto range = [](double lo, double hi, const char* what) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) {
      throw std::invalid_argument(std::string(what) + " range [" + FormatShort(lo) + ", " + FormatShort(hi) +
                                  "] must be finite with min < max");
    }
  };
  range(options.min_pan, options.max_pan, "the pan");
  range(options.min_tilt, options.max_tilt, "the tilt");
  range(options.min_extension, options.max_extension, "the extension");
  if (!(options.min_extension > 0.0)) {
    throw std::invalid_argument("min_extension is " + FormatShort(options.min_extension) + " m; it must be positive");
  }
  if (!(options.tip_radius > 0.0) || !std::isfinite(options.tip_radius)) {
    throw std::invalid_argument("tip_radius is " + FormatShort(options.tip_radius) + " m; it must be positive");
  }
  if (!(options.step > 0.0) || !std::isfinite(options.step)) {
    throw std::invalid_argument("step is " + FormatShort(options.step) + " m; it must be positive");
  }
}

Eigen::Vector3d SimulatedAntenna::TipPosition(const Eigen::Vector3d& q) {
  const double p = q[0];
  const double t = q[1];
  return q[2] * Eigen::Vector3d(std::cos(t) * std::sin(p), -std::sin(t), std::cos(t) * std::cos(p));
}

std::optional<Eigen::Vector3d> SimulatedAntenna::InverseKinematics(const Eigen::Vector3d& p_A) const {
  const double length = p_A.norm();
  if (!(length >= options_.min_extension) || length > options_.max_extension) return std::nullopt;
  const double tilt = std::asin(std::clamp(-p_A.y() / length, -1.0, 1.0));
  const double pan = std::atan2(p_A.x(), p_A.z());
  if (pan < options_.min_pan || pan > options_.max_pan || tilt < options_.min_tilt || tilt > options_.max_tilt) {
    return std::nullopt;
  }
  return Eigen::Vector3d(pan, tilt, length);
}

AntennaInteraction SimulatedAntenna::Probe(const std::vector<Eigen::Vector3d>& targets_A,
                                           const std::vector<HapticSceneObject>& objects_W,
                                           const Eigen::Isometry3d& X_WA) const {
  if (targets_A.size() > static_cast<std::size_t>(kMaxTargets)) {
    throw std::invalid_argument("the interaction has " + FormatShort(targets_A.size()) + " targets; at most " +
                                FormatShort(kMaxTargets) + " are followed");
  }
  AntennaInteraction result;
  std::vector<Eigen::Vector3d> joints;
  for (const Eigen::Vector3d& target : targets_A) {
    if (!target.allFinite()) throw std::invalid_argument("an antenna target is not finite");
    const auto q = InverseKinematics(target);
    if (q) {
      joints.push_back(*q);
    } else {
      ++result.targets_unreachable;
    }
  }
  Eigen::Vector3d q = Eigen::Vector3d(0.0, 0.0, options_.min_extension);
  result.tip_W = X_WA * TipPosition(q);
  if (joints.empty()) return result;
  const auto touches = [&](const Eigen::Vector3d& p_W) {
    for (const HapticSceneObject& object : objects_W) {
      if (object.StiffDistance(p_W) < options_.tip_radius) return true;
    }
    return false;
  };
  // Moves the joints to `goal`, checking the tip on the way; false when blocked.
  const auto move = [&](const Eigen::Vector3d& goal) {
    const Eigen::Vector3d start = q;
    const Eigen::Vector3d from = TipPosition(start);
    // Enough samples that consecutive tip positions are at most `step` apart (the tip moves at most
    // L |Δangles| + |ΔL| per unit of interpolation).
    const double bound = std::max(start[2], goal[2]) * ((goal - start).head<2>().cwiseAbs().sum()) +
                         std::abs(goal[2] - start[2]);
    const int samples = std::max(1, static_cast<int>(std::ceil(bound / options_.step)));
    Eigen::Vector3d previous = from;
    for (int i = 1; i <= samples; ++i) {
      const Eigen::Vector3d qi = start + (goal - start) * (static_cast<double>(i) / samples);
      const Eigen::Vector3d tip = TipPosition(qi);
      const Eigen::Vector3d tip_W = X_WA * tip;
      if (touches(tip_W)) {
        result.blocked = true;
        result.tip_W = X_WA * previous;
        return false;
      }
      result.path_length += (tip - previous).norm();
      previous = tip;
      q = qi;
    }
    result.tip_W = X_WA * previous;
    return true;
  };
  double furthest = 0.0;
  for (const Eigen::Vector3d& j : joints) furthest = std::max(furthest, j[2]);
  // Point along the first target, then stretch to the furthest distance (Fig. 8).
  q = Eigen::Vector3d(joints.front()[0], joints.front()[1], options_.min_extension);
  if (touches(X_WA * TipPosition(q))) {
    result.blocked = true;
    return result;
  }
  if (!move(Eigen::Vector3d(joints.front()[0], joints.front()[1], furthest))) return result;
  for (const Eigen::Vector3d& j : joints) {
    if (!move(j)) return result;
    ++result.targets_reached;
  }
  return result;
}

}  // namespace cairn::perception
