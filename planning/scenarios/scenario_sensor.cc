#include "cairn/planning/scenarios/scenario_sensor.h"

#include <cmath>
#include <vector>

namespace cairn::planning {

ScenarioSensor::ScenarioSensor(TraverseScenario scenario) : scenario_(std::move(scenario)) {
  DeclareVectorInputPort("robot", 2);
  DeclareAbstractOutputPort("points_W", systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd()),
                            [this](const systems::Context& c, systems::AbstractValue* v) {
                              Eigen::MatrixXd unused;
                              Sample(get_robot_input_port().Eval<Eigen::VectorXd>(c).head<2>(),
                                     &v->get_mutable_value<Eigen::Matrix3Xd>(), &unused);
                            });
  DeclareVectorOutputPort("sensor_W", 3, [this](const systems::Context& c, Eigen::VectorXd* y) {
    const Eigen::VectorXd& robot = get_robot_input_port().Eval<Eigen::VectorXd>(c);
    *y << robot[0], robot[1], scenario_.sensor_height;
  });
  DeclareAbstractOutputPort("probabilities", systems::Value<Eigen::MatrixXd>(Eigen::MatrixXd()),
                            [this](const systems::Context& c, systems::AbstractValue* v) {
                              Eigen::Matrix3Xd unused;
                              Sample(get_robot_input_port().Eval<Eigen::VectorXd>(c).head<2>(), &unused,
                                     &v->get_mutable_value<Eigen::MatrixXd>());
                            });
}

void ScenarioSensor::Sample(const Eigen::Vector2d& robot, Eigen::Matrix3Xd* points,
                            Eigen::MatrixXd* probabilities) const {
  const auto& s = scenario_;
  const double spacing = s.point_spacing;
  const int span = static_cast<int>(std::ceil(s.sensor_range / spacing));
  const Eigen::Vector2d base = ((robot - s.world_min) / spacing).array().floor();
  std::vector<Eigen::Vector2d> xy;
  for (int a = -span; a <= span; ++a) {
    for (int b = -span; b <= span; ++b) {
      const Eigen::Vector2d p = s.world_min + (base + Eigen::Vector2d(a + 0.5, b + 0.5)) * spacing;
      if ((p - robot).norm() > s.sensor_range) continue;
      if ((p.array() < s.world_min.array()).any() || (p.array() >= (s.world_min + s.world_size).array()).any()) continue;
      xy.push_back(p);
    }
  }
  points->resize(3, static_cast<Eigen::Index>(xy.size()));
  probabilities->resize(2, static_cast<Eigen::Index>(xy.size()));
  const double other = 0.5 * (1.0 - s.segmentation_confidence);
  for (std::size_t k = 0; k < xy.size(); ++k) {
    points->col(k) = Eigen::Vector3d(xy[k].x(), xy[k].y(), s.HeightAt(xy[k]));
    const int c = s.ClassAt(xy[k]);
    (*probabilities)(0, k) = c == 0 ? s.segmentation_confidence : other;
    (*probabilities)(1, k) = c == 1 ? s.segmentation_confidence : other;
  }
}

}  // namespace cairn::planning
