#include <cairn/planning/run/scenario_stereo_scene.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <cairn/common/number_text.h>
#include <cairn/perception/synthetic/material_texture.h>
#include <cairn/perception/synthetic/procedural_texture.h>

namespace cairn::planning {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kRegionThickness = 0.02;
constexpr double kLayerStep = 0.001;

int LabelIndex(const std::string& label, const std::string& what) {
  const auto& labels = perception::MaterialTexture::SupportedLabels();
  const auto it = std::find(labels.begin(), labels.end(), label);
  if (it == labels.end()) {
    std::string known;
    for (const auto& l : labels) known += (known.empty() ? "" : ", ") + l;
    throw std::invalid_argument("ScenarioStereoScene: " + what + " has material '" + label +
                                "', which has no texture; use one of " + known);
  }
  return static_cast<int>(it - labels.begin());
}

// The region's rectangle [min, max] when its polygon is an axis-aligned rectangle.
bool AxisAlignedRectangle(const FootstepScenario::Region& region, Eigen::Vector2d* lo, Eigen::Vector2d* hi) {
  if (region.polygon.size() != 4) return false;
  *lo = region.polygon[0];
  *hi = region.polygon[0];
  for (const auto& p : region.polygon) {
    *lo = lo->cwiseMin(p);
    *hi = hi->cwiseMax(p);
  }
  for (const auto& p : region.polygon) {
    const bool x_on_side = p.x() == lo->x() || p.x() == hi->x();
    const bool y_on_side = p.y() == lo->y() || p.y() == hi->y();
    if (!x_on_side || !y_on_side) return false;
  }
  return hi->x() > lo->x() && hi->y() > lo->y();
}

}  // namespace

