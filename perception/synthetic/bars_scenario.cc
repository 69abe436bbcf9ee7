#include "cairn/common/number_text.h"
#include "cairn/perception/synthetic/bars_scenario.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cairn::perception {

BarsScenario BarsScenario::Make(int frames) {
  if (frames < 1 || frames > OccupancyScenario::kMaxFrames) {
    throw std::invalid_argument("BarsScenario: " + cairn::FormatShort(frames) + " frames; ask for 1 to " +
                                cairn::FormatShort(OccupancyScenario::kMaxFrames) + " (the thesis uses 20)");
  }
  BarsScenario s;
  s.calibration = StereoCalibration{600.0, 600.0, 319.5, 239.5, 0.3};
  const Eigen::Vector3d center(0.0, 3.0, 0.0);
  ProceduralTexture bar_texture;
  bar_texture.kind = ProceduralTexture::Kind::kNoise;
  bar_texture.scale = 0.03;
  bar_texture.mean = 200.0;
  bar_texture.contrast = 50.0;
  bar_texture.seed = 7;
  for (int i = 0; i < 7; ++i) {
    Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
    X_WB.translation() = center + Eigen::Vector3d(0.3 * (i - 3), 0.0, 0.0);
    const Eigen::Vector3d half(0.04, 0.04, 3.0);
    s.scene.AddBox(X_WB, half, bar_texture, 1);
    s.bars.emplace_back();
    s.bars.back().AddBox(X_WB, half, bar_texture, 1);
  }
  // The wall must be matchable between the bars, or nothing can clear the space behind them: its disparity
  // jump from the bars (60 - fb / depth px) is the width of the band beside each bar that the right camera cannot
  // see, and the gaps between bars are 44 px wide. A wall 10 m away (jump 42 px) is hidden from one camera almost
  // everywhere, so every background pixel matches a bar-like disparity and paints false surfaces behind the bars;
  // at 1 m behind the bars (jump 15 px) two thirds of each gap is seen by both cameras. The texture
  // is as fine and contrasted as the bars' so that the wall is matched as reliably as they are.
  ProceduralTexture wall;
  wall.kind = ProceduralTexture::Kind::kNoise;
  wall.scale = 0.05;
  wall.mean = 70.0;
  wall.contrast = 50.0;
  wall.seed = 3;
  s.scene.AddPlane(center + Eigen::Vector3d(0.0, 1.0, 0.0), Eigen::Vector3d(0.0, -1.0, 0.0), wall, 2);
  const double radius = 3.0;
  for (int f = 0; f < frames; ++f) {
    const double angle = frames == 1 ? 0.0 : (-25.0 + 50.0 * f / (frames - 1)) * M_PI / 180.0;
    const Eigen::Vector3d position = center + radius * Eigen::Vector3d(std::sin(angle), -std::cos(angle), 0.0);
    const Eigen::Vector3d forward = (center - position).normalized();
    const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d down = forward.cross(right);
    Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
    X_WC.linear().col(0) = right;
    X_WC.linear().col(1) = down;
    X_WC.linear().col(2) = forward;
    X_WC.translation() = position;
    s.trajectory.push_back(X_WC);
  }
  return s;
}

OccupancyScenario BarsScenario::ToOccupancyScenario() const {
  OccupancyScenario s;
  s.scene = scene;
  s.calibration = calibration;
  s.width = width;
  s.height = height;
  s.min_disparity = min_disparity;
  s.max_disparity = max_disparity;
  s.trajectory = trajectory;
  s.grid_min_corner = grid_min_corner;
  s.grid_resolution = grid_resolution;
  s.grid_dims = grid_dims;
  return s;
}

}  // namespace cairn::perception
