#pragma once

#include <functional>
#include <string>

#include <opencv2/core.hpp>

namespace cairn::cli {

/// Black anti-aliased text with its baseline's left end at `at`.
void DrawText(cv::Mat& image, const std::string& text, cv::Point at, double scale = 0.42);

/// PNG bytes of `image`, to be written atomically. Throws std::runtime_error naming `what` if encoding fails.
std::string EncodePng(const cv::Mat& image, const std::string& what);

/// Friction to colour (BGR) as every picture of friction draws it: red at 0, yellow at 0.5, green from 1,
/// darkened by `shade` in [0, 1].
cv::Vec3b FrictionColour(double mu, double shade = 1.0);

/// The colour (BGR) of material label `index` (registry order) in segmentation pictures.
cv::Vec3b MaterialColour(int index);

/// A horizontal colour bar in `area`: `colour(t)` for t from 0 (left) to 1 (right), framed, with `lo` and `hi`
/// printed under its ends and `title` above it.
void DrawColourBar(cv::Mat& image, cv::Rect area, const std::function<cv::Vec3b(double)>& colour,
                   const std::string& lo, const std::string& hi, const std::string& title);

/// Metric ticks every `step` m along a panel's bottom (u from u0 at its left edge) and left (v from v0 at its
/// bottom edge, upwards) edges, labelled in metres, with "<u_label> right, <v_label> up" under the panel; at most
/// 1000 ticks per edge. Throws std::invalid_argument for a step or scale that is not positive and finite.
void MetricTicks(cv::Mat& canvas, cv::Rect panel, double u0, double v0, double metres_per_pixel,
                 const std::string& u_label, const std::string& v_label, double step = 0.5);

}  // namespace cairn::cli
