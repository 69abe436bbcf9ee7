#include "cairn/planning/locomotion/transition_oracle.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

class TransitionOracleTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new WalkingModel(WalkingModel::Load(std::string(CAIRN_SOURCE_DIR) +
                                                 "/data/robots/cairn_humanoid_walking.yaml"));
    OracleBuildOptions options;
    options.num_threads = 1;
    oracle_ = new TransitionOracle(TransitionOracle::Build(*model_, WalkingObjective::kComWorkPlusHeat, Grid(), options));
  }
  static void TearDownTestSuite() {
    delete oracle_;
    delete model_;
  }
  // Coarse: 2 x 2 x 2 x 2 displacements x 3 mu = 48 entries.
  static OracleGrid Grid() {
    OracleGrid grid;
    grid.dx = {0.15, 0.25};
    grid.dy = {0.18, 0.24};
    grid.dz = {0.0, 0.05};
    grid.dtheta = {0.0, 0.5};
    grid.mu = {0.06, 0.12, 1.0};
    return grid;
  }
  static std::string TempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("cairn_oracle_test_" + name)).string();
  }
  static WalkingModel* model_;
  static TransitionOracle* oracle_;
};
WalkingModel* TransitionOracleTest::model_ = nullptr;
TransitionOracle* TransitionOracleTest::oracle_ = nullptr;

void ExpectSame(const TransitionCost& a, const TransitionCost& b) {
  EXPECT_EQ(a.feasible, b.feasible);
  if (!a.feasible) return;
  EXPECT_DOUBLE_EQ(a.cost, b.cost);
  EXPECT_DOUBLE_EQ(a.parameters.t_ds, b.parameters.t_ds);
  EXPECT_DOUBLE_EQ(a.parameters.t_sw, b.parameters.t_sw);
  EXPECT_DOUBLE_EQ(a.parameters.com_height, b.parameters.com_height);
  EXPECT_DOUBLE_EQ(a.rcof, b.rcof);
  EXPECT_DOUBLE_EQ(a.heat, b.heat);
}

TEST_F(TransitionOracleTest, EntriesAreOptimalTransitionsMonotoneInMu) {
  const OracleGrid grid = Grid();
  ASSERT_EQ(oracle_->num_entries(), 48u);
  EXPECT_GT(oracle_->num_feasible(), 12u);
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t k = 0; k < 2; ++k) {
      const StepDisplacement d{grid.dx[i], grid.dy[1], grid.dz[k], 0.0};
      double previous = INFINITY;  // cost at the next smaller mu
      bool seen_feasible = false;
      for (std::size_t m = 0; m < grid.mu.size(); ++m) {
        const TransitionCost& e = oracle_->entry(i, 1, k, 0, m);
        if (!e.feasible) {
          EXPECT_FALSE(seen_feasible) << "feasible at a smaller mu but not at " << grid.mu[m];
          continue;
        }
        seen_feasible = true;
        EXPECT_LE(e.rcof, grid.mu[m] + 1e-9);
        EXPECT_LE(e.cost, previous * (1.0 + 1e-12));
        previous = e.cost;
        // An independent solve is not better than the table by more than the solvers' tolerance.
        const TransitionCost direct = OptimizeTransition(*model_, d, grid.mu[m], WalkingObjective::kComWorkPlusHeat);
        ASSERT_TRUE(direct.feasible);
        EXPECT_GE(direct.cost, e.cost * (1.0 - 1e-3));
      }
    }
  }
  // Lookups at grid points return the entries; mu is floored.
  ExpectSame(oracle_->Evaluate({0.25, 0.18, 0.05, 0.5}, 0.12), oracle_->entry(1, 0, 1, 1, 1));
  ExpectSame(oracle_->Evaluate({0.25, 0.18, 0.0, 0.0}, 0.5), oracle_->entry(1, 0, 0, 0, 1));
  ExpectSame(oracle_->Evaluate({0.15, 0.24, 0.0, 0.0}, 7.0), oracle_->entry(0, 1, 0, 0, 2));
  EXPECT_FALSE(oracle_->Evaluate({0.15, 0.24, 0.0, 0.0}, 0.05).feasible);  // below the smallest mu
  EXPECT_FALSE(oracle_->Evaluate({0.15, 0.24, 0.0, 0.0}, 0.0).feasible);
  EXPECT_FALSE(oracle_->Evaluate({0.30, 0.24, 0.0, 0.0}, 1.0).feasible);   // outside the grid
  EXPECT_EQ(oracle_->reach().dx_max, 0.25);
  EXPECT_NE(oracle_->description().find("48 entries"), std::string::npos);
  CAIRN_EXPECT_THROWS_WITH(oracle_->Evaluate({0.2, 0.2, 0.0, 0.0}, -1.0), std::invalid_argument, "mu_allowed is -1");
  CAIRN_EXPECT_THROWS_WITH(oracle_->Evaluate({NAN, 0.2, 0.0, 0.0}, 1.0), std::invalid_argument, "not finite");
}

