#pragma once

#include <memory>
#include <string>

#include "cairn/systems/framework/context.h"
#include "cairn/systems/framework/dependency_ticket.h"
#include "cairn/systems/framework/port_data_type.h"
#include "cairn/systems/framework/value.h"

namespace cairn::systems {

class System;

/// An output port of a system. Eval() returns the cached value (computing it when a prerequisite changed);
/// Calc() always computes into caller-owned storage.
class OutputPort {
 public:
  OutputPort(const OutputPort&) = delete;
  OutputPort& operator=(const OutputPort&) = delete;

  const std::string& get_name() const { return name_; }
  int get_index() const { return index_; }
  PortDataType get_data_type() const { return data_type_; }
  /// Size of a vector port (0 for abstract ports).
  int size() const { return size_; }
  const System& get_system() const { return *system_; }

  /// The cached value as a T (for vector ports, T = Eigen::VectorXd); throws if T is not the port's type.
  template <typename T>
  const T& Eval(const Context& context) const {
    const AbstractValue& value = EvalAbstract(context);
    if (value.type_info() != typeid(T)) ThrowTypeMismatch(typeid(T));
    return static_cast<const Value<T>&>(value).get();
  }
  const AbstractValue& EvalAbstract(const Context& context) const;

  /// Computes the value into `value` (from Allocate()), bypassing the cache.
  void Calc(const Context& context, AbstractValue* value) const;
  /// Storage for Calc().
  std::unique_ptr<AbstractValue> Allocate() const { return model_value_->Clone(); }

  const AbstractValue& model_value() const { return *model_value_; }

  /// "output port 'y' of system '::diagram::plant'".
  std::string GetFullDescription() const;
  /// "vector of size 3" or "abstract value of type Foo".
  std::string GetTypeDescription() const;

 private:
  friend class System;
  [[noreturn]] void ThrowTypeMismatch(const std::type_info& requested) const;
  OutputPort(const System* system, int index, std::string name, PortDataType data_type, int size,
             std::unique_ptr<AbstractValue> model_value);

  const System* system_;
  int index_;
  std::string name_;
  PortDataType data_type_;
  int size_;
  std::unique_ptr<AbstractValue> model_value_;
};

}  // namespace cairn::systems
