#pragma once

/// @file
/// ContactFrictionLearner: what the feet felt, turned into the material registry friction from vision should use.

#include <vector>

#include <Eigen/Core>

#include "cairn/perception/friction/contact_observation.h"
#include "cairn/perception/friction/friction_point_cloud.h"
#include "cairn/perception/friction/material_registry.h"
#include "cairn/systems/framework/leaf_system.h"

namespace cairn::perception {

/// One contact of a foot with the ground: where, and what it taught about the friction there (a slip while using
/// a coefficient, a hold, or a measured coefficient).
struct FootContact {
  Eigen::Vector3d position_W{Eigen::Vector3d::Zero()};
  ContactObservation observation;
};

/// What ContactFrictionLearner holds as state: the learned registry and how the contacts so far were used.
struct ContactLearning {
  MaterialRegistry registry;
  int seen{0};      ///< contacts of the log already read
  int learned{0};   ///< of those, the ones that updated the registry
  int skipped{0};   ///< of those, the ones with no perceived point under the foot (no material to credit)
  int rejected{0};  ///< of those, the ones MaterialRegistry::UpdateFromContact refused (bad value, or labels that
                    ///< cannot learn, e.g. a "held" on not-walkable materials)
};

/// Learning from touch (thesis 6.3.1 names it as the missing feedback; issue 18): each new contact of the log on
/// its `contacts` input is credited to the materials perception saw under the foot, through
/// MaterialRegistry::UpdateFromContact: the material mixture is the mean of the friction points' mixtures within
/// `radius` (horizontally) and `height_window` (vertically) of the contact point, so a slip on what looked like
/// ceramic lowers ceramic's distribution, in proportion to how sure the segmenter was. A contact with no point
/// under it teaches nothing and is counted as skipped; one the registry refuses (UpdateFromContact throws) is
/// counted as rejected, and learning goes on with the next.
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `contacts` | std::vector<FootContact> | every contact so far, oldest first (an append-only log) |
/// | input `friction_points` | FrictionPointCloud | perceived points with their material mixtures (registry order) |
/// | output `registry` | MaterialRegistry | the learned registry (the state's) |
///
/// State: one abstract ContactLearning, initially the registry given to the constructor; a periodic unrestricted
/// update every `period` seconds, and a forced one, read the contacts not read yet. The output depends on the state
/// only. To make perception use what was learned, hand the output to FrictionEstimator's and TerrainAssembler's
/// registry parameters (and save it with MaterialRegistry::SaveYaml, which writes atomically).
class ContactFrictionLearner final : public systems::LeafSystem {
 public:
  /// Throws std::invalid_argument for an empty registry, a period that is not positive and finite, or a radius or
  /// height window outside (0, 10] m.
  ContactFrictionLearner(MaterialRegistry registry, double period, double radius = 0.05, double height_window = 0.05);

  double period() const { return period_; }
  double radius() const { return radius_; }
  double height_window() const { return height_window_; }

  const systems::InputPort& get_contacts_input_port() const { return get_input_port(0); }
  const systems::InputPort& get_friction_points_input_port() const { return get_input_port(1); }
  const systems::OutputPort& get_registry_output_port() const { return get_output_port(0); }

  /// The state of `context` (this system's).
  const ContactLearning& learning(const systems::Context& context) const;

  /// The material mixture (registry order, summing to 1) of the points within the radius and height window of
  /// `position_W`; false when there is none. Throws std::invalid_argument when the points' weights do not have one
  /// column per registry label.
  bool MixtureUnder(const FrictionPointCloud& points, const Eigen::Vector3d& position_W,
                    Eigen::VectorXd* mixture) const;

 private:
  void Learn(const systems::Context& context, systems::State* next) const;

  double period_;
  double radius_;
  double height_window_;
  int num_labels_;
  int state_{};
};

}  // namespace cairn::perception
