#include "plot_axes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "report_drawing.h"

namespace cairn::cli {
namespace {

const cv::Scalar kBlack(0, 0, 0), kGrid(225, 225, 225);

// A tick label: three significant digits are enough to read a plot.
std::string Tick(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", std::abs(value) < 1e-12 ? 0.0 : value);
  return text;
}

}  // namespace

cv::Point PlotAxes::Map(double x, double y) const {
  return {area.x + static_cast<int>(std::lround((x - x0) / (x1 - x0) * area.width)),
          area.y + area.height - static_cast<int>(std::lround((y - y0) / (y1 - y0) * area.height))};
}

void PlotAxes::Draw(cv::Mat& image, const std::string& title, const std::string& x_label,
                    const std::string& y_label) const {
  for (int k = 0; k <= 4; ++k) {
    const double y = y0 + (y1 - y0) * k / 4.0;
    const cv::Point py = Map(x0, y);
    cv::line(image, {area.x, py.y}, {area.x + area.width, py.y}, kGrid, 1);
    DrawText(image, Tick(y), {area.x - 52, py.y + 4}, 0.38);
  }
  std::vector<double> xs;
  if (integer_x) {
    for (int i = static_cast<int>(std::ceil(x0)); i <= static_cast<int>(std::floor(x1)) && xs.size() < 200; ++i) {
      xs.push_back(i);
    }
  } else {
    for (int k = 0; k <= 4; ++k) xs.push_back(x0 + (x1 - x0) * k / 4.0);
  }
  for (double x : xs) {
    const cv::Point px = Map(x, y0);
    cv::line(image, {px.x, area.y}, {px.x, area.y + area.height}, kGrid, 1);
    DrawText(image, Tick(x), {px.x - 12, area.y + area.height + 16}, 0.38);
  }
  cv::rectangle(image, area, kBlack, 1);
  DrawText(image, title, {area.x + 40, area.y - 10}, 0.5);
  DrawText(image, x_label, {area.x + area.width / 2 - 30, area.y + area.height + 36});
  DrawText(image, y_label, {4, area.y - 10});
}

std::pair<double, double> PlotRange(const std::vector<double>& values, double margin) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!std::isfinite(lo)) return {0.0, 1.0};
  if (hi - lo < 1e-9) {
    lo -= 0.5;
    hi += 0.5;
  }
  const double pad = margin * (hi - lo);
  return {lo - pad, hi + pad};
}

void PlotLegend(cv::Mat& image, cv::Point at, const std::vector<std::pair<std::string, cv::Scalar>>& entries) {
  for (const auto& [label, colour] : entries) {
    cv::line(image, at, {at.x + 22, at.y}, colour, 2, cv::LINE_AA);
    DrawText(image, label, {at.x + 28, at.y + 4}, 0.4);
    at.y += 16;
  }
}

void PlotPolyline(cv::Mat& image, const PlotAxes& axes, const std::vector<Eigen::Vector2d>& points, cv::Scalar colour,
                  int thickness) {
  std::vector<cv::Point> pixels;
  for (const Eigen::Vector2d& p : points) {
    if (p.allFinite()) pixels.push_back(axes.Map(p.x(), p.y()));
  }
  if (pixels.size() >= 2) cv::polylines(image, pixels, false, colour, thickness, cv::LINE_AA);
}

}  // namespace cairn::cli
