#include "cairn/perception/terrain/traversability_analyzer.h"

#include <algorithm>
#include <vector>

#include "cairn/perception/terrain/kalman_cell_update.h"

namespace cairn::perception {

TraversabilityAnalyzer::TraversabilityAnalyzer(const HierarchicalTraversability::Options& options) : rule_(options) {
  const GridMap empty(Eigen::Vector2i(1, 1), 1.0, Eigen::Vector2d::Zero());
  DeclareAbstractInputPort("map", systems::Value<GridMap>(empty));
  DeclareAbstractInputPort("probes", systems::Value<std::vector<ProbedRegion>>(std::vector<ProbedRegion>()));
  DeclareAbstractOutputPort(
      "map", systems::Value<GridMap>(empty),
      [this](const systems::Context& c, systems::AbstractValue* v) {
        CalcMap(get_map_input_port().Eval<GridMap>(c), get_probes_input_port().Eval<std::vector<ProbedRegion>>(c),
                &v->get_mutable_value<GridMap>());
      },
      {all_input_ports_ticket()});
  DeclareAbstractOutputPort(
      "traversability", systems::Value<Eigen::MatrixXd>(Eigen::MatrixXd()),
      [this](const systems::Context& c, systems::AbstractValue* v) {
        const GridMap& map = get_map_output_port().Eval<GridMap>(c);
        const int t = map.LayerIndex("traversability");
        Eigen::MatrixXd& out = v->get_mutable_value<Eigen::MatrixXd>();
        out.resize(map.size().x(), map.size().y());
        for (int i = 0; i < map.size().x(); ++i) {
          for (int j = 0; j < map.size().y(); ++j) out(i, j) = map.at(t, i, j);
        }
      },
      {all_input_ports_ticket()});
}

void TraversabilityAnalyzer::CalcMap(const GridMap& map, const std::vector<ProbedRegion>& probes,
                                     GridMap* out) const {
  *out = map;
  if (!out->HasLayer("collapsibility")) out->AddLayer("collapsibility");
  if (!out->HasLayer("collapsibility_variance")) out->AddLayer("collapsibility_variance");
  const int c = out->LayerIndex("collapsibility");
  const int c_variance = out->LayerIndex("collapsibility_variance");
  const double variance = rule_.options().probe_variance;
  std::vector<int> cells;
  for (const ProbedRegion& probe : probes) {
    // One probe is one measurement of each cell it covers, however many of its points fall in the cell.
    cells.clear();
    for (const Eigen::Vector2d& p : probe.points) {
      Eigen::Vector2i cell;
      if (out->CellOf(p, &cell)) cells.push_back(out->StorageIndex(cell.x(), cell.y()));
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    for (const int s : cells) {
      KalmanCellUpdate(probe.collapsibility, variance, &out->layer_data(c)[s], &out->layer_data(c_variance)[s]);
    }
  }
  rule_.Compute(out);
}

}  // namespace cairn::perception
