#include "cairn/common/number_text.h"
#include "cairn/perception/stereo/compute_cost_volume.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "cairn/common/cairn_assert.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/internal/multiversion.h"
#include "cairn/perception/stereo/internal/winner_take_all_row.h"

namespace cairn::perception {
namespace {

// Per-row inputs of the pixel cost, in "doubled" integer units for BTSAD so that Birchfield-Tomasi's
// half-pixel interpolations stay integers: value = 2 I, min/max over {2 I(x), I(x) + I(x-1), I(x) + I(x+1)}.
struct RowSignals {
  std::vector<int32_t> left;       // W: 2 I_L (BTSAD) or I_L (SSD).
  std::vector<int32_t> left_min;   // W (BTSAD only).
  std::vector<int32_t> left_max;   // W (BTSAD only).
  std::vector<int32_t> right;      // W + D - 1, reversed and edge-replicated (see FillRow()).
  std::vector<int32_t> right_min;  // W + D - 1 (BTSAD only).
  std::vector<int32_t> right_max;  // W + D - 1 (BTSAD only).
  std::vector<int32_t> right_image, right_image_min, right_image_max;  // W, in image order (scratch)
};

// Birchfield-Tomasi's range of row[x] in doubled units: min and max over {2 I(x), I(x) + I(x-1), I(x) + I(x+1)},
// the edge pixels standing in for their missing neighbours. Plain loops that the compiler vectorises.
CAIRN_MULTIVERSION
void BtRanges(const uint8_t* row, int width, int32_t* doubled, int32_t* lo, int32_t* hi) {
  for (int x = 0; x < width; ++x) doubled[x] = 2 * row[x];
  lo[0] = hi[0] = doubled[0];
  for (int x = 1; x < width; ++x) {  // with the left neighbour
    const int32_t half_left = row[x] + row[x - 1];
    lo[x] = std::min(doubled[x], half_left);
    hi[x] = std::max(doubled[x], half_left);
  }
  for (int x = 0; x + 1 < width; ++x) {  // with the right neighbour
    const int32_t half_right = row[x] + row[x + 1];
    lo[x] = std::min(lo[x], half_right);
    hi[x] = std::max(hi[x], half_right);
  }
}

// The right-image arrays are stored reversed so that, for a fixed left column x, consecutive disparities read
// consecutive memory: index i holds right column clamp(W - 1 - dmin - i), and disparity index k at column x
// reads index W - 1 - x + k.
void FillRow(const uint8_t* left, const uint8_t* right, int width, int dmin, int num_disp, bool bt, RowSignals* s) {
  const int span = width + num_disp - 1;
  if (bt) {
    BtRanges(left, width, s->left.data(), s->left_min.data(), s->left_max.data());
    BtRanges(right, width, s->right_image.data(), s->right_image_min.data(), s->right_image_max.data());
  } else {
    for (int x = 0; x < width; ++x) s->left[x] = left[x];
    for (int x = 0; x < width; ++x) s->right_image[x] = right[x];
  }
  for (int i = 0; i < span; ++i) {
    const int xr = std::clamp(width - 1 - dmin - i, 0, width - 1);
    s->right[i] = s->right_image[xr];
    if (bt) {
      s->right_min[i] = s->right_image_min[xr];
      s->right_max[i] = s->right_image_max[xr];
    }
  }
}

// The vertical running sum: for every (x, k) of one image row, the pixel cost e(x, k) (k contiguous) replaces
// the cost of the row leaving the window, held in `slot`: colsum += e - slot; slot = e. Computing e in the same
// pass avoids writing and re-reading a separate row of fresh costs. A pixel cost fits 16 bits (SSD: 255^2; BTSAD:
// 510 in doubled units), which halves the ring's memory traffic.
CAIRN_MULTIVERSION
void SlidePixelCostsSsd(const RowSignals& s, int width, int num_disp, int32_t* colsum, uint16_t* slot) {
  for (int x = 0; x < width; ++x) {
    const int32_t l = s.left[x];
    const int32_t* r = s.right.data() + (width - 1 - x);
    const std::size_t offset = static_cast<std::size_t>(x) * num_disp;
    int32_t* sum = colsum + offset;
    uint16_t* old = slot + offset;
    for (int k = 0; k < num_disp; ++k) {
      const int32_t diff = l - r[k];
      const int32_t e = diff * diff;
      sum[k] += e - old[k];
      old[k] = static_cast<uint16_t>(e);
    }
  }
}

CAIRN_MULTIVERSION
void SlidePixelCostsBt(const RowSignals& s, int width, int num_disp, int32_t* colsum, uint16_t* slot) {
  for (int x = 0; x < width; ++x) {
    const int32_t l = s.left[x];
    const int32_t lmin = s.left_min[x];
    const int32_t lmax = s.left_max[x];
    const std::size_t base = static_cast<std::size_t>(width - 1 - x);
    const int32_t* r = s.right.data() + base;
    const int32_t* rmin = s.right_min.data() + base;
    const int32_t* rmax = s.right_max.data() + base;
    const std::size_t offset = static_cast<std::size_t>(x) * num_disp;
    int32_t* sum = colsum + offset;
    uint16_t* old = slot + offset;
    for (int k = 0; k < num_disp; ++k) {
      const int32_t left_to_right = std::max(std::max(0, l - rmax[k]), rmin[k] - l);
      const int32_t right_to_left = std::max(std::max(0, r[k] - lmax), lmin - r[k]);
      const int32_t e = std::min(left_to_right, right_to_left);
      sum[k] += e - old[k];
      old[k] = static_cast<uint16_t>(e);
    }
  }
}

// One output row: horizontal running sum over the column sums, scaled to float.
CAIRN_MULTIVERSION
void HorizontalPass(const int32_t* colsum, int width, int num_disp, int radius, float scale, int32_t* acc,
                    float* out) {
  auto col = [&](int x) { return colsum + static_cast<std::size_t>(std::clamp(x, 0, width - 1)) * num_disp; };
  std::fill(acc, acc + num_disp, 0);
  for (int x = -radius; x <= radius; ++x) {
    const int32_t* c = col(x);
    for (int k = 0; k < num_disp; ++k) acc[k] += c[k];
  }
  for (int x = 0; x < width; ++x) {
    if (x > 0) {
      const int32_t* add = col(x + radius);
      const int32_t* sub = col(x - radius - 1);
      for (int k = 0; k < num_disp; ++k) acc[k] += add[k] - sub[k];
    }
    float* o = out + static_cast<std::size_t>(x) * num_disp;
    for (int k = 0; k < num_disp; ++k) o[k] = static_cast<float>(acc[k]) * scale;
  }
}

}  // namespace

cv::Mat ToGray8(const cv::Mat& image, const char* what) {
  if (image.empty()) throw std::invalid_argument(std::string(what) + " image is empty; pass a loaded image");
  if (image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3)) {
    throw std::invalid_argument(std::string(what) + " image has OpenCV type " + cairn::FormatShort(image.type()) +
                                " (depth " + cairn::FormatShort(image.depth()) + ", " +
                                cairn::FormatShort(image.channels()) +
                                " channels); stereo matching takes 8-bit grey (CV_8UC1) or BGR (CV_8UC3) images");
  }
  if (image.channels() == 1) return image;
  cv::Mat gray;
  cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  return gray;
}

