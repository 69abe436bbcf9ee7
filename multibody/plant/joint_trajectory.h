#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>

namespace cairn::multibody {

/// A joint-space reference trajectory for the plant's PD control, read from a CSV file: the header is `time`
/// followed by joint names of the model, each row a time (s) and those joints' angles (rad). Between rows the
/// angles are interpolated linearly (the reference velocity is the slope); before the first row and after the
/// last the angles are held with zero velocity; joints not in the file keep the base configuration's values.
class JointTrajectory {
 public:
  /// Largest file read (bytes) and most rows, checked before the file is parsed.
  static constexpr long long kMaxFileBytes = 64LL << 20;
  static constexpr std::size_t kMaxRows = 1000000;

  /// Reads `path` for `model`. Throws std::invalid_argument naming the file and the line for: a missing or
  /// unreadable file, a file over kMaxFileBytes or with more than kMaxRows rows, a header that does not start with
  /// `time` or names an unknown, repeated or non-revolute/prismatic joint, a row with the wrong number of fields or
  /// a field that is not a finite number, times not strictly increasing or negative, an angle outside the joint's
  /// URDF limits.
  static JointTrajectory LoadCsv(const Model& model, const std::string& path);

  /// The reference (q, v) at time t: `q_base` (size nq) with the file's joints set; v of size nv.
  void Evaluate(double t, const Eigen::VectorXd& q_base, Eigen::VectorXd* q, Eigen::VectorXd* v) const;

  /// Time of the last row (s).
  double end_time() const { return times_.back(); }
  /// Number of rows.
  std::size_t num_rows() const { return times_.size(); }

 private:
  JointTrajectory() = default;

  int nv_ = 0;
  std::vector<int> q_index_;
  std::vector<int> v_index_;
  std::vector<double> times_;
  std::vector<Eigen::VectorXd> values_;  // one per row, the file's joints in header order
};

}  // namespace cairn::multibody
