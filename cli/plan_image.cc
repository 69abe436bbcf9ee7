#include "plan_image.h"
#include "report_drawing.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "cairn/common/number_text.h"

namespace cairn::cli {
namespace {

using planning::FootPose;

constexpr double kMaxPixels = 64e6;
constexpr double kMinLongSide = 600.0;  // pixels: a small terrain still shows its soles and labels
// The canvas around the map: the title above, metric axes left and below, the legend under them.
constexpr int kLeft = 48, kTop = 30, kRight = 16, kBelow = 110, kMinCanvasWidth = 700;

double Scale(const planning::TerrainMap& terrain, double pixels_per_metre) {
  const Eigen::Vector2d extent = terrain.max_corner() - terrain.min_corner();
  const double longer = std::max(extent.x(), extent.y());
  return longer > 0.0 ? std::max(pixels_per_metre, kMinLongSide / longer) : pixels_per_metre;
}

// The key's sole outline, drawn on a dark swatch so that the white start shows.
void KeySole(cv::Mat& canvas, cv::Point at, const cv::Scalar& colour, const std::string& label) {
  cv::rectangle(canvas, cv::Rect(at.x, at.y - 12, 26, 16), cv::Scalar(60, 60, 60), cv::FILLED);
  cv::rectangle(canvas, cv::Rect(at.x + 4, at.y - 9, 18, 10), colour, 2, cv::LINE_AA);
  DrawText(canvas, label, {at.x + 32, at.y}, 0.4);
}

}  // namespace

std::pair<int, int> PlanImageSize(const planning::TerrainMap& terrain, double pixels_per_metre) {
  const Eigen::Vector2d lo = terrain.min_corner(), hi = terrain.max_corner();
  pixels_per_metre = Scale(terrain, pixels_per_metre);
  const double width = std::max(1.0, std::round((hi.x() - lo.x()) * pixels_per_metre));
  const double height = std::max(1.0, std::round((hi.y() - lo.y()) * pixels_per_metre));
  const double canvas = std::max(width + kLeft + kRight, static_cast<double>(kMinCanvasWidth)) * (height + kTop + kBelow);
  if (!(canvas <= kMaxPixels)) {
    throw std::invalid_argument("The plan image of the " + FormatShort(hi.x() - lo.x()) + " m x " +
                                FormatShort(hi.y() - lo.y()) + " m terrain would be " + FormatShort(width) + " x " +
                                FormatShort(height) + " pixels with its axes and legend, more than the limit of " +
                                FormatShort(kMaxPixels) + "; plan without --out or on a smaller terrain.");
  }
  return {static_cast<int>(width), static_cast<int>(height)};
}

std::string PlanImagePng(const planning::TerrainMap& terrain, const planning::FootstepPlan& plan,
                         const planning::StanceGoal& goal, const planning::BipedGeometry& geometry,
                         const std::string& title, double pixels_per_metre) {
  const auto [width, height] = PlanImageSize(terrain, pixels_per_metre);
  pixels_per_metre = Scale(terrain, pixels_per_metre);
  const Eigen::Vector2d lo = terrain.min_corner(), hi = terrain.max_corner();
  // Image rows grow downwards while y grows up: row 0 is the largest y.
  auto to_pixel = [&](double x, double y) {
    return cv::Point2d((x - lo.x()) * pixels_per_metre, (hi.y() - y) * pixels_per_metre);
  };
  double zmin = 1e300, zmax = -1e300;
  for (int r = 0; r < terrain.rows(); ++r) {
    for (int c = 0; c < terrain.cols(); ++c) {
      if (terrain.has_ground(c, r)) {
        zmin = std::min(zmin, terrain.height(c, r));
        zmax = std::max(zmax, terrain.height(c, r));
      }
    }
  }
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const double x = lo.x() + (u + 0.5) / pixels_per_metre, y = hi.y() - (v + 0.5) / pixels_per_metre;
      int c, r;
      if (!terrain.CellAt(x, y, &c, &r) || !terrain.has_ground(c, r)) continue;
      const double shade = zmax > zmin ? 0.6 + 0.4 * (terrain.height(c, r) - zmin) / (zmax - zmin) : 1.0;
      image.at<cv::Vec3b>(v, u) = FrictionColour(terrain.friction(c, r), shade);
    }
  }
  auto polygon = [&](const Eigen::Vector2d& center, double half_x, double half_y, double yaw) {
    const Eigen::Vector2d ax(std::cos(yaw), std::sin(yaw)), ay(-std::sin(yaw), std::cos(yaw));
    std::vector<cv::Point> points;
    for (const auto& [sx, sy] : {std::pair{1, 1}, std::pair{-1, 1}, std::pair{-1, -1}, std::pair{1, -1}}) {
      const Eigen::Vector2d p = center + sx * half_x * ax + sy * half_y * ay;
      points.push_back(to_pixel(p.x(), p.y()));
    }
    return points;
  };
  for (const planning::TerrainMap::Obstacle& o : terrain.obstacles()) {
    const std::vector<cv::Point> box = polygon(o.center.head<2>(), o.half_extents.x(), o.half_extents.y(), o.yaw);
    cv::fillConvexPoly(image, box, cv::Scalar(70, 70, 70), cv::LINE_AA);
  }
  const int thickness = std::max(1, static_cast<int>(std::lround(pixels_per_metre / 60.0)));
  auto sole = [&](const FootPose& pose, const cv::Scalar& colour) {
    const std::vector<cv::Point> outline =
        polygon(Eigen::Vector2d(pose.x, pose.y), 0.5 * geometry.foot_length, 0.5 * geometry.foot_width, pose.theta);
    cv::polylines(image, outline, true, colour, thickness, cv::LINE_AA);
  };
  sole(goal.stance.left, cv::Scalar(0, 255, 255));
  sole(goal.stance.right, cv::Scalar(0, 255, 255));
  sole(plan.start.left, cv::Scalar(255, 255, 255));
  sole(plan.start.right, cv::Scalar(255, 255, 255));
  for (const planning::PlannedStep& step : plan.steps) {
    sole(step.pose, step.side == planning::FootSide::kLeft ? cv::Scalar(255, 80, 0) : cv::Scalar(40, 0, 200));
  }
  // The map framed on a white canvas.
  cv::Mat canvas(height + kTop + kBelow, std::max(width + kLeft + kRight, kMinCanvasWidth), CV_8UC3,
                 cv::Scalar(255, 255, 255));
  const cv::Rect map(kLeft, kTop, width, height);
  image.copyTo(canvas(map));
  cv::rectangle(canvas, cv::Rect(map.x - 1, map.y - 1, map.width + 2, map.height + 2), cv::Scalar(0, 0, 0), 1);
  DrawText(canvas, title, {kLeft, kTop - 10}, 0.5);
  const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  MetricTicks(canvas, map, lo.x(), lo.y(), 1.0 / pixels_per_metre, "x (m)", "y (m)",
              extent > 20.0 ? 5.0 : extent > 5.0 ? 1.0 : 0.5);
  const int legend = map.y + map.height + 62;
  DrawColourBar(canvas, cv::Rect(kLeft, legend, 200, 12), [](double t) { return FrictionColour(t); }, "0", "1",
                "friction (darker: lower ground; black: none)");
  int x = kLeft + 230;
  for (const auto& [colour, label] : {std::pair{cv::Scalar(255, 255, 255), "start"},
                                      std::pair{cv::Scalar(0, 255, 255), "goal"},
                                      std::pair{cv::Scalar(255, 80, 0), "left foot"},
                                      std::pair{cv::Scalar(40, 0, 200), "right foot"}}) {
    KeySole(canvas, {x, legend + 10}, colour, label);
    x += 32 + 8 * static_cast<int>(std::string(label).size()) + 16;
  }
  return EncodePng(canvas, "the plan image");
}

}  // namespace cairn::cli
