#include "abstract_values.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/nice_type_name.h"

namespace cairn::python {

using systems::AbstractValue;
using systems::Value;

// ---------------------------------------------------------------------------------------------------------------
// PythonObject

PythonObject::PythonObject() {
  py::gil_scoped_acquire gil;
  object_ = py::none();
}

PythonObject::PythonObject(py::object object) : object_(std::move(object)) {}

namespace {
py::object DeepCopy(const py::object& object) {
  py::gil_scoped_acquire gil;
  try {
    return py::module_::import("copy").attr("deepcopy")(object);
  } catch (py::error_already_set& e) {
    throw std::runtime_error("cairn: a Python value held by a context could not be copied (copy.deepcopy failed: " +
                             std::string(e.what()) +
                             "); abstract values, states and parameters holding Python objects must be "
                             "deep-copyable.");
  }
}
}  // namespace

PythonObject::PythonObject(const PythonObject& other) : object_(DeepCopy(other.object_)) {}

PythonObject::PythonObject(PythonObject&& other) noexcept : object_(std::move(other.object_)) {}

PythonObject& PythonObject::operator=(const PythonObject& other) {
  if (this != &other) {
    py::object copy = DeepCopy(other.object_);
    py::gil_scoped_acquire gil;
    object_ = std::move(copy);
  }
  return *this;
}

PythonObject& PythonObject::operator=(PythonObject&& other) noexcept {
  if (this != &other) {
    py::gil_scoped_acquire gil;
    object_ = std::move(other.object_);
  }
  return *this;
}

PythonObject::~PythonObject() {
  if (!object_) return;
  if (Py_IsInitialized() == 0) {
    object_.release();
    return;
  }
  py::gil_scoped_acquire gil;
  object_ = py::object();
}

// ---------------------------------------------------------------------------------------------------------------
// Registry

namespace {

std::vector<AbstractValueType>& Registry() {
  static auto* registry = new std::vector<AbstractValueType>();  // Never destroyed: it holds Python handles.
  return *registry;
}

std::string PythonTypeName(py::handle object) {
  return py::str(py::type::handle_of(object).attr("__qualname__"));
}

// The registered type's name if any, else the demangled C++ name.
std::string DescribeCppType(const std::type_info& type) {
  if (const AbstractValueType* found = FindAbstractValueType(type)) return found->name;
  if (type == typeid(PythonObject)) return "Python object";
  return NiceTypeName(type);
}

}  // namespace

void RegisterAbstractValueType(AbstractValueType type) {
  for (const AbstractValueType& existing : Registry()) {
    if (existing.type == type.type || existing.name == type.name) {
      throw std::logic_error("cairn: abstract value type '" + type.name + "' registered twice");
    }
  }
  Registry().push_back(std::move(type));
}

const std::vector<AbstractValueType>& RegisteredAbstractValueTypes() { return Registry(); }

const AbstractValueType* FindAbstractValueType(const std::type_info& type) {
  const std::type_index index(type);
  for (const AbstractValueType& registered : Registry()) {
    if (registered.type == index) return &registered;
  }
  return nullptr;
}

py::object AbstractValueToPython(const AbstractValue& value, bool copy, py::handle owner) {
  if (value.type_info() == typeid(PythonObject)) return value.get_value<PythonObject>().get();
  const AbstractValueType* type = FindAbstractValueType(value.type_info());
  if (type == nullptr) {
    throw py::type_error("cairn: no Python conversion for values of C++ type " + value.GetNiceTypeName() +
                         "; it is not among the types the bindings register (see AbstractValue.registered_types())");
  }
  return type->to_python(value, copy, owner);
}

std::unique_ptr<AbstractValue> AbstractValueFromPython(py::handle object, const AbstractValue& model,
                                                       const std::string& what) {
  if (py::isinstance<AbstractValue>(object)) {
    const auto& given = object.cast<const AbstractValue&>();
    if (given.type_info() != model.type_info()) {
      throw py::type_error(what + " holds values of type " + DescribeCppType(model.type_info()) +
                           ", but an AbstractValue of type " + DescribeCppType(given.type_info()) + " was given");
    }
    return given.Clone();
  }
  if (model.type_info() == typeid(PythonObject)) {
    return std::make_unique<Value<PythonObject>>(PythonObject(py::reinterpret_borrow<py::object>(object)));
  }
  const AbstractValueType* type = FindAbstractValueType(model.type_info());
  if (type == nullptr) {
    throw py::type_error(what + " holds values of C++ type " + model.GetNiceTypeName() +
                         ", which the Python bindings cannot convert to");
  }
  try {
    return type->from_python(object);
  } catch (const py::cast_error&) {
    throw py::type_error(what + " holds values of type " + type->name + "; a " + PythonTypeName(object) +
                         " cannot be converted to it");
  }
}

void AssignAbstractValueFromPython(py::handle object, AbstractValue* destination, const std::string& what) {
  if (destination->type_info() == typeid(PythonObject)) {
    destination->get_mutable_value<PythonObject>().set(py::reinterpret_borrow<py::object>(object));
    return;
  }
  std::unique_ptr<AbstractValue> converted = AbstractValueFromPython(object, *destination, what);
  destination->SetFrom(*converted);
}

std::unique_ptr<AbstractValue> MakeAbstractValue(py::handle object, const std::string& type_name) {
  if (!type_name.empty()) {
    if (type_name == "object") {
      return std::make_unique<Value<PythonObject>>(PythonObject(py::reinterpret_borrow<py::object>(object)));
    }
    std::string known = "object";
    for (const AbstractValueType& type : Registry()) {
      if (type.name == type_name) {
        try {
          return type.from_python(object);
        } catch (const py::cast_error&) {
          throw py::type_error("AbstractValue.Make: a " + PythonTypeName(object) +
                               " cannot be converted to type '" + type_name + "'");
        }
      }
      known += ", " + type.name;
    }
    throw py::value_error("AbstractValue.Make: unknown type '" + type_name + "'; known types: " + known);
  }
  if (py::isinstance<AbstractValue>(object)) return object.cast<const AbstractValue&>().Clone();
  for (const AbstractValueType& type : Registry()) {
    if (type.python_type && py::isinstance(object, type.python_type)) return type.from_python(object);
  }
  return std::make_unique<Value<PythonObject>>(PythonObject(py::reinterpret_borrow<py::object>(object)));
}

std::unique_ptr<AbstractValue> ModelValueFromPython(py::handle object) { return MakeAbstractValue(object); }

}  // namespace cairn::python
