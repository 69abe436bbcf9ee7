#include "cairn/perception/synthetic/stereo_material_scene.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>

#include "cairn/common/text_suggestions.h"
#include "cairn/perception/synthetic/internal/material_label_sets.h"
#include "cairn/perception/synthetic/material_texture.h"

namespace cairn::perception {
namespace {

constexpr double kPi = 3.141592653589793;

int IndexIn(const std::vector<std::string>& labels, const std::string& label, const char* option) {
  return internal::IndexOfLabel(labels, label, "StereoMaterialScene", option);
}

StereoMaterialScene::Options Completed(StereoMaterialScene::Options o) {
  if (o.width <= 0 || o.height <= 0) {
    throw std::invalid_argument("StereoMaterialScene: the image size must be positive; got " +
                                std::to_string(o.width) + "x" + std::to_string(o.height) + ".");
  }
  if (!(o.field_of_view_deg > 10.0 && o.field_of_view_deg < 150.0)) {
    throw std::invalid_argument("StereoMaterialScene: field_of_view_deg must be in (10, 150); got " +
                                std::to_string(o.field_of_view_deg) + ".");
  }
  if (!(o.baseline > 0.0) || !std::isfinite(o.baseline)) {
    throw std::invalid_argument("StereoMaterialScene: baseline must be > 0 metres; got " +
                                std::to_string(o.baseline) + ".");
  }
  if (o.tiles_per_side < 1) {
    throw std::invalid_argument("StereoMaterialScene: tiles_per_side must be at least 1; got " +
                                std::to_string(o.tiles_per_side) + ".");
  }
  if (o.num_boxes < 0) {
    throw std::invalid_argument("StereoMaterialScene: num_boxes must be >= 0; got " + std::to_string(o.num_boxes) +
                                ".");
  }
  internal::ResolveMaterialLabelSets("StereoMaterialScene", &o.labels, &o.ground_labels, &o.box_labels);
  return o;
}

StereoCalibration CalibrationOf(const StereoMaterialScene::Options& o) {
  const double focal = 0.5 * o.width / std::tan(0.5 * o.field_of_view_deg * kPi / 180.0);
  return StereoCalibration{focal, focal, 0.5 * (o.width - 1), 0.5 * (o.height - 1), o.baseline};
}

}  // namespace

StereoMaterialScene::StereoMaterialScene(Options options)
    : options_(Completed(std::move(options))),
      calibration_(CalibrationOf(options_)),
      renderer_(calibration_, options_.width, options_.height, options_.noise_variance) {}

StereoMaterialScene::Scenario StereoMaterialScene::MakeScenario(std::uint32_t seed) const {
  const Options& o = options_;
  std::mt19937 rng(seed * 2654435761u + 40503u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };

  // Lighting: the stereo renderer is unlit, so colours carry it: a scene gain and tint, a brightness per object.
  const double gain = uniform(0.6, 1.2);
  const Eigen::Vector3d tint(uniform(0.9, 1.1), uniform(0.95, 1.05), uniform(0.9, 1.1));
  auto material = [&](const std::string& label) {
    const MaterialTexture texture = MaterialTexture::Make(label, static_cast<std::uint32_t>(rng()));
    const Eigen::Vector3d light = tint * gain * uniform(0.8, 1.1);
    return SyntheticStereoScene::ColourTexture([texture, light](double u, double v) -> Eigen::Vector3d {
      return texture.Evaluate(u, v).cwiseProduct(light).cwiseMin(255.0);
    });
  };
  // The grey ProceduralTexture is unused where a colour texture is set (the grey images are the colour's luma).
  const ProceduralTexture unused;

  // Camera: height, pitch below the horizon, yaw and a small roll. World z is up; camera x right, y down,
  // z forward.
  const double height = uniform(0.5, 1.6);
  const double pitch = uniform(25.0, 70.0) * kPi / 180.0;
  const double yaw = uniform(-kPi, kPi);
  const double roll = uniform(-6.0, 6.0) * kPi / 180.0;
  const Eigen::Vector3d forward(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), -std::sin(pitch));
  const Eigen::Vector3d right0(std::sin(yaw), -std::cos(yaw), 0.0);
  const Eigen::Vector3d down0 = forward.cross(right0);
  Scenario scenario;
  scenario.X_WC.linear().col(0) = std::cos(roll) * right0 + std::sin(roll) * down0;
  scenario.X_WC.linear().col(1) = -std::sin(roll) * right0 + std::cos(roll) * down0;
  scenario.X_WC.linear().col(2) = forward;
  scenario.X_WC.translation() = Eigen::Vector3d(0.0, 0.0, height);
  SyntheticStereoScene& scene = scenario.scene;

