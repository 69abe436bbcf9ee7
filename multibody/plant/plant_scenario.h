#pragma once

#include <string>
#include <vector>

#include <cairn/multibody/plant/terrain_box.h>

namespace cairn::multibody {

/// A plant scenario file (YAML) of `cairn simulate`: the terrain as boxes, each with its true friction, and how
/// the robot starts. Documented in docs/simulate.md.
///
///     terrain:                       # at least one box
///       - name: ice                  # unique
///         center: [1.0, 0.0, -0.5]   # m, world
///         size: [2.0, 2.0, 1.0]      # m, full side lengths, each in (0, 1000]
///         rpy_deg: [0, 10, 0]        # optional roll, pitch, yaw (deg, applied as Rz Ry Rx)
///         friction: 0.1              # in [0, 10]
///     drop_height: 0.0               # optional: the soles start this far (m, [0, 2]) above z = 0
struct PlantScenario {
  /// Most terrain boxes a scenario file may list.
  static constexpr int kMaxTerrainBoxes = 10000;

  /// Reads and validates `path`. Throws std::invalid_argument naming the file, the line and the key on a mistake
  /// (a missing or unknown key, a size or friction out of range, a duplicate name, more than kMaxTerrainBoxes boxes).
  static PlantScenario Load(const std::string& path);

  /// The terrain.
  std::vector<TerrainBox> terrain;
  /// Height of the soles above z = 0 at the start (m).
  double drop_height = 0.0;
};

}  // namespace cairn::multibody
