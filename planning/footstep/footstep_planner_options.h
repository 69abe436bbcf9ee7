#pragma once

#include <cmath>

#include <cairn/planning/footstep/ara_star.h>

namespace cairn::planning {

/// Settings of the footstep search (thesis 2.4.1a: 5 cm grid, D = 24 footstep directions, ARA*).
struct FootstepPlannerOptions {
  /// Spacing of the foothold lattice, m.
  double lattice_resolution{0.05};
  /// Number of uniform footstep directions D (at most 32).
  int orientations{24};
  /// Steepest ground a sole may stand on, rad.
  double max_slope{30.0 * M_PI / 180.0};
  /// Largest distance of the ground under the sole from the foothold's plane, m: larger gaps or bumps (a stair
  /// edge under the heel) leave the foot unsupported.
  double support_tolerance{0.02};
  /// Largest height difference between two footholds that is priced as a level step (dz = 0), m. The cost model
  /// knows heights only at its grid's knots (5 cm apart by default) and interpolates, so on perceived ground,
  /// whose heights carry a few millimetres of stereo noise, a 3 mm bump would be priced partly as a 5 cm step
  /// (and refused on low friction). Set it to the terrain's height noise; 0 (the default) prices every height as
  /// measured. The plan's footholds keep their measured heights either way.
  double level_step_tolerance{0.0};
  /// Smallest probability eta_geom that a stance's body box is free of the terrain's occupied voxels
  /// (TerrainMap::BoxFreeProbability; stereo uncertainty as a chance constraint on collision). In (0, 1]; 1 allows
  /// no voxel evidence at all in the box. Box obstacles are certain and always block.
  double min_body_free_probability{0.9};
  /// ARA*: initial ε, its decrement and the wall-clock budget.
  AraStarOptions search;
};

}  // namespace cairn::planning
