#include "report_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace cairn::cli {

void DrawText(cv::Mat& image, const std::string& text, cv::Point at, double scale) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

std::string EncodePng(const cv::Mat& image, const std::string& what) {
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", image, bytes)) throw std::runtime_error("cannot encode " + what + " as PNG");
  return std::string(bytes.begin(), bytes.end());
}

cv::Vec3b FrictionColour(double mu, double shade) {
  const double t = std::clamp(mu, 0.0, 1.0);
  const double r = t < 0.5 ? 1.0 : 2.0 * (1.0 - t);
  const double g = t < 0.5 ? 2.0 * t : 1.0;
  return cv::Vec3b(0, static_cast<uchar>(std::lround(220 * g * shade)), static_cast<uchar>(std::lround(220 * r * shade)));
}

cv::Vec3b MaterialColour(int index) {
  // Chosen for contrast between neighbouring labels of the thesis' list (Table 3.3's order).
  static const cv::Vec3b kPalette[] = {
      {128, 128, 128}, {0, 160, 0},     {60, 90, 120},   {160, 0, 160}, {230, 230, 230}, {200, 200, 255}, {200, 160, 60},
      {30, 90, 170},   {120, 200, 230}, {255, 200, 120}, {255, 255, 255}, {200, 80, 0},  {0, 0, 200},     {80, 220, 220},
  };
  constexpr int kSize = static_cast<int>(sizeof(kPalette) / sizeof(kPalette[0]));
  return kPalette[((index % kSize) + kSize) % kSize];
}

void DrawColourBar(cv::Mat& image, cv::Rect area, const std::function<cv::Vec3b(double)>& colour,
                   const std::string& lo, const std::string& hi, const std::string& title) {
  for (int x = 0; x < area.width; ++x) {
    const cv::Vec3b c = colour(area.width > 1 ? static_cast<double>(x) / (area.width - 1) : 0.0);
    cv::line(image, {area.x + x, area.y}, {area.x + x, area.y + area.height - 1}, cv::Scalar(c[0], c[1], c[2]), 1);
  }
  cv::rectangle(image, area, cv::Scalar(0, 0, 0), 1);
  DrawText(image, lo, {area.x - 4, area.y + area.height + 14}, 0.38);
  DrawText(image, hi, {area.x + area.width - 14, area.y + area.height + 14}, 0.38);
  DrawText(image, title, {area.x, area.y - 6}, 0.4);
}

void MetricTicks(cv::Mat& canvas, cv::Rect panel, double u0, double v0, double metres_per_pixel,
                 const std::string& u_label, const std::string& v_label, double step) {
  auto metres = [](double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.1f", std::abs(value) < 1e-9 ? 0.0 : value);
    return std::string(text);
  };
  const double u1 = u0 + panel.width * metres_per_pixel, v1 = v0 + panel.height * metres_per_pixel;
  if (!(step > 0.0) || !std::isfinite(step) || !std::isfinite(u0) || !std::isfinite(v0) ||
      !(metres_per_pixel > 0.0) || !std::isfinite(metres_per_pixel)) {
    throw std::invalid_argument("MetricTicks: the tick step (" + metres(step) + " m), the origin and the scale must be "
                                "finite and the step and scale positive");
  }
  // Counted by index, so that a step too small to change a large coordinate cannot loop forever.
  const double first_u = std::ceil(u0 / step), first_v = std::ceil(v0 / step);
  for (double k = first_u; k * step <= u1 + 1e-9 && k < first_u + 1000.0; ++k) {
    const double u = k * step;
    const int x = panel.x + static_cast<int>(std::lround((u - u0) / metres_per_pixel));
    cv::line(canvas, {x, panel.y + panel.height}, {x, panel.y + panel.height + 4}, cv::Scalar(0, 0, 0), 1);
    DrawText(canvas, metres(u), {x - 10, panel.y + panel.height + 17}, 0.36);
  }
  for (double k = first_v; k * step <= v1 + 1e-9 && k < first_v + 1000.0; ++k) {
    const double v = k * step;
    const int y = panel.y + panel.height - static_cast<int>(std::lround((v - v0) / metres_per_pixel));
    cv::line(canvas, {panel.x - 4, y}, {panel.x, y}, cv::Scalar(0, 0, 0), 1);
    DrawText(canvas, metres(v), {panel.x - 34, y + 4}, 0.36);
  }
  DrawText(canvas, u_label + " right, " + v_label + " up", {panel.x + panel.width / 2 - 50, panel.y + panel.height + 32},
           0.4);
}

}  // namespace cairn::cli
