// `cairn oracle build`: a transition oracle (the footstep planner's step-cost table) built over a grid, on one
// process or spread over MPI ranks (`mpirun -np N cairn oracle build ...`), checkpointed in chunks so a killed
// build resumes where it stopped, and merged into the same bytes whatever the number of ranks. Its entries come
// from the analytic walking model (`--source model`), from periodic gaits walked in the physics plant
// (`--source plant`), or from the same gaits optimised and stabilised but not walked (`--source pipeline`).
//
// `cairn oracle check`: how well a table predicts its own source between its grid values (held-out steps; the
// thesis' SMSE), printed and, with --out, written as heldout.json and heldout.png.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/planning/locomotion/model_transition_source.h"
#include "cairn/planning/locomotion/oracle_held_out_error.h"
#include "cairn/planning/locomotion/oracle_shard_builder.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "cairn/planning/walk/plant_transition_source.h"
#include "choice_option.h"
#include "command_registry.h"
#include "data_directory.h"
#include "file_checks.h"
#include "mpi_session.h"
#include "numeric_option.h"
#include "oracle_cache.h"
#include "oracle_check_plot.h"
#include "progress_bar.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

using namespace cairn::planning;

// The options that say which table: the robot, the grid, the objective and the source with its settings. Shared
// by `build` and `check`.
struct TableArguments {
  std::string walking = DataDirectory() + "/robots/cairn_humanoid_walking.yaml";
  std::string grid;
  std::string objective = "ecom_heat";
  std::string source = TransitionOracle::kSource;
  // --source plant or pipeline only.
  std::string control = DefaultControlYaml();
  std::string t_ds, t_sw;                        // as given
  std::vector<double> t_ds_values, t_sw_values;  // parsed (empty: the source's defaults)
};

struct OracleBuildArguments {
  TableArguments table;
  std::string out;    // --out, or after parsing the file --cache names
  std::string cache;  // --cache
  std::string checkpoint;
  int chunk_cells = 16;
  bool chunk_cells_given = false;
  int threads = 0;
  bool json = false;
};

struct OracleCheckArguments {
  TableArguments table;
  std::string oracle;
  int samples = 20;
  long long seed = 1;
  std::string out;
  bool json = false;
};

// A comma-separated list of numbers given for `option` ("" when not given: empty).
std::vector<double> ParseNumberList(const std::string& option, const std::string& text) {
  std::vector<double> values;
  if (text.empty()) return values;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    values.push_back(ParseNumber<double>(option, text.substr(begin, comma - begin), NumberRange::Open(0.0, 100.0)));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return values;
}

void AddTableOptions(CLI::App& app, TableArguments* args) {
  app.add_option("--grid", args->grid,
                 "Grid YAML (dx, dy, dz, dtheta, mu: lists or {from, to, step}; docs/oracle.md); default: the "
                 "source's default grid");
  app.add_option("--walking", args->walking, "Walking-model YAML")->capture_default_str();
  AddChoiceOption(app, "--objective", &args->objective, "Step objective", WalkingObjectiveNames());
  AddChoiceOption(app, "--source", &args->source,
                  "Where the entries come from: the analytic walking model, periodic gaits walked in the physics "
                  "plant, or the same gaits optimised and stabilised but not walked (pipeline: the whole-body "
                  "cost; objectives torque, ecom, time). Gaits are slow (seconds each); their default grid is "
                  "PlantTransitionSource::DefaultGrid (docs/oracle.md)",
                  OracleSourceNames());
  app.add_option("--t-ds", args->t_ds,
                 "--source plant|pipeline: double-support times to try, s, comma-separated (default 0.2,0.5,0.9)");
  app.add_option("--t-sw", args->t_sw,
                 "--source plant|pipeline: swing times to try, s, comma-separated (default 0.9,1.2)");
  app.add_option("--control", args->control, "--source plant|pipeline: joint-controller YAML")->capture_default_str();
}

// In the action, after parsing: the gait sources' options with --source model are a mistake, and the timing lists
// are parsed (usage errors, exit 2).
void FinishTableOptions(const CLI::App& app, TableArguments* args) {
  if (args->source == TransitionOracle::kSource) {
    for (const char* name : {"--t-ds", "--t-sw", "--control"}) {
      if (app.count(name) > 0) {
        throw UsageError(std::string(name) +
                         " applies to --source plant or pipeline only; drop it or add --source plant");
      }
    }
  }
  args->t_ds_values = ParseNumberList("--t-ds", args->t_ds);
  args->t_sw_values = ParseNumberList("--t-sw", args->t_sw);
}

