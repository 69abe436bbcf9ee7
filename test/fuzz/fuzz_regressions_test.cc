// Replays the fuzzers' inputs through the same harnesses (fuzz/fuzz_harnesses.h): every crashing input kept in
// fuzz/regressions/<target>/ must now be refused with a std::invalid_argument or std::runtime_error (the project's
// two error types: a std::bad_alloc or an OpenCV exception escaping is the bug itself), and every seed (the
// repository's files and the hand-written ones in fuzz/corpus/<target>/) must be accepted, else the fuzzer would
// start from inputs that its parser rejects at the first line.
//
// Some inputs make a parser allocate without bound (that is what they are kept for). So that such a regression
// fails instead of exhausting the machine's memory, allocations are capped. In a sanitized build (the sanitized
// suite that CI runs) any single allocation over 1 GiB aborts the test with AddressSanitizer's report, so an
// input that merely tries a huge allocation fails even where the parser would turn the failure into an error
// message. In a plain build the process's address space is limited, so such an allocation fails with
// std::bad_alloc (which fails the test), or with an error the parser reports (which passes it there).

#if defined(__SANITIZE_ADDRESS__)
#define CAIRN_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CAIRN_TEST_ASAN 1
#endif
#endif

#if defined(CAIRN_TEST_ASAN)
// Read by AddressSanitizer at start-up (ASAN_OPTIONS still override it): an allocation over 1 GiB is reported
// and aborts.
extern "C" const char* __asan_default_options() { return "max_allocation_size_mb=1024"; }
#endif

#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fuzz_harnesses.h"
#include "test_paths.h"

namespace cairn::fuzz {
namespace {

namespace fs = std::filesystem;

#if !defined(CAIRN_TEST_ASAN)
// 2 GiB of address space: far more than any harness needs for a valid input, and an unbounded allocation fails
// with std::bad_alloc long before the machine runs short. (AddressSanitizer reserves terabytes of address space,
// hence its own limit above.)
const bool kAddressSpaceLimited = [] {
  rlimit limit{};
  limit.rlim_cur = limit.rlim_max = rlim_t{2} << 30;
  return ::setrlimit(RLIMIT_AS, &limit) == 0;
}();
#endif

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

// gtest prints a failing case's parameter: its path, not its bytes.
void PrintTo(const FuzzCase& c, std::ostream* out) { *out << c.path; }

std::string CaseName(const ::testing::TestParamInfo<FuzzCase>& info) {
  std::string name = info.param.target + "_" + fs::path(info.param.path).filename().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// What running `input` through `target` did: "" when it returned or threw a std::invalid_argument or
// std::runtime_error (then `error` holds its message), else a description of what it threw.
std::string Outcome(const FuzzTarget& target, const std::string& input, std::string* error) {
  try {
    target.run(input);
    return "";
  } catch (const std::invalid_argument& e) {
    *error = e.what();
    return "";
  } catch (const std::runtime_error& e) {
    *error = e.what();
    return "";
  } catch (const std::bad_alloc& e) {
    return std::string("ran out of memory (std::bad_alloc: ") + e.what() + ")";
  } catch (const std::exception& e) {
    return std::string("threw a std::exception that is neither std::invalid_argument nor std::runtime_error: ") +
           e.what();
  } catch (...) {
    return "threw an exception that is not a std::exception";
  }
}

class FuzzRegressionTest : public ::testing::TestWithParam<FuzzCase> {};

TEST_P(FuzzRegressionTest, IsRefusedWithAClearError) {
  const FuzzTarget& target = TargetNamed(GetParam().target);
  std::string error;
  const std::string outcome = Outcome(target, ReadBytes(GetParam().path), &error);
  EXPECT_EQ(outcome, "") << GetParam().path;
  if (outcome.empty()) {
    EXPECT_NE(error, "") << GetParam().path << " was accepted; a crashing input should be refused.";
  }
  if (!error.empty()) std::cout << "refused: " << error << "\n";
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