TEST_F(TransitionOracleTest, InterpolatesAndBoundsCostPerMetre) {
  // Midpoint of a cell: the mean of its corners.
  const TransitionCost mid = oracle_->Evaluate({0.2, 0.21, 0.0, 0.25}, 1.0);
  ASSERT_TRUE(mid.feasible);
  double mean = 0.0;
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j)
      for (std::size_t t = 0; t < 2; ++t) mean += oracle_->entry(i, j, 0, t, 2).cost / 8.0;
  EXPECT_NEAR(mid.cost, mean, 1e-12 * mean);
  // The heuristic's bound holds for interpolated costs.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int feasible = 0;
  for (int i = 0; i < 500; ++i) {
    const StepDisplacement d{0.15 + 0.1 * u(rng), 0.18 + 0.06 * u(rng), 0.05 * u(rng), 0.5 * u(rng)};
    const double mu = 0.06 + 1.5 * u(rng);
    const TransitionCost c = oracle_->Evaluate(d, mu);
    if (!c.feasible) continue;
    ++feasible;
    EXPECT_LE(oracle_->min_cost_per_metre(), c.cost / std::hypot(d.dx, d.dy) * (1.0 + 1e-12));
    // The footstep heuristic's line bounds: friction-free, and at this friction and every larger one.
    const double length = std::hypot(d.dx, d.dy);
    EXPECT_LE(oracle_->min_cost_per_step() + oracle_->min_cost_per_metre() * length, c.cost * (1.0 + 1e-12));
    for (const double m : {mu, mu + 0.1, 2.0}) {
      const StepCostLowerBound b = oracle_->cost_lower_bound(m);
      ASSERT_TRUE(b.any_feasible);
      EXPECT_LE(b.per_step + b.per_metre * length, c.cost * (1.0 + 1e-12)) << "mu " << mu << " bound at " << m;
    }
    EXPECT_LE(c.rcof, 1.0 + 1e-9);
  }
  EXPECT_GT(feasible, 100);
  EXPECT_GT(oracle_->min_cost_per_metre(), 0.0);
  // Below the grid's smallest friction nothing is feasible, and slippery ground is dearer per metre.
  EXPECT_FALSE(oracle_->cost_lower_bound(0.5 * oracle_->grid().mu.front()).any_feasible);
  const StepCostLowerBound slippery = oracle_->cost_lower_bound(oracle_->grid().mu.front());
  const StepCostLowerBound grippy = oracle_->cost_lower_bound(oracle_->grid().mu.back());
  if (slippery.any_feasible) {
    EXPECT_GE(slippery.per_step + 0.3 * slippery.per_metre, grippy.per_step + 0.3 * grippy.per_metre);
  }
}

// MinCostOverHeights is the exact minimum over the height range: the interpolation is linear in dz between grid
// values, so dense samples never go below it and its value is attained at an end or a grid value.
TEST_F(TransitionOracleTest, MinCostOverHeightsIsTheMinimumOverTheRange) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 200; ++i) {
    const StepDisplacement d{0.15 + 0.1 * u(rng), 0.18 + 0.06 * u(rng), 0.0, 0.5 * u(rng)};
    const double mu = 0.06 + 1.5 * u(rng);
    const double lo = -0.01 + 0.06 * u(rng), hi = std::min(0.05, lo + 0.04 * u(rng));
    const double bound = oracle_->MinCostOverHeights(d, lo, hi, mu);
    double sampled = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 100; ++k) {
      StepDisplacement at = d;
      at.dz = lo + (hi - lo) * k / 100.0;
      const TransitionCost c = oracle_->Evaluate(at, mu);
      if (c.feasible) sampled = std::min(sampled, c.cost);
    }
    StepDisplacement knot = d;  // the grid's dz value 0 inside the range
    knot.dz = 0.0;
    const TransitionCost at_knot = oracle_->Evaluate(knot, mu);
    if (lo < 0.0 && hi > 0.0 && at_knot.feasible) sampled = std::min(sampled, at_knot.cost);
    if (std::isinf(sampled)) {
      EXPECT_TRUE(std::isinf(bound)) << "nothing in the range is feasible";
      continue;
    }
    ++compared;
    EXPECT_LE(bound, sampled * (1.0 + 1e-12));
    EXPECT_GE(bound, sampled * (1.0 - 1e-12)) << "the bound is the minimum, not below it";
  }
  EXPECT_GT(compared, 50);
  // A single height is that step's cost.
  const StepDisplacement d{0.2, 0.21, 0.02, 0.25};
  EXPECT_EQ(oracle_->MinCostOverHeights(d, 0.02, 0.02, 1.0), oracle_->Evaluate(d, 1.0).cost);
}