cv::Mat SobelPrefilter(const cv::Mat& gray, int size, int cap) {
  if (gray.type() != CV_8UC1) {
    throw std::invalid_argument("SobelPrefilter takes a CV_8UC1 image, got OpenCV type " +
                                cairn::FormatShort(gray.type()) + "; convert with ToGray8()");
  }
  if (size != 3 && size != 5 && size != 7 && size != 9) {
    throw std::invalid_argument("Sobel prefilter size " + cairn::FormatShort(size) + " is not supported; use 3, 5, 7 or 9");
  }
  if (cap < 1 || cap > 63) {
    throw std::invalid_argument("Sobel prefilter cap " + cairn::FormatShort(cap) + " is outside 1..63; OpenCV uses 31");
  }
  // A size-s Sobel pair answers a unit ramp with 2^(s-1) * 2^(s-2); the 3x3 pair answers 8. Rescale to 3x3 units so
  // that the cap means the same for every aperture.
  const double scale = 8.0 / static_cast<double>(1LL << (2 * size - 3));
  cv::Mat dx;
  cv::Sobel(gray, dx, CV_32F, 1, 0, size, scale, 0.0, cv::BORDER_REPLICATE);
  cv::Mat out(gray.size(), CV_8UC1);
  for (int y = 0; y < gray.rows; ++y) {
    const float* in = dx.ptr<float>(y);
    uint8_t* o = out.ptr<uint8_t>(y);
    for (int x = 0; x < gray.cols; ++x) {
      // std::lround (half away from zero) without the library call: |v| + 0.5 is exact in double for |v| <= 63.
      const float v = std::clamp(in[x], static_cast<float>(-cap), static_cast<float>(cap));
      const int magnitude = static_cast<int>(std::abs(static_cast<double>(v)) + 0.5);
      o[x] = static_cast<uint8_t>((v < 0.0f ? -magnitude : magnitude) + cap);
    }
  }
  return out;
}

