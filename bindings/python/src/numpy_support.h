#pragma once

/// @file
/// numpy views of C++ buffers, and the conversion of Eigen::Isometry3d to and from 4x4 arrays.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "cairn/common/number_text.h"

namespace cairn::python {

namespace py = pybind11;

/// A numpy array over `data` (no copy) with the given shape and byte strides. `owner` (any Python object, which
/// must keep `data` valid) becomes the array's base, so the buffer outlives every view of it. Read-only unless
/// `writable`.
template <typename T>
py::array ArrayView(const T* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                    py::handle owner, bool writable = false) {
  py::array array(py::dtype::of<T>(), std::move(shape), std::move(strides), data, owner);
  if (!writable) py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

/// A view of a column-major Eigen matrix or vector (no copy): 1-D for vectors, 2-D (Fortran order) otherwise.
template <typename Derived>
py::array EigenView(const Eigen::PlainObjectBase<Derived>& m, py::handle owner, bool writable = false) {
  using Scalar = typename Derived::Scalar;
  static_assert(!Derived::IsRowMajor, "EigenView expects a column-major matrix");
  const auto item = static_cast<py::ssize_t>(sizeof(Scalar));
  if (Derived::ColsAtCompileTime == 1) {
    return ArrayView<Scalar>(m.data(), {static_cast<py::ssize_t>(m.size())}, {item}, owner, writable);
  }
  return ArrayView<Scalar>(m.data(), {static_cast<py::ssize_t>(m.rows()), static_cast<py::ssize_t>(m.cols())},
                           {item, item * static_cast<py::ssize_t>(m.rows())}, owner, writable);
}

/// A writable 1-D view of `size` doubles at `data` for the duration of a callback (the caller keeps the memory
/// valid while Python code runs; the array must not be kept beyond the call).
py::array CallbackVectorView(double* data, Eigen::Index size);

/// A read-only 1-D view of `size` doubles at `data` for the duration of a callback.
py::array CallbackConstVectorView(const double* data, Eigen::Index size);

/// An (n, columns) array copied from fixed-size Eigen vectors (points, spatial vectors).
template <typename Vector>
py::array_t<typename Vector::Scalar> StackRows(const std::vector<Vector>& rows) {
  constexpr int columns = Vector::RowsAtCompileTime;
  py::array_t<typename Vector::Scalar> out({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(columns)});
  auto view = out.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (int j = 0; j < columns; ++j) view(static_cast<py::ssize_t>(i), j) = rows[i][j];
  }
  return out;
}

/// Fixed-size vectors from the rows of an (n, columns) array; throws ValueError naming `what` on another shape.
template <typename Vector>
std::vector<Vector> UnstackRows(const py::array_t<typename Vector::Scalar, py::array::forcecast>& array,
                                const std::string& what) {
  constexpr int columns = Vector::RowsAtCompileTime;
  if (array.ndim() != 2 || array.shape(1) != columns) {
    throw py::value_error(what + ": expected an (n, " + cairn::FormatShort(columns) + ") array");
  }
  auto view = array.template unchecked<2>();
  std::vector<Vector> rows(static_cast<std::size_t>(array.shape(0)));
  for (py::ssize_t i = 0; i < array.shape(0); ++i) {
    for (int j = 0; j < columns; ++j) rows[static_cast<std::size_t>(i)][j] = view(i, j);
  }
  return rows;
}

}  // namespace cairn::python

namespace pybind11::detail {

/// Eigen::Isometry3d as a 4x4 homogeneous transform (numpy float64): poses on ports (X_WC), camera trajectories.
/// Loading checks the shape, the last row [0, 0, 0, 1] and that the rotation block is orthonormal (to 1e-6), since
/// an Isometry3d silently assumes it.
template <>
struct type_caster<Eigen::Isometry3d> {
  PYBIND11_TYPE_CASTER(Eigen::Isometry3d, const_name("numpy.ndarray[4, 4]"));

  bool load(handle src, bool convert) {
    if (!convert && !isinstance<array_t<double>>(src)) return false;
    auto array = array_t<double, array::forcecast | array::c_style>::ensure(src);
    if (!array) return false;
    if (array.ndim() != 2 || array.shape(0) != 4 || array.shape(1) != 4) {
      if (!convert) return false;
      throw value_error("a pose must be a 4x4 homogeneous transform, got an array of shape " +
                        std::string(str(src.attr("shape"))));
    }
    Eigen::Matrix4d m;
    auto view = array.unchecked<2>();
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) m(i, j) = view(i, j);
    }
    const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
    if (!(m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).isZero(1e-12) ||
        !((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-6)) {
      throw value_error(
          "a pose must be a rigid transform: last row [0, 0, 0, 1] and an orthonormal rotation block (to 1e-6)");
    }
    value.matrix() = m;
    return true;
  }

  static handle cast(const Eigen::Isometry3d& pose, return_value_policy, handle) {
    array_t<double> out({4, 4});
    auto view = out.mutable_unchecked<2>();
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) view(i, j) = pose.matrix()(i, j);
    }
    return out.release();
  }
};

}  // namespace pybind11::detail
