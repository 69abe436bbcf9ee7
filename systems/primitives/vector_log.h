#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::systems {

/// A time series of vectors of fixed size: what VectorLogSink records.
class VectorLog {
 public:
  explicit VectorLog(int size = 0) : size_(size) {}

  int size() const { return size_; }
  int num_samples() const { return static_cast<int>(times_.size()); }
  /// Sample times, ascending as recorded.
  Eigen::Map<const Eigen::VectorXd> sample_times() const;
  /// size() x num_samples(): column k is the sample at sample_times()[k].
  Eigen::Map<const Eigen::MatrixXd> data() const;

  /// Appends one sample; throws std::invalid_argument if its size differs.
  void AddData(double time, const Eigen::Ref<const Eigen::VectorXd>& value);
  void Clear();

  /// Writes "time,<names...>" and one row per sample, atomically. `column_names` may be empty (then x0, x1, ...).
  void WriteCsv(const std::string& path, const std::vector<std::string>& column_names = {}) const;

 private:
  int size_;
  std::vector<double> times_;
  std::vector<double> values_;  // Column-major, size_ per sample.
};

}  // namespace cairn::systems