Eigen::Isometry3d ScenarioCameraPose(const Stance& start, const HeadCamera& camera) {
  if (!(camera.height > 0.0 && camera.height <= 10.0)) {
    throw std::invalid_argument("HeadCamera: height must be in (0, 10] m; got " + cairn::FormatShort(camera.height));
  }
  if (!(camera.pitch_deg > 0.0 && camera.pitch_deg <= 90.0)) {
    throw std::invalid_argument("HeadCamera: pitch_deg must be in (0, 90] (degrees below the horizon); got " +
                                cairn::FormatShort(camera.pitch_deg));
  }
  if (!(std::abs(camera.behind) <= 10.0)) {
    throw std::invalid_argument("HeadCamera: behind must be within +-10 m; got " + cairn::FormatShort(camera.behind));
  }
  const double yaw = 0.5 * (start.left.theta + start.right.theta);
  const double pitch = camera.pitch_deg * kPi / 180.0;
  const Eigen::Vector3d ahead(std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d forward = std::cos(pitch) * ahead - std::sin(pitch) * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d right(std::sin(yaw), -std::cos(yaw), 0.0);
  Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
  X_WC.linear().col(0) = right;
  X_WC.linear().col(1) = forward.cross(right);
  X_WC.linear().col(2) = forward;
  const Eigen::Vector3d middle(0.5 * (start.left.x + start.right.x), 0.5 * (start.left.y + start.right.y),
                               std::max(start.left.z, start.right.z));
  X_WC.translation() = middle - camera.behind * ahead + camera.height * Eigen::Vector3d::UnitZ();
  return X_WC;
}

perception::SyntheticStereoScene ScenarioStereoScene(const FootstepScenario& scenario, std::uint32_t seed,
                                                     const std::string& obstacle_material,
                                                     const std::string& floor_material) {
  perception::SyntheticStereoScene scene;
  const perception::ProceduralTexture unused;  // colour textures replace the grey one
  auto texture = [&](int object, const std::string& label) {
    const perception::MaterialTexture material =
        perception::MaterialTexture::Make(label, seed * 7919u + static_cast<std::uint32_t>(object));
    scene.SetColourTexture(object, [material](double u, double v) { return material.Evaluate(u, v); });
  };
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& region : scenario.regions()) lowest = std::min(lowest, region.height);
  if (scenario.regions().empty()) lowest = 0.0;
  const int floor_label = LabelIndex(floor_material, "the floor");
  texture(scene.AddPlane(Eigen::Vector3d(0.0, 0.0, lowest - 0.03), Eigen::Vector3d::UnitZ(), unused, floor_label),
          floor_material);
  int layer = 0;
  for (const auto& region : scenario.regions()) {
    const std::string what = "region '" + region.name + "'";
    if (region.material.empty()) {
      throw std::invalid_argument("ScenarioStereoScene: " + what +
                                  " states a friction, not a material; the camera sees materials, so give it "
                                  "`material: <label>`");
    }
    const int label = LabelIndex(region.material, what);
    Eigen::Vector2d lo, hi;
    if (!AxisAlignedRectangle(region, &lo, &hi)) {
      throw std::invalid_argument("ScenarioStereoScene: " + what +
                                  " is not an axis-aligned rectangle; give it as `box: {min: .., max: ..}`");
    }
    if (region.slope != 0.0) {
      throw std::invalid_argument("ScenarioStereoScene: " + what + " slopes; only level regions are rendered");
    }
    const double top = region.height + kLayerStep * layer++;
    Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
    X_WB.translation() << 0.5 * (lo + hi), top - 0.5 * kRegionThickness;
    const Eigen::Vector3d half(0.5 * (hi.x() - lo.x()), 0.5 * (hi.y() - lo.y()), 0.5 * kRegionThickness);
    texture(scene.AddBox(X_WB, half, unused, label), region.material);
  }
  const int obstacle_label = LabelIndex(obstacle_material, "an obstacle");
  for (const auto& obstacle : scenario.obstacles()) {
    Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
    X_WB.linear() = Eigen::AngleAxisd(obstacle.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    X_WB.translation() = obstacle.center;
    texture(scene.AddBox(X_WB, obstacle.half_extents, unused, obstacle_label), obstacle_material);
  }
  return scene;
}

perception::StereoCalibration SyntheticCamera::Calibration() const {
  if (width < 8 || width > 4096 || height < 8 || height > 4096) {
    throw std::invalid_argument("SyntheticCamera: the image size must be within [8, 4096] pixels per side; got " +
                                cairn::FormatShort(width) + "x" + cairn::FormatShort(height));
  }
  if (!(field_of_view_deg > 10.0 && field_of_view_deg < 150.0)) {
    throw std::invalid_argument("SyntheticCamera: field_of_view_deg must be in (10, 150); got " +
                                cairn::FormatShort(field_of_view_deg));
  }
  if (!(baseline > 0.0 && baseline <= 1.0)) {
    throw std::invalid_argument("SyntheticCamera: baseline must be in (0, 1] m; got " + cairn::FormatShort(baseline));
  }
  if (!(noise_variance >= 0.0) || !std::isfinite(noise_variance)) {
    throw std::invalid_argument("SyntheticCamera: noise_variance must be finite and >= 0; got " +
                                cairn::FormatShort(noise_variance));
  }
  const double focal = 0.5 * width / std::tan(0.5 * field_of_view_deg * kPi / 180.0);
  return perception::StereoCalibration{focal, focal, 0.5 * (width - 1), 0.5 * (height - 1), baseline};
}

std::unique_ptr<perception::SyntheticStereoSource> ScenarioCamera(const FootstepScenario& scenario,
                                                                  const SyntheticCamera& camera, double period) {
  perception::SyntheticStereoRenderer renderer(camera.Calibration(), camera.width, camera.height,
                                               camera.noise_variance);
  return std::make_unique<perception::SyntheticStereoSource>(
      ScenarioStereoScene(scenario, camera.seed), std::move(renderer),
      std::vector<Eigen::Isometry3d>{ScenarioCameraPose(scenario.start(), camera.head)}, period);
}

}  // namespace cairn::planning
