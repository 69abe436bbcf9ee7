#include "cv_mat_caster.h"

#include <cstring>
#include <vector>

#include "cairn/common/number_text.h"

namespace cairn::python {
namespace {

// OpenCV's depth for a numpy array's dtype, or -1.
int DepthOfArray(const py::array& array) {
  if (py::isinstance<py::array_t<std::uint8_t>>(array)) return CV_8U;
  if (py::isinstance<py::array_t<std::int8_t>>(array)) return CV_8S;
  if (py::isinstance<py::array_t<std::uint16_t>>(array)) return CV_16U;
  if (py::isinstance<py::array_t<std::int16_t>>(array)) return CV_16S;
  if (py::isinstance<py::array_t<std::int32_t>>(array)) return CV_32S;
  if (py::isinstance<py::array_t<float>>(array)) return CV_32F;
  if (py::isinstance<py::array_t<double>>(array)) return CV_64F;
  return -1;
}

// Owns a cv::Mat header (sharing its reference-counted buffer) for as long as numpy arrays point into it.
void DeleteMat(void* mat) { delete static_cast<cv::Mat*>(mat); }

}  // namespace

py::dtype DtypeOfDepth(int depth) {
  switch (depth) {
    case CV_8U: return py::dtype::of<std::uint8_t>();
    case CV_8S: return py::dtype::of<std::int8_t>();
    case CV_16U: return py::dtype::of<std::uint16_t>();
    case CV_16S: return py::dtype::of<std::int16_t>();
    case CV_32S: return py::dtype::of<std::int32_t>();
    case CV_32F: return py::dtype::of<float>();
    case CV_64F: return py::dtype::of<double>();
    default: break;
  }
  throw py::value_error("cairn: images of OpenCV depth " + cairn::FormatShort(depth) +
                        " (16-bit float) have no numpy equivalent here; convert them to float32 in C++");
}

py::array MatToArray(const cv::Mat& image, bool writable) {
  if (image.dims > 2) {
    throw py::value_error("cairn: a cv::Mat with " + cairn::FormatShort(image.dims) +
                          " dimensions cannot become an image array (2 dimensions and channels expected)");
  }
  const py::dtype dtype = DtypeOfDepth(image.depth());
  // A Mat over foreign memory (u == nullptr) could be freed behind the array's back: copy it.
  auto* held = new cv::Mat(image.u == nullptr && !image.empty() ? image.clone() : image);
  py::capsule owner(held, &DeleteMat);
  const auto rows = static_cast<py::ssize_t>(held->rows);
  const auto cols = static_cast<py::ssize_t>(held->cols);
  const auto channels = static_cast<py::ssize_t>(held->channels());
  const auto item = static_cast<py::ssize_t>(held->elemSize1());
  const auto row_step = static_cast<py::ssize_t>(held->empty() ? cols * channels * item : held->step[0]);
  std::vector<py::ssize_t> shape{rows, cols};
  std::vector<py::ssize_t> strides{row_step, channels * item};
  if (channels > 1) {
    shape.push_back(channels);
    strides.push_back(item);
  }
  py::array array(dtype, shape, strides, held->empty() ? nullptr : held->data, owner);
  if (!writable) py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

cv::Mat ArrayToMat(py::handle object, const std::string& what) {
  const bool is_array = py::isinstance<py::array>(object);
  py::array array = is_array ? py::reinterpret_borrow<py::array>(object) : py::array::ensure(object);
  if (!array) {
    PyErr_Clear();
    throw py::type_error(what + ": expected a numpy array, got a " +
                         std::string(py::str(py::type::handle_of(object).attr("__name__"))));
  }
  const int depth = DepthOfArray(array);
  if (depth < 0) {
    throw py::value_error(what + ": numpy dtype " + std::string(py::str(array.dtype())) +
                          " is not an image type; use uint8, int8, uint16, int16, int32, float32 or float64");
  }
  if (array.ndim() != 2 && array.ndim() != 3) {
    throw py::value_error(what + ": expected an H x W or H x W x C array, got " + cairn::FormatShort(array.ndim()) +
                          " dimensions");
  }
  const py::ssize_t channels = array.ndim() == 3 ? array.shape(2) : 1;
  if (channels < 1 || channels > CV_CN_MAX) {
    throw py::value_error(what + ": " + cairn::FormatShort(channels) + " channels; OpenCV images have 1 to " +
                          cairn::FormatShort(CV_CN_MAX));
  }
  if (array.shape(0) > INT32_MAX || array.shape(1) > INT32_MAX) {
    throw py::value_error(what + ": " + cairn::FormatShort(array.shape(0)) + " x " + cairn::FormatShort(array.shape(1)) +
                          " pixels exceed OpenCV's limit of 2^31 - 1 per side");
  }
  const int type = CV_MAKETYPE(depth, static_cast<int>(channels));
  const auto rows = static_cast<int>(array.shape(0));
  const auto cols = static_cast<int>(array.shape(1));
  const py::ssize_t item = array.itemsize();
  const bool pixels_contiguous = (array.ndim() == 2 || array.strides(2) == item || channels == 1) &&
                                 (cols <= 1 || array.strides(1) == item * channels);
  const bool rows_ok = rows <= 1 || (array.strides(0) >= item * channels * cols && array.strides(0) % item == 0);
  const bool aligned = reinterpret_cast<std::uintptr_t>(array.data()) % static_cast<std::uintptr_t>(item) == 0;
  if (is_array && pixels_contiguous && rows_ok && aligned && rows > 0 && cols > 0) {
    const auto step = static_cast<std::size_t>(rows <= 1 ? item * channels * cols : array.strides(0));
    return cv::Mat(rows, cols, type, const_cast<void*>(array.data()), step);
  }
  // Another layout, or an array-like: a C-ordered copy, which the returned Mat owns.
  py::array contiguous = py::array::ensure(array, py::array::c_style);
  cv::Mat owned(rows, cols, type);
  if (owned.total() > 0) {
    std::memcpy(owned.data, contiguous.data(), owned.total() * owned.elemSize());
  }
  return owned;
}

}  // namespace cairn::python
