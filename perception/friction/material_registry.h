#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/perception/friction/contact_observation.h"
#include "cairn/perception/friction/friction_distribution.h"

namespace cairn::perception {

/// The materials a segmenter can report, each with its friction distribution p(μ | label), in a fixed order that
/// matches the segmenter's probability channels.
///
/// Learning from touch (past the thesis, whose main limitation 6.3.1 is the missing feedback from contact): each
/// label's distribution is the robot's belief about the friction of surfaces it calls by that label, and
/// UpdateFromContact() refines it by assumed-density filtering — the exact posterior given the observation
/// (normal–normal for a measured coefficient, a truncated normal for "slipped at r" / "held at r"), weighted by
/// how much that label explains the observation, moment-matched back to a normal.
class MaterialRegistry {
 public:
  struct Material {
    std::string label;
    FrictionDistribution friction;
    /// Contacts that updated this material's distribution.
    int num_contacts{0};
  };

  MaterialRegistry() = default;
  /// Throws std::invalid_argument on an empty or duplicate label.
  explicit MaterialRegistry(std::vector<Material> materials);

  /// The thesis' Table 3.3: asphalt 0.74±0.12, grass 0.53±0.10, rock 0.80±0.08, carpet 0.82±0.02,
  /// ceramic 0.97±0.05, marble 0.83±0.15, metal 0.80±0.15, wood 0.88±0.12 (normal); sand, sky, snow, water, cloth,
  /// paper not walkable. 14 labels in that order.
  static MaterialRegistry ThesisTable33();

  /// Reads a registry from YAML (schema in docs of SaveYaml). Throws std::invalid_argument naming the file, the
  /// line and the key. Every distribution must be physical friction (CheckPhysicalFriction(): means in (0, 10],
  /// ...); a file lists at most 1000 materials, each with at most 1e9 contacts.
  static MaterialRegistry LoadYaml(const std::string& path);
  /// Writes the registry (with learned parameters and contact counts) atomically:
  /// @code{.yaml}
  /// materials:
  ///   - {label: asphalt, distribution: normal, mean: 0.74, stddev: 0.12}
  ///   - {label: ice, distribution: gev, location: 0.1, scale: 0.03, shape: -0.1}
  ///   - {label: water, distribution: not_walkable}
  /// @endcode
  void SaveYaml(const std::string& path) const;

  int size() const { return static_cast<int>(materials_.size()); }
  const Material& material(int index) const;
  const std::vector<Material>& materials() const { return materials_; }
  /// Index of `label`; throws std::invalid_argument listing the closest labels.
  int IndexOf(const std::string& label) const;
  std::vector<std::string> labels() const;

  /// Checks that `probabilities` has one entry per label, each in [0, 1], summing to 1 within 1e-6; throws
  /// std::invalid_argument naming the bad value otherwise.
  void ValidateProbabilities(const Eigen::Ref<const Eigen::VectorXd>& probabilities) const;

  /// Updates the labels' distributions from one contact whose surface had material `probabilities` (from the
  /// segmenter at the contact point). Returns the posterior label probabilities given the observation. Labels
  /// that cannot explain the observation (zero likelihood) keep their distributions. Only normal distributions
  /// learn; an observation that a GEV or truncated-normal label would have to explain is rejected with a message,
  /// as is a value outside [0, kMaxFrictionCoefficient] or a measurement noise outside (0, 10].
  Eigen::VectorXd UpdateFromContact(const Eigen::Ref<const Eigen::VectorXd>& probabilities,
                                    const ContactObservation& observation);

 private:
  std::vector<Material> materials_;
};

}  // namespace cairn::perception
