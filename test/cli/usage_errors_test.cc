// Usage errors of every subcommand, as a user meets them: exit code 2 and one line on stderr that names the
// option, the value given and what to give instead. (Failures are exit 1; see output_files_test.cc.)

#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn_streams.h"

namespace {

using cairn::test::CairnStreams;
using cairn::test::RunCairnStreams;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

// Checks a usage error: exit 2, nothing on stdout, one line on stderr starting with "cairn <subcommand>: "
// and containing `expected`.
// `top_level`: the error is about the subcommand itself (the line starts "cairn: ").
void ExpectUsageError(const std::string& arguments, const std::string& expected, bool top_level = false) {
  const CairnStreams run = RunCairnStreams(arguments);
  EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.err;
  EXPECT_EQ(run.err_lines(), 1) << arguments << "\n" << run.err;
  EXPECT_THAT(run.err, HasSubstr(expected)) << arguments;
  EXPECT_EQ(run.out, "") << arguments;
  const std::string subcommand = arguments.substr(0, arguments.find(' '));
  EXPECT_THAT(run.err, StartsWith(top_level ? "cairn: " : "cairn " + subcommand + ": ")) << arguments;
}

struct NumericOption {
  std::string subcommand;  // with the arguments it requires
  std::string option;
  std::string range;  // as the message states it
};

// Names the case in test listings (gtest would print the bytes).
void PrintTo(const NumericOption& o, std::ostream* out) { *out << o.subcommand << " " << o.option; }

// Every numeric option of every subcommand (diagram and model-info have none).
std::vector<NumericOption> AllNumericOptions() {
  const std::string stereo = "stereo-eval --left l.png --right r.png --gt d.png";
  const std::string train = "friction-train --out model.yaml";
  const std::string dataset = "friction-dataset --out data";
  return {
      {"pendulum", "--duration", "a number greater than 0 and at most 10000"},
      {"pendulum", "--max-step", "a number from 1e-06 to 1"},
      {"pendulum", "--theta0", "a number from -1000 to 1000"},
      {"pendulum", "--target", "a number from -1000 to 1000"},
      {"pendulum", "--kp", "a number from 0 to 1e+06"},
      {"pendulum", "--kd", "a number from 0 to 1e+06"},
      {stereo, "--gt-scale", "a number greater than 0 and at most 255"},
      {stereo + " --gt-scale 8", "--dmax", "an integer from 0 to 4095"},
      {stereo + " --gt-scale 8", "--window", "an odd integer from 1 to 2051"},
      {stereo + " --gt-scale 8", "--border", "an integer from 0 to 10000"},
      {"occupancy", "--noise-var", "a number from 0 to 65025"},
      {"occupancy", "--peak-ratio", "a number from 0 to 100"},
      {"occupancy", "--frames", "an integer from 1 to 10000"},
      {"occupancy", "--window", "an odd integer from 1 to 2051"},
      {"friction --image i.png --out o", "--eta", "a number from 1e-06 to 0.999999"},
      {train, "--images", "an integer from 2 to 100000"},
      {train, "--test-images", "an integer from 1 to 100000"},
      {train, "--seed", "an integer from 0 to 4294967295"},
      {train, "--width", "an integer from 16 to 4096"},
      {train, "--height", "an integer from 16 to 4096"},
      {train, "--noise", "a number from 0 to 255"},
      {train, "--epochs", "an integer from 1 to 10000"},
      {train, "--hidden", "an integer from 1 to 4096"},
      {dataset, "--images", "an integer from 1 to 100000"},
      {dataset, "--seed", "an integer from 0 to 4294967295"},
      {dataset, "--width", "an integer from 16 to 4096"},
      {dataset, "--height", "an integer from 16 to 4096"},
      {dataset, "--noise", "a number from 0 to 255"},
      {"plan --scenario s.yaml", "--time-limit", "a number greater than 0 and at most 86400"},
  };
}

class NumericOptionTest : public ::testing::TestWithParam<NumericOption> {};

TEST_P(NumericOptionTest, RefusesTextNonFiniteAndOutOfRangeValuesTheSameWay) {
  // A negative number and a NaN for one option used to get different exit codes; text got a 309-digit range.
  const NumericOption& o = GetParam();
  const std::string call = o.subcommand + " " + o.option + " ";
  ExpectUsageError(call + "abc", o.option + " 'abc' is not a number; give " + o.range);
  ExpectUsageError(call + "nan", o.option + " 'nan' is not a finite number; give " + o.range);
  ExpectUsageError(call + "-1e300", o.option + " '-1e300' is out of range; give " + o.range);
}

INSTANTIATE_TEST_SUITE_P(EveryNumericOptionOfEverySubcommand, NumericOptionTest,
                         ::testing::ValuesIn(AllNumericOptions()),
                         [](const ::testing::TestParamInfo<NumericOption>& info) {
                           std::string name = info.param.subcommand.substr(0, info.param.subcommand.find(' ')) +
                                              info.param.option;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

TEST(UsageErrorsTest, InfinitiesAndOverflowsAreRefusedLikeNaN) {
  ExpectUsageError("pendulum --duration inf", "--duration 'inf' is not a finite number");
  ExpectUsageError("pendulum --kp -Infinity", "--kp '-Infinity' is not a finite number");
  ExpectUsageError("pendulum --duration 1e400", "--duration '1e400' is out of range");
  ExpectUsageError("occupancy --frames 1e300", "--frames '1e300' is out of range");
}

TEST(UsageErrorsTest, IntegerOptionsRefuseFractionsAndOddOptionsEvenValues) {
  ExpectUsageError("occupancy --frames 2.5", "--frames '2.5' is not an integer; give an integer from 1 to 1000");
  ExpectUsageError("occupancy --window 8", "--window '8' is even; give an odd integer from 1 to 2051");
  ExpectUsageError("friction-dataset --out d --seed 0x10", "--seed '0x10' is not a number");
  ExpectUsageError("friction-dataset --out d --images 99999999999999999999", "is out of range");
}

TEST(UsageErrorsTest, PendulumRefusesStepCountsThatWouldHangOrExhaustMemory) {
  ExpectUsageError("pendulum --max-step 1e-20", "--max-step '1e-20' is out of range; give a number from 1e-06 to 1");
  ExpectUsageError("pendulum --duration 1e300", "--duration '1e300' is out of range");
  ExpectUsageError("pendulum --duration 10000 --max-step 1e-5",
                   "needs 1e+09 integrator steps, more than the limit of 1e+07; shorten --duration or raise "
                   "--max-step");
}

TEST(UsageErrorsTest, FrictionTrainRefusesMoreTrainingPixelsThanItCanHold) {
  ExpectUsageError("friction-train --out m.yaml --images 1000 --width 4096 --height 4096",
                   "more than the limit of 268435456; use fewer or smaller images");
}

TEST(UsageErrorsTest, SeedsThatWouldWrapPastTwoToThe32AreRefused) {
  // Scene i uses seed + i: 4294967295 + 1 wrapped round to seed 0.
  ExpectUsageError("friction-dataset --out data --seed 4294967295 --images 2",
                   "--seed 4294967295 with --images 2 would use seeds up to 4294967296, past 4294967295; give "
                   "--seed at most 4294967294");
  // Test scenes start 1000000 after the seed.
  ExpectUsageError("friction-train --out model.yaml --seed 4294000000",
                   "--seed 4294000000 with --test-images 40 would use seeds up to 4295000039 (test scenes start "
                   "1000000 after the seed), past 4294967295; give --seed at most 4293967256");
  // The largest seed that fits is used.
  const std::string out = ::testing::TempDir() + "/usage_errors_last_seed";
  const CairnStreams last = RunCairnStreams("friction-dataset --out " + out +
                                            " --seed 4294967294 --images 2 --width 16 --height 16");
  EXPECT_EQ(last.exit_code, 0) << last.err;
  std::filesystem::remove_all(out);
}

TEST(UsageErrorsTest, EveryChoiceOptionListsTheChoicesAndSuggestsTheClosest) {
  ExpectUsageError("pendulum --integrator rk44",
                   "--integrator 'rk44' is not one of 'euler', 'rk4', 'rk45'; did you mean 'rk4'?");
  ExpectUsageError("stereo-eval --left l --right r --gt g --gt-scale 8 --model merel",
                   "--model 'merel' is not one of 'matthies', 'merrell', 'exp', 'hsm'; did you mean 'merrell'?");
  ExpectUsageError("stereo-eval --left l --right r --gt g --gt-scale 8 --cost sad", "--cost 'sad' is not one of");
  ExpectUsageError("stereo-eval --left l --right r --gt g --gt-scale 8 --prefilter sobol", "did you mean 'sobel'?");
  ExpectUsageError("stereo-eval --left l --right r --gt g --gt-scale 8 --params many",
                   "--params 'many' is neither 'ml', 'gt' nor a number");
  ExpectUsageError("stereo-eval --left l --right r --gt g --gt-scale 8 --params -3", "--params '-3' is out of range");
  ExpectUsageError("occupancy --model gaussian",
                   "--model 'gaussian' is not one of 'merrell', 'matthies', 'exp', 'hsm', 'wta'");
  ExpectUsageError("occupancy --cost ncc", "--cost 'ncc' is not one of 'ssd', 'btsad'");
  ExpectUsageError("friction --image i --out o --method exakt", "did you mean 'exact'?");
  ExpectUsageError("friction-train --out m --source photos", "--source 'photos' is not one of 'material', 'stereo'");
  ExpectUsageError("friction-dataset --out d --source photos", "--source 'photos' is not one of 'material', 'stereo'");
  ExpectUsageError("plan --scenario s --objective energy", "--objective 'energy' is not one of");
}

TEST(UsageErrorsTest, CliElevenMessagesAreReplacedByClearOnes) {
  // Was "A subcommand is required".
  ExpectUsageError("--bogus", "unknown option '--bogus'; cairn takes a subcommand first", true);
  ExpectUsageError("pendlum", "unknown subcommand 'pendlum'; did you mean 'pendulum'?", true);
  ExpectUsageError("xyzzy", "unknown subcommand 'xyzzy'; the subcommands are 'pendulum', 'diagram'", true);
  // Was "At Most 1 required but received 2".
  ExpectUsageError("pendulum --duration 1 --duration 2", "--duration is given 2 times; give it once");
  ExpectUsageError("friction --image a --image b --out o", "--image is given 2 times; give it once");
  // Was "The following arguments were not expected: 3 --duraton".
  ExpectUsageError("pendulum --duraton 3", "unknown option '--duraton'; did you mean '--duration'?");
  ExpectUsageError("pendulum extra", "unexpected argument 'extra'");
  ExpectUsageError("pendulum --duration", "--duration needs a value");
  ExpectUsageError("pendulum --json=maybe", "--json is a flag and takes no value; got 'maybe'");
  ExpectUsageError("model-info", "is required");
  const CairnStreams run = RunCairnStreams("pendulum --duration abc");
  EXPECT_THAT(run.err, HasSubstr("(see 'cairn pendulum --help')"));
  EXPECT_THAT(run.err, Not(HasSubstr("Usage:")));
}

TEST(UsageErrorsTest, HelpStatesTheRanges) {
  const CairnStreams run = RunCairnStreams("pendulum --help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_THAT(run.out, HasSubstr("--duration NUMBER=10"));
  EXPECT_THAT(run.out, HasSubstr("a number greater than 0 and at most 10000"));
  EXPECT_THAT(run.out, HasSubstr("one of euler, rk4, rk45"));
}

}  // namespace
