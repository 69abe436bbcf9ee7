#include "perception_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "report_drawing.h"

namespace cairn::cli {
namespace {

constexpr int kMargin = 46;   // room for tick labels left of and below a panel
constexpr int kTitle = 26;    // room for a title above a panel
constexpr int kPanelWidth = 320;

// Occupancy probability to colour: blue where seen free, white unknown (0.5), dark red where occupied.
cv::Vec3b OccupancyColour(double p) {
  const double t = std::clamp(p, 0.0, 1.0);
  if (t < 0.5) {
    const double s = t / 0.5;  // 0 free .. 1 unknown
    return cv::Vec3b(230, static_cast<uchar>(std::lround(120 + 135 * s)), static_cast<uchar>(std::lround(60 + 195 * s)));
  }
  const double s = (t - 0.5) / 0.5;  // 0 unknown .. 1 occupied
  return cv::Vec3b(static_cast<uchar>(std::lround(255 - 215 * s)), static_cast<uchar>(std::lround(255 - 215 * s)),
                   static_cast<uchar>(std::lround(255 - 95 * s)));
}

// Pastes `panel` at `at` on `canvas`, framed, with `title` above it.
void Paste(cv::Mat& canvas, const cv::Mat& panel, cv::Point at, const std::string& title) {
  panel.copyTo(canvas(cv::Rect(at, panel.size())));
  cv::rectangle(canvas, cv::Rect(at.x - 1, at.y - 1, panel.cols + 2, panel.rows + 2), cv::Scalar(0, 0, 0), 1);
  DrawText(canvas, title, {at.x, at.y - 8}, 0.45);
}

}  // namespace

std::string PerceptionReportPng(const planning::MainRecord& record, const perception::MaterialRegistry& registry,
                                double eta) {
  if (record.grid == nullptr || record.image.empty() || record.material_probabilities.empty() ||
      record.friction_quantile.empty()) {
    throw std::invalid_argument("PerceptionReportPng: the run holds no perception (it stopped before the first "
                                "frame was perceived)");
  }
  const int labels = registry.size();
  if (record.image.type() != CV_8UC3 || record.material_probabilities.depth() != CV_32F ||
      record.friction_quantile.type() != CV_32FC1) {
    throw std::invalid_argument("PerceptionReportPng: the image must be 8-bit BGR and the probabilities and quantiles "
                                "32-bit float, as the main diagram makes them");
  }
  if (record.material_probabilities.channels() != labels ||
      record.material_probabilities.size() != record.image.size() ||
      record.friction_quantile.size() != record.image.size()) {
    throw std::invalid_argument("PerceptionReportPng: the material probabilities have " +
                                std::to_string(record.material_probabilities.channels()) + " channels for " +
                                std::to_string(labels) + " registry labels, or the images differ in size");
  }
  // The camera's three images at a common panel width.
  const double scale = static_cast<double>(kPanelWidth) / record.image.cols;
  const cv::Size panel(kPanelWidth, std::max(1, static_cast<int>(std::lround(record.image.rows * scale))));
  cv::Mat camera, segmentation(record.image.size(), CV_8UC3), quantile(record.image.size(), CV_8UC3);
  cv::resize(record.image, camera, panel, 0.0, 0.0, cv::INTER_AREA);
  std::vector<double> share(static_cast<std::size_t>(labels), 0.0);
  for (int r = 0; r < record.image.rows; ++r) {
    const float* p = record.material_probabilities.ptr<float>(r);
    const float* q = record.friction_quantile.ptr<float>(r);
    for (int c = 0; c < record.image.cols; ++c, p += labels) {
      const int best = static_cast<int>(std::max_element(p, p + labels) - p);
      segmentation.at<cv::Vec3b>(r, c) = MaterialColour(best);
      share[static_cast<std::size_t>(best)] += 1.0;
      quantile.at<cv::Vec3b>(r, c) = FrictionColour(q[c]);
    }
  }
  cv::resize(segmentation, segmentation, panel, 0.0, 0.0, cv::INTER_NEAREST);
  cv::resize(quantile, quantile, panel, 0.0, 0.0, cv::INTER_NEAREST);
  std::vector<int> present;
  for (int i = 0; i < labels; ++i) {
    if (share[static_cast<std::size_t>(i)] >= 0.01 * static_cast<double>(record.image.total())) present.push_back(i);
  }

  // The grid from above (highest probability per column) and the x-z slice through the row with the most
  // occupied cells.
  const perception::OccupancyGrid& grid = *record.grid;
  const Eigen::Vector3i dims = grid.dims();
  // The grid's longest side gets at most 384 pixels in either panel.
  const int cell_pixels = std::max(1, static_cast<int>(std::floor(384.0 / std::max({dims.x(), dims.y(), dims.z(), 1}))));
  cv::Mat top(dims.y(), dims.x(), CV_8UC3), slice(dims.z(), dims.x(), CV_8UC3);
  int slice_row = 0, most = -1;
  for (int y = 0; y < dims.y(); ++y) {
    int occupied = 0;
    for (int x = 0; x < dims.x(); ++x) {
      double highest = 0.0;
      for (int z = 0; z < dims.z(); ++z) {
        const double p = grid.probability(grid.Index(Eigen::Vector3i(x, y, z)));
        highest = std::max(highest, p);
        occupied += p > 0.5 ? 1 : 0;
      }
      top.at<cv::Vec3b>(dims.y() - 1 - y, x) = OccupancyColour(highest);
    }
    if (occupied > most) {
      most = occupied;
      slice_row = y;
    }
  }
  for (int z = 0; z < dims.z(); ++z) {
    for (int x = 0; x < dims.x(); ++x) {
      slice.at<cv::Vec3b>(dims.z() - 1 - z, x) = OccupancyColour(grid.probability(grid.Index(Eigen::Vector3i(x, slice_row, z))));
    }
  }
  cv::resize(top, top, cv::Size(), cell_pixels, cell_pixels, cv::INTER_NEAREST);
  cv::resize(slice, slice, cv::Size(), cell_pixels, cell_pixels, cv::INTER_NEAREST);

  // Layout: the camera's three panels in a row, the legend and colour bar under them, then the grid's two panels.
  const int legend_rows = (static_cast<int>(present.size()) + 1) / 2;
  const int row1 = kTitle;
  const int under1 = row1 + panel.height + 12;
  const int row2 = under1 + std::max(16 * legend_rows, 40) + kTitle + 14;
  const int width = std::max(3 * (kPanelWidth + 14) + 14, 2 * kMargin + top.cols + slice.cols + kMargin + 20);
  const int height = row2 + std::max(top.rows, slice.rows) + kMargin + 40;
  cv::Mat canvas(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  Paste(canvas, camera, {14, row1}, "camera (left)");
  Paste(canvas, segmentation, {14 + kPanelWidth + 14, row1}, "materials (most probable label)");
  char title[96];
  std::snprintf(title, sizeof(title), "friction quantile Q(1-%.2g)", eta);
  Paste(canvas, quantile, {14 + 2 * (kPanelWidth + 14), row1}, title);
  for (std::size_t k = 0; k < present.size(); ++k) {
    const cv::Point at(14 + kPanelWidth + 14 + static_cast<int>(k % 2) * 160, under1 + 12 + 16 * static_cast<int>(k / 2));
    const cv::Vec3b c = MaterialColour(present[k]);
    cv::rectangle(canvas, cv::Rect(at.x, at.y - 10, 12, 12), cv::Scalar(c[0], c[1], c[2]), cv::FILLED);
    cv::rectangle(canvas, cv::Rect(at.x, at.y - 10, 12, 12), cv::Scalar(0, 0, 0), 1);
    char entry[96];
    std::snprintf(entry, sizeof(entry), "%s %.0f%%", registry.material(present[k]).label.c_str(),
                  100.0 * share[static_cast<std::size_t>(present[k])] / static_cast<double>(record.image.total()));
    DrawText(canvas, entry, {at.x + 18, at.y}, 0.4);
  }
  DrawColourBar(canvas, cv::Rect(14 + 2 * (kPanelWidth + 14) + 20, under1 + 18, kPanelWidth - 40, 12),
                [](double t) { return FrictionColour(t); }, "0", "1", "friction (red 0, green 1 and above)");

  const Eigen::Vector3d corner = grid.min_corner();
  const double metres_per_pixel = grid.resolution() / cell_pixels;
  const cv::Rect top_area(kMargin, row2, top.cols, top.rows);
  Paste(canvas, top, top_area.tl(), "occupancy from above (highest per column)");
  MetricTicks(canvas, top_area, corner.x(), corner.y(), metres_per_pixel, "x (m)", "y (m)");
  const cv::Rect slice_area(top_area.x + top.cols + kMargin + 20, row2, slice.cols, slice.rows);
  std::snprintf(title, sizeof(title), "occupancy, slice at y = %.2f m", grid.CellCenter(Eigen::Vector3i(0, slice_row, 0)).y());
  Paste(canvas, slice, slice_area.tl(), title);
  MetricTicks(canvas, slice_area, corner.x(), corner.z(), metres_per_pixel, "x (m)", "z (m)");
  DrawColourBar(canvas, cv::Rect(slice_area.x, slice_area.y + slice_area.height + 56, std::min(240, slice_area.width), 12),
                OccupancyColour, "0 free", "1", "occupancy probability (white: unknown)");
  return EncodePng(canvas, "the perception report");
}

std::vector<visualization::SceneBox> PerceivedTerrainBoxes(const planning::TerrainMap& terrain, std::size_t max_boxes) {
  constexpr double kThickness = 0.01;
  std::vector<visualization::SceneBox> boxes;
  const double res = terrain.resolution();
  for (int row = 0; row < terrain.rows(); ++row) {
    int col = 0;
    while (col < terrain.cols()) {
      if (!terrain.has_ground(col, row)) {
        ++col;
        continue;
      }
      const double height = terrain.height(col, row), friction = terrain.friction(col, row);
      int end = col + 1;
      while (end < terrain.cols() && terrain.has_ground(end, row) &&
             std::abs(terrain.height(end, row) - height) <= 0.002 &&
             std::abs(terrain.friction(end, row) - friction) <= 0.005) {
        ++end;
      }
      const Eigen::Vector2d lo = terrain.CellCenter(col, row) - Eigen::Vector2d::Constant(0.5 * res);
      const Eigen::Vector3d centre(lo.x() + 0.5 * res * (end - col), lo.y() + 0.5 * res, height - 0.5 * kThickness);
      boxes.push_back({"perceived ground", multibody::Pose(Eigen::Matrix3d::Identity(), centre),
                       Eigen::Vector3d(res * (end - col), res, kThickness), friction});
      col = end;
    }
  }
  if (boxes.size() > max_boxes) {
    throw std::invalid_argument("PerceivedTerrainBoxes: the ground alone takes " + std::to_string(boxes.size()) +
                                " boxes, more than " + std::to_string(max_boxes) + "; coarsen the terrain");
  }
  std::vector<planning::TerrainMap::OccupiedVoxel> voxels = terrain.occupied_voxels();
  const std::size_t room = max_boxes - boxes.size();
  if (voxels.size() > room) {
    std::stable_sort(voxels.begin(), voxels.end(),
                     [](const auto& a, const auto& b) { return a.probability > b.probability; });
    voxels.resize(room);
  }
  const double side = terrain.voxel_size();
  for (const planning::TerrainMap::OccupiedVoxel& v : voxels) {
    boxes.push_back({"occupied", multibody::Pose(Eigen::Matrix3d::Identity(), v.center), Eigen::Vector3d::Constant(side),
                     0.0, v.probability});
  }
  return boxes;
}

}  // namespace cairn::cli
