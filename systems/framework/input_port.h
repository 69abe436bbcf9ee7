#pragma once

#include <memory>
#include <string>
#include <type_traits>

#include <Eigen/Core>

#include "cairn/systems/framework/context.h"
#include "cairn/systems/framework/dependency_ticket.h"
#include "cairn/systems/framework/port_data_type.h"
#include "cairn/systems/framework/value.h"

namespace cairn::systems {

class System;

/// An input port of a system. Its value comes from the output it is connected to in a diagram, from the diagram
/// input it is exported as, or from a value fixed in the context (FixValue, mostly for tests of one system).
///
/// Vector ports carry Eigen::VectorXd of the declared size(); abstract ports carry the declared C++ type.
class InputPort {
 public:
  InputPort(const InputPort&) = delete;
  InputPort& operator=(const InputPort&) = delete;

  const std::string& get_name() const { return name_; }
  int get_index() const { return index_; }
  PortDataType get_data_type() const { return data_type_; }
  /// Size of a vector port (0 for abstract ports).
  int size() const { return size_; }
  const System& get_system() const { return *system_; }
  DependencyTicket ticket() const { return ticket_; }

  /// Returns the port's value as a T (for vector ports, T = Eigen::VectorXd). Pulls from upstream, computing
  /// (and caching) what is out of date. Throws if the port has no value or T is not the port's type.
  template <typename T>
  const T& Eval(const Context& context) const {
    const AbstractValue& value = EvalAbstract(context);
    if (value.type_info() != typeid(T)) ThrowTypeMismatch(typeid(T));
    return static_cast<const Value<T>&>(value).get();
  }
  const AbstractValue& EvalAbstract(const Context& context) const;

  /// True if the port is connected, exported or fixed in `context`.
  bool HasValue(const Context& context) const;

  /// Fixes the port's value in `context` (the port must be neither connected nor exported there). For vector
  /// ports pass any Eigen vector of the declared size; for abstract ports, a value of the declared type.
  template <typename T>
  void FixValue(Context* context, const T& value) const {
    if constexpr (std::is_base_of_v<Eigen::EigenBase<T>, T>) {
      FixAbstractValue(context, Value<Eigen::VectorXd>(Eigen::VectorXd(value)));
    } else if constexpr (std::is_base_of_v<AbstractValue, T>) {
      FixAbstractValue(context, value);
    } else {
      FixAbstractValue(context, Value<T>(value));
    }
  }
  /// Fixes a string-literal value as std::string.
  void FixValue(Context* context, const char* value) const { FixValue(context, std::string(value)); }
  void FixAbstractValue(Context* context, const AbstractValue& value) const;

  /// A model value of the port's type (a zero vector of size() for vector ports).
  const AbstractValue& model_value() const { return *model_value_; }

  /// "input port 'u' of system '::diagram::plant'".
  std::string GetFullDescription() const;
  /// "vector of size 3" or "abstract value of type Foo".
  std::string GetTypeDescription() const;

  /// Throws std::invalid_argument (naming the port and both types) unless `value` can be this port's value.
  void ValidateValue(const AbstractValue& value) const;

 private:
  friend class System;
  [[noreturn]] void ThrowTypeMismatch(const std::type_info& requested) const;
  InputPort(const System* system, int index, std::string name, PortDataType data_type, int size,
            std::unique_ptr<AbstractValue> model_value, DependencyTicket ticket);

  const System* system_;
  int index_;
  std::string name_;
  PortDataType data_type_;
  int size_;
  std::unique_ptr<AbstractValue> model_value_;
  DependencyTicket ticket_;
};

}  // namespace cairn::systems
