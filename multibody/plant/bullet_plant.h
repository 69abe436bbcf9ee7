#pragma once

/// @file
/// A Bullet (btMultiBody) physics plant built from Cairn's own Model: the floating base, the moving joints, the
/// masses, centres of mass and inertias, and the primitive collision shapes, on static terrain boxes that each
/// have their own Coulomb friction. Bullet's headers stay inside bullet_plant.cc.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/multibody/plant/bullet_plant_options.h>
#include <cairn/multibody/plant/contact_point.h>
#include <cairn/multibody/plant/terrain_box.h>

namespace cairn::multibody {

/// Steps a robot Model with Bullet's articulated-body algorithm and its contact solver.
///
/// Bodies connected by fixed joints are merged into the moving body that carries them (their inertias added), so
/// Bullet sees one link per moving joint; the root body is Bullet's base, floating if the model's joint 1 is a
/// floating joint and welded to the world if it is fixed. States are exchanged in Cairn's coordinates (q: floating
/// joint [x y z qw qx qy qz] then joint angles; v: the base twist in the base frame [ω; v] then joint rates), so a
/// plant and Cairn's algorithms read the same vectors. Bullet's link damping and velocity clamps are disabled:
/// the plant adds no dissipation of its own. Not copyable; deterministic (the same calls give the same bits).
class BulletPlant {
 public:
  /// Largest number of terrain boxes.
  static constexpr int kMaxTerrainBoxes = 100000;

  /// Builds the Bullet world. Throws std::invalid_argument naming the offending value for: a model whose body 1
  /// is not the only body attached to the world, or whose joint 1 is neither floating nor fixed; a floating base
  /// or moving subtree without mass; options out of range; more than kMaxTerrainBoxes boxes, a box with a size
  /// that is not finite and > 0 or a friction outside [0, 10]; with contacts on, a mesh collision shape.
  BulletPlant(const Model& model, const std::vector<TerrainBox>& terrain,
              const BulletPlantOptions& options = BulletPlantOptions());
  ~BulletPlant();
  BulletPlant(const BulletPlant&) = delete;
  BulletPlant& operator=(const BulletPlant&) = delete;

  /// The model the plant was built from (with the gravity the plant uses).
  const Model& model() const;
  /// The terrain boxes.
  const std::vector<TerrainBox>& terrain() const;
  /// The options.
  const BulletPlantOptions& options() const;
  /// Number of Bullet links (moving joints below the base).
  int num_links() const;
  /// The moving body (or 0, the world, for a welded base) that body `body` is merged into through fixed joints:
  /// the `body` of the ContactPoint of any of its shapes. Throws std::invalid_argument for an unknown index.
  int merged_body(int body) const;
  /// Simulated time (s): the number of steps times the step.
  double time() const;

  /// Sets the state (sizes nq and nv; the quaternion is normalised). Throws std::invalid_argument on a size
  /// mismatch or a non-finite entry.
  void SetState(const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::Ref<const Eigen::VectorXd>& v);
  /// The configuration q in Cairn's coordinates.
  Eigen::VectorXd positions() const;
  /// The velocity v in Cairn's coordinates.
  Eigen::VectorXd velocities() const;

  /// Advances one time step with generalized forces `tau` (size nv, Cairn's order; the floating-base entries are a
  /// wrench [n; f] at the base origin in the base frame, as in InverseDynamics) held over the step. Contacts and
  /// their forces are those of this step. Throws std::invalid_argument on a size mismatch or a non-finite entry.
  void Step(const Eigen::Ref<const Eigen::VectorXd>& tau);

  /// The contact points of the last step (empty before the first step or with contacts off).
  const std::vector<ContactPoint>& contacts() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cairn::multibody
