#pragma once

/// @file
/// cv::Mat <-> numpy, as OpenCV's own cv2 module does: an H x W x C array of uint8, int8, uint16, int16, int32,
/// float32 or float64 is a C-channel image (an H x W array, one channel).
///
/// Python to C++ (arguments): an array whose pixels and channels are contiguous (any row stride, e.g. a crop of
/// rows) is wrapped without a copy, for the duration of the call; any other layout (Fortran order, a column crop,
/// a transposed view) and any other array-like (nested lists) is copied into a Mat of the same values. Where C++
/// keeps an image beyond the call (fixed port values, state), the bindings copy it.
/// C++ to Python (results): the array shares the cv::Mat's reference-counted buffer (no copy) and keeps it alive;
/// a cv::Mat over memory it does not own is copied.

#include <cstdint>
#include <string>

#include <opencv2/core.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace cairn::python {

namespace py = pybind11;

/// The numpy dtype of an OpenCV depth (CV_8U, ...); throws ValueError for depths numpy cannot hold (CV_16F).
py::dtype DtypeOfDepth(int depth);

/// `image` as a numpy array sharing its buffer (copying it first when the Mat does not own its memory). Read-only
/// unless `writable`.
py::array MatToArray(const cv::Mat& image, bool writable = true);

/// `object` (a numpy array, or anything numpy can make one of) as a cv::Mat. An array whose layout allows it is
/// wrapped without a copy, so it must outlive the Mat; anything else is copied into a Mat that owns its pixels.
/// Throws ValueError naming `what` for an unsupported dtype or number of dimensions.
cv::Mat ArrayToMat(py::handle object, const std::string& what = "image");

}  // namespace cairn::python

namespace pybind11::detail {

template <>
struct type_caster<cv::Mat> {
  PYBIND11_TYPE_CASTER(cv::Mat, const_name("numpy.ndarray"));

  bool load(handle src, bool convert) {
    if (!isinstance<array>(src) && !convert) return false;
    // The argument (held by the call) outlives a wrapping Mat; anything copied is owned by the Mat.
    value = cairn::python::ArrayToMat(src);
    return true;
  }

  static handle cast(const cv::Mat& image, return_value_policy, handle) {
    return cairn::python::MatToArray(image).release();
  }
};

}  // namespace pybind11::detail
