#pragma once

#include <cstdint>
#include <memory>

#include "cairn/systems/framework/abstract_value.h"

namespace cairn::systems {

/// The per-context storage of one cached computation (an output port or a declared cache entry): the value,
/// whether it is up to date, and how many times it has been computed (tests use the count to prove caching).
class CacheEntryValue {
 public:
  CacheEntryValue() = default;
  explicit CacheEntryValue(std::unique_ptr<AbstractValue> value) : value_(std::move(value)) {}

  bool has_value() const { return value_ != nullptr; }
  bool is_up_to_date() const { return up_to_date_; }
  void mark_up_to_date() { up_to_date_ = true; }
  void mark_out_of_date() { up_to_date_ = false; }

  const AbstractValue& value() const { return *value_; }
  AbstractValue& mutable_value() { return *value_; }

  /// Number of times the value has been (re)computed in this context.
  int64_t num_calculations() const { return num_calculations_; }
  void count_calculation() { ++num_calculations_; }

  /// Copies `other`'s value, validity and count (for cloning contexts).
  void SetFrom(const CacheEntryValue& other) {
    value_->SetFrom(*other.value_);
    up_to_date_ = other.up_to_date_;
    num_calculations_ = other.num_calculations_;
  }

 private:
  std::unique_ptr<AbstractValue> value_;
  bool up_to_date_{false};
  int64_t num_calculations_{0};
};

}  // namespace cairn::systems
