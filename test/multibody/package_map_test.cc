#include <cairn/multibody/package_map.h>

#include <filesystem>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_models.h"

namespace cairn::multibody {
namespace {

using test::ExpectThrowWithMessage;

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
  ExpectThrowWithMessage<std::invalid_argument>([&] { map.AddSpec("nopath"); }, {"'nopath'", "name=path"});
  ExpectThrowWithMessage<std::invalid_argument>([&] { map.Add("p", "/no/such/folder"); },
                                                {"package 'p'", "/no/such/folder", "does not exist"});
  map.AddSearchPath(test::DartDataDir() + "/urdf");
  ExpectThrowWithMessage<std::runtime_error>([&] { map.ResolvePackage("drchub"); },
                                             {"package 'drchub'", "--package drchub=", "'drchubo'"});
}

}  // namespace
}  // namespace cairn::multibody
