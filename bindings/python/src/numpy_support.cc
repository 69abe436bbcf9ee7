#include "numpy_support.h"

namespace cairn::python {
namespace {

// The base of callback views: any object makes numpy keep the pointer instead of copying, and the memory belongs to
// C++ code that outlives the call. One object, never freed (it would need the GIL at exit).
py::handle CallbackBase() {
  static int anchor = 0;
  static PyObject* base = [] {
    py::capsule capsule(static_cast<void*>(&anchor), "cairn.callback_view");
    return capsule.release().ptr();
  }();
  return base;
}

}  // namespace

py::array CallbackVectorView(double* data, Eigen::Index size) {
  return ArrayView<double>(data, {static_cast<py::ssize_t>(size)}, {static_cast<py::ssize_t>(sizeof(double))},
                           CallbackBase(), true);
}

py::array CallbackConstVectorView(const double* data, Eigen::Index size) {
  return ArrayView<double>(data, {static_cast<py::ssize_t>(size)}, {static_cast<py::ssize_t>(sizeof(double))},
                           CallbackBase(), false);
}

}  // namespace cairn::python
