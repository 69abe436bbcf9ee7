#pragma once

/// @file
/// The checks the URDF parser runs on the XML text before urdfdom sees it.

#include <cstddef>
#include <string>
#include <utility>

namespace cairn::multibody {

/// Largest URDF text the parser accepts: 64 MiB. Real robot descriptions are well under 1 MiB (Atlas is about
/// 60 KiB); the limit keeps a wrong file (a mesh, a log, /dev/zero) from being read into memory whole.
inline constexpr std::size_t kMaxUrdfBytes = std::size_t{64} << 20;

/// Deepest XML element nesting the parser accepts: 100 levels. A URDF needs 5 (robot/link/visual/geometry/box);
/// TinyXML and urdfdom recurse once per level, so a file nesting thousands of elements would overflow the stack.
inline constexpr int kMaxUrdfNestingDepth = 100;

namespace internal {

/// Validates URDF text strictly before urdfdom parses it, because urdfdom reads an unparsable number as 0 or
/// drops the element holding it, recurses once per nesting level, and reports errors without positions.
///
/// Every error throws std::runtime_error whose message starts with the source name and names the line, the
/// link or joint, the attribute and its value.
class UrdfXmlCheck {
 public:
  /// `source` names the file in messages.
  explicit UrdfXmlCheck(std::string source) : source_(std::move(source)) {}

  /// Refuses text longer than kMaxUrdfBytes and element nesting deeper than kMaxUrdfNestingDepth, scanning the
  /// raw text without recursion (so it is safe on any input).
  void CheckSizeAndNesting(const std::string& xml) const;

  /// Parses `xml` with TinyXML (call CheckSizeAndNesting first) and checks that the root is <robot> and that
  /// every numeric attribute URDF defines (origins, inertials, shape sizes, axes, limits, dynamics, safety
  /// controllers, calibration, mimic, colours) holds exactly the expected count of finite numbers. Values
  /// whose sign is fixed by their meaning are checked too: mass >= 0, box sides, sphere and cylinder radii > 0,
  /// cylinder length >= 0, effort and velocity limits >= 0, and lower <= upper for revolute and prismatic
  /// joints.
  void CheckDocument(const std::string& xml) const;

 private:
  [[noreturn]] void Fail(const std::string& what) const;
  std::string source_;
};

}  // namespace internal
}  // namespace cairn::multibody
