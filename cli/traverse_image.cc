#include "traverse_image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cairn/common/number_text.h"
#include "cairn/perception/terrain/semantic_fusion.h"

namespace cairn::cli {
namespace {

constexpr int kLegendHeight = 56;
const cv::Vec3b kUnknown(90, 90, 90);

// OpenCV's viridis colour map as a 256-entry table (BGR), built once: applyColorMap per cell is slow.
const cv::Mat& Viridis() {
  static const cv::Mat table = [] {
    cv::Mat ramp(1, 256, CV_8UC1);
    for (int k = 0; k < 256; ++k) ramp.at<uchar>(0, k) = static_cast<uchar>(k);
    cv::Mat out;
    cv::applyColorMap(ramp, out, cv::COLORMAP_VIRIDIS);
    return out;
  }();
  return table;
}

// The colour of t in [0, 1] (clamped for display only).
cv::Vec3b Ramp(double t) {
  return Viridis().at<cv::Vec3b>(0, static_cast<int>(std::lround(255.0 * std::clamp(t, 0.0, 1.0))));
}

}  // namespace

std::string TraverseLayerPng(const perception::GridMap& map, const std::string& layer, double lo, double hi,
                             const std::string& unit, const planning::TraverseScenario& scenario,
                             const planning::ProbingRun& result) {
  const int nx = map.size().x(), ny = map.size().y();
  // At most about 800 pixels a side, at least one per cell (the scenario bounds the cells to 2^22).
  const int scale = std::max(1, std::min(8, 800 / std::max(nx, ny)));
  const int width = std::max(nx * scale, 320);
  cv::Mat image(ny * scale + kLegendHeight, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const bool semantics = layer == "semantics";
  const int plants = semantics ? map.LayerIndex(perception::SemanticFusion::LayerName("plants")) : -1;
  const int water = semantics ? map.LayerIndex(perception::SemanticFusion::LayerName("water")) : -1;
  const int index = semantics ? -1 : map.LayerIndex(layer);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      cv::Vec3b colour = kUnknown;
      if (semantics) {
        const double p = map.at(plants, i, j), w = map.at(water, i, j);
        if (!std::isnan(p) || !std::isnan(w)) {
          const double pp = std::isnan(p) ? 0.0 : std::clamp(p, 0.0, 1.0);
          const double ww = std::isnan(w) ? 0.0 : std::clamp(w, 0.0, 1.0);
          // Blend of bare ground (light grey), plants (green) and water (blue) by their probabilities.
          const double sum = std::max(1.0, pp + ww);
          const double a = pp / sum, b = ww / sum, g = 1.0 - a - b;
          colour = cv::Vec3b(static_cast<uchar>(std::lround(200 * g + 50 * a + 255 * b)),
                             static_cast<uchar>(std::lround(200 * g + 200 * a + 170 * b)),
                             static_cast<uchar>(std::lround(200 * g + 30 * a)));
        }
      } else {
        const double v = map.at(index, i, j);
        if (!std::isnan(v)) colour = Ramp((v - lo) / (hi - lo));
      }
      const cv::Rect cell(i * scale, (ny - 1 - j) * scale, scale, scale);
      image(cell).setTo(cv::Scalar(colour[0], colour[1], colour[2]));
    }
  }
  const Eigen::Vector2d origin = map.min_corner();
  const double ppm = scale / map.resolution();
  const auto pixel = [&](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::lround((p.x() - origin.x()) * ppm)),
                     static_cast<int>(std::lround(ny * scale - (p.y() - origin.y()) * ppm)));
  };
  for (std::size_t k = 1; k < result.last_path.size(); ++k) {
    cv::line(image, pixel(result.last_path[k - 1]), pixel(result.last_path[k]), cv::Scalar(255, 0, 255), 1,
             cv::LINE_AA);
  }
  for (std::size_t k = 1; k < result.trajectory.size(); ++k) {
    cv::line(image, pixel(result.trajectory[k - 1]), pixel(result.trajectory[k]), cv::Scalar(255, 255, 255), 2,
             cv::LINE_AA);
  }
  for (const auto& probe : result.probes) {
    const cv::Scalar colour = probe.collapsibility >= 0.5 ? cv::Scalar(0, 0, 255) : cv::Scalar(0, 200, 0);
    cv::circle(image, pixel(probe.target), std::max(4, scale * 2), colour, 2, cv::LINE_AA);
    cv::line(image, pixel(probe.robot), pixel(probe.target), colour, 1, cv::LINE_AA);
  }
  cv::drawMarker(image, pixel(scenario.start), cv::Scalar(255, 255, 255), cv::MARKER_SQUARE, 10, 2);
  cv::drawMarker(image, pixel(scenario.goal), cv::Scalar(0, 255, 255), cv::MARKER_STAR, 14, 2);
  // Legend: colour bar (or class swatches), its range, and a 1 m scale bar.
  const int top = ny * scale + 8;
  const auto text = [&](const std::string& s, int x, int y) {
    cv::putText(image, s, cv::Point(x, y), cv::FONT_HERSHEY_SIMPLEX, 0.4, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  };
  if (semantics) {
    image(cv::Rect(8, top, 16, 12)).setTo(cv::Scalar(50, 200, 30));
    text("plants", 28, top + 11);
    image(cv::Rect(90, top, 16, 12)).setTo(cv::Scalar(255, 170, 0));
    text("water", 110, top + 11);
  } else {
    const int bar = std::min(200, width - 120);
    for (int x = 0; x < bar; ++x) {
      const cv::Vec3b c = Ramp(static_cast<double>(x) / (bar - 1));
      image(cv::Rect(8 + x, top, 1, 12)).setTo(cv::Scalar(c[0], c[1], c[2]));
    }
    text(FormatShort(lo), 8, top + 26);
    text(FormatShort(hi) + " " + unit, 8 + bar - 40, top + 26);
  }
  image(cv::Rect(width - 100, top, 16, 12)).setTo(cv::Scalar(kUnknown[0], kUnknown[1], kUnknown[2]));
  text("unknown", width - 80, top + 11);
  const int metre = static_cast<int>(std::lround(ppm));
  cv::line(image, cv::Point(8, top + 40), cv::Point(8 + metre, top + 40), cv::Scalar(0, 0, 0), 2);
  text("1 m   " + layer + "   path (white) plan (magenta) probes (red: collapsible)", 16 + metre, top + 44);
  std::vector<uchar> png;
  if (!cv::imencode(".png", image, png)) throw std::runtime_error("Could not encode the " + layer + " PNG");
  return std::string(png.begin(), png.end());
}

}  // namespace cairn::cli
