// Runs `cairn simulate` as a user would: the humanoid stands, its files are written, two runs give the same bytes,
// and bad input is one line (usage errors exit 2, failures exit 1).

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
using ::testing::Not;
using ::testing::StartsWith;

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The "com_energy_J" number of a summary.
double ComEnergy(const std::string& json) {
  const std::string key = "\"com_energy_J\": ";
  const auto at = json.find(key);
  return at == std::string::npos ? -1.0 : std::stod(json.substr(at + key.size()));
}

class SimulateCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(CAIRN_BINARY_DIR) / "test-simulate" / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  fs::path dir_;
};

TEST_F(SimulateCommandTest, StandsAndWritesLogSummaryAndPlot) {
  const std::string out = (dir_ / "run").string();
  const CairnStreams run = RunCairnStreams("simulate --duration 0.5 --out " + out);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("fall       none"));
  EXPECT_THAT(run.out, HasSubstr("slips      0"));
  const std::string csv = Slurp(fs::path(out) / "log.csv");
  EXPECT_THAT(csv, StartsWith("time,base_x,base_y,base_z"));
  // One row at t = 0 and one every 10 ms.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 51);
  EXPECT_THAT(Slurp(fs::path(out) / "summary.json"), HasSubstr("\"fell\": false"));
  EXPECT_THAT(Slurp(fs::path(out) / "plot.png"), StartsWith("\x89PNG"));
}

TEST_F(SimulateCommandTest, TwoRunsWriteIdenticalLogs) {
  const std::string a = (dir_ / "a").string(), b = (dir_ / "b").string();
  const std::string args = "simulate --duration 0.3 --drop 0.05 --scenario " + std::string(CAIRN_SOURCE_DIR) +
                           "/examples/scenarios/plant/ice_and_carpet.yaml --out ";
  ASSERT_EQ(RunCairnStreams(args + a).exit_code, 0);
  ASSERT_EQ(RunCairnStreams(args + b).exit_code, 0);
  EXPECT_EQ(Slurp(fs::path(a) / "log.csv"), Slurp(fs::path(b) / "log.csv"));
  EXPECT_EQ(Slurp(fs::path(a) / "summary.json"), Slurp(fs::path(b) / "summary.json"));
}

TEST_F(SimulateCommandTest, AFallIsReportedNotAnError) {
  // Ground under the left foot only: the robot tips over to its right, and the fall ends the run early.
  const fs::path scenario = dir_ / "half_floor.yaml";
  std::ofstream(scenario) << "terrain:\n  - {name: left_half, center: [0, 1.0, -0.5], size: [4, 2, 1], friction: 0.8}\n";
  const CairnStreams run = RunCairnStreams("simulate --duration 5 --json --scenario " + scenario.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("\"fell\": true"));
  EXPECT_THAT(run.out, HasSubstr("the robot fell at t = "));
  EXPECT_THAT(run.out, Not(HasSubstr("\"duration\": 5.000000")));
}

TEST_F(SimulateCommandTest, FollowsAJointTrajectory) {
  // The right elbow bends to -1 rad in 0.5 s and back; the robot keeps standing.
  const fs::path trajectory = dir_ / "wave.csv";
  std::ofstream(trajectory) << "time,r_elbow\n0,0\n0.5,-1.0\n1.0,0\n";
  const std::string out = (dir_ / "run").string();
  const CairnStreams run =
      RunCairnStreams("simulate --duration 1 --json --trajectory " + trajectory.string() + " --out " + out);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_THAT(run.out, HasSubstr("\"fell\": false"));
  // The swinging forearm moves the centre of mass: E_COM (eq. 2.1) exceeds that of standing still (measured
  // 0.126 J against 0.075 J, the latter from settling into the PD offsets).
  const CairnStreams still = RunCairnStreams("simulate --duration 1 --json");
  ASSERT_EQ(still.exit_code, 0) << still.err;
  EXPECT_GT(ComEnergy(run.out), 1.3 * ComEnergy(still.out)) << run.out << "\n" << still.out;
  const CairnStreams bad = RunCairnStreams("simulate --trajectory " + (dir_ / "missing.csv").string());
  EXPECT_EQ(bad.exit_code, 1);
  std::ofstream(dir_ / "limit.csv") << "time,r_elbow\n0,3\n";
  const CairnStreams limit = RunCairnStreams("simulate --trajectory " + (dir_ / "limit.csv").string());
  EXPECT_EQ(limit.exit_code, 1);
  EXPECT_THAT(limit.err, HasSubstr("outside its limits"));
  EXPECT_EQ(limit.err_lines(), 1);
}

void ExpectOneLine(const CairnStreams& run, int code, const std::string& expected) {
  EXPECT_EQ(run.exit_code, code) << run.err;
  EXPECT_EQ(run.err_lines(), 1) << run.err;
  EXPECT_THAT(run.err, StartsWith("cairn simulate: "));
  EXPECT_THAT(run.err, HasSubstr(expected));
  EXPECT_EQ(run.out, "");
}

TEST_F(SimulateCommandTest, RefusesBadInputWithOneLine) {
  ExpectOneLine(RunCairnStreams("simulate --duration -1"), 2, "--duration");
  ExpectOneLine(RunCairnStreams("simulate --step 0.02"), 2, "--step");
  ExpectOneLine(RunCairnStreams("simulate --friction nan"), 2, "--friction");
  ExpectOneLine(RunCairnStreams("simulate --robot " + (dir_ / "missing.urdf").string()), 1, "missing.urdf");
  const fs::path gains = dir_ / "nan_gains.yaml";
  std::ofstream(gains) << "gains:\n  all: {joints: [l_knee], kp: .nan, kd: 1}\n";
  ExpectOneLine(RunCairnStreams("simulate --control " + gains.string()), 1, "kp");
  ExpectOneLine(RunCairnStreams("simulate --duration 60 --step 1e-5"), 2, "plant steps, more than the limit");
}

}  // namespace
