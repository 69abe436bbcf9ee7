// Transition sources (issue 21): the base class checks what it is asked and what it returns, the analytic source
// gives the table the oracle always built, and an oracle records its source so it is never loaded for another.
#include "cairn/planning/locomotion/transition_source.h"

#include <filesystem>
#include <mutex>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "../support/shared_oracle.h"
#include "cairn/planning/locomotion/model_transition_source.h"
#include "cairn/planning/locomotion/oracle_held_out_error.h"
#include "cairn/planning/locomotion/oracle_shard_builder.h"
#include "cairn/planning/locomotion/transition_oracle.h"
#include "expect_throws.h"

namespace cairn::planning {
namespace {

// Entries from a formula: cost 1 + dx, feasible from mu = 0.1 on. Records the threads it was called from.
class FormulaSource final : public TransitionSource {
 public:
  explicit FormulaSource(bool concurrent, std::string settings = "slope 1", std::size_t extra_entries = 0)
      : concurrent_(concurrent), settings_(std::move(settings)), extra_entries_(extra_entries) {}
  std::size_t num_threads() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return threads_.size();
  }

 private:
  std::string do_name() const override { return "formula"; }
  std::string do_settings() const override { return settings_; }
  bool do_concurrent() const override { return concurrent_; }
  std::vector<TransitionCost> DoCellEntries(const WalkingModel&, WalkingObjective, const StepDisplacement& d,
                                            const std::vector<double>& mu) const override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      threads_.insert(std::this_thread::get_id());
    }
    std::vector<TransitionCost> entries(mu.size() + extra_entries_);
    for (std::size_t k = 0; k < mu.size(); ++k) {
      if (mu[k] < 0.1) continue;
      entries[k].feasible = true;
      entries[k].cost = 1.0 + d.dx;
      entries[k].parameters = {0.3, 0.9, 0.7};
      entries[k].rcof = 0.1;
      entries[k].duration = 1.2;
    }
    return entries;
  }

  bool concurrent_;
  std::string settings_;
  std::size_t extra_entries_;
  mutable std::mutex mutex_;
  mutable std::set<std::thread::id> threads_;
};

OracleGrid Grid() {
  OracleGrid grid;
  grid.dx = {0.1, 0.2};
  grid.dy = {0.18, 0.24};
  grid.dz = {0.0};
  grid.dtheta = {0.0, 0.3};
  grid.mu = {0.05, 0.2, 1.0};
  return grid;
}

TEST(TransitionSourceTest, ChecksTheFrictionLimitsTheDisplacementAndTheEntryCount) {
  const WalkingModel& model = *test::SharedWalkingModel();
  const FormulaSource source(true);
  const StepDisplacement d{0.1, 0.2, 0.0, 0.0};
  EXPECT_EQ(source.CellEntries(model, WalkingObjective::kComWork, d, {0.05, 0.5}).size(), 2u);
  CAIRN_EXPECT_THROWS_WITH(source.CellEntries(model, WalkingObjective::kComWork, d, {}), std::invalid_argument,
                           "at least one friction limit");
  CAIRN_EXPECT_THROWS_WITH(source.CellEntries(model, WalkingObjective::kComWork, d, {0.5, 0.5}),
                           std::invalid_argument, "friction limit 0.5", "larger than the one before it");
  CAIRN_EXPECT_THROWS_WITH(source.CellEntries(model, WalkingObjective::kComWork, d, {-0.1}), std::invalid_argument,
                           "friction limit -0.1");
  CAIRN_EXPECT_THROWS_WITH(
      source.CellEntries(model, WalkingObjective::kComWork, StepDisplacement{NAN, 0.2, 0.0, 0.0}, {0.5}),
      std::invalid_argument, "not finite");
  const FormulaSource wrong(true, "", 1);
  CAIRN_EXPECT_THROWS_WITH(wrong.CellEntries(model, WalkingObjective::kComWork, d, {0.5}), std::logic_error,
                           "'formula' gave 2 entries for 1 friction limits");
  EXPECT_EQ(wrong.Describe(), "formula");
  EXPECT_EQ(source.Describe(), "formula slope 1");
}

