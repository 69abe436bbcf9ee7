// Runs `cairn oracle build` as a user would: on one process and under `mpirun -np 2` the file is the same, byte
// for byte; a build killed midway resumes from its checkpoints and still gives those bytes; bad input is one line.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn_streams.h"
#include "test_paths.h"

namespace {

namespace fs = std::filesystem;
using cairn::test::CairnStreams;
using cairn::test::RunCairnStreams;
using ::testing::HasSubstr;

// Two ranks on whatever cores there are, as root if need be; the sanitized build's leak check stays off for
// Open MPI's own start-up allocations.
constexpr const char* kMpirun =
    "mpirun --allow-run-as-root --oversubscribe -x ASAN_OPTIONS=detect_leaks=0 -np 2";

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class OracleCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(CAIRN_BINARY_DIR) / "test-oracle" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    grid_ = (dir_ / "grid.yaml").string();
    // 4 x 2 x 2 x 1 = 16 displacement cells x 2 mu values.
    std::ofstream(grid_) << "dx: {from: 0.10, to: 0.25, step: 0.05}\ndy: [0.18, 0.24]\ndz: [0.0, 0.05]\n"
                            "dtheta: [0.0]\nmu: [0.1, 1.0]\n";
  }
  std::string Build(const std::string& out, const std::string& extra = "") const {
    return "oracle build --grid " + grid_ + " --out " + out + " --threads 1 --json " + extra;
  }
  fs::path dir_;
  std::string grid_;
};

TEST_F(OracleCommandTest, OneRankAndTwoRanksWriteTheSameBytes) {
  const fs::path one = dir_ / "one.oracle", two = dir_ / "two.oracle";
  const CairnStreams single = RunCairnStreams(Build(one.string(), "--chunk-cells 3"));
  ASSERT_EQ(single.exit_code, 0) << single.err;
  EXPECT_THAT(single.out, HasSubstr("\"entries\": 32"));
  EXPECT_THAT(single.out, HasSubstr("\"ranks\": 1"));
  EXPECT_THAT(single.out, HasSubstr("\"chunks\": 6, \"computed_chunks\": 6"));
  const CairnStreams pair = RunCairnStreams(Build(two.string(), "--chunk-cells 3"), "", kMpirun);
  ASSERT_EQ(pair.exit_code, 0) << pair.err;
  EXPECT_THAT(pair.out, HasSubstr("\"ranks\": 2"));
  EXPECT_THAT(pair.out, HasSubstr("\"computed_chunks\": 6"));
  const std::string bytes = Slurp(one);
  EXPECT_THAT(bytes, HasSubstr("\nsource model\n"));
  EXPECT_EQ(Slurp(two), bytes);
  // The checkpoints are gone once the file is written.
  EXPECT_FALSE(fs::exists(one.string() + ".parts"));
  EXPECT_FALSE(fs::exists(two.string() + ".parts"));
}

// kill -9 once some chunks are on disk, then the same command again: it computes only what is missing and writes
// the bytes of an uninterrupted build.
TEST_F(OracleCommandTest, AKilledBuildResumesFromItsCheckpoints) {
  const fs::path clean = dir_ / "clean.oracle", resumed = dir_ / "resumed.oracle";
  ASSERT_EQ(RunCairnStreams(Build(clean.string(), "--chunk-cells 1")).exit_code, 0);
  const fs::path parts = dir_ / "parts";
  const std::string script = (dir_ / "kill.sh").string();
  // At most 60 s of polling, so a build that never writes a chunk cannot hang the test. Only finished chunks count
  // (WriteFileAtomically's temporary files carry ".tmp." and a random suffix after ".bin").
  std::ofstream(script) << CAIRN_CLI_PATH << " " << Build(resumed.string(), "--chunk-cells 1 --checkpoint " + parts.string())
                        << " >/dev/null 2>&1 &\npid=$!\nfor i in $(seq 1200); do\n"
                        << "  [ \"$(ls " << parts.string() << " 2>/dev/null | grep -c '^chunk-[0-9]*\\.bin$')\" -ge 3 ] && break\n"
                        << "  sleep 0.05\ndone\nkill -9 $pid 2>/dev/null\nwait $pid 2>/dev/null\nexit 0\n";
  ASSERT_EQ(std::system(("sh " + script).c_str()), 0);
  // 16 chunks of about 50 ms each against a 50 ms poll: the kill lands long before the last chunk.
  ASSERT_FALSE(fs::exists(resumed)) << "the build finished before it was killed";
  ASSERT_TRUE(fs::exists(parts));
  const CairnStreams again = RunCairnStreams(Build(resumed.string(), "--chunk-cells 1 --checkpoint " + parts.string()));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const auto at = again.out.find("\"resumed_chunks\": ");
  ASSERT_NE(at, std::string::npos) << again.out;
  const int count = std::stoi(again.out.substr(at + 18));
  EXPECT_GE(count, 3) << again.out;
  EXPECT_LT(count, 16) << again.out;
  EXPECT_EQ(Slurp(resumed), Slurp(clean));
  EXPECT_FALSE(fs::exists(parts));
}

