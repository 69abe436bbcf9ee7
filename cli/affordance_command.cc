// `cairn affordance`: the haptic traversability-affordance experiments of seed 000 §4 on the simulated objects.

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "affordance_plot.h"
#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/simulation/haptic_affordance_experiment.h"
#include "command_registry.h"
#include "numeric_option.h"

namespace cairn::cli {
namespace {

using namespace cairn::perception;

struct AffordanceArguments {
  int episodes{20};
  int samples{4};
  long long seed{1};
  std::string out;
  bool json{false};
};

bool IsAffordanceOutput(const std::string& name) {
  return name == "affordance.json" || name == "confidence.png" || name == "interactions.png" ||
         name == "confusion.png";
}

struct Results {
  TraversabilityConfusion k1;
  TraversabilityConfusion k3;
  std::vector<HapticEncounter> incremental;
  std::vector<double> alphas{0.5, 1.0, 1.5};
  std::vector<std::vector<int>> sweep;
  std::vector<HapticAffordanceExperiment::ChangeRun> changes;
  std::vector<HapticEncounter> transfer;
};

void Confusion(JsonWriter& json, const TraversabilityConfusion& c) {
  json.BeginObject().Key("accuracy").Number(c.accuracy(), JsonWriter::Fixed(4)).Key("confusion").BeginArray();
  for (const auto& row : c.counts) json.BeginArray().Integer(row[0]).Integer(row[1]).EndArray();
  json.EndArray().EndObject();
}

std::string ResultsJson(const AffordanceArguments& args, const Results& r) {
  JsonWriter json;
  json.BeginObject();
  json.Key("seed").Integer(args.seed).Key("episodes").Integer(args.episodes).Key("samples_per_object").Integer(args.samples);
  json.Key("confusion_layout").String("rows actual, columns predicted; traversable first");
  json.Key("leave_one_out").BeginObject();
  json.Key("k1");
  Confusion(json, r.k1);
  json.Key("k3");
  Confusion(json, r.k3);
  json.Key("paper_accuracy").BeginObject().Key("k1").Number(0.67).Key("k3").Number(0.78).EndObject();
  json.EndObject();
  json.Key("incremental").BeginArray();
  for (std::size_t i = 0; i < r.incremental.size(); ++i) {
    const HapticEncounter& e = r.incremental[i];
    json.BeginObject().Key("object").String(HapticObjectName(e.kind)).Key("encounter").Integer(i);
    json.Key("confidence").Number(e.recall.confidence, JsonWriter::Fixed(4));
    json.Key("classified_traversable").Bool(e.recall.traversable).Key("interaction_points").Integer(e.interaction_points);
    json.Key("touched").Bool(e.touched).Key("blocked").Bool(e.blocked).EndObject();
  }
  json.EndArray();
  json.Key("alpha_sweep").BeginObject().Key("object").String(HapticObjectName(HapticObjectKind::kNovelGrass));
  json.Key("alphas").BeginArray();
  for (double a : r.alphas) json.Number(a);
  json.EndArray().Key("interaction_points_by_memory_size").BeginArray();
  for (const auto& row : r.sweep) {
    json.BeginArray();
    for (int v : row) json.Integer(v);
    json.EndArray();
  }
  json.EndArray().EndObject();
  json.Key("change_detection").BeginArray();
  for (const auto& run : r.changes) {
    json.BeginObject().Key("run").String(run.name).Key("differences").BeginArray();
    for (double d : run.differences) json.Number(d, JsonWriter::Fixed(4));
    json.EndArray().Key("detected").Bool(run.detected).Key("exit_step").Integer(run.exit_step).EndObject();
  }
  json.EndArray();
  json.Key("data_set_2_to_1").BeginObject().Key("k").Integer(5).Key("samples").BeginArray();
  for (const HapticEncounter& e : r.transfer) {
    json.BeginObject().Key("object").String(HapticObjectName(e.kind)).Key("traversable").Bool(e.traversable);
    json.Key("classified_traversable").Bool(e.recall.traversable);
    json.Key("confidence").Number(e.recall.confidence, JsonWriter::Fixed(4)).EndObject();
  }
  json.EndArray().EndObject();
  json.EndObject();
  return json.text();
}

std::string ConfidencePng(const Results& r) {
  std::vector<PlotSeries> series;
  const std::array<int, 3> colours[] = {{200, 80, 0}, {0, 0, 200}};
  for (std::size_t i = 0; i < r.incremental.size(); ++i) {
    const HapticEncounter& e = r.incremental[i];
    const std::string name = HapticObjectName(e.kind);
    if (series.empty() || series.back().name != name) {
      series.push_back({name, colours[series.size() % 2], {}, {}});
    }
    series.back().x.push_back(static_cast<double>(i + 1));
    series.back().y.push_back(e.recall.confidence);
  }
  return LinePlotPng("Classification confidence over encounters (cf. Fig. 13)", "encounter", "confidence c(o)",
                     series);
}

std::string InteractionsPng(const Results& r) {
  std::vector<PlotSeries> series;
  const std::array<int, 3> colours[] = {{200, 80, 0}, {0, 140, 0}, {0, 0, 200}};
  for (std::size_t a = 0; a < r.alphas.size(); ++a) {
    PlotSeries s{"alpha = " + FormatShort(r.alphas[a]), colours[a % 3], {}, {}};
    for (std::size_t n = 0; n < r.sweep[a].size(); ++n) {
      s.x.push_back(static_cast<double>(n));
      s.y.push_back(r.sweep[a][n]);
    }
    series.push_back(s);
  }
  return LinePlotPng("Haptic interaction points against memory size (cf. Fig. 15)", "samples in memory",
                     "interaction points", series);
}

void PrintSummary(const Results& r) {
  const auto row = [](const char* name, const TraversabilityConfusion& c) {
    std::printf("%-22s %5.1f%%  [[%d, %d], [%d, %d]]\n", name, 100.0 * c.accuracy(), c.counts[0][0], c.counts[0][1],
                c.counts[1][0], c.counts[1][1]);
  };
  row("leave-one-out k=1", r.k1);
  row("leave-one-out k=3", r.k3);
  std::printf("%-22s", "confidence curve");
  for (const HapticEncounter& e : r.incremental) std::printf(" %.2f", e.recall.confidence);
  std::printf("\n");
  for (std::size_t a = 0; a < r.alphas.size(); ++a) {
    std::printf("interactions a=%-7s", FormatShort(r.alphas[a]).c_str());
    for (int v : r.sweep[a]) std::printf(" %d", v);
    std::printf("\n");
  }
  for (const auto& run : r.changes) {
    std::printf("change %-15s %s:", run.name.c_str(), run.detected ? "detected" : "none");
    for (double d : run.differences) std::printf(" %.3f", d);
    std::printf("\n");
  }
  int wrong = 0;
  for (const HapticEncounter& e : r.transfer) wrong += e.recall.traversable != e.traversable;
  std::printf("%-22s %d of %d samples misclassified\n", "data set 2 -> 1, k=5", wrong,
              static_cast<int>(r.transfer.size()));
}

int Run(const AffordanceArguments& args) {
  // Before the experiments: an --out that cannot be written fails now.
  std::unique_ptr<AtomicOutputDirectory> out;
  if (!args.out.empty()) out = std::make_unique<AtomicOutputDirectory>(args.out, IsAffordanceOutput);
  HapticAffordanceExperiment::Options options;
  options.seed = static_cast<std::uint64_t>(args.seed);
  options.samples_per_object = args.samples;
  const HapticAffordanceExperiment experiment(options);
  Results r;
  r.k1 = experiment.LeaveOneOut(DataSet1(), 1);
  r.k3 = experiment.LeaveOneOut(DataSet1(), 3);
  TraversabilityMemory memory(options.memory, options.descriptor.lines);
  r.incremental = experiment.Incremental(DataSet2(), args.episodes, &memory);
  r.sweep = experiment.AlphaSweep(HapticObjectKind::kNovelGrass, r.alphas, args.episodes);
  r.changes = experiment.ChangeDetection(0.03, 0.01);
  r.transfer = experiment.Transfer(DataSet2(), DataSet1(), 5);
  const std::string json = ResultsJson(args, r);
  if (out) {
    out->WriteFile("affordance.json", json + "\n");
    out->WriteFile("confidence.png", ConfidencePng(r));
    out->WriteFile("interactions.png", InteractionsPng(r));
    out->WriteFile("confusion.png", ConfusionPng({{"leave-one-out, k = 1", r.k1.counts},
                                                  {"leave-one-out, k = 3", r.k3.counts}}));
    out->Commit();
  }
  if (args.json) {
    std::printf("%s\n", json.c_str());
  } else {
    PrintSummary(r);
    if (out) std::printf("wrote      %s/affordance.json, confidence.png, interactions.png, confusion.png\n", args.out.c_str());
  }
  return 0;
}

}  // namespace

void RegisterAffordanceCommand(CommandRegistry* registry) {
  registry->Add("affordance",
                "Learn traversability from an antenna's touch on simulated objects (seed 000 experiments)",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<AffordanceArguments>();
                  AddNumberOption(app, "--episodes", &args->episodes,
                                  "Encounters with each novel object in the learning sequence (and the largest "
                                  "memory of the alpha sweep)",
                                  NumberRange::Closed(1, HapticAffordanceExperiment::kMaxSamples));
                  AddNumberOption(app, "--samples", &args->samples,
                                  "Approach samples per object in leave-one-out and data set 2 -> 1",
                                  NumberRange::Closed(1, 100));
                  AddNumberOption(app, "--seed", &args->seed, "Seed of the objects, views and sensor noise",
                                  NumberRange::Closed(0, 1e15));
                  app.add_option("--out", args->out,
                                 "Folder for affordance.json and the PNG plots (replaced as a whole)");
                  app.add_flag("--json", args->json, "Print the results as one JSON object");
                  return [args] { return Run(*args); };
                });
}

}  // namespace cairn::cli
