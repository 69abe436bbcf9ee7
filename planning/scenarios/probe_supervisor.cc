#include "cairn/planning/scenarios/probe_supervisor.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/perception/terrain/grid_map.h"
#include "cairn/perception/terrain/semantic_fusion.h"
#include "cairn/systems/framework/state.h"

namespace cairn::planning {

ProbeSupervisor::ProbeSupervisor(const ProbingPlanner::Options& options, double semantic_threshold,
                                 int probe_periods, double period)
    : semantic_threshold_(semantic_threshold), probe_periods_(probe_periods) {
  if (probe_periods < 1) {
    throw std::invalid_argument("ProbeSupervisor: probe_periods " + FormatShort(probe_periods) +
                                " must be at least 1 (periods to wait for the probe's window)");
  }
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("ProbeSupervisor: period " + FormatShort(period) + " s must be positive and finite");
  }
  const perception::GridMap empty(Eigen::Vector2i(1, 1), 1.0, Eigen::Vector2d::Zero());
  DeclareAbstractInputPort("map", systems::Value<perception::GridMap>(empty));
  DeclareVectorInputPort("robot", 2);
  DeclareVectorInputPort("collapsibility", 2);
  memory_state_ = DeclareAbstractState(systems::Value<Memory>(Memory{ProbingPlanner(options), {}, 0, false,
                                                                     0, Eigen::Vector2d::Zero(), {}, {}}));
  const int m = memory_state_;
  DeclareAbstractOutputPort(
      "probes", systems::Value<std::vector<perception::ProbedRegion>>(std::vector<perception::ProbedRegion>()),
      [m](const systems::Context& c, systems::AbstractValue* v) {
        v->get_mutable_value<std::vector<perception::ProbedRegion>>() = c.get_abstract_state<Memory>(m).probes;
      },
      {abstract_state_ticket(m)});
  DeclareVectorOutputPort(
      "probe_command", 3,
      [m](const systems::Context& c, Eigen::VectorXd* y) {
        const Memory& memory = c.get_abstract_state<Memory>(m);
        *y << memory.target.x(), memory.target.y(), memory.probing ? 1.0 : 0.0;
      },
      {abstract_state_ticket(m)});
  DeclareVectorOutputPort(
      "pause", 1,
      [m](const systems::Context& c, Eigen::VectorXd* y) { (*y)[0] = c.get_abstract_state<Memory>(m).probing; },
      {abstract_state_ticket(m)});
  DeclarePeriodicUnrestrictedUpdateEvent(period, 0.0, &ProbeSupervisor::Update);
}

const ProbeSupervisor::Memory& ProbeSupervisor::memory(const systems::Context& context) const {
  return context.get_abstract_state<Memory>(memory_state_);
}

void ProbeSupervisor::Update(const systems::Context& context, systems::State* next) const {
  Memory& memory = next->get_mutable_abstract_state<Memory>(memory_state_);
  const auto cluster_region = [&](double c) {
    perception::ProbedRegion region;
    region.collapsibility = c;
    for (int k : memory.cluster.members) region.points.push_back(memory.cluster_points.col(k));
    return region;
  };
  if (memory.probing) {
    if (--memory.periods_left > 0) return;
    const Eigen::VectorXd& reading = get_collapsibility_input_port().Eval<Eigen::VectorXd>(context);
    if (std::isnan(reading[0])) return;  // no sample yet: keep probing
    memory.probes.push_back(cluster_region(reading[0]));
    memory.planner.RecordProbe(memory.cluster, memory.cluster_points, memory.target, reading[0]);
    ++memory.probes_made;
    memory.probing = false;
    return;
  }
  const auto& map = get_map_input_port().Eval<perception::GridMap>(context);
  if (!map.HasLayer(perception::SemanticFusion::LayerName("plants"))) return;
  const auto& plants = map.layer_data(map.LayerIndex(perception::SemanticFusion::LayerName("plants")));
  const auto& water = map.layer_data(map.LayerIndex(perception::SemanticFusion::LayerName("water")));
  const std::vector<double>* known =
      map.HasLayer("collapsibility") ? &map.layer_data(map.LayerIndex("collapsibility")) : nullptr;
  std::vector<Eigen::Vector2d> xy;
  std::vector<int> labels;
  for (int s = 0; s < static_cast<int>(map.num_cells()); ++s) {
    if (known != nullptr && !std::isnan((*known)[s])) continue;
    int label = -1;
    if (plants[s] >= semantic_threshold_ && !(water[s] > plants[s])) label = 0;
    if (water[s] >= semantic_threshold_ && !(plants[s] >= water[s])) label = 1;
    if (label < 0) continue;
    xy.push_back(map.CellCenter(map.MapIndexOfStorage(s)));
    labels.push_back(label);
  }
  Eigen::Matrix2Xd points(2, static_cast<Eigen::Index>(xy.size()));
  for (std::size_t k = 0; k < xy.size(); ++k) points.col(static_cast<Eigen::Index>(k)) = xy[k];
  const auto clusters = memory.planner.FindClusters(points, labels);
  for (const auto& cluster : clusters) {
    const int probe = memory.planner.TouchingProbe(cluster, points);
    if (probe < 0) continue;
    memory.cluster = cluster;
    memory.cluster_points = points;
    memory.probes.push_back(cluster_region(memory.planner.probes()[probe].collapsibility));
  }
  const Eigen::VectorXd& robot = get_robot_input_port().Eval<Eigen::VectorXd>(context);
  const auto decision = memory.planner.Decide(clusters, points, robot.head<2>());
  if (decision.action != ProbingPlanner::Decision::Action::kProbe) return;
  memory.probing = true;
  memory.periods_left = probe_periods_;
  memory.target = decision.target;
  memory.cluster = clusters[decision.cluster];
  memory.cluster_points = points;
}

}  // namespace cairn::planning
