#include "cairn/planning/locomotion/oracle_shard_builder.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_paths.h"

namespace cairn::planning {
namespace {

class OracleShardBuilderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new WalkingModel(WalkingModel::Load(std::string(CAIRN_SOURCE_DIR) +
                                                 "/data/robots/cairn_humanoid_walking.yaml"));
    reference_ = new std::string(
        TransitionOracle::Build(*model_, WalkingObjective::kComWorkPlusHeat, Grid(), Options()).Serialize());
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete model_;
  }
  // 2 x 2 x 2 x 1 displacements x 2 mu = 16 entries; in chunks of 3 cells: 3 chunks (3, 3, 2 cells).
  static OracleGrid Grid() {
    OracleGrid grid;
    grid.dx = {0.15, 0.25};
    grid.dy = {0.18, 0.24};
    grid.dz = {0.0, 0.05};
    grid.dtheta = {0.0};
    grid.mu = {0.1, 1.0};
    return grid;
  }
  static OracleBuildOptions Options() {
    OracleBuildOptions options;
    options.num_threads = 1;
    return options;
  }
  std::string Folder(const std::string& name) const {
    const auto folder = std::filesystem::temp_directory_path() / ("cairn_shard_test_" + name);
    std::filesystem::remove_all(folder);
    return folder.string();
  }
  OracleShardBuilder Builder(const std::string& folder) const {
    return OracleShardBuilder(*model_, WalkingObjective::kComWorkPlusHeat, Grid(), folder, 3);
  }
  static WalkingModel* model_;
  static std::string* reference_;
};
WalkingModel* OracleShardBuilderTest::model_ = nullptr;
std::string* OracleShardBuilderTest::reference_ = nullptr;

TEST_F(OracleShardBuilderTest, AnyNumberOfRanksMergesToTheBytesOfOneBuild) {
  for (int ranks : {1, 2, 3, 5}) {
    const std::string folder = Folder("ranks" + std::to_string(ranks));
    const OracleShardBuilder builder = Builder(folder);
    ASSERT_EQ(builder.num_chunks(), 3);
    int computed = 0;
    // Ranks in reverse order: the result must not depend on which finishes first.
    for (int rank = ranks - 1; rank >= 0; --rank) computed += builder.BuildShard(rank, ranks, Options()).computed;
    EXPECT_EQ(computed, 3) << ranks;
    EXPECT_TRUE(builder.MissingChunks().empty());
    EXPECT_EQ(builder.Merge().Serialize(), *reference_) << ranks << " ranks";
    builder.RemoveCheckpoints();
    EXPECT_FALSE(std::filesystem::exists(folder));
  }
  EXPECT_EQ(Builder(Folder("split")).ChunksOfRank(1, 2), (std::vector<int>{1}));
  EXPECT_EQ(Builder(Folder("split")).ChunksOfRank(0, 2), (std::vector<int>{0, 2}));
}

