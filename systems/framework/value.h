#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>

#include "cairn/common/nice_type_name.h"
#include "cairn/systems/framework/abstract_value.h"

namespace cairn::systems {

/// Holds a value of type T behind the AbstractValue interface. T may be any copyable type, or a move-only type
/// (then Clone() and SetFrom() throw, so contexts holding it cannot be cloned).
template <typename T>
class Value final : public AbstractValue {
  static_assert(std::is_same_v<T, std::decay_t<T>>, "Value<T> needs a plain (non-reference, non-const) type.");
  static_assert(!std::is_base_of_v<AbstractValue, T>, "Value<AbstractValue> is not allowed.");

 public:
  Value() : value_() {}
  explicit Value(const T& value) : value_(value) {}
  explicit Value(T&& value) : value_(std::move(value)) {}

  std::unique_ptr<AbstractValue> Clone() const override {
    if constexpr (std::is_copy_constructible_v<T>) {
      return std::make_unique<Value<T>>(value_);
    } else {
      throw std::logic_error("Cannot clone a Value<" + NiceTypeName<T>() +
                             ">: the type is move-only. Give it a copy constructor to clone contexts holding it.");
    }
  }

  void SetFrom(const AbstractValue& other) override {
    if constexpr (std::is_copy_assignable_v<T>) {
      value_ = other.get_value<T>();
    } else {
      throw std::logic_error("Cannot copy into a Value<" + NiceTypeName<T>() + ">: the type is not copy-assignable.");
    }
  }

  const std::type_info& type_info() const override { return typeid(T); }

  const T& get() const { return value_; }
  T& get_mutable() { return value_; }

 private:
  T value_;
};

template <typename T>
const T& AbstractValue::get_value() const {
  if (type_info() != typeid(T)) ThrowTypeMismatch(typeid(T));
  return static_cast<const Value<T>*>(this)->get();
}

template <typename T>
T& AbstractValue::get_mutable_value() {
  if (type_info() != typeid(T)) ThrowTypeMismatch(typeid(T));
  return static_cast<Value<T>*>(this)->get_mutable();
}

template <typename T>
void AbstractValue::set_value(const T& value) {
  get_mutable_value<T>() = value;
}

template <typename T>
std::unique_ptr<AbstractValue> AbstractValue::Make(const T& value) {
  return std::make_unique<Value<T>>(value);
}

}  // namespace cairn::systems