  auto add_ground_object = [&](int object, const std::string& label) {
    scene.SetColourTexture(object, material(label));
  };
  auto ground_label = [&]() -> const std::string& { return o.ground_labels[rng() % o.ground_labels.size()]; };

  // Ground plane under the tiles (seen past them), then the tile grid centred on the camera's footprint.
  {
    const std::string& label = ground_label();
    add_ground_object(scene.AddPlane(Eigen::Vector3d(0.0, 0.0, -0.03), Eigen::Vector3d::UnitZ(), unused,
                                     IndexIn(o.labels, label, "ground_labels")),
                      label);
  }
  const Eigen::Vector2d ahead(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d footprint = ahead * (height / std::tan(pitch));
  const double tile = uniform(0.8, 2.0);
  const double grid_yaw = uniform(-kPi, kPi);
  const Eigen::Matrix3d R_grid = Eigen::AngleAxisd(grid_yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (int a = 0; a < o.tiles_per_side; ++a) {
    for (int b = 0; b < o.tiles_per_side; ++b) {
      const double centre = 0.5 * (o.tiles_per_side - 1);
      const Eigen::Vector3d offset = R_grid * Eigen::Vector3d((a - centre) * tile, (b - centre) * tile, 0.0);
      Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
      X_WB.linear() = R_grid;
      X_WB.translation() = Eigen::Vector3d(footprint.x(), footprint.y(), -0.01) + offset;
      const std::string& label = ground_label();
      add_ground_object(scene.AddBox(X_WB, Eigen::Vector3d(0.5 * tile, 0.5 * tile, 0.01), unused,
                                     IndexIn(o.labels, label, "ground_labels")),
                        label);
    }
  }
  // Boxes standing on the ground in front of the camera.
  for (int i = 0; i < o.num_boxes; ++i) {
    const double distance = uniform(1.0, 1.0 + 2.0 * tile * o.tiles_per_side);
    const double side = uniform(-0.5, 0.5) * distance;
    const Eigen::Vector2d centre = ahead * distance + Eigen::Vector2d(-ahead.y(), ahead.x()) * side;
    const Eigen::Vector3d half(uniform(0.15, 0.6), uniform(0.15, 0.6), uniform(0.1, 0.9));
    Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
    X_WB.linear() = Eigen::AngleAxisd(uniform(-kPi, kPi), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    X_WB.translation() = Eigen::Vector3d(centre.x(), centre.y(), half.z());
    const std::string& label = o.box_labels[rng() % o.box_labels.size()];
    const int object = scene.AddBox(X_WB, half, unused, IndexIn(o.labels, label, "box_labels"));
    scene.SetColourTexture(object, material(label));
  }
  // A far wall behind everything, facing the camera: sky when that is a label (else rays there have none).
  const auto sky = std::find(o.labels.begin(), o.labels.end(), "sky");
  if (sky != o.labels.end()) {
    const Eigen::Vector3d far = Eigen::Vector3d(ahead.x(), ahead.y(), 0.0) * 60.0;
    const int object = scene.AddPlane(far, -Eigen::Vector3d(ahead.x(), ahead.y(), 0.0), unused,
                                      static_cast<int>(sky - o.labels.begin()));
    scene.SetColourTexture(object, material("sky"));
  }
  return scenario;
}

StereoMaterialScene::Rendering StereoMaterialScene::Render(std::uint32_t seed) const {
  const Scenario scenario = MakeScenario(seed);
  Rendering rendering;
  rendering.frame = renderer_.Render(scenario.scene, scenario.X_WC, static_cast<int>(seed % 1000003u));
  rendering.image = rendering.frame.left_colour;
  rendering.labels.create(options_.height, options_.width, CV_8UC1);
  for (int y = 0; y < options_.height; ++y) {
    const std::int32_t* in = rendering.frame.labels.ptr<std::int32_t>(y);
    std::uint8_t* out = rendering.labels.ptr<std::uint8_t>(y);
    for (int x = 0; x < options_.width; ++x) out[x] = in[x] < 0 ? 255 : static_cast<std::uint8_t>(in[x]);
  }
  return rendering;
}

}  // namespace cairn::perception
