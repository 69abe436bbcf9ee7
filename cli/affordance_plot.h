#pragma once

/// @file
/// The PNG plots of `cairn affordance`: line charts with axes, labels and a legend, and confusion matrices.

#include <array>
#include <string>
#include <vector>

namespace cairn::cli {

/// One line of a chart; `colour` is BGR.
struct PlotSeries {
  std::string name;
  std::array<int, 3> colour{0, 0, 0};
  std::vector<double> x;
  std::vector<double> y;
};

/// A line chart (markers at the points) as PNG bytes. Throws std::runtime_error if encoding fails.
std::string LinePlotPng(const std::string& title, const std::string& x_label, const std::string& y_label,
                        const std::vector<PlotSeries>& series);

/// A titled 2 x 2 confusion matrix (rows actual, columns predicted; traversable first).
struct ConfusionPanel {
  std::string title;
  std::array<std::array<int, 2>, 2> counts{};
};

/// Confusion matrices side by side as PNG bytes.
std::string ConfusionPng(const std::vector<ConfusionPanel>& panels);

}  // namespace cairn::cli
