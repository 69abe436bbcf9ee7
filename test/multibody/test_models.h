#pragma once

// Shared helpers for the multibody tests: the robot files. (Error-message tests use CAIRN_EXPECT_THROWS_WITH from
// test/support/expect_throws.h.)

#include <string>

#include <cairn/multibody/model.h>
#include <cairn/multibody/urdf_parser.h>
#include "test_paths.h"

namespace cairn::multibody::test {

/// DART's documentation data folder (Debian package dart-doc).
inline std::string DartDataDir() { return "/usr/share/doc/dart/data"; }
inline std::string AtlasUrdf() { return DartDataDir() + "/sdf/atlas/atlas_v3_no_head.urdf"; }
inline std::string AtlasBrokenUrdf() { return DartDataDir() + "/sdf/atlas/atlas_v3.urdf"; }
inline std::string DrcHuboUrdf() { return DartDataDir() + "/urdf/drchubo/drchubo.urdf"; }
inline std::string DrcHuboPackageDir() { return DartDataDir() + "/urdf/drchubo"; }
/// The project's humanoid.
inline std::string HumanoidUrdf() { return std::string(CAIRN_SOURCE_DIR) + "/data/robots/cairn_humanoid.urdf"; }

/// A test-name-friendly robot name for a URDF path.
inline std::string RobotName(const std::string& path) {
  if (path.find("atlas") != std::string::npos) return "Atlas";
  if (path.find("drchubo") != std::string::npos) return "DrcHubo";
  return "Humanoid";
}

/// Loads one of the robots above with or without a floating base.
inline Model LoadRobot(const std::string& path, bool floating_base) {
  UrdfOptions options;
  options.floating_base = floating_base;
  if (path == DrcHuboUrdf()) options.packages.Add("drchubo", DrcHuboPackageDir());
  return ParseUrdfFile(path, options);
}

}  // namespace cairn::multibody::test
