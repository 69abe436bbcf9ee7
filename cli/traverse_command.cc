// `cairn traverse`: the seed 001 pipeline on a probing scenario — see, map, probe, plan, walk — as the probing
// diagram (planning/scenarios/probing_diagram.h, the one examples/probing runs) simulated with the Simulator, with
// PNGs of every layer and a JSON summary (docs/traverse.md).

#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/planning/scenarios/traverse_scenario.h"
#include "cairn/planning/scenarios/probing_diagram.h"
#include "command_registry.h"
#include "data_directory.h"
#include "file_checks.h"
#include "traverse_image.h"

namespace cairn::cli {
namespace {

struct TraverseArgs {
  std::string scenario;
  std::string out;
  bool no_probing{false};
  bool json{false};
  std::string probe_model;
};

// The files `--out` holds; the folder is replaced as a whole (AtomicOutputDirectory).
constexpr const char* kLayerFiles[] = {"elevation.png", "slope.png", "roughness.png", "semantics.png",
                                       "collapsibility.png", "traversability.png"};

bool IsTraverseOutput(const std::string& name) {
  if (name == "summary.json") return true;
  for (const char* f : kLayerFiles) {
    if (name == f) return true;
  }
  return false;
}

std::string SummaryJson(const TraverseArgs& args, const planning::ProbingRun& r) {
  JsonWriter json;
  json.BeginObject().Key("scenario").String(args.scenario).Key("probing").Bool(!args.no_probing);
  json.Key("probe_model").String(args.probe_model);
  json.Key("reached_goal").Bool(r.reached_goal).Key("failure").String(r.failure);
  json.Key("ticks").Integer(r.ticks).Key("path_length_m").Number(r.distance_walked);
  json.Key("replans").Integer(r.replans).Key("probes_made").Integer(r.probes.size());
  json.Key("inherited_clusters").Integer(r.inherited_clusters);
  json.Key("stepped_on_collapsible").Bool(r.collapsible_steps > 0).Key("collapsible_steps").Integer(r.collapsible_steps);
  json.Key("regions_entered").BeginArray();
  for (const auto& name : r.regions_entered) json.String(name);
  json.EndArray().Key("probes").BeginArray();
  for (const auto& p : r.probes) {
    json.BeginObject().Key("tick").Integer(p.tick).Key("x").Number(p.target.x()).Key("y").Number(p.target.y());
    json.Key("class").String(p.cluster_class).Key("region").String(p.region).Key("cluster_cells").Integer(p.cluster_cells);
    json.Key("force_N").Number(p.average_force).Key("collapsibility").Number(p.collapsibility);
    json.Key("plant_time_s").Number(p.simulated_time);
    json.Key("path_crossed_cluster").Bool(p.path_crossed_cluster).Key("path_crosses_after").Bool(p.path_crosses_after);
    json.EndObject();
  }
  json.EndArray().EndObject();
  return json.text();
}

int RunTraverse(const TraverseArgs& args) {
  CheckInputFile("--scenario", args.scenario, "a traverse scenario YAML file (docs/traverse.md)");
  const planning::TraverseScenario scenario = planning::TraverseScenario::Load(args.scenario);
  // Fail fast on an unusable output folder, before the run.
  std::optional<AtomicOutputDirectory> out;
  if (!args.out.empty()) out.emplace(args.out, IsTraverseOutput);
  TraverseArgs described = args;
  described.probe_model = scenario.probe_model == planning::TraverseScenario::ProbeModel::kPlant ? "plant" : "spring";
  // One tick of TraverseSimulation is one 0.1 s period of the diagram.
  const planning::ProbingRun r = planning::RunProbingDiagram(
      scenario, DataDirectory() + "/robots/cairn_probe_arm.urdf", 0.1 * scenario.max_ticks, !args.no_probing);
  const std::string summary = SummaryJson(described, r);
  if (out) {
    const auto& map = r.map;
    double zmax = 0.0;
    for (double z : map.layer_data(map.LayerIndex("elevation"))) {
      if (z > zmax) zmax = z;
    }
    out->WriteFile("elevation.png", TraverseLayerPng(map, "elevation", 0.0, std::max(zmax, 0.05), "m", scenario, r));
    out->WriteFile("slope.png", TraverseLayerPng(map, "slope", 0.0, 0.7854, "rad", scenario, r));
    out->WriteFile("roughness.png", TraverseLayerPng(map, "roughness", 0.0, 0.1, "m", scenario, r));
    out->WriteFile("semantics.png", TraverseLayerPng(map, "semantics", 0.0, 1.0, "", scenario, r));
    out->WriteFile("collapsibility.png", TraverseLayerPng(map, "collapsibility", 0.0, 1.0, "C", scenario, r));
    out->WriteFile("traversability.png", TraverseLayerPng(map, "traversability", 0.0, 1.0, "t", scenario, r));
    out->WriteFile("summary.json", summary + "\n");
    out->Commit();
  }
  if (args.json) {
    std::printf("%s\n", summary.c_str());
    return 0;
  }
  std::printf("probing    %s (%s probe model)\n", args.no_probing ? "off" : "on", described.probe_model.c_str());
  for (const auto& p : r.probes) {
    std::printf("probe      tick %d at (%s, %s) %s '%s': %s N, C = %s\n", p.tick, FormatShort(p.target.x()).c_str(),
                FormatShort(p.target.y()).c_str(), p.cluster_class.c_str(), p.region.c_str(),
                FormatShort(p.average_force).c_str(), FormatShort(p.collapsibility).c_str());
  }
  std::printf("goal       %s after %d ticks, %s m walked, %d replans\n",
              r.reached_goal ? "reached" : ("not reached: " + r.failure).c_str(), r.ticks,
              FormatShort(r.distance_walked).c_str(), r.replans);
  std::printf("collapsible ground stepped on: %s (%d steps)\n", r.collapsible_steps > 0 ? "YES" : "no",
              r.collapsible_steps);
  if (out) std::printf("wrote      %s/summary.json and 6 layer PNGs\n", args.out.c_str());
  return 0;
}

}  // namespace

void RegisterTraverseCommand(CommandRegistry* registry) {
  registry->Add("traverse", "Map, probe and cross terrain with plants and water (seed 001 §6.1)",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<TraverseArgs>();
                  app.add_option("--scenario", args->scenario, "Traverse scenario YAML file (docs/traverse.md)")
                      ->required();
                  app.add_option("--out", args->out,
                                 "Folder for summary.json and the layer PNGs (replaced as a whole)");
                  app.add_flag("--no-probing", args->no_probing,
                               "Vision only: never probe (the robot may step on collapsible ground)");
                  app.add_flag("--json", args->json, "Print the summary as one JSON object");
                  return [args] { return RunTraverse(*args); };
                });
}

}  // namespace cairn::cli