TEST_F(TransitionOracleTest, SavesLoadsAndIsThreadCountIndependent) {
  const std::string path = TempPath("roundtrip.bin");
  oracle_->Save(path);
  const TransitionOracle loaded = TransitionOracle::Load(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid());
  EXPECT_EQ(loaded.Serialize(), oracle_->Serialize());
  for (const StepDisplacement& d : {StepDisplacement{0.2, 0.2, 0.01, 0.1}, StepDisplacement{0.16, 0.23, 0.04, 0.4}}) {
    for (double mu : {0.07, 0.2, 1.0}) ExpectSame(loaded.Evaluate(d, mu), oracle_->Evaluate(d, mu));
  }
  EXPECT_EQ(loaded.min_cost_per_metre(), oracle_->min_cost_per_metre());
  OracleBuildOptions options;
  options.num_threads = 2;
  std::size_t last_done = 0, calls = 0;
  options.progress = [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(total, 48u);
    EXPECT_GT(done, last_done);
    last_done = done;
    ++calls;
  };
  const TransitionOracle two = TransitionOracle::Build(*model_, WalkingObjective::kComWorkPlusHeat, Grid(), options);
  EXPECT_EQ(two.Serialize(), oracle_->Serialize());
  EXPECT_EQ(last_done, 48u);
  EXPECT_EQ(calls, 16u);
}

TEST_F(TransitionOracleTest, RebuildsStaleOrCorruptFiles) {
  const std::string path = TempPath("stale.bin");
  std::filesystem::remove(path);
  std::ostringstream log;
  OracleBuildOptions options;
  options.num_threads = 2;
  TransitionOracle::LoadOrBuild(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid(), options, &log);
  EXPECT_NE(log.str().find("Building transition oracle"), std::string::npos) << log.str();

  log.str("");
  TransitionOracle::LoadOrBuild(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid(), options, &log);
  EXPECT_NE(log.str().find("Loaded transition oracle"), std::string::npos) << log.str();

  // One flipped byte in the payload.
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  bytes[bytes.size() - 20] ^= 0x40;
  std::ofstream(path, std::ios::binary) << bytes;
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid()),
                           std::runtime_error, path, "checksum mismatch");
  log.str("");
  const TransitionOracle rebuilt =
      TransitionOracle::LoadOrBuild(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid(), options, &log);
  EXPECT_NE(log.str().find("Rebuilding transition oracle"), std::string::npos);
  EXPECT_NE(log.str().find("checksum"), std::string::npos);
  EXPECT_EQ(rebuilt.Serialize(), oracle_->Serialize());

  // Truncated file.
  std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid()),
                           std::runtime_error, "corrupt");

  // Header mismatches: objective and grid.
  oracle_->Save(path);
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, *model_, WalkingObjective::kComWork, Grid()),
                           std::runtime_error, "objective 'ecom_heat', not 'ecom'");
  OracleGrid other = Grid();
  other.mu = {0.06, 1.0};
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, *model_, WalkingObjective::kComWorkPlusHeat, other),
                           std::runtime_error, "different grid");
  log.str("");
  TransitionOracle::LoadOrBuild(path, *model_, WalkingObjective::kComWorkPlusHeat, other, options, &log);
  EXPECT_NE(log.str().find("Rebuilding transition oracle"), std::string::npos);
  EXPECT_NE(log.str().find("different grid"), std::string::npos);
  std::filesystem::remove(path);
}

