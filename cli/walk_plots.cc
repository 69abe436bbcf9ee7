#include "walk_plots.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "plot_axes.h"
#include "report_drawing.h"

namespace cairn::cli {
namespace {

const cv::Scalar kBlue(200, 90, 0), kRed(0, 0, 210), kGreen(0, 140, 0), kGrey(150, 150, 150),
    kOrange(0, 140, 255);

std::vector<std::array<Eigen::Vector2d, 4>> Footholds(const planning::FootstepPlan& plan,
                                                       const planning::BipedGeometry& geometry) {
  std::vector<planning::FootPose> poses{plan.start.left, plan.start.right};
  for (const planning::PlannedStep& step : plan.steps) poses.push_back(step.pose);
  std::vector<std::array<Eigen::Vector2d, 4>> corners;
  for (const planning::FootPose& p : poses) {
    const Eigen::Vector2d c(p.x, p.y), a(std::cos(p.theta), std::sin(p.theta)), b(-a.y(), a.x());
    const double l = 0.5 * geometry.foot_length, w = 0.5 * geometry.foot_width;
    corners.push_back({c + l * a + w * b, c - l * a + w * b, c - l * a - w * b, c + l * a - w * b});
  }
  return corners;
}

}  // namespace

std::string WalkZmpPng(const planning::WalkRecord& record, const planning::BipedGeometry& geometry) {
  const auto feet = Footholds(record.plan, geometry);
  std::vector<double> xs, ys;
  for (const auto& foot : feet) {
    for (const Eigen::Vector2d& c : foot) {
      xs.push_back(c.x());
      ys.push_back(c.y());
    }
  }
  std::vector<Eigen::Vector2d> zmp_ref(record.reference.zmp_reference), zmp, com;
  for (const planning::WalkSample& s : record.samples) {
    zmp.emplace_back(s.zmp.x(), s.zmp.y());
    com.emplace_back(s.com.x(), s.com.y());
  }
  for (const auto* series : {&zmp_ref, &zmp, &com}) {
    for (const Eigen::Vector2d& p : *series) {
      if (!p.allFinite() || p.cwiseAbs().maxCoeff() > 1e3) continue;
      xs.push_back(p.x());
      ys.push_back(p.y());
    }
  }
  auto [x0, x1] = PlotRange(xs);
  auto [y0, y1] = PlotRange(ys);
  // Equal scales on both axes: widen the narrower range.
  const int width = 1000, left = 70, top = 50;
  const double scale = std::min(880.0 / (x1 - x0), 500.0 / (y1 - y0));
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  x0 = cx - 440.0 / scale;
  x1 = cx + 440.0 / scale;
  y0 = cy - 250.0 / scale;
  y1 = cy + 250.0 / scale;
  cv::Mat image(top + 500 + 130, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const PlotAxes axes{cv::Rect(left, top, 880, 500), x0, x1, y0, y1};
  axes.Draw(image, "ZMP and COM, top view (footholds of the plan in grey)", "x [m]", "y [m]");
  for (const auto& foot : feet) {
    std::vector<cv::Point> polygon;
    for (const Eigen::Vector2d& c : foot) polygon.push_back(axes.Map(c.x(), c.y()));
    cv::polylines(image, polygon, true, kGrey, 1, cv::LINE_AA);
  }
  PlotPolyline(image, axes, zmp_ref, kBlue, 2);
  for (const Eigen::Vector2d& p : zmp) {
    if (p.allFinite()) cv::circle(image, axes.Map(p.x(), p.y()), 1, kRed, cv::FILLED);
  }
  PlotPolyline(image, axes, com, kGreen, 1);
  PlotLegend(image, {left + 10, top + 500 + 60},
         {{"reference ZMP (stabiliser)", kBlue}, {"measured ZMP (plant)", kRed}, {"measured COM", kGreen},
          {"planned footholds", kGrey}});
  return EncodePng(image, "the walk's plot");
}

std::string WalkComPng(const planning::WalkRecord& record) {
  const int width = 1000, left = 70, panel = 240;
  cv::Mat image(2 * panel + 190, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const double period = record.reference.period;
  const double t_end = std::max({record.duration, record.reference.duration(), 1e-3});
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<Eigen::Vector2d> reference, measured;
    std::vector<double> values;
    for (std::size_t k = 0; k < record.reference.com.size(); ++k) {
      reference.emplace_back(period * static_cast<double>(k), record.reference.com[k][axis]);
      values.push_back(record.reference.com[k][axis]);
    }
    for (const planning::WalkSample& s : record.samples) {
      measured.emplace_back(s.time, s.com[axis]);
      values.push_back(s.com[axis]);
    }
    const auto [y0, y1] = PlotRange(values);
    const PlotAxes axes{cv::Rect(left, 40 + axis * (panel + 60), 880, panel), 0.0, t_end, y0, y1};
    axes.Draw(image, axis == 0 ? "COM x against time" : "COM y against time", "time [s]",
              axis == 0 ? "x [m]" : "y [m]");
    PlotPolyline(image, axes, reference, kBlue, 2);
    PlotPolyline(image, axes, measured, kRed, 1);
  }
  PlotLegend(image, {left + 10, 2 * panel + 150}, {{"stabilised reference", kBlue}, {"plant", kRed}});
  return EncodePng(image, "the walk's plot");
}

std::string WalkStepsPng(const std::vector<WalkStepComparison>& steps) {
  const int width = 1000, left = 70, panel = 240;
  cv::Mat image(2 * panel + 190, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const int n = std::max<int>(1, static_cast<int>(steps.size()));
  struct Series {
    std::string label;
    cv::Scalar colour;
    std::vector<double> values;
  };
  const auto panel_plot = [&](int row, const std::string& title, const std::string& unit,
                              const std::vector<Series>& series) {
    std::vector<double> all{0.0};
    for (const Series& s : series) all.insert(all.end(), s.values.begin(), s.values.end());
    const auto [lo, hi] = PlotRange(all);
    const PlotAxes axes{cv::Rect(left, 40 + row * (panel + 60), 880, panel), 0.5, n + 0.5, std::min(0.0, lo), hi, true};
    axes.Draw(image, title, "step", unit);
    const double bar = 0.8 / static_cast<double>(series.size());
    for (std::size_t s = 0; s < series.size(); ++s) {
      for (std::size_t k = 0; k < series[s].values.size(); ++k) {
        const double v = series[s].values[k];
        if (!std::isfinite(v)) continue;
        const double x = static_cast<double>(k + 1) - 0.4 + bar * static_cast<double>(s);
        cv::rectangle(image, axes.Map(x, 0.0), axes.Map(x + bar, v), series[s].colour, cv::FILLED);
      }
    }
    PlotLegend(image, {left + 700, 40 + row * (panel + 60) + 14}, [&] {
      std::vector<std::pair<std::string, cv::Scalar>> entries;
      for (const Series& s : series) entries.emplace_back(s.label, s.colour);
      return entries;
    }());
  };
  Series rcof_p{"predicted RCOF", kBlue, {}}, rcof_m{"measured RCOF (support sole)", kRed, {}},
      rcof_net{"measured RCOF (net force)", kGreen, {}}, mu{"mu allowed", kGrey, {}};
  Series e_p{"predicted E_COM + heat", kBlue, {}}, e_m{"measured E_ele", kRed, {}},
      ecom_p{"predicted E_COM", kOrange, {}}, ecom_m{"measured E_COM", kGreen, {}};
  for (const WalkStepComparison& s : steps) {
    rcof_p.values.push_back(s.predicted_rcof);
    rcof_m.values.push_back(s.measured_rcof);
    rcof_net.values.push_back(s.measured_net_rcof);
    mu.values.push_back(s.mu_allowed);
    e_p.values.push_back(s.predicted_com_work + s.predicted_heat);
    e_m.values.push_back(s.measured_electrical_energy);
    ecom_p.values.push_back(s.predicted_com_work);
    ecom_m.values.push_back(s.measured_com_energy);
  }
  panel_plot(0, "RCOF per step: planner's prediction, plant's measurements, allowed friction", "RCOF",
             {rcof_p, rcof_net, rcof_m, mu});
  panel_plot(1, "Energy per step (missing bars: the step was not completed)", "J", {ecom_p, ecom_m, e_p, e_m});
  return EncodePng(image, "the walk's plot");
}

}  // namespace cairn::cli
