#include <cairn/multibody/plant/plant_scenario.h>

#include <cmath>
#include <set>
#include <stdexcept>

#include <Eigen/Geometry>

#include "cairn/common/internal/yaml_reader.h"
#include <cairn/common/number_text.h>

namespace cairn::multibody {

PlantScenario PlantScenario::Load(const std::string& path) {
  const internal::YamlReader yaml(path);
  yaml.CheckKeys(yaml.root(), {"terrain", "drop_height"}, "the scenario");
  PlantScenario scenario;
  scenario.drop_height = yaml.Number(yaml.root(), "drop_height", "the scenario", 0.0);
  if (scenario.drop_height < 0.0 || scenario.drop_height > 2.0) {
    yaml.Fail(yaml.root()["drop_height"], "drop_height " + FormatShort(scenario.drop_height) +
                                              " m is outside [0, 2] m");
  }
  const YAML::Node terrain = yaml.Require(yaml.root(), "terrain", "the scenario");
  if (!terrain.IsSequence() || terrain.size() == 0) {
    yaml.Fail(terrain, "'terrain' must be a non-empty list of boxes {name, center, size, friction}");
  }
  if (terrain.size() > static_cast<std::size_t>(kMaxTerrainBoxes)) {
    yaml.Fail(terrain, "'terrain' lists " + FormatShort(terrain.size()) + " boxes, more than the limit of " +
                           FormatShort(kMaxTerrainBoxes));
  }
  std::set<std::string> names;
  for (std::size_t i = 0; i < terrain.size(); ++i) {
    const YAML::Node& node = terrain[i];
    const std::string where = "terrain[" + FormatShort(i) + "]";
    yaml.CheckKeys(node, {"name", "center", "size", "rpy_deg", "friction"}, where);
    TerrainBox box;
    box.name = yaml.String(node, "name", where);
    if (!names.insert(box.name).second) yaml.Fail(node, where + " repeats the name '" + box.name + "'");
    const Eigen::Vector3d center = yaml.Numbers(yaml.Require(node, "center", where), where + ".center", 3);
    box.size = yaml.Numbers(yaml.Require(node, "size", where), where + ".size", 3);
    for (int a = 0; a < 3; ++a) {
      if (!(box.size[a] > 0.0 && box.size[a] <= 1000.0)) {
        yaml.Fail(node, where + ".size[" + FormatShort(a) + "] = " + FormatShort(box.size[a]) +
                            " m is outside (0, 1000] m");
      }
    }
    Eigen::Vector3d rpy = Eigen::Vector3d::Zero();
    if (internal::YamlReader::Has(node, "rpy_deg")) rpy = yaml.Numbers(node["rpy_deg"], where + ".rpy_deg", 3);
    rpy *= 3.14159265358979323846 / 180.0;
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    box.X_WB = Pose(R, center);
    box.friction = yaml.Number(node, "friction", where);
    if (!(box.friction >= 0.0 && box.friction <= 10.0)) {
      yaml.Fail(node, where + ".friction " + FormatShort(box.friction) + " is outside [0, 10]");
    }
    scenario.terrain.push_back(box);
  }
  return scenario;
}

}  // namespace cairn::multibody