// The fingerprint names a grid's values: the same values give the same digits (on every machine: a known answer,
// FNV-1a 64 of the header's axis lines computed independently), and changing any value changes it.
TEST_F(TransitionOracleTest, GridFingerprintNamesTheGridsValues) {
  EXPECT_EQ(Grid().Fingerprint(), "55ac21ae5066908c");
  EXPECT_EQ(Grid().Fingerprint(), Grid().Fingerprint());
  OracleGrid other = Grid();
  other.mu.back() = std::nextafter(1.0, 2.0);
  EXPECT_NE(other.Fingerprint(), Grid().Fingerprint());
  other = Grid();
  std::swap(other.dx, other.dz);  // the axes' names count, not only the values
  EXPECT_NE(other.Fingerprint(), Grid().Fingerprint());
}

// A cache folder that cannot be created (its parent is a file: even root cannot) or a cache path that cannot be
// written (it is a folder) costs a warning, not the table.
TEST_F(TransitionOracleTest, AnUnusableCacheWarnsOnceAndKeepsTheTableInMemory) {
  const std::filesystem::path root = TempPath("unusable");
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root);
  std::ofstream(root / "blocker") << "a file where the cache folder should be\n";
  OracleBuildOptions options;
  options.num_threads = 2;
  for (const std::filesystem::path& path : {root / "blocker" / "cache" / "oracle.bin", root / "folder.bin"}) {
    std::filesystem::create_directories(root / "folder.bin");
    std::ostringstream log;
    const TransitionOracle oracle =
        TransitionOracle::LoadOrBuild(path.string(), *model_, WalkingObjective::kComWorkPlusHeat, Grid(), options, &log);
    EXPECT_EQ(oracle.Serialize(), oracle_->Serialize()) << path;
    const std::string text = log.str();
    const auto warning = text.find("Warning: the transition oracle is not cached");
    EXPECT_NE(warning, std::string::npos) << text;
    EXPECT_EQ(text.find("Warning", warning + 1), std::string::npos) << "warned more than once: " << text;
    EXPECT_NE(text.find("continuing with the table in memory"), std::string::npos) << text;
  }
  // A missing folder is created.
  const std::filesystem::path nested = root / "a" / "b" / "oracle.bin";
  std::ostringstream log;
  TransitionOracle::LoadOrBuild(nested.string(), *model_, WalkingObjective::kComWorkPlusHeat, Grid(), options, &log);
  EXPECT_TRUE(std::filesystem::exists(nested)) << log.str();
  EXPECT_EQ(log.str().find("Warning"), std::string::npos) << log.str();
  std::filesystem::remove_all(root);
}

TEST_F(TransitionOracleTest, FilesRecordTheSourceAndOlderFormatsAreStale) {
  const std::string bytes = oracle_->Serialize();
  EXPECT_NE(bytes.find("\nsource model\n"), std::string::npos);
  const std::string path = TempPath("source.bin");
  std::string other = bytes;
  other.replace(other.find("source model"), 12, "source plant");
  std::ofstream(path, std::ios::binary) << other;
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid()),
                           std::runtime_error, "built from source 'plant', not 'model'");
  std::string old = bytes;
  old.replace(0, old.find('\n'), "cairn-transition-oracle 1");
  std::ofstream(path, std::ios::binary) << old;
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Load(path, *model_, WalkingObjective::kComWorkPlusHeat, Grid()),
                           std::runtime_error, "format 1", "build it again");
  std::filesystem::remove(path);
}

// Cells built in pieces and assembled are the table Build makes.
TEST_F(TransitionOracleTest, CellsBuiltInPiecesAssembleToTheSameTable) {
  const OracleGrid grid = Grid();
  OracleBuildOptions options;
  options.num_threads = 1;
  std::vector<TransitionOracle::Entry> entries;
  for (std::size_t first = 0; first < grid.num_displacements(); first += 5) {
    const std::size_t count = std::min<std::size_t>(5, grid.num_displacements() - first);
    const auto piece = TransitionOracle::BuildCells(*model_, WalkingObjective::kComWorkPlusHeat, grid, first, count, options);
    ASSERT_EQ(piece.size(), count * grid.mu.size());
    entries.insert(entries.end(), piece.begin(), piece.end());
  }
  const std::string encoded = TransitionOracle::EncodeEntries(entries);
  EXPECT_EQ(encoded.size(), entries.size() * TransitionOracle::kBytesPerEntry);
  const TransitionOracle assembled = TransitionOracle::FromEntries(
      *model_, WalkingObjective::kComWorkPlusHeat, grid, TransitionOracle::DecodeEntries(encoded, entries.size()));
  EXPECT_EQ(assembled.Serialize(), oracle_->Serialize());
  CAIRN_EXPECT_THROWS_WITH(
      TransitionOracle::BuildCells(*model_, WalkingObjective::kComWorkPlusHeat, grid, 15, 2, options),
      std::invalid_argument, "cells [15, 17) lie outside the grid's 16 displacement cells");
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::FromEntries(*model_, WalkingObjective::kComWorkPlusHeat, grid, {}),
                           std::invalid_argument, "0 entries for a grid of 48");
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::DecodeEntries(encoded.substr(1), entries.size()), std::invalid_argument,
                           "do not hold 48 entries");
}

