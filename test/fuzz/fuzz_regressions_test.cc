// Replays the fuzzers' inputs through the same harnesses (fuzz/fuzz_harnesses.h): every crashing input kept in
// fuzz/regressions/<target>/ must now be refused with a std::exception, and every seed (the repository's files
// and the hand-written ones in fuzz/corpus/<target>/) must be accepted, else the fuzzer would start from inputs
// that its parser rejects at the first line.

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz_harnesses.h"

namespace cairn::fuzz {
namespace {

namespace fs = std::filesystem;

/// One input file for one target.
struct FuzzCase {
  std::string target;
  std::string path;
};

const FuzzTarget& TargetNamed(const std::string& name) {
  for (const FuzzTarget& target : FuzzTargets()) {
    if (target.name == name) return target;
  }
  throw std::invalid_argument("no fuzz target '" + name + "'");
}

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// The files in fuzz/<kind>/<target>/ for every target, sorted. A folder named after no target is kept (its cases
// fail, naming it).
std::vector<FuzzCase> CasesIn(const std::string& kind) {
  std::vector<FuzzCase> cases;
  const fs::path root = fs::path(CAIRN_SOURCE_DIR) / "fuzz" / kind;
  if (!fs::is_directory(root)) return cases;
  for (const auto& folder : fs::directory_iterator(root)) {
    if (!folder.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(folder.path())) {
      if (file.is_regular_file()) cases.push_back({folder.path().filename().string(), file.path().string()});
    }
  }
  std::sort(cases.begin(), cases.end(), [](const FuzzCase& a, const FuzzCase& b) { return a.path < b.path; });
  return cases;
}

std::string CaseName(const ::testing::TestParamInfo<FuzzCase>& info) {
  std::string name = info.param.target + "_" + fs::path(info.param.path).filename().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// What running `input` through `target` did: "" when it returned or threw a std::exception (then `error` holds
// its message), else a description.
std::string Outcome(const FuzzTarget& target, const std::string& input, std::string* error) {
  try {
    target.run(input);
    return "";
  } catch (const std::exception& e) {
    *error = e.what();
    return "";
  } catch (...) {
    return "threw an exception that is not a std::exception";
  }
}

class FuzzRegressionTest : public ::testing::TestWithParam<FuzzCase> {};

TEST_P(FuzzRegressionTest, IsRefusedWithAStdException) {
  const FuzzTarget& target = TargetNamed(GetParam().target);
  std::string error;
  const std::string outcome = Outcome(target, ReadBytes(GetParam().path), &error);
  EXPECT_EQ(outcome, "") << GetParam().path;
  EXPECT_NE(error, "") << GetParam().path << " was accepted; a crashing input should be refused.";
}

INSTANTIATE_TEST_SUITE_P(Regressions, FuzzRegressionTest, ::testing::ValuesIn(CasesIn("regressions")), CaseName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(FuzzRegressionTest);

class FuzzSeedTest : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzSeedTest, EverySeedIsAccepted) {
  const FuzzTarget& target = TargetNamed(GetParam());
  std::vector<FuzzSeed> seeds = target.seeds();
  ASSERT_FALSE(seeds.empty());
  for (const FuzzCase& extra : CasesIn("corpus")) {
    if (extra.target == target.name) seeds.push_back({extra.path, ReadBytes(extra.path)});
  }
  for (const FuzzSeed& seed : seeds) {
    std::string error;
    EXPECT_EQ(Outcome(target, seed.contents, &error), "") << seed.name;
    EXPECT_EQ(error, "") << seed.name;
  }
}

std::vector<std::string> TargetNames() {
  std::vector<std::string> names;
  for (const FuzzTarget& target : FuzzTargets()) names.push_back(target.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Seeds, FuzzSeedTest, ::testing::ValuesIn(TargetNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace cairn::fuzz
