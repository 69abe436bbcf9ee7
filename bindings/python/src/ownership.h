#pragma once

/// @file
/// Ownership of systems passed from Python to C++ builders and diagrams.
///
/// DiagramBuilder::AddSystem takes a std::unique_ptr: the builder, then the diagram, own their systems. A system
/// made in Python is owned by its Python object until it is added; AddSystem then moves the C++ object out of the
/// Python object's holder, which becomes a non-owning view. Three Python references, all stored in instance
/// dictionaries so that Python's garbage collector sees the cycles they form, keep everything valid:
///   - the owner (builder, then diagram) lists the Python objects of its systems (`_cairn_owned`), so a system
///     written in Python (whose methods C++ calls back) lives as long as the C++ diagram that runs it;
///   - each system's Python object names its owner (`_cairn_owner`), so a Python reference to an added system
///     keeps the builder or diagram, hence the C++ object, alive;
///   - a builder names the diagram it built (`_cairn_built`).

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

namespace cairn::python {

namespace py = pybind11;

/// True if the Python object `object` (of a class bound with a std::unique_ptr holder) owns its C++ object.
bool PythonOwnsCppObject(py::handle object);

/// Moves the C++ object out of the holder of `object` (a bound class with a std::unique_ptr holder whose C++
/// type derives from T by single inheritance). `what` names the operation in the error raised (ValueError) when
/// `object` no longer owns it.
template <typename T>
std::unique_ptr<T> ReleaseFromPython(py::handle object, const std::string& what);

/// Records that `owner` owns `child` (see the file comment).
void Adopt(py::handle owner, py::handle child);

/// Moves the children adopted by `from` to `to`, and makes each child name `to` as its owner.
void TransferAdopted(py::handle from, py::handle to);

/// Makes `object`'s instance dictionary name `owner` as `_cairn_owner`, unless it already names one.
void TieToOwner(py::handle object, py::handle owner);

/// The attribute `name` of `object`'s instance dictionary, or None.
py::object GetInstanceAttribute(py::handle object, const char* name);

/// Python 3.11 and pybind11 2.10 count the instance dictionary of a Python subclass of a py::dynamic_attr class twice
/// when the garbage collector traverses it (CPython's subtype_traverse visits the managed dictionary, then pybind11's
/// tp_traverse visits it again), which makes every reference cycle through such an object look externally
/// referenced, so it is never collected. This replaces tp_traverse of every such class in `module` (recursively)
/// with one that leaves subclasses' dictionaries to CPython. A no-op on other Python versions.
void FixDynamicAttributeTraversal(py::module_ module);

namespace internal {
/// Destroys the holder of `object` without deleting the C++ object (a released std::unique_ptr).
void DisownHolder(py::handle object, const std::string& what);
}  // namespace internal

template <typename T>
std::unique_ptr<T> ReleaseFromPython(py::handle object, const std::string& what) {
  T* raw = object.cast<T*>();
  internal::DisownHolder(object, what);
  return std::unique_ptr<T>(raw);
}

}  // namespace cairn::python
