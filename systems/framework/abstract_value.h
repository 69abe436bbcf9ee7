#pragma once

#include <memory>
#include <string>
#include <typeinfo>

namespace cairn::systems {

template <typename T>
class Value;

/// A type-erased value: what abstract ports, abstract state and abstract parameters hold. The concrete type is
/// Value<T>; get_value<T>() checks the type and names both types when they differ.
///
/// Include value.h to use the templated accessors.
class AbstractValue {
 public:
  virtual ~AbstractValue();
  AbstractValue(const AbstractValue&) = delete;
  AbstractValue& operator=(const AbstractValue&) = delete;

  /// Returns a copy. Throws std::logic_error for a move-only T (a context holding one cannot be cloned).
  virtual std::unique_ptr<AbstractValue> Clone() const = 0;

  /// Copies `other`'s value into this one; throws std::logic_error if the types differ or T is move-only.
  virtual void SetFrom(const AbstractValue& other) = 0;

  /// The std::type_info of T.
  virtual const std::type_info& type_info() const = 0;

  /// The demangled name of T, for messages.
  std::string GetNiceTypeName() const;

  /// Returns the value as a T; throws std::logic_error naming both types when this holds another type.
  template <typename T>
  const T& get_value() const;

  /// Returns the value as a mutable T; throws std::logic_error naming both types when this holds another type.
  template <typename T>
  T& get_mutable_value();

  /// Sets the value; throws std::logic_error naming both types when this holds another type.
  template <typename T>
  void set_value(const T& value);

  /// Makes a Value<T> holding `value`.
  template <typename T>
  static std::unique_ptr<AbstractValue> Make(const T& value = T{});

 protected:
  AbstractValue() = default;

 private:
  [[noreturn]] void ThrowTypeMismatch(const std::type_info& requested) const;
};

}  // namespace cairn::systems
