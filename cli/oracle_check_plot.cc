#include "oracle_check_plot.h"

#include <algorithm>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "cairn/common/number_text.h"
#include "plot_axes.h"
#include "report_drawing.h"

namespace cairn::cli {

std::string OracleHeldOutPng(const planning::OracleHeldOutError& error, const std::string& title,
                             const std::string& unit) {
  const cv::Scalar blue(200, 90, 0), grey(150, 150, 150);
  std::vector<double> costs;
  for (const planning::HeldOutSample& s : error.samples) {
    if (!(s.predicted.feasible && s.measured.feasible)) continue;
    costs.push_back(s.predicted.cost);
    costs.push_back(s.measured.cost);
  }
  // One range for both axes, so the diagonal is the line of perfect prediction.
  const auto [lo, hi] = PlotRange(costs);
  cv::Mat image(680, 700, CV_8UC3, cv::Scalar(255, 255, 255));
  const PlotAxes axes{cv::Rect(80, 70, 480, 480), lo, hi, lo, hi};
  // The title goes on a line of its own: the y label is as long as the space beside it.
  axes.Draw(image, "", "measured by the source (" + unit + ")", "predicted by the table (" + unit + ")");
  DrawText(image, title, {axes.area.x, 30}, 0.5);
  cv::line(image, axes.Map(lo, lo), axes.Map(hi, hi), grey, 1, cv::LINE_AA);
  for (const planning::HeldOutSample& s : error.samples) {
    if (s.predicted.feasible && s.measured.feasible) {
      cv::circle(image, axes.Map(s.measured.cost, s.predicted.cost), 4, blue, cv::FILLED, cv::LINE_AA);
    }
  }
  PlotLegend(image, {90, 610}, {{"held-out step (both feasible)", blue}, {"perfect prediction", grey}});
  const int x = 380;
  DrawText(image, "SMSE " + FormatShort(error.smse) + ", correlation " + FormatShort(error.correlation), {x, 614});
  DrawText(image,
           "both feasible " + FormatShort(error.both_feasible) + ", table only " + FormatShort(error.only_predicted) +
               ", source only " + FormatShort(error.only_measured) + ", neither " + FormatShort(error.neither),
           {x - 290, 644});
  return EncodePng(image, "the held-out comparison");
}

}  // namespace cairn::cli
