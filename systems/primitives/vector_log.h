#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::systems {

/// A time series of vectors of fixed size: what VectorLogSink records.
///
/// A log holds at most capacity() samples, so a long simulation logging every step fails with a message instead
/// of exhausting memory: each sample costs 8 (size() + 1) bytes.
class VectorLog {
 public:
  /// Samples a log holds unless given another capacity: 10 million (240 MB for a 2-vector).
  static constexpr int kDefaultCapacity = 10'000'000;

  /// A log of `size`-vectors holding at most `capacity` samples; throws std::invalid_argument unless
  /// size >= 0 and capacity >= 1.
  explicit VectorLog(int size = 0, int capacity = kDefaultCapacity);

  int size() const { return size_; }
  /// Most samples this log holds.
  int capacity() const { return capacity_; }
  int num_samples() const { return static_cast<int>(times_.size()); }
  /// Sample times, ascending as recorded.
  Eigen::Map<const Eigen::VectorXd> sample_times() const;
  /// size() x num_samples(): column k is the sample at sample_times()[k].
  Eigen::Map<const Eigen::MatrixXd> data() const;

  /// Appends one sample; throws std::invalid_argument if its size differs or the time is not finite, and
  /// std::runtime_error (naming the capacity and how to log less) if the log already holds capacity() samples.
  void AddData(double time, const Eigen::Ref<const Eigen::VectorXd>& value);
  void Clear();

  /// Writes "time,<names...>" and one row per sample, atomically. `column_names` may be empty (then x0, x1, ...).
  void WriteCsv(const std::string& path, const std::vector<std::string>& column_names = {}) const;

 private:
  int size_;
  int capacity_;
  std::vector<double> times_;
  std::vector<double> values_;  // Column-major, size_ per sample.
};

}  // namespace cairn::systems
