#include <cairn/multibody/plant/joint_drive.h>

#include <stdexcept>

#include "cairn/common/internal/yaml_reader.h"
#include <cairn/common/number_text.h>

namespace cairn::multibody {

std::vector<JointDrive> LoadJointDrives(const Model& model, const std::string& walking_yaml_path) {
  const internal::YamlReader yaml(walking_yaml_path);
  const YAML::Node motors = yaml.Require(yaml.root(), "motors", "the walking model");
  if (!motors.IsMap()) yaml.Fail(motors, "'motors' must be a mapping of joint names (without l_/r_) to drives");
  std::vector<JointDrive> drives(static_cast<std::size_t>(model.nv()));
  for (const auto& entry : motors) {
    const std::string key = yaml.AsString(entry.first, "motors");
    const std::string where = "motors." + key;
    yaml.CheckKeys(entry.second, {"resistance", "torque_constant", "gear_ratio"}, where);
    JointDrive drive;
    drive.resistance = yaml.Number(entry.second, "resistance", where);
    drive.torque_constant = yaml.Number(entry.second, "torque_constant", where);
    drive.gear_ratio = yaml.Number(entry.second, "gear_ratio", where);
    if (drive.resistance < 0.0 || drive.torque_constant <= 0.0 || drive.gear_ratio <= 0.0) {
      yaml.Fail(entry.second, where + " needs resistance >= 0, torque_constant > 0 and gear_ratio > 0");
    }
    int matched = 0;
    for (const std::string& name : {key, "l_" + key, "r_" + key}) {
      if (!model.HasJoint(name)) continue;
      const Joint& joint = model.joint(model.GetJointIndex(name));
      if (joint.nv != 1) yaml.Fail(entry.second, where + " names joint '" + name + "', which has no single axis");
      drives[static_cast<std::size_t>(joint.idx_v)] = drive;
      ++matched;
    }
    if (matched == 0) {
      yaml.Fail(entry.second, where + " matches no joint of '" + model.name() + "' (tried '" + key + "', 'l_" + key +
                                  "' and 'r_" + key + "')");
    }
  }
  return drives;
}

}  // namespace cairn::multibody
