#include "cairn/systems/primitives/vector_log.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "cairn/common/atomic_file.h"
#include "cairn/common/number_text.h"

namespace cairn::systems {

VectorLog::VectorLog(int size, int capacity) : size_(size), capacity_(capacity) {
  if (size < 0) throw std::invalid_argument("VectorLog: size must be >= 0; got " + std::to_string(size) + ".");
  if (capacity < 1) {
    throw std::invalid_argument("VectorLog: capacity must be >= 1 sample; got " + std::to_string(capacity) + ".");
  }
}

Eigen::Map<const Eigen::VectorXd> VectorLog::sample_times() const {
  return Eigen::Map<const Eigen::VectorXd>(times_.data(), num_samples());
}

Eigen::Map<const Eigen::MatrixXd> VectorLog::data() const {
  return Eigen::Map<const Eigen::MatrixXd>(values_.data(), size_, num_samples());
}

void VectorLog::AddData(double time, const Eigen::Ref<const Eigen::VectorXd>& value) {
  if (value.size() != size_) {
    throw std::invalid_argument("VectorLog of size " + std::to_string(size_) + " was given a sample of size " +
                                std::to_string(value.size()) + ".");
  }
  if (!std::isfinite(time)) {
    throw std::invalid_argument("VectorLog: the sample time " + FormatShort(time) + " must be finite.");
  }
  if (num_samples() >= capacity_) {
    throw std::runtime_error("VectorLog of size " + std::to_string(size_) + " is full: it holds its capacity of " +
                             std::to_string(capacity_) + " samples (reached at t = " + FormatShort(time) +
                             "); log less often (a publish period instead of every step, or a longer one), simulate "
                             "a shorter time, or give the VectorLogSink a larger capacity.");
  }
  times_.push_back(time);
  values_.insert(values_.end(), value.data(), value.data() + value.size());
}

void VectorLog::Clear() {
  times_.clear();
  values_.clear();
}

void VectorLog::WriteCsv(const std::string& path, const std::vector<std::string>& column_names) const {
  if (!column_names.empty() && static_cast<int>(column_names.size()) != size_) {
    throw std::invalid_argument("VectorLog::WriteCsv: " + std::to_string(column_names.size()) +
                                " column names for a log of size " + std::to_string(size_) +
                                "; pass one name per element or none.");
  }
  std::string text = "time";
  for (int i = 0; i < size_; ++i) text += "," + (column_names.empty() ? "x" + std::to_string(i) : column_names[i]);
  text += "\n";
  char number[32];
  for (int k = 0; k < num_samples(); ++k) {
    // %.17g round-trips doubles exactly, so a log read back equals the one written.
    std::snprintf(number, sizeof(number), "%.17g", times_[k]);
    text += number;
    for (int i = 0; i < size_; ++i) {
      std::snprintf(number, sizeof(number), "%.17g", values_[static_cast<std::size_t>(k) * size_ + i]);
      text += ",";
      text += number;
    }
    text += "\n";
  }
  WriteFileAtomically(path, text);
}

}  // namespace cairn::systems
