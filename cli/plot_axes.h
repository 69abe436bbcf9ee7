#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace cairn::cli {

/// A plot area of a report picture mapping data (x, y) to pixels, with grid lines, ticks, axis labels and a title;
/// `integer_x` puts one x tick at every integer (steps) instead of five evenly spaced ones.
struct PlotAxes {
  cv::Rect area;
  double x0, x1, y0, y1;
  bool integer_x{false};

  cv::Point Map(double x, double y) const;
  void Draw(cv::Mat& image, const std::string& title, const std::string& x_label, const std::string& y_label) const;
};

/// The range of the finite `values` widened by `margin` of its width on each side; a flat range becomes one unit
/// wide, and no finite value gives [0, 1].
std::pair<double, double> PlotRange(const std::vector<double>& values, double margin = 0.05);

/// A legend: one short line of each colour with its label, downwards from `at`.
void PlotLegend(cv::Mat& image, cv::Point at, const std::vector<std::pair<std::string, cv::Scalar>>& entries);

/// The finite points joined by a line (nothing with fewer than two).
void PlotPolyline(cv::Mat& image, const PlotAxes& axes, const std::vector<Eigen::Vector2d>& points, cv::Scalar colour,
                  int thickness = 1);

}  // namespace cairn::cli