namespace {

// ComputeCostVolume(), and ComputeWinnerTakeAll() row by row when `wta` is given.
void CostVolumeImpl(const cv::Mat& left_image, const cv::Mat& right_image, const CostVolumeOptions& options,
                    const WtaOptions* wta_options, DisparityVolume* costs, WtaResult* wta) {
  CAIRN_CHECK(costs != nullptr);
  if (wta != nullptr) internal::ValidateWtaOptions(*wta_options);
  const cv::Mat left_gray = ToGray8(left_image, "left");
  const cv::Mat right_gray = ToGray8(right_image, "right");
  if (left_gray.size() != right_gray.size()) {
    throw std::invalid_argument("left image is " + cairn::FormatShort(left_gray.cols) + "x" +
                                cairn::FormatShort(left_gray.rows) + " but right image is " +
                                cairn::FormatShort(right_gray.cols) + "x" + cairn::FormatShort(right_gray.rows) +
                                "; pass a rectified pair of equal size");
  }
  options.Validate(left_gray.cols, left_gray.rows);
  cv::Mat left = left_gray;
  cv::Mat right = right_gray;
  if (options.prefilter == Prefilter::kSobel) {
    left = SobelPrefilter(left_gray, options.prefilter_size, options.prefilter_cap);
    right = SobelPrefilter(right_gray, options.prefilter_size, options.prefilter_cap);
  }

  const int width = left.cols;
  const int height = left.rows;
  const int dmin = options.min_disparity;
  const int dmax = options.max_disparity;
  const int num_disp = dmax - dmin + 1;
  const int radius = options.window / 2;
  const int window = options.window;
  const bool bt = options.cost == CostFunction::kBtSad;
  const float scale = bt ? 0.5f : 1.0f;
  costs->Resize(height, width, dmin, dmax);
  const std::size_t row_size = static_cast<std::size_t>(width) * num_disp;
  const int threads = ResolveThreadCount(options.num_threads);

  if (wta != nullptr) internal::AllocateWtaResult(height, width, wta);
  const bool fused_avx2 = wta != nullptr && internal::CpuHasAvx2();

  ParallelFor(height, threads, [&](int, int y0, int y1) {
    // Per-band workspace: a ring of `window` pixel-cost rows and their column sums.
    RowSignals signals;
    const std::size_t span = static_cast<std::size_t>(width + num_disp - 1);
    signals.left.resize(width);
    signals.right.resize(span);
    signals.right_image.resize(width);
    signals.right_image_min.resize(width);
    signals.right_image_max.resize(width);
    if (bt) {
      signals.left_min.resize(width);
      signals.left_max.resize(width);
      signals.right_min.resize(span);
      signals.right_max.resize(span);
    }
    // The ring starts at zero, so sliding the first `window` rows in builds the first column sums.
    std::vector<uint16_t> ring(row_size * window, 0);
    std::vector<int32_t> colsum(row_size, 0);
    std::vector<int32_t> acc(num_disp);
    const bool portable_wta = wta != nullptr && !fused_avx2;  // the AVX2 kernel keeps its own in `scratch`
    std::vector<float> right_value(portable_wta ? width : 0);
    std::vector<int32_t> right_index(portable_wta ? width : 0);
    auto slide_in = [&](int y) {
      const int yc = std::clamp(y, 0, height - 1);
      FillRow(left.ptr<uint8_t>(yc), right.ptr<uint8_t>(yc), width, dmin, num_disp, bt, &signals);
      uint16_t* slot = ring.data() + static_cast<std::size_t>(((y % window) + window) % window) * row_size;
      if (bt) {
        SlidePixelCostsBt(signals, width, num_disp, colsum.data(), slot);
      } else {
        SlidePixelCostsSsd(signals, width, num_disp, colsum.data(), slot);
      }
    };
    internal::WtaRowScratch scratch;
    if (fused_avx2) scratch.Resize(width, num_disp, dmin);
    for (int y = y0 - radius; y <= y0 + radius; ++y) slide_in(y);
    for (int y = y0; y < y1; ++y) {
      if (y > y0) slide_in(y + radius);
      float* out = costs->mutable_curve(y, 0);
      if (fused_avx2) {
        internal::AggregateRowAndWinnerTakeAllAvx2(colsum.data(), width, num_disp, dmin, radius, scale, *wta_options,
                                                   y, &scratch, out, wta);
        continue;
      }
      HorizontalPass(colsum.data(), width, num_disp, radius, scale, acc.data(), out);
      // Disparities whose right column falls outside the image have no match.
      constexpr float kInf = std::numeric_limits<float>::infinity();
      for (int x = 0; x < width; ++x) {
        float* curve = out + static_cast<std::size_t>(x) * num_disp;
        const int k_hi = std::min(num_disp - 1, x - dmin);           // d <= x
        const int k_lo = std::max(0, x - (width - 1) - dmin);        // d >= x - (W - 1)
        for (int k = 0; k < k_lo && k < num_disp; ++k) curve[k] = kInf;
        for (int k = std::max(k_hi + 1, 0); k < num_disp; ++k) curve[k] = kInf;
      }
      if (wta != nullptr) {
        internal::WinnerTakeAllRow(out, width, num_disp, dmin, *wta_options, y, right_value.data(),
                                   right_index.data(), wta);
      }
    }
  });
}

}  // namespace

void ComputeCostVolume(const cv::Mat& left, const cv::Mat& right, const CostVolumeOptions& options,
                       DisparityVolume* costs) {
  CostVolumeImpl(left, right, options, nullptr, costs, nullptr);
}

void ComputeCostVolumeAndWinnerTakeAll(const cv::Mat& left, const cv::Mat& right, const CostVolumeOptions& options,
                                       const WtaOptions& wta_options, DisparityVolume* costs, WtaResult* wta) {
  CAIRN_CHECK(wta != nullptr);
  CostVolumeImpl(left, right, options, &wta_options, costs, wta);
}

}  // namespace cairn::perception