TEST_F(OracleShardBuilderTest, AnInterruptedBuildResumesAndReplacesBadChunks) {
  const std::string folder = Folder("resume");
  const OracleShardBuilder builder = Builder(folder);
  // Rank 0 of 2 finished (chunks 0 and 2), rank 1 was killed: chunk 1 is missing.
  EXPECT_EQ(builder.BuildShard(0, 2, Options()).computed, 2);
  EXPECT_EQ(builder.MissingChunks(), (std::vector<int>{1}));
  CAIRN_EXPECT_THROWS_WITH(builder.Merge(), std::runtime_error, "1 of 3 chunks are not ready", "chunk-000001.bin is missing",
                           "run the build again");
  // A later run on one process computes only what is missing.
  std::ostringstream log;
  OracleBuildOptions counted = Options();
  std::size_t last_done = 0, last_total = 0;
  counted.progress = [&](std::size_t done, std::size_t total) {
    EXPECT_GE(done, last_done);
    last_done = done;
    last_total = total;
  };
  const OracleShardBuilder::ShardReport report = builder.BuildShard(0, 1, counted, &log);
  EXPECT_EQ(last_total, 16u);  // every entry of the rank's chunks, the resumed ones included
  EXPECT_EQ(last_done, 16u);
  EXPECT_EQ(report.computed, 1);
  EXPECT_EQ(report.resumed, 2);
  EXPECT_EQ(report.replaced, 0);
  EXPECT_NE(log.str().find("chunk 2 of 3"), std::string::npos) << log.str();
  EXPECT_EQ(builder.Merge().Serialize(), *reference_);

  // A flipped payload byte and a truncated file are recomputed, not merged.
  const std::string path = builder.ChunkPath(2);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::string flipped = bytes;
  flipped[flipped.size() - 5] ^= 0x10;
  std::ofstream(path, std::ios::binary) << flipped;
  std::ofstream(builder.ChunkPath(0), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_EQ(builder.MissingChunks(), (std::vector<int>{0, 2}));
  CAIRN_EXPECT_THROWS_WITH(builder.Merge(), std::runtime_error, "2 of 3 chunks", "fails its checksum");
  log.str("");
  const OracleShardBuilder::ShardReport repaired = builder.BuildShard(0, 1, Options(), &log);
  EXPECT_EQ(repaired.computed, 2);
  EXPECT_EQ(repaired.replaced, 2);
  EXPECT_NE(log.str().find("replaced: the old file fails its checksum"), std::string::npos) << log.str();
  EXPECT_EQ(builder.Merge().Serialize(), *reference_);
  builder.RemoveCheckpoints();
}

TEST_F(OracleShardBuilderTest, ChunksOfAnotherBuildAreNeverUsed) {
  const std::string folder = Folder("other");
  const OracleShardBuilder builder = Builder(folder);
  builder.BuildShard(0, 1, Options());
  // Another objective over the same folder: every chunk belongs to the first build.
  const OracleShardBuilder other(*model_, WalkingObjective::kComWork, Grid(), folder, 3);
  EXPECT_EQ(other.MissingChunks(), (std::vector<int>{0, 1, 2}));
  CAIRN_EXPECT_THROWS_WITH(other.Merge(), std::runtime_error, "belongs to another build");
  // Another chunk size: the cells differ.
  const OracleShardBuilder resized(*model_, WalkingObjective::kComWorkPlusHeat, Grid(), folder, 4);
  CAIRN_EXPECT_THROWS_WITH(resized.Merge(), std::runtime_error, "covers other cells");
  builder.RemoveCheckpoints();
}

TEST_F(OracleShardBuilderTest, RejectsBadArguments) {
  CAIRN_EXPECT_THROWS_WITH(OracleShardBuilder(*model_, WalkingObjective::kComWork, Grid(), "x", 0),
                           std::invalid_argument, "cells_per_chunk is 0; give a count in [1, 100000]");
  CAIRN_EXPECT_THROWS_WITH(OracleShardBuilder(*model_, WalkingObjective::kComWork, Grid(), "", 3),
                           std::invalid_argument, "checkpoint folder name is empty");
  const OracleShardBuilder builder = Builder(Folder("bad"));
  CAIRN_EXPECT_THROWS_WITH(builder.BuildShard(2, 2), std::invalid_argument, "rank 2 is outside [0, 2)");
  CAIRN_EXPECT_THROWS_WITH(builder.BuildShard(0, 0), std::invalid_argument, "num_ranks is 0; give at least 1");
  // A folder that cannot be created: its parent is a file.
  const auto blocker = std::filesystem::temp_directory_path() / "cairn_shard_test_blocker";
  std::ofstream(blocker) << "a file\n";
  const OracleShardBuilder blocked(*model_, WalkingObjective::kComWork, Grid(), (blocker / "parts").string(), 3);
  CAIRN_EXPECT_THROWS_WITH(blocked.BuildShard(0, 1, Options()), std::runtime_error,
                           "cannot create the checkpoint folder", "choose a writable folder");
  std::filesystem::remove(blocker);
}

}  // namespace
}  // namespace cairn::planning