// The analytic source is the oracle's default: a table built with it named is the table built without a source.
TEST(TransitionSourceTest, TheModelSourceIsTheDefaultTable) {
  const WalkingModel& model = *test::SharedWalkingModel();
  OracleBuildOptions options;
  options.num_threads = 1;
  const TransitionOracle implicit = TransitionOracle::Build(model, WalkingObjective::kComWorkPlusHeat, Grid(), options);
  options.source = std::make_shared<ModelTransitionSource>(options.optimizer);
  const TransitionOracle named = TransitionOracle::Build(model, WalkingObjective::kComWorkPlusHeat, Grid(), options);
  EXPECT_EQ(named.Serialize(), implicit.Serialize());
  EXPECT_EQ(named.source(), "model");
  EXPECT_EQ(TransitionOracle::BuildKey(model, WalkingObjective::kComWorkPlusHeat, Grid(), options.source.get()),
            TransitionOracle::BuildKey(model, WalkingObjective::kComWorkPlusHeat, Grid()));
  // Its cells are the source's own entries.
  const std::vector<TransitionCost> cell = options.source->CellEntries(
      model, WalkingObjective::kComWorkPlusHeat, StepDisplacement{0.2, 0.24, 0.0, 0.3}, Grid().mu);
  for (std::size_t k = 0; k < cell.size(); ++k) {
    const TransitionCost& e = implicit.entry(1, 1, 0, 1, k);
    EXPECT_EQ(e.feasible, cell[k].feasible);
    if (e.feasible) {
      EXPECT_EQ(e.cost, cell[k].cost);
    }
  }
}

TEST(TransitionSourceTest, AnOracleRecordsItsSourceAndIsNotLoadedForAnother) {
  const WalkingModel& model = *test::SharedWalkingModel();
  const auto source = std::make_shared<FormulaSource>(false);
  OracleBuildOptions options;
  options.num_threads = 2;
  options.source = source;
  const TransitionOracle oracle = TransitionOracle::Build(model, WalkingObjective::kComWork, Grid(), options);
  EXPECT_EQ(source->num_threads(), 1u) << "a source that is not concurrent is built on one thread";
  EXPECT_EQ(oracle.source(), "formula slope 1");
  EXPECT_NE(oracle.Serialize().find("\nsource formula slope 1\n"), std::string::npos);
  EXPECT_NE(oracle.description().find("source formula slope 1"), std::string::npos) << oracle.description();
  EXPECT_FALSE(oracle.entry(0, 0, 0, 0, 0).feasible);
  EXPECT_DOUBLE_EQ(oracle.entry(1, 0, 0, 1, 2).cost, 1.2);

  const std::string path = (std::filesystem::temp_directory_path() / "cairn_transition_source_test.bin").string();
  oracle.Save(path);
  EXPECT_EQ(TransitionOracle::Load(path, model, WalkingObjective::kComWork, Grid(), source.get()).Serialize(),
            oracle.Serialize());
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, model, WalkingObjective::kComWork, Grid()), std::runtime_error,
                           path, "built from source 'formula slope 1', not 'model'");
  const FormulaSource steeper(false, "slope 2");
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, model, WalkingObjective::kComWork, Grid(), &steeper),
                           std::runtime_error, "not 'formula slope 2'");
  EXPECT_NE(TransitionOracle::BuildKey(model, WalkingObjective::kComWork, Grid(), &steeper),
            TransitionOracle::BuildKey(model, WalkingObjective::kComWork, Grid(), source.get()));
  std::filesystem::remove(path);

  const FormulaSource two_lines(true, "a\nb");
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::BuildKey(model, WalkingObjective::kComWork, Grid(), &two_lines),
                           std::invalid_argument, "must be one non-empty line");
}

// A build in chunks from a source merges to the table one Build makes from it.
TEST(TransitionSourceTest, ShardedBuildsUseTheirSource) {
  const WalkingModel& model = *test::SharedWalkingModel();
  const auto source = std::make_shared<FormulaSource>(true);
  OracleBuildOptions options;
  options.num_threads = 1;
  options.source = source;
  const TransitionOracle whole = TransitionOracle::Build(model, WalkingObjective::kComWork, Grid(), options);
  const std::string folder = (std::filesystem::temp_directory_path() / "cairn_transition_source_shards").string();
  std::filesystem::remove_all(folder);
  const OracleShardBuilder builder(model, WalkingObjective::kComWork, Grid(), folder, 3, source);
  builder.BuildShard(0, 1, OracleBuildOptions{});
  EXPECT_EQ(builder.Merge().Serialize(), whole.Serialize());
  std::filesystem::remove_all(folder);
}

