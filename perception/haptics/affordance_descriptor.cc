#include "cairn/perception/haptics/affordance_descriptor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception {
namespace {

void CheckBins(long long bins, const char* what) {
  if (bins < 1 || bins > AffordanceDescriptor::kMaxBins) {
    throw std::invalid_argument(std::string(what) + " is " + FormatShort(bins) + "; it must be between 1 and " +
                                FormatShort(AffordanceDescriptor::kMaxBins));
  }
}

}  // namespace

AffordanceDescriptor::AffordanceDescriptor(int lines) {
  CheckBins(lines, "the number of descriptor lines");
  values_ = Eigen::VectorXd::Zero(4 * lines);
}

AffordanceDescriptor AffordanceDescriptor::FromValues(const Eigen::VectorXd& values) {
  if (values.size() == 0 || values.size() % 4 != 0 || values.size() > 4 * kMaxBins) {
    throw std::invalid_argument("a descriptor has 4 values (n, s, d, m) per line and at most " +
                                FormatShort(kMaxBins) + " lines; got " +
                                FormatShort(static_cast<long long>(values.size())) + " values");
  }
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (!(values[i] >= 0.0) || !std::isfinite(values[i])) {
      throw std::invalid_argument("descriptor value " + FormatShort(static_cast<long long>(i)) + " is " +
                                  FormatShort(values[i]) + "; every value must be a non-negative, finite number");
    }
  }
  AffordanceDescriptor result(static_cast<int>(values.size() / 4));
  result.values_ = values;
  return result;
}

AffordanceDescriptor AffordanceDescriptor::FromHistogram(const Eigen::MatrixXi& histogram) {
  CheckBins(static_cast<long long>(histogram.rows()), "the number of histogram lines");
  CheckBins(static_cast<long long>(histogram.cols()), "the number of histogram columns");
  if (histogram.minCoeff() < 0) {
    throw std::invalid_argument("the histogram holds the count " + FormatShort(histogram.minCoeff()) +
                                "; bin counts cannot be negative");
  }
  AffordanceDescriptor result(static_cast<int>(histogram.rows()));
  for (Eigen::Index l = 0; l < histogram.rows(); ++l) {
    int clusters = 0;
    int largest_size = 0;
    double largest_points = 0.0;
    double line_points = 0.0;
    int run_size = 0;
    double run_points = 0.0;
    for (Eigen::Index c = 0; c <= histogram.cols(); ++c) {
      const int count = c < histogram.cols() ? histogram(l, c) : 0;  // a virtual empty bin closes the last run
      if (count > 0) {
        if (run_size == 0) ++clusters;
        ++run_size;
        run_points += count;
        line_points += count;
      } else if (run_size > 0) {
        largest_size = std::max(largest_size, run_size);
        largest_points = std::max(largest_points, run_points);
        run_size = 0;
        run_points = 0.0;
      }
    }
    result.values_[4 * l] = clusters;
    result.values_[4 * l + 1] = largest_size;
    result.values_[4 * l + 2] = line_points / static_cast<double>(histogram.cols());
    result.values_[4 * l + 3] = largest_points;
  }
  return result;
}

void AffordanceDescriptor::Validate(const Options& options) {
  if (!(options.min_point_distance > 0.0) || !std::isfinite(options.min_point_distance)) {
    throw std::invalid_argument("min_point_distance is " + FormatShort(options.min_point_distance) +
                                " m; it must be a positive, finite length (the paper uses 0.01)");
  }
  if (!(options.reach_radius > 0.0) || !std::isfinite(options.reach_radius)) {
    throw std::invalid_argument("reach_radius is " + FormatShort(options.reach_radius) +
                                " m; it must be a positive, finite length (the antenna reaches 1 m)");
  }
  if (!options.reach_center_C.allFinite()) throw std::invalid_argument("reach_center_C is not finite");
  CheckBins(options.columns, "columns");
  CheckBins(options.lines, "lines");
  if (options.window_C) {
    const Eigen::AlignedBox2d& w = *options.window_C;
    if (!w.min().allFinite() || !w.max().allFinite() || !(w.min().x() < w.max().x()) ||
        !(w.min().y() < w.max().y())) {
      throw std::invalid_argument("window_C [" + FormatShort(w.min().x()) + ", " + FormatShort(w.max().x()) +
                                  "] x [" + FormatShort(w.min().y()) + ", " + FormatShort(w.max().y()) +
                                  "] must be finite with min < max on both axes");
    }
  }
}

Eigen::MatrixXi AffordanceDescriptor::Histogram(const Eigen::Matrix3Xd& points_C, const Options& options) {
  Validate(options);
  const Eigen::Matrix3Xd reached =
      KeepWithinReach(DownsampleByMinDistance(points_C, options.min_point_distance), options.reach_center_C,
                      options.reach_radius);
  Eigen::MatrixXi histogram = Eigen::MatrixXi::Zero(options.lines, options.columns);
  if (reached.cols() == 0) return histogram;
  Eigen::Vector2d lo;
  Eigen::Vector2d hi;
  if (options.window_C) {
    lo = options.window_C->min();
    hi = options.window_C->max();
  } else {
    lo = reached.topRows<2>().rowwise().minCoeff();
    hi = reached.topRows<2>().rowwise().maxCoeff();
  }
  const Eigen::Vector2d extent = hi - lo;
  const auto bin = [](double v, double low, double size, int bins) {
    // A flat extent (one column of points) puts everything in the first bin; the far edge belongs to the last.
    if (!(size > 0.0)) return 0;
    return std::min(bins - 1, static_cast<int>(std::floor((v - low) / size * bins)));
  };
  for (Eigen::Index i = 0; i < reached.cols(); ++i) {
    const double x = reached(0, i);
    const double y = reached(1, i);
    if (x < lo.x() || x > hi.x() || y < lo.y() || y > hi.y()) continue;
    ++histogram(bin(y, lo.y(), extent.y(), options.lines), bin(x, lo.x(), extent.x(), options.columns));
  }
  return histogram;
}

AffordanceDescriptor AffordanceDescriptor::Compute(const Eigen::Matrix3Xd& points_C, const Options& options) {
  return FromHistogram(Histogram(points_C, options));
}

}  // namespace cairn::perception
