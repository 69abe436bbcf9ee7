#include <cairn/planning/terrain/terrain_assembler.h>

#include <utility>

namespace cairn::planning {

using systems::AbstractValue;
using systems::Context;
using systems::Value;

TerrainAssembler::TerrainAssembler(perception::MaterialRegistry registry, const TerrainAssemblyOptions& options)
    : options_(options) {
  ValidateTerrainAssemblyOptions(options);
  DeclareAbstractParameter(Value<perception::MaterialRegistry>(std::move(registry)));
  const auto& grid = DeclareAbstractInputPort(
      "grid", Value<perception::OccupancyGrid>(perception::OccupancyGrid(Eigen::Vector3d::Zero(), 1.0, Eigen::Vector3i::Ones())));
  const auto& points = DeclareAbstractInputPort("friction_points", Value<perception::FrictionPointCloud>());
  DeclareAbstractOutputPort(
      "terrain", Value<TerrainMap>(TerrainMap(Eigen::Vector2d::Zero(), 1, 1, 1.0)),
      [this](const Context& context, AbstractValue* value) {
        value->set_value(AssembleTerrain(GetInputPort("grid").Eval<perception::OccupancyGrid>(context),
                                         GetInputPort("friction_points").Eval<perception::FrictionPointCloud>(context),
                                         context.get_abstract_parameter<perception::MaterialRegistry>(registry_parameter()),
                                         options_));
      },
      {grid.ticket(), points.ticket(), abstract_parameter_ticket(registry_parameter())});
}

}  // namespace cairn::planning
