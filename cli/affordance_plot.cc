#include "affordance_plot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cairn/common/number_text.h"

namespace cairn::cli {
namespace {

const cv::Scalar kBlack(0, 0, 0);

void Text(cv::Mat& image, const std::string& text, cv::Point at, double scale = 0.45) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, kBlack, 1, cv::LINE_AA);
}

std::string Encode(const cv::Mat& image) {
  std::vector<uchar> png;
  if (!cv::imencode(".png", image, png)) throw std::runtime_error("cannot encode the plot as PNG");
  return std::string(png.begin(), png.end());
}

}  // namespace

std::string LinePlotPng(const std::string& title, const std::string& x_label, const std::string& y_label,
                        const std::vector<PlotSeries>& series) {
  const int width = 800, height = 480, left = 70, right = width - 20, top = 60, bottom = height - 60;
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  double x_lo = 0.0, x_hi = 1.0, y_lo = 0.0, y_hi = 1.0;
  bool first = true;
  for (const PlotSeries& s : series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      if (first) {
        x_lo = x_hi = s.x[i];
        y_lo = y_hi = s.y[i];
        first = false;
      }
      x_lo = std::min(x_lo, s.x[i]);
      x_hi = std::max(x_hi, s.x[i]);
      y_lo = std::min(y_lo, s.y[i]);
      y_hi = std::max(y_hi, s.y[i]);
    }
  }
  y_lo = std::min(y_lo, 0.0);  // counts and confidences read from zero
  if (x_hi - x_lo < 1e-9) x_hi = x_lo + 1.0;
  if (y_hi - y_lo < 1e-9) y_hi = y_lo + 1.0;
  y_hi += 0.05 * (y_hi - y_lo);
  const auto px = [&](double x) { return left + static_cast<int>(std::lround((right - left) * (x - x_lo) / (x_hi - x_lo))); };
  const auto py = [&](double y) { return bottom - static_cast<int>(std::lround((bottom - top) * (y - y_lo) / (y_hi - y_lo))); };
  for (int k = 0; k <= 5; ++k) {
    const double y = y_lo + (y_hi - y_lo) * k / 5.0;
    cv::line(image, cv::Point(left, py(y)), cv::Point(right, py(y)), cv::Scalar(225, 225, 225), 1);
    Text(image, FormatShort(std::round(y * 100.0) / 100.0), cv::Point(8, py(y) + 4), 0.4);
    const double x = x_lo + (x_hi - x_lo) * k / 5.0;
    Text(image, FormatShort(std::round(x * 10.0) / 10.0), cv::Point(px(x) - 10, bottom + 18), 0.4);
  }
  cv::rectangle(image, cv::Point(left, top), cv::Point(right, bottom), kBlack, 1);
  Text(image, title, cv::Point(left, 22), 0.55);
  Text(image, x_label, cv::Point((left + right) / 2 - 4 * static_cast<int>(x_label.size()), height - 18));
  // The y label above the axis (OpenCV draws no rotated text).
  Text(image, y_label, cv::Point(8, top - 14), 0.4);
  int legend_y = top + 18;
  for (const PlotSeries& s : series) {
    const cv::Scalar colour(s.colour[0], s.colour[1], s.colour[2]);
    std::vector<cv::Point> points;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      points.emplace_back(px(s.x[i]), py(s.y[i]));
      cv::circle(image, points.back(), 3, colour, cv::FILLED, cv::LINE_AA);
    }
    if (points.size() >= 2) cv::polylines(image, points, false, colour, 2, cv::LINE_AA);
    cv::line(image, cv::Point(right - 190, legend_y - 4), cv::Point(right - 165, legend_y - 4), colour, 2);
    Text(image, s.name, cv::Point(right - 158, legend_y), 0.4);
    legend_y += 18;
  }
  return Encode(image);
}

std::string ConfusionPng(const std::vector<ConfusionPanel>& panels) {
  const int cell = 90, panel_width = 3 * cell + 70, width = std::max<int>(1, static_cast<int>(panels.size())) * panel_width;
  cv::Mat image(2 * cell + 90, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const char* names[] = {"trav.", "non-trav."};
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const int x0 = static_cast<int>(p) * panel_width + 50;
    const int y0 = 50;
    Text(image, panels[p].title, cv::Point(x0, 22), 0.5);
    Text(image, "predicted", cv::Point(x0 + cell + 40, y0 - 6), 0.4);
    Text(image, "actual", cv::Point(x0 - 30, y0 + 20 + cell + 4), 0.4);
    int total = 0;
    for (const auto& row : panels[p].counts) total += row[0] + row[1];
    for (int a = 0; a < 2; ++a) {
      Text(image, names[a], cv::Point(x0 + (a + 1) * cell + 15, y0 + 14), 0.4);
      Text(image, names[a], cv::Point(x0 + 10, y0 + 20 + a * cell + cell / 2 + 4), 0.4);
      for (int b = 0; b < 2; ++b) {
        const cv::Point corner(x0 + (b + 1) * cell, y0 + 20 + a * cell);
        const double share = total > 0 ? static_cast<double>(panels[p].counts[a][b]) / total : 0.0;
        const int shade = 255 - static_cast<int>(std::lround(150.0 * share));
        cv::rectangle(image, corner, corner + cv::Point(cell - 4, cell - 4),
                      a == b ? cv::Scalar(shade, 255, shade) : cv::Scalar(shade, shade, 255), cv::FILLED);
        cv::rectangle(image, corner, corner + cv::Point(cell - 4, cell - 4), kBlack, 1);
        Text(image, FormatShort(panels[p].counts[a][b]), corner + cv::Point(cell / 2 - 12, cell / 2 + 4), 0.7);
      }
    }
  }
  return Encode(image);
}

}  // namespace cairn::cli
