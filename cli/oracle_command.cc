// `cairn oracle build`: a transition oracle (the footstep planner's step-cost table) built over a grid, on one
// process or spread over MPI ranks (`mpirun -np N cairn oracle build ...`), checkpointed in chunks so a killed
// build resumes where it stopped, and merged into the same bytes whatever the number of ranks.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/planning/locomotion/oracle_shard_builder.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "cairn/planning/locomotion/walking_model.h"
#include "cairn/planning/locomotion/walking_objective.h"
#include "choice_option.h"
#include "command_registry.h"
#include "data_directory.h"
#include "file_checks.h"
#include "mpi_session.h"
#include "numeric_option.h"
#include "progress_bar.h"

namespace cairn::cli {
namespace {

using namespace cairn::planning;

struct OracleBuildArguments {
  std::string walking = DataDirectory() + "/robots/cairn_humanoid_walking.yaml";
  std::string grid;
  std::string objective = "ecom_heat";
  std::string source = TransitionOracle::kSource;
  std::string out;
  std::string checkpoint;
  int chunk_cells = 16;
  int threads = 0;
  bool json = false;
};

// Prints the outcome on rank 0.
void PrintSummary(const OracleBuildArguments& args, const TransitionOracle& oracle, const MpiSession& mpi,
                  int num_chunks, int computed, int resumed, double seconds) {
  if (args.json) {
    JsonWriter json;
    json.BeginObject()
        .Key("out").String(args.out)
        .Key("source").String(args.source)
        .Key("objective").String(args.objective)
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
              oracle.robot_name().c_str(), args.objective.c_str(), args.source.c_str());
  std::printf("built      %d chunks on %d rank%s: %d computed, %d resumed from checkpoints, %s s\n", num_chunks,
              mpi.size(), mpi.size() == 1 ? "" : "s", computed, resumed, FormatShort(seconds).c_str());
}

int RunBuild(const OracleBuildArguments& args) {
  MpiSession mpi;
  const auto start = std::chrono::steady_clock::now();
  // Every rank checks and loads the same inputs; a mistake fails every rank with the same message, before any
  // work, and rank 0 alone prints it (main() prints the exception of each rank, so the others exit quietly).
  int computed = 0, resumed = 0, num_chunks = 0;
  std::string error;
  std::unique_ptr<WalkingModel> model;
  std::unique_ptr<OracleShardBuilder> builder;
  try {
    CheckInputFile("--walking", args.walking, "a walking-model YAML file");
    if (!args.grid.empty()) CheckInputFile("--grid", args.grid, "an oracle grid YAML file");
    CheckOutputFile("--out", args.out);
    model = std::make_unique<WalkingModel>(WalkingModel::Load(args.walking));
    const OracleGrid grid = args.grid.empty() ? OracleGrid::Default(*model) : OracleGrid::Load(args.grid);
    const std::string checkpoint = args.checkpoint.empty() ? args.out + ".parts" : args.checkpoint;
    builder = std::make_unique<OracleShardBuilder>(*model, ParseWalkingObjective(args.objective), grid, checkpoint,
                                                   args.chunk_cells);
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

}  // namespace

void RegisterOracleCommand(CommandRegistry* registry) {
  registry->Add("oracle", "Build transition oracles (step-cost tables), on one process or over MPI ranks",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<OracleBuildArguments>();
                  app.require_subcommand(1);
                  CLI::App* build = app.add_subcommand(
                      "build", "Build an oracle over a grid; resumable; `mpirun -np N cairn oracle build ...` shares it");
                  build->add_option("--out", args->out, "The oracle file to write")->required();
                  build->add_option("--grid", args->grid,
                                    "Grid YAML (dx, dy, dz, dtheta, mu: lists or {from, to, step}; docs/oracle.md); "
                                    "default: the walking model's default grid");
                  build->add_option("--walking", args->walking, "Walking-model YAML")->capture_default_str();
                  AddChoiceOption(*build, "--objective", &args->objective, "Step objective", WalkingObjectiveNames());
                  AddChoiceOption(*build, "--source", &args->source, "Where the entries come from",
                                  {TransitionOracle::kSource});
                  build->add_option("--checkpoint", args->checkpoint,
                                    "Folder of the chunk checkpoints (default: <out>.parts)");
                  AddNumberOption(*build, "--chunk-cells", &args->chunk_cells,
                                  "Displacement cells per checkpointed chunk",
                                  NumberRange::Closed(1, OracleShardBuilder::kMaxCellsPerChunk));
                  AddNumberOption(*build, "--threads", &args->threads,
                                  "Worker threads per rank (0: the cores divided among the ranks)",
                                  NumberRange::Closed(0, 256));
                  build->add_flag("--json", args->json, "Print the summary as one JSON object");
                  return [args]() { return RunBuild(*args); };
                });
}

}  // namespace cairn::cli
