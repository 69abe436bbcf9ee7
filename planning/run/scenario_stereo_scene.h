#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <Eigen/Geometry>

#include <cairn/perception/stereo/stereo_calibration.h>
#include <cairn/perception/synthetic/synthetic_stereo_scene.h>
#include <cairn/perception/synthetic/synthetic_stereo_source.h>
#include <cairn/planning/scenarios/footstep_scenario.h>

namespace cairn::planning {

/// Where the robot's head camera looks from, for ScenarioCameraPose.
struct HeadCamera {
  /// Height of the left camera's centre above the start stance, m; in (0, 10].
  double height{1.3};
  /// Angle of the optical axis below the horizon, degrees; in (0, 90]. With SyntheticCamera's 70 degree field of
  /// view, 70 shows the ground from just behind the feet to 1.4 m ahead from a height of 1.3 m.
  double pitch_deg{70.0};
  /// Distance of the camera behind the start stance's midpoint along the heading, m (negative: ahead); |.| <= 10.
  double behind{0.0};
};

/// The left camera's pose in the world for a camera on the head of a robot standing at `start`, looking down along
/// its heading (camera x right, y down, z forward; world z up). Throws std::invalid_argument for options out of
/// range.
Eigen::Isometry3d ScenarioCameraPose(const Stance& start, const HeadCamera& camera);

/// A footstep scenario as the synthetic stereo camera sees it (thesis 5.2.3's mock-up and its variants): each
/// region becomes a thin box of its material's texture (perception::MaterialTexture) with its top face on the
/// region's plane, and each obstacle a box of `obstacle_material`; beyond the regions lies a floor plane of
/// `floor_material` 3 cm below the lowest region. Later regions paint over earlier ones in the planner's terrain,
/// so each later region's box stands 1 mm higher than the one before (a cloth lies on the tiles), well below the
/// planners' support tolerance.
///
/// Objects are labelled with their material's index in perception::MaterialTexture::SupportedLabels() (the
/// renderer's ground-truth label image); textures are seeded by `seed` and the object's index, so the same
/// scenario and seed give the same images.
///
/// Throws std::invalid_argument naming the region that has no `material:` (the camera sees materials, not
/// coefficients), whose material has no texture, that is not an axis-aligned rectangle or that slopes.
perception::SyntheticStereoScene ScenarioStereoScene(const FootstepScenario& scenario, std::uint32_t seed = 1,
                                                     const std::string& obstacle_material = "metal",
                                                     const std::string& floor_material = "asphalt");

/// A synthetic stereo head camera for a scenario: image size, optics, noise and where it looks from.
struct SyntheticCamera {
  int width{320};                  ///< pixels; in [8, 4096]
  int height{240};                 ///< pixels; in [8, 4096]
  double field_of_view_deg{70.0};  ///< horizontal; in (10, 150)
  double baseline{0.12};           ///< m; in (0, 1]
  double noise_variance{4.0};      ///< of the renderer's Gaussian image noise (0..255 scale); >= 0
  HeadCamera head;
  std::uint32_t seed{1};           ///< textures' seed (ScenarioStereoScene)

  /// Square pixels, principal point at the image centre. Throws std::invalid_argument for options out of range.
  perception::StereoCalibration Calibration() const;
};

/// The camera of the main diagram for a scenario: a SyntheticStereoSource of ScenarioStereoScene(scenario, seed),
/// held at ScenarioCameraPose(scenario.start(), camera.head) (a robot whose head does not move while it plans),
/// one frame per `period` seconds. Throws std::invalid_argument as the functions it calls.
std::unique_ptr<perception::SyntheticStereoSource> ScenarioCamera(const FootstepScenario& scenario,
                                                                  const SyntheticCamera& camera, double period);

}  // namespace cairn::planning
