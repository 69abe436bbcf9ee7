#include "cairn/perception/terrain/elevation_mapper.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/systems/framework/state.h"

namespace cairn::perception {

namespace {

GridMap WithLayers(GridMap map, const SemanticFusion& semantics) {
  ElevationFusion::AddLayers(&map);
  semantics.AddLayers(&map);
  if (!map.HasLayer("slope")) map.AddLayer("slope");
  if (!map.HasLayer("roughness")) map.AddLayer("roughness");
  return map;
}

double CheckedPeriod(double period) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ElevationMapper: period " + FormatShort(period) +
                                " s must be positive and finite (the sensor's frame period, e.g. 0.2)");
  }
  return period;
}

}  // namespace

ElevationMapper::ElevationMapper(const GridMap& prototype, double period, const Options& options)
    : period_(CheckedPeriod(period)), options_(options), filter_(options.geometry) {
  const Workspace workspace{ElevationFusion(options.elevation), SemanticFusion(options.semantics)};
  const GridMap initial = WithLayers(prototype, workspace.semantics);
  DeclareAbstractInputPort("points_W", systems::Value<Eigen::Matrix3Xd>(Eigen::Matrix3Xd()));
  DeclareVectorInputPort("sensor_W", 3);
  DeclareAbstractInputPort("probabilities", systems::Value<Eigen::MatrixXd>(Eigen::MatrixXd()));
  map_state_ = DeclareAbstractState(systems::Value<GridMap>(initial));
  workspace_state_ = DeclareAbstractState(systems::Value<Workspace>(workspace));
  const int map = map_state_;
  DeclareAbstractOutputPort(
      "map", systems::Value<GridMap>(initial),
      [map](const systems::Context& c, systems::AbstractValue* v) { v->SetFrom(c.get_abstract_state_value(map)); },
      {abstract_state_ticket(map)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &ElevationMapper::Update);
}

void ElevationMapper::Update(const systems::Context& context, systems::State* next) const {
  const auto& points = get_points_input_port().Eval<Eigen::Matrix3Xd>(context);
  const Eigen::VectorXd& sensor = get_sensor_input_port().Eval<Eigen::VectorXd>(context);
  const auto& probabilities = get_probabilities_input_port().Eval<Eigen::MatrixXd>(context);
  GridMap& map = next->get_mutable_abstract_state<GridMap>(map_state_);
  Workspace& workspace = next->get_mutable_abstract_state<Workspace>(workspace_state_);
  if (options_.follow_sensor) map.Move(sensor.head<2>());
  workspace.elevation.Integrate(points, sensor.head<3>(), &map);
  if (probabilities.cols() > 0) workspace.semantics.Integrate(points, probabilities, &map);
  filter_.Compute(&map);
}

}  // namespace cairn::perception
