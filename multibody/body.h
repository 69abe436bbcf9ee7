#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/geometry.h>
#include <cairn/multibody/spatial_inertia.h>

namespace cairn::multibody {

/// A rigid body: its inertia in its own frame and the shapes attached to it.
struct Body {
  /// Body (URDF link) name.
  std::string name;
  /// Mass, centre of mass and rotational inertia, expressed in the body frame.
  SpatialInertia inertia;
  /// False if the URDF link had no <inertial> element (it is then massless here; DART would give it 1 kg).
  bool has_inertial = false;
  /// Collision shapes.
  std::vector<Geometry> collisions;
  /// Visual shapes (references only: mesh files are not loaded).
  std::vector<Geometry> visuals;
};

}  // namespace cairn::multibody