// What a table is made of, loaded and checked from its options.
struct TableInputs {
  std::shared_ptr<const WalkingModel> model;
  WalkingObjective objective{WalkingObjective::kComWorkPlusHeat};
  std::shared_ptr<const TransitionSource> source;  // null: the analytic model
  OracleGrid grid;
};

TableInputs LoadTableInputs(const TableArguments& args) {
  CheckInputFile("--walking", args.walking, "a walking-model YAML file");
  if (!args.grid.empty()) CheckInputFile("--grid", args.grid, "an oracle grid YAML file");
  TableInputs inputs;
  inputs.model = std::make_shared<const WalkingModel>(WalkingModel::Load(args.walking));
  inputs.objective = ParseWalkingObjective(args.objective);
  inputs.source =
      OracleSource(args.source, inputs.model, args.control, inputs.objective, args.t_ds_values, args.t_sw_values);
  inputs.grid =
      !args.grid.empty() ? OracleGrid::Load(args.grid) : DefaultOracleGrid(inputs.source.get(), *inputs.model);
  return inputs;
}

// Prints the outcome on rank 0.
void PrintSummary(const OracleBuildArguments& args, const TransitionOracle& oracle, const MpiSession& mpi,
                  int num_chunks, int computed, int resumed, double seconds) {
  if (args.json) {
    JsonWriter json;
    json.BeginObject()
        .Key("out").String(args.out)
        .Key("source").String(args.table.source)
        .Key("objective").String(args.table.objective)
        .Key("robot").String(oracle.robot_name())
        .Key("entries").Integer(static_cast<long long>(oracle.num_entries()))
        .Key("feasible").Integer(static_cast<long long>(oracle.num_feasible()))
        .Key("ranks").Integer(mpi.size())
        .Key("chunks").Integer(num_chunks)
        .Key("computed_chunks").Integer(computed)
        .Key("resumed_chunks").Integer(resumed)
        .Key("seconds").Number(seconds)
        .EndObject();
    std::printf("%s\n", json.text().c_str());
    return;
  }
  std::printf("oracle     %s\n", args.out.c_str());
  std::printf("table      %s entries (%s feasible), robot %s, objective %s, source %s\n",
              FormatShort(oracle.num_entries()).c_str(), FormatShort(oracle.num_feasible()).c_str(),
              oracle.robot_name().c_str(), args.table.objective.c_str(), args.table.source.c_str());
  std::printf("built      %d chunks on %d rank%s: %d computed, %d resumed from checkpoints, %s s\n", num_chunks,
              mpi.size(), mpi.size() == 1 ? "" : "s", computed, resumed, FormatShort(seconds).c_str());
}

int RunBuild(OracleBuildArguments args) {
  MpiSession mpi;
  const auto start = std::chrono::steady_clock::now();
  // Every rank checks and loads the same inputs; a mistake fails every rank with the same message, before any
  // work, and rank 0 alone prints it (main() prints the exception of each rank, so the others exit quietly).
  int computed = 0, resumed = 0, num_chunks = 0;
  std::string error;
  TableInputs table;
  std::unique_ptr<OracleShardBuilder> builder;
  try {
    if (args.cache.empty()) CheckOutputFile("--out", args.out);
    table = LoadTableInputs(args.table);
    if (!args.cache.empty()) {
      args.out = OracleCachePath(args.cache, *table.model, table.objective, table.source.get(), table.grid);
      // plan creates its cache folder on first use; so does this.
      std::error_code folder_error;
      std::filesystem::create_directories(args.cache, folder_error);
      if (folder_error) {
        throw std::runtime_error("--cache '" + args.cache + "' cannot be created (" + folder_error.message() +
                                 "); give a writable folder");
      }
      CheckOutputFile("--cache", args.out);
    }
    const std::string checkpoint = args.checkpoint.empty() ? args.out + ".parts" : args.checkpoint;
    // A gait source's cell measures several gaits (seconds each): one cell per chunk spreads them over the ranks
    // and loses little to a kill.
    const bool gaits = table.source != nullptr;
    const int chunk_cells = gaits && !args.chunk_cells_given ? 1 : args.chunk_cells;
    builder = std::make_unique<OracleShardBuilder>(*table.model, table.objective, table.grid, checkpoint,
                                                   chunk_cells, table.source);
    num_chunks = builder->num_chunks();
    OracleBuildOptions options;
    // The ranks share the machine's cores unless told otherwise.
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    options.num_threads = args.threads > 0 ? args.threads : std::max(1, cores / mpi.size());
    // Rank 0 draws its own chunks' progress; the other ranks stay quiet.
    ProgressBar bar = ProgressBar::ForStderr("building the transition oracle (rank 0's entries)");
    if (mpi.rank() == 0) options.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
    const OracleShardBuilder::ShardReport report = builder->BuildShard(mpi.rank(), mpi.size(), options);
    computed = report.computed;
    resumed = report.resumed;
  } catch (const std::exception& e) {
    error = e.what();
  }
  const int failures = mpi.Sum(error.empty() ? 0 : 1);
  if (!error.empty()) {
    if (mpi.rank() == 0 || failures < mpi.size()) throw std::runtime_error(error);
    return 1;  // every rank failed, presumably on the same input: rank 0 says why
  }
  if (failures > 0) {
    if (mpi.rank() != 0) return 1;
    throw std::runtime_error(FormatShort(failures) + " of " + FormatShort(mpi.size()) +
                             " ranks failed (their messages are above); the chunks finished so far are kept: run the "
                             "same command again to resume");
  }
  // Sum waits for every rank, so every rank's chunks are on disk before rank 0 merges them.
  const int total_computed = mpi.Sum(computed);
  const int total_resumed = mpi.Sum(resumed);
  if (mpi.rank() != 0) return 0;
  const TransitionOracle oracle = builder->Merge();
  oracle.Save(args.out);
  builder->RemoveCheckpoints();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  PrintSummary(args, oracle, mpi, num_chunks, total_computed, total_resumed, seconds);
  return 0;
}