TEST_F(TransitionOracleTest, LoadsGridsFromYaml) {
  const std::string path = TempPath("grid.yaml");
  std::ofstream(path) << "dx: {from: 0.15, to: 0.26, step: 0.05}\ndy: [0.18, 0.24]\ndz: [0.0]\n"
                         "dtheta: [0.0]\nmu: [0.1, 1.0]\n";
  const OracleGrid grid = OracleGrid::Load(path);
  ASSERT_EQ(grid.dx.size(), 3u);
  EXPECT_DOUBLE_EQ(grid.dx[2], 0.25);
  EXPECT_EQ(grid.dy, (std::vector<double>{0.18, 0.24}));
  EXPECT_NO_THROW(grid.Validate(model_->reach()));
  std::ofstream(path) << "dx: {from: 0.15, to: 0.25, step: 0}\ndy: [0.18]\ndz: [0.0]\ndtheta: [0.0]\nmu: [1.0]\n";
  CAIRN_EXPECT_THROWS_WITH(OracleGrid::Load(path), std::invalid_argument, path, "line 1", "dx.step is 0");
  std::ofstream(path) << "dx: {from: 0, to: 1000, step: 0.001}\ndy: [0.18]\ndz: [0.0]\ndtheta: [0.0]\nmu: [1.0]\n";
  CAIRN_EXPECT_THROWS_WITH(OracleGrid::Load(path), std::invalid_argument, "1e+06 values, more than the limit of 10000");
  std::ofstream(path) << "dx: [0.2]\ndy: [0.18]\ndz: [0.0]\ndtheta: [0.0]\nmus: [1.0]\n";
  CAIRN_EXPECT_THROWS_WITH(OracleGrid::Load(path), std::invalid_argument, "mus");
  std::filesystem::remove(path);
}

TEST_F(TransitionOracleTest, ValidatesGrids) {
  OracleGrid grid = Grid();
  grid.dx = {0.25, 0.15};
  CAIRN_EXPECT_THROWS_WITH(grid.Validate(model_->reach()), std::invalid_argument, "'dx'", "strictly increasing");
  grid = Grid();
  grid.dy = {0.18, 0.5};
  CAIRN_EXPECT_THROWS_WITH(grid.Validate(model_->reach()), std::invalid_argument, "'dy'", "0.5", "reach");
  grid = Grid();
  grid.mu = {0.0, 1.0};
  CAIRN_EXPECT_THROWS_WITH(grid.Validate(model_->reach()), std::invalid_argument, "'mu'", "positive");
  grid = Grid();
  grid.dz.clear();
  CAIRN_EXPECT_THROWS_WITH(TransitionOracle::Build(*model_, WalkingObjective::kComWork, grid), std::invalid_argument,
                           "'dz' is empty");
  // 10,000 dx x 2 x 2 x 2 x 1,000 mu = 8e7 entries: refused before anything is allocated.
  grid = Grid();
  grid.dx.clear();
  for (int i = 0; i < 10000; ++i) grid.dx.push_back(0.1 + 0.2 * i / 10000.0);
  grid.mu.clear();
  for (int i = 1; i <= 1000; ++i) grid.mu.push_back(0.001 * i);
  CAIRN_EXPECT_THROWS_WITH(grid.Validate(model_->reach()), std::invalid_argument, "8e+07 entries",
                           "more than the limit of 6.71089e+07");
  const OracleGrid standard = OracleGrid::Default(*model_);
  EXPECT_NO_THROW(standard.Validate(model_->reach()));
  EXPECT_EQ(standard.dx.size(), 8u);
  EXPECT_EQ(standard.dy, (std::vector<double>{0.17, 0.20, 0.25, 0.30}));
  EXPECT_EQ(standard.dtheta.size(), 3u);
  EXPECT_EQ(standard.mu.front(), 0.04);
}

}  // namespace
}  // namespace cairn::planning
