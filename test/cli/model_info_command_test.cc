// Runs `cairn model-info` as a user would and checks exit codes and key output.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace {

using ::testing::HasSubstr;

struct CliRun {
  int exit_code;
  std::string output;  // stdout and stderr together
};

CliRun Cairn(const std::string& arguments) {
  const std::string command = std::string(CAIRN_CLI_PATH) + " " + arguments + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  CliRun run{-1, ""};
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) run.output += buffer.data();
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

const std::string kDart = "/usr/share/doc/dart/data";

TEST(ModelInfoCommandTest, SummarisesTheHumanoid) {
  const CliRun run =
      Cairn("model-info --floating-base " + std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* key : {"Model 'cairn_humanoid'", "nq = 37, nv = 36", "total mass: 64 kg", "centre of mass", "l_sole",
                          "r_knee", "floating (quaternion)"}) {
    EXPECT_THAT(run.output, HasSubstr(key));
  }
}

TEST(ModelInfoCommandTest, JsonWithPackageMapping) {
  const CliRun run =
      Cairn("model-info " + kDart + "/urdf/drchubo/drchubo.urdf --package drchubo=" + kDart + "/urdf/drchubo --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.front(), '{');
  for (const char* key : {"\"name\": \"drchubo\"", "\"nq\": 51", "\"nv\": 51", "\"total_mass\": 43.98",
                          "\"com_at_zero\": [", "\"frames\": ["}) {
    EXPECT_THAT(run.output, HasSubstr(key));
  }
}

TEST(ModelInfoCommandTest, BadFilePrintsTheParserMessageAndExitsOne) {
  const CliRun broken = Cairn("model-info " + kDart + "/sdf/atlas/atlas_v3.urdf");
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_THAT(broken.output, HasSubstr("atlas_v3.urdf"));
  EXPECT_THAT(broken.output, HasSubstr("neck_ry"));
  const CliRun missing = Cairn("model-info /no/such/robot.urdf");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.output, HasSubstr("cannot open"));
  const CliRun spec = Cairn("model-info " + kDart + "/urdf/drchubo/drchubo.urdf --package drchubo");
  EXPECT_EQ(spec.exit_code, 1);
  EXPECT_THAT(spec.output, HasSubstr("name=path"));
  EXPECT_EQ(Cairn("model-info").exit_code, 2);  // missing positional argument is a usage error
}

}  // namespace
