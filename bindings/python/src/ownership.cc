#include "ownership.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <vector>

namespace cairn::python {
namespace {

py::dict InstanceDict(py::handle object) {
  PyObject** dict = _PyObject_GetDictPtr(object.ptr());
  if (dict == nullptr) {
    throw std::logic_error("cairn: " + std::string(py::str(py::type::handle_of(object).attr("__name__"))) +
                           " objects have no instance dictionary (bind the class with py::dynamic_attr)");
  }
  if (*dict == nullptr) *dict = PyDict_New();
  return py::reinterpret_borrow<py::dict>(*dict);
}

}  // namespace

bool PythonOwnsCppObject(py::handle object) {
  auto* instance = reinterpret_cast<py::detail::instance*>(object.ptr());
  const py::detail::value_and_holder holder = instance->get_value_and_holder();
  return instance->owned && holder.holder_constructed();
}

namespace internal {

void DisownHolder(py::handle object, const std::string& what) {
  if (!PythonOwnsCppObject(object)) {
    throw py::value_error(what + ": the " + std::string(py::str(py::type::handle_of(object).attr("__name__"))) +
                          " already belongs to a DiagramBuilder or Diagram; a system can be added to one builder "
                          "only. Create a separate instance for each diagram.");
  }
  auto* instance = reinterpret_cast<py::detail::instance*>(object.ptr());
  py::detail::value_and_holder holder = instance->get_value_and_holder();
  // Every class that may be passed here is bound with std::unique_ptr<Class> (the default holder), and a
  // std::unique_ptr with the default deleter is one pointer whatever its pointee: releasing it through
  // std::unique_ptr<char> storage leaves the object alive. Python keeps the instance registered (its methods still
  // reach the C++ object), but no longer deletes it.
  using AnyUniquePtr = std::unique_ptr<char>;
  static_cast<void>(holder.holder<AnyUniquePtr>().release());
  holder.holder<AnyUniquePtr>().~AnyUniquePtr();
  holder.set_holder_constructed(false);
  instance->owned = false;
}

}  // namespace internal

#if PY_VERSION_HEX >= 0x030B0000 && PY_VERSION_HEX < 0x030C0000
extern "C" int CairnDynamicAttributeTraverse(PyObject* self, visitproc visit, void* arg) {
  // Only for the bound class itself: a Python subclass's tp_traverse (CPython's subtype_traverse) has visited the
  // managed dictionary before calling this one.
  if (Py_TYPE(self)->tp_traverse == &CairnDynamicAttributeTraverse) {
    PyObject** dict = _PyObject_GetDictPtr(self);
    if (dict != nullptr) Py_VISIT(*dict);
  }
  Py_VISIT(Py_TYPE(self));
  return 0;
}

namespace {
void FixTypes(py::handle scope, std::vector<PyObject*>* seen) {
  for (py::handle item : scope.attr("__dict__").attr("values")()) {
    if (std::find(seen->begin(), seen->end(), item.ptr()) != seen->end()) continue;
    if (PyType_Check(item.ptr())) {
      seen->push_back(item.ptr());
      auto* type = reinterpret_cast<PyTypeObject*>(item.ptr());
      if (type->tp_traverse == &py::detail::pybind11_traverse) type->tp_traverse = &CairnDynamicAttributeTraverse;
      FixTypes(item, seen);  // nested classes (Options, enums)
    } else if (PyModule_Check(item.ptr())) {
      seen->push_back(item.ptr());
      FixTypes(item, seen);
    }
  }
}
}  // namespace

void FixDynamicAttributeTraversal(py::module_ module) {
  std::vector<PyObject*> seen;
  FixTypes(module, &seen);
}
#else
void FixDynamicAttributeTraversal(py::module_) {}
#endif

void Adopt(py::handle owner, py::handle child) {
  py::dict owner_dict = InstanceDict(owner);
  if (!owner_dict.contains("_cairn_owned")) owner_dict["_cairn_owned"] = py::list();
  owner_dict["_cairn_owned"].cast<py::list>().append(child);
  InstanceDict(child)["_cairn_owner"] = owner;
}

void TransferAdopted(py::handle from, py::handle to) {
  py::dict from_dict = InstanceDict(from);
  if (!from_dict.contains("_cairn_owned")) return;
  py::list children = from_dict["_cairn_owned"];
  for (py::handle child : children) Adopt(to, child);
  PyDict_DelItemString(from_dict.ptr(), "_cairn_owned");
}

void TieToOwner(py::handle object, py::handle owner) {
  py::dict dict = InstanceDict(object);
  if (!dict.contains("_cairn_owner")) dict["_cairn_owner"] = owner;
}

py::object GetInstanceAttribute(py::handle object, const char* name) {
  PyObject** dict = _PyObject_GetDictPtr(object.ptr());
  if (dict == nullptr || *dict == nullptr) return py::none();
  PyObject* value = PyDict_GetItemString(*dict, name);
  return value == nullptr ? py::none() : py::reinterpret_borrow<py::object>(value);
}

}  // namespace cairn::python
