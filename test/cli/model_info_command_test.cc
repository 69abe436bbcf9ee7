// Runs `cairn model-info` as a user would and checks exit codes and key output.

#include <array>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "run_cairn.h"
#include "test_paths.h"

namespace {

using cairn::test::CairnRun;
using cairn::test::RunCairn;

using ::testing::HasSubstr;

const std::string kDart = "/usr/share/doc/dart/data";

TEST(ModelInfoCommandTest, SummarisesTheHumanoid) {
  const CairnRun run =
      RunCairn("model-info --floating-base " + std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* key : {"Model 'cairn_humanoid'", "nq = 37, nv = 36", "total mass: 64 kg", "centre of mass", "l_sole",
                          "r_knee", "floating (quaternion)"}) {
    EXPECT_THAT(run.output, HasSubstr(key));
  }
}

TEST(ModelInfoCommandTest, JsonWithPackageMapping) {
  const CairnRun run =
      RunCairn("model-info " + kDart + "/urdf/drchubo/drchubo.urdf --package drchubo=" + kDart + "/urdf/drchubo --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.front(), '{');
  for (const char* key : {"\"name\": \"drchubo\"", "\"nq\": 51", "\"nv\": 51", "\"total_mass\": 43.98",
                          "\"com_at_zero\": [", "\"frames\": ["}) {
    EXPECT_THAT(run.output, HasSubstr(key));
  }
}

TEST(ModelInfoCommandTest, BadFilePrintsTheParserMessageAndExitsOne) {
  const CairnRun broken = RunCairn("model-info " + kDart + "/sdf/atlas/atlas_v3.urdf");
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_THAT(broken.output, HasSubstr("atlas_v3.urdf"));
  EXPECT_THAT(broken.output, HasSubstr("neck_ry"));
  const CairnRun missing = RunCairn("model-info /no/such/robot.urdf");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.output, HasSubstr("the URDF '/no/such/robot.urdf' does not exist"));
  const CairnRun spec = RunCairn("model-info " + kDart + "/urdf/drchubo/drchubo.urdf --package drchubo");
  EXPECT_EQ(spec.exit_code, 1);
  EXPECT_THAT(spec.output, HasSubstr("name=path"));
  EXPECT_EQ(RunCairn("model-info").exit_code, 2);  // missing positional argument is a usage error
}

}  // namespace