// Periodic gaits walked in the plant (two cells, one timing each): one rank and two write the same bytes, and the
// header names the source with its settings.
TEST_F(OracleCommandTest, ThePlantSourceWalksEachCellAndTwoRanksWriteTheSameBytes) {
  std::ofstream(grid_) << "dx: [0.1, 0.15]\ndy: [0.2]\ndz: [0.0]\ndtheta: [0.0]\nmu: [0.01, 1.0]\n";
  const fs::path one = dir_ / "one.oracle", two = dir_ / "two.oracle";
  const std::string plant = "--source plant --t-ds 0.5 --t-sw 1.2";
  const CairnStreams single = RunCairnStreams(Build(one.string(), plant));
  ASSERT_EQ(single.exit_code, 0) << single.err;
  EXPECT_THAT(single.out, HasSubstr("\"source\": \"plant\""));
  EXPECT_THAT(single.out, HasSubstr("\"entries\": 4, \"feasible\": 2"));
  EXPECT_THAT(single.out, HasSubstr("\"chunks\": 2"));
  const CairnStreams pair = RunCairnStreams(Build(two.string(), plant), "", kMpirun);
  ASSERT_EQ(pair.exit_code, 0) << pair.err;
  const std::string bytes = Slurp(one);
  EXPECT_THAT(bytes, HasSubstr("\nsource plant t_ds 0.5 t_sw 1.2 steps 6 transient 2 friction 1 "));
  EXPECT_EQ(Slurp(two), bytes);
}

// `oracle check` asks the table's own source at held-out steps and writes the comparison; a table is only
// checked against the source (and grid) it was built from.
TEST_F(OracleCommandTest, CheckComparesATableWithItsSourceAtHeldOutSteps) {
  const fs::path table = dir_ / "table.oracle", report = dir_ / "report";
  ASSERT_EQ(RunCairnStreams(Build(table.string())).exit_code, 0);
  const std::string check = "oracle check --oracle " + table.string() + " --grid " + grid_ + " --samples 6 --seed 3";
  const CairnStreams run = RunCairnStreams(check + " --out " + report.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("held out   6 steps (seed 3)"));
  EXPECT_THAT(run.out, HasSubstr("SMSE "));
  const std::string json = Slurp(report / "heldout.json");
  for (const char* key : {"\"source\": \"model\"", "\"samples\": 6", "\"smse\": ", "\"correlation\": ",
                          "\"steps\": [{\"dx\": "}) {
    EXPECT_THAT(json, HasSubstr(key));
  }
  ASSERT_TRUE(fs::exists(report / "heldout.png"));
  EXPECT_GT(fs::file_size(report / "heldout.png"), 1000u);
  // The same seed gives the same bytes.
  const CairnStreams again = RunCairnStreams(check + " --json");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out, json);

  const CairnStreams other = RunCairnStreams(check + " --objective ecom");
  EXPECT_EQ(other.exit_code, 1);
  EXPECT_THAT(other.err, HasSubstr("objective 'ecom_heat', not 'ecom'"));
  EXPECT_EQ(other.err_lines(), 1) << other.err;
  const CairnStreams zero = RunCairnStreams("oracle check --oracle " + table.string() + " --samples 0");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_THAT(zero.err, HasSubstr("--samples '0'"));
}

TEST_F(OracleCommandTest, BadInputIsOneLine) {
  const std::string out = (dir_ / "x.oracle").string();
  CairnStreams run = RunCairnStreams("oracle");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  run = RunCairnStreams("oracle build --grid " + grid_);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("oracle build needs --out FILE (the table to write) or --cache DIR"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  run = RunCairnStreams(Build(out, "--cache " + dir_.string()));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--out excludes --cache"));
  const std::string file = (dir_ / "a_file").string();
  std::ofstream(file) << "not a folder\n";
  run = RunCairnStreams("oracle build --grid " + grid_ + " --cache " + file + "/cache");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("--cache '" + file + "/cache' cannot be created"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  run = RunCairnStreams(Build(out, "--chunk-cells 0"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--chunk-cells '0'"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  run = RunCairnStreams(Build(out, "--source plants"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--source 'plants' is not one of 'model', 'plant'"));
  run = RunCairnStreams(Build(out, "--t-ds 0.5"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--t-ds applies to --source plant or pipeline only"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  run = RunCairnStreams(Build(out, "--source plant --t-sw 1.2,abc"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.err, HasSubstr("--t-sw 'abc' is not a number"));
  run = RunCairnStreams(Build(out, "--source pipeline"));  // the default objective, ecom_heat
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("the pipeline source runs no motors, so it measures no heat"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  run = RunCairnStreams(Build(out, "--source plant --t-ds 9"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("t_ds value 9 s is outside the walking model's bounds"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  run = RunCairnStreams("oracle build --grid " + (dir_ / "missing.yaml").string() + " --out " + out);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("--grid"));
  EXPECT_THAT(run.err, HasSubstr("missing.yaml"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  std::ofstream(grid_) << "dx: [0.1, 0.9]\ndy: [0.18]\ndz: [0.0]\ndtheta: [0.0]\nmu: [1.0]\n";
  run = RunCairnStreams(Build(out));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("'dx'"));
  EXPECT_THAT(run.err, HasSubstr("0.9"));
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  // The same mistake under two ranks is still one line of Cairn's (rank 0 reports it; mpirun adds its own
  // notice that a rank exited non-zero).
  run = RunCairnStreams(Build(out), "", kMpirun);
  EXPECT_EQ(run.exit_code, 1);
  int cairn_lines = 0;
  for (std::size_t at = run.err.find("cairn oracle: "); at != std::string::npos; at = run.err.find("cairn oracle: ", at + 1)) {
    ++cairn_lines;
  }
  EXPECT_EQ(cairn_lines, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("cairn oracle: error: OracleGrid: axis 'dx' value 0.9"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