bool IsCheckOutput(const std::string& name) { return name == "heldout.json" || name == "heldout.png"; }

// The unit of a table's cost: the pipeline's torque cost is the whole-body optimiser's, of torques normalised by
// their effort limits.
std::string ObjectiveUnit(WalkingObjective objective, const std::string& source) {
  switch (objective) {
    case WalkingObjective::kTravelTime: return "s";
    case WalkingObjective::kSquaredTorque:
      return source == PlantTransitionSource::kPipelineName ? "normalised" : "N^2 m^2 s";
    default: return "J";
  }
}

std::string CheckJson(const OracleCheckArguments& args, const TransitionOracle& oracle,
                      const OracleHeldOutError& error) {
  JsonWriter json;
  json.BeginObject()
      .Key("oracle").String(args.oracle)
      .Key("source").String(oracle.source())
      .Key("objective").String(to_string(oracle.objective()))
      .Key("samples").Integer(args.samples)
      .Key("seed").Integer(args.seed)
      .Key("both_feasible").Integer(error.both_feasible)
      .Key("only_predicted").Integer(error.only_predicted)
      .Key("only_measured").Integer(error.only_measured)
      .Key("neither").Integer(error.neither)
      .Key("smse").Number(error.smse)
      .Key("mean_absolute_error").Number(error.mean_absolute_error)
      .Key("mean_relative_error").Number(error.mean_relative_error)
      .Key("correlation").Number(error.correlation)
      .Key("steps").BeginArray();
  for (const HeldOutSample& s : error.samples) {
    const double none = std::numeric_limits<double>::quiet_NaN();
    json.BeginObject()
        .Key("dx").Number(s.d.dx).Key("dy").Number(s.d.dy).Key("dz").Number(s.d.dz).Key("dtheta").Number(s.d.dtheta)
        .Key("mu").Number(s.mu)
        .Key("predicted").Number(s.predicted.feasible ? s.predicted.cost : none)
        .Key("measured").Number(s.measured.feasible ? s.measured.cost : none)
        .EndObject();
  }
  json.EndArray().EndObject();
  return json.text();
}

