#include <cairn/multibody/package_map.h>

#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"
#include "test_models.h"

namespace cairn::multibody {
namespace {

TEST(PackageMapTest, ResolvesExplicitEntriesSearchPathsAndPlainPaths) {
  PackageMap map;
  map.AddSpec("drchubo=" + test::DrcHuboPackageDir());
  EXPECT_EQ(map.ResolveUri("package://drchubo/meshes/a.stl", "/x"),
            std::filesystem::canonical(test::DrcHuboPackageDir()).string() + "/meshes/a.stl");
  map.AddSearchPath(test::DartDataDir() + "/urdf");
  EXPECT_TRUE(map.Contains("wam"));
  EXPECT_EQ(map.ResolvePackage("wam"), test::DartDataDir() + "/urdf/wam");
  EXPECT_EQ(map.ResolveUri("meshes/b.stl", "/robots/r"), "/robots/r/meshes/b.stl");
  EXPECT_EQ(map.ResolveUri("/abs/c.stl", "/robots/r"), "/abs/c.stl");
  EXPECT_EQ(map.ResolveUri("file:///abs/d.stl", "/robots/r"), "/abs/d.stl");
}

TEST(PackageMapTest, ErrorsNameTheBadValue) {
  PackageMap map;
  CAIRN_EXPECT_THROWS_WITH(map.AddSpec("nopath"), std::invalid_argument, "'nopath'", "name=path");
  CAIRN_EXPECT_THROWS_WITH(map.Add("p", "/no/such/folder"), std::invalid_argument, "package 'p'", "/no/such/folder",
                           "does not exist");
  map.AddSearchPath(test::DartDataDir() + "/urdf");
  CAIRN_EXPECT_THROWS_WITH(map.ResolvePackage("drchub"), std::runtime_error, "package 'drchub'",
                           "--package drchub=", "'drchubo'");
}

}  // namespace
}  // namespace cairn::multibody