// A cost linear in dx is what multilinear interpolation reproduces: the held-out error is zero, and the steps below
// the formula's friction limit are infeasible for both.
TEST(OracleHeldOutErrorTest, ATableOfALinearCostPredictsItExactly) {
  const WalkingModel& model = *test::SharedWalkingModel();
  const auto source = std::make_shared<FormulaSource>(true);
  OracleBuildOptions options;
  options.num_threads = 1;
  options.source = source;
  const TransitionOracle oracle = TransitionOracle::Build(model, WalkingObjective::kComWork, Grid(), options);
  OracleHeldOutOptions held_out;
  held_out.num_samples = 30;
  std::size_t calls = 0;
  held_out.progress = [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(total, 30u);
    EXPECT_EQ(done, ++calls);
  };
  const OracleHeldOutError error = MeasureOracleHeldOutError(oracle, *source, model, held_out);
  ASSERT_EQ(error.samples.size(), 30u);
  EXPECT_EQ(error.both_feasible + error.neither, 30);
  EXPECT_EQ(error.only_predicted + error.only_measured, 0);
  EXPECT_GT(error.both_feasible, 5);
  EXPECT_GT(error.neither, 3) << "a third of the samples are at mu 0.05";
  EXPECT_NEAR(error.smse, 0.0, 1e-20);
  EXPECT_NEAR(error.mean_absolute_error, 0.0, 1e-12);
  EXPECT_NEAR(error.correlation, 1.0, 1e-12);
  for (const HeldOutSample& s : error.samples) {
    EXPECT_GE(s.d.dx, 0.1);
    EXPECT_LE(s.d.dx, 0.2);
    EXPECT_GE(s.d.dtheta, 0.0);
    EXPECT_LE(s.d.dtheta, 0.3);
  }
  // The same seed draws the same steps.
  calls = 0;
  const OracleHeldOutError again = MeasureOracleHeldOutError(oracle, *source, model, held_out);
  EXPECT_EQ(again.samples.back().d.dy, error.samples.back().d.dy);

  held_out.num_samples = 0;
  CAIRN_EXPECT_THROWS_WITH(MeasureOracleHeldOutError(oracle, *source, model, held_out), std::invalid_argument,
                           "num_samples 0");
  held_out.num_samples = 5;
  const ModelTransitionSource analytic;
  CAIRN_EXPECT_THROWS_WITH(MeasureOracleHeldOutError(oracle, analytic, model, held_out), std::invalid_argument,
                           "built from source 'formula slope 1', not 'model'");
}

// The analytic table between its grid values: close to the optimiser's own answer (the thesis' fitted models had
// an SMSE of a few percent), and never feasible where the optimiser finds nothing.
TEST(OracleHeldOutErrorTest, TheAnalyticTableIsCloseToTheOptimiserBetweenItsGridValues) {
  const WalkingModel& model = *test::SharedWalkingModel();
  OracleBuildOptions options;
  options.num_threads = 1;
  OracleGrid grid = Grid();
  grid.mu = {0.2, 1.0};
  const TransitionOracle oracle = TransitionOracle::Build(model, WalkingObjective::kComWorkPlusHeat, grid, options);
  OracleHeldOutOptions held_out;
  held_out.num_samples = 12;
  const OracleHeldOutError error = MeasureOracleHeldOutError(oracle, ModelTransitionSource(), model, held_out);
  // Measured (2026-12-07): all 12 feasible for both, SMSE 0.044, correlation 0.998, mean relative error 3.3%.
  EXPECT_EQ(error.only_predicted, 0);
  EXPECT_GE(error.both_feasible, 10);
  EXPECT_LT(error.smse, 0.1);
  EXPECT_GT(error.correlation, 0.98);
  EXPECT_LT(error.mean_relative_error, 0.06);
}

}  // namespace
}  // namespace cairn::planning
