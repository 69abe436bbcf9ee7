#pragma once

#include <string>

namespace cairn::cli {

/// The values a numeric command-line option accepts: an interval of finite numbers (each end open or closed),
/// optionally odd integers only. It both checks values and states itself in messages and --help, so the range a
/// user reads is the range that is enforced.
class NumberRange {
 public:
  /// lower <= x <= upper.
  static NumberRange Closed(double lower, double upper);
  /// lower < x <= upper.
  static NumberRange AboveAtMost(double lower, double upper);
  /// lower < x < upper.
  static NumberRange Open(double lower, double upper);

  /// The same range, odd integers only (e.g. a window whose pixel sits at its centre).
  NumberRange OddOnly() const;

  /// Whether the finite value `x` is in the range (and odd, if OddOnly()).
  bool Contains(double x) const;

  /// The range in words, for messages: "a number greater than 0 and at most 10000", "an integer from 1 to 20",
  /// "an odd integer from 1 to 2051". `integer` picks the wording and the exact formatting of integer bounds.
  std::string Describe(bool integer) const;

  double lower() const { return lower_; }
  bool odd_only() const { return odd_only_; }
  double upper() const { return upper_; }

 private:
  NumberRange(double lower, bool lower_open, double upper, bool upper_open);

  double lower_;
  bool lower_open_;
  double upper_;
  bool upper_open_;
  bool odd_only_{false};
};

}  // namespace cairn::cli