int RunCheck(const OracleCheckArguments& args) {
  CheckInputFile("--oracle", args.oracle, "a transition oracle file (cairn oracle build)");
  std::optional<AtomicOutputDirectory> out;
  if (!args.out.empty()) out.emplace(args.out, IsCheckOutput);
  const TableInputs table = LoadTableInputs(args.table);
  const TransitionOracle oracle =
      TransitionOracle::Load(args.oracle, *table.model, table.objective, table.grid, table.source.get());
  const ModelTransitionSource analytic;
  const TransitionSource& source = table.source != nullptr ? *table.source : analytic;
  OracleHeldOutOptions options;
  options.num_samples = args.samples;
  options.seed = static_cast<std::uint64_t>(args.seed);
  ProgressBar bar = ProgressBar::ForStderr("asking the source at held-out steps");
  options.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  const OracleHeldOutError error = MeasureOracleHeldOutError(oracle, source, *table.model, options);
  if (out) {
    out->WriteFile("heldout.json", CheckJson(args, oracle, error) + "\n");
    out->WriteFile("heldout.png", OracleHeldOutPng(error, "held-out steps: " + source.name() + " table vs source",
                                                   ObjectiveUnit(oracle.objective(), args.table.source)));
    out->Commit();
  }
  if (args.json) {
    std::printf("%s\n", CheckJson(args, oracle, error).c_str());
    return 0;
  }
  std::printf("oracle     %s (source %s, objective %s)\n", args.oracle.c_str(), oracle.source().c_str(),
              to_string(oracle.objective()));
  std::printf("held out   %d steps (seed %lld): both feasible %d, table only %d, source only %d, neither %d\n",
              args.samples, args.seed, error.both_feasible, error.only_predicted, error.only_measured, error.neither);
  std::printf("cost       SMSE %s, mean absolute error %s %s, mean relative error %s, correlation %s\n",
              FormatShort(error.smse).c_str(), FormatShort(error.mean_absolute_error).c_str(),
              ObjectiveUnit(oracle.objective(), args.table.source).c_str(),
              FormatShort(error.mean_relative_error).c_str(), FormatShort(error.correlation).c_str());
  if (out) std::printf("wrote      %s/heldout.json, %s/heldout.png\n", args.out.c_str(), args.out.c_str());
  return 0;
}

}  // namespace

void RegisterOracleCommand(CommandRegistry* registry) {
  registry->Add("oracle", "Build transition oracles (step-cost tables), on one process or over MPI ranks; check them",
                [](CLI::App& app) -> CommandAction {
                  auto build_args = std::make_shared<OracleBuildArguments>();
                  auto check_args = std::make_shared<OracleCheckArguments>();
                  app.require_subcommand(1);
                  CLI::App* build = app.add_subcommand(
                      "build", "Build an oracle over a grid; resumable; `mpirun -np N cairn oracle build ...` shares it");
                  CLI::Option* out = build->add_option("--out", build_args->out, "The oracle file to write");
                  build->add_option("--cache", build_args->cache,
                                    "Instead of --out: write into this oracle cache folder, under the name plan, "
                                    "walk and run look up for the same robot, objective, source and grid")
                      ->excludes(out);
                  AddTableOptions(*build, &build_args->table);
                  build->add_option("--checkpoint", build_args->checkpoint,
                                    "Folder of the chunk checkpoints (default: <out>.parts)");
                  AddNumberOption(*build, "--chunk-cells", &build_args->chunk_cells,
                                  "Displacement cells per checkpointed chunk (--source plant|pipeline: default 1)",
                                  NumberRange::Closed(1, OracleShardBuilder::kMaxCellsPerChunk));
                  AddNumberOption(*build, "--threads", &build_args->threads,
                                  "Worker threads per rank (0: the cores divided among the ranks)",
                                  NumberRange::Closed(0, 256));
                  build->add_flag("--json", build_args->json, "Print the summary as one JSON object");

                  CLI::App* check = app.add_subcommand(
                      "check", "How well a table predicts its source between its grid values (held-out steps, SMSE)");
                  check->add_option("--oracle", check_args->oracle, "The oracle file (give the options it was built "
                                                                    "with: --grid, --objective, --source, ...)")
                      ->required();
                  AddTableOptions(*check, &check_args->table);
                  AddNumberOption(*check, "--samples", &check_args->samples, "Held-out steps",
                                  NumberRange::Closed(1, 100000));
                  AddNumberOption(*check, "--seed", &check_args->seed, "Seeds the held-out steps",
                                  NumberRange::Closed(0, 1e15));
                  check->add_option("--out", check_args->out, "Folder for heldout.json and heldout.png");
                  check->add_flag("--json", check_args->json, "Print the result as one JSON object");

                  return [build_args, check_args, build, check]() {
                    if (check->parsed()) {
                      FinishTableOptions(*check, &check_args->table);
                      return RunCheck(*check_args);
                    }
                    if (build_args->out.empty() && build_args->cache.empty()) {
                      throw UsageError("oracle build needs --out FILE (the table to write) or --cache DIR (an "
                                       "oracle cache folder, as plan --oracle-cache takes)");
                    }
                    build_args->chunk_cells_given = build->count("--chunk-cells") > 0;
                    FinishTableOptions(*build, &build_args->table);
                    return RunBuild(*build_args);
                  };
                });
}

}  // namespace cairn::cli
