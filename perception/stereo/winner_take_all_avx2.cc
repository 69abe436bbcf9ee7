// AVX2 kernels of the winner-take-all (declared in perception/stereo/internal/winner_take_all_row.h).
//
// The portable row kernel in winner_take_all.cc makes five passes over a row of curves that no longer fits in L1;
// here each pixel's curve is handled once, from a small padded buffer in L1, eight disparities per instruction:
// the minimum, its first index, the right view's running minima and the second-best local minimum are all
// element-wise compares, selects and minima, so the results are the portable kernel's exactly (no arithmetic is
// reordered; only exact minima are taken in a different order, with the operands ordered so that a NaN cost is
// passed over as std::min passes it over, and the reported cost is the one at the winning index, so that a
// curve holding both +0 and -0 reports the same zero). The fused variant also aggregates the row's costs
// from the column sums, so the cost volume is written once and never read back.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "cairn/common/cairn_assert.h"
#include "cairn/perception/stereo/internal/winner_take_all_row.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define CAIRN_HAVE_AVX2_KERNELS 1
#define CAIRN_TARGET_AVX2 __attribute__((target("avx2")))
#endif

namespace cairn::perception::internal {

bool CpuHasAvx2() {
#ifdef CAIRN_HAVE_AVX2_KERNELS
  static const bool has_avx2 = __builtin_cpu_supports("avx2") != 0;
  return has_avx2;
#else
  return false;
#endif
}

void WtaRowScratch::Resize(int width, int num_disp, int dmin) {
  chunks = (num_disp + 7) / 8;
  const int padded = 8 * chunks;
  // Curve buffer: 8 leading floats (the last one is c[-1]), the padded curve, 8 trailing floats; +infinity
  // everywhere outside [0, num_disp) so that the padding never wins a minimum and reads as an infinite neighbour.
  curve_storage.assign(static_cast<std::size_t>(padded) + 16 + 8, std::numeric_limits<float>::infinity());
  const auto address = reinterpret_cast<std::uintptr_t>(curve_storage.data());
  const std::size_t misalignment = (32 - address % 32) % 32 / sizeof(float);
  curve = curve_storage.data() + misalignment + 8;
  // Right-view slots: left column x at disparity index k writes slot width - 1 - x + dmin + k (+ shift so the
  // smallest, dmin, is not negative); the k of the padding run past num_disp.
  shift = std::max(0, -dmin);
  const std::size_t slots = static_cast<std::size_t>(shift) + width + std::max(dmin, 0) + padded;
  right_value.assign(slots, std::numeric_limits<float>::infinity());
  right_index.assign(slots, -1);
  acc.assign(static_cast<std::size_t>(padded), 0);
}

#ifdef CAIRN_HAVE_AVX2_KERNELS
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

CAIRN_TARGET_AVX2 inline float HorizontalMin(__m256 v) {
  __m128 m = _mm_min_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  m = _mm_min_ps(m, _mm_movehl_ps(m, m));
  m = _mm_min_ss(m, _mm_shuffle_ps(m, m, 1));
  return _mm_cvtss_f32(m);
}

// The winner-take-all of one pixel whose curve c[0, 8 chunks) is padded with +infinity (c[-1] too), 32-byte
// aligned. `value` and `index` are the right view's slots of this pixel's disparity index 0.
CAIRN_TARGET_AVX2 inline void WtaPixel(const float* c, int chunks, int num_disp, int dmin, bool subpixel,
                                       float* value, int32_t* index, float* disparity, int32_t* best_index,
                                       float* best_cost, float* peak_ratio) {
  const __m256 inf = _mm256_set1_ps(kInf);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  __m256 minimum = inf;
  for (int j = 0; j < chunks; ++j) {
    const __m256 v = _mm256_load_ps(c + 8 * j);
    // min(v, m) keeps m when v is NaN, as std::min(m, v) does in the portable kernel: NaN costs never win.
    minimum = _mm256_min_ps(v, minimum);
    // Right view: the strict compare keeps the smallest k of a right column, since left columns arrive in order.
    const __m256 old_value = _mm256_loadu_ps(value + 8 * j);
    const __m256 better = _mm256_cmp_ps(v, old_value, _CMP_LT_OQ);
    _mm256_storeu_ps(value + 8 * j, _mm256_blendv_ps(old_value, v, better));
    const __m256i old_index = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(index + 8 * j));
    const __m256i k = _mm256_add_epi32(lane, _mm256_set1_epi32(8 * j));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(index + 8 * j),
                        _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(old_index),
                                                             _mm256_castsi256_ps(k), better)));
  }
  const float best_value = HorizontalMin(minimum);
  if (!(best_value < kInf)) {
    *best_index = -1;
    *best_cost = best_value;
    *disparity = std::numeric_limits<float>::quiet_NaN();
    *peak_ratio = kInf;
    return;
  }
  const __m256 best_broadcast = _mm256_set1_ps(best_value);
  int best = 0;
  for (int j = 0; j < chunks; ++j) {
    const int mask = _mm256_movemask_ps(_mm256_cmp_ps(_mm256_load_ps(c + 8 * j), best_broadcast, _CMP_EQ_OQ));
    if (mask != 0) {
      best = 8 * j + __builtin_ctz(static_cast<unsigned>(mask));
      break;
    }
  }
  // Second-best local minimum: a cost no larger than either neighbour (the padding is an infinite neighbour, so
  // the ends compare with their one real neighbour), other than the winner.
  __m256 second = inf;
  const __m256i best_lane = _mm256_set1_epi32(best & 7);
  const int best_chunk = best >> 3;
  for (int j = 0; j < chunks; ++j) {
    const __m256 v = _mm256_load_ps(c + 8 * j);
    const __m256 local = _mm256_and_ps(_mm256_cmp_ps(v, _mm256_loadu_ps(c + 8 * j - 1), _CMP_LE_OQ),
                                       _mm256_cmp_ps(v, _mm256_loadu_ps(c + 8 * j + 1), _CMP_LE_OQ));
    __m256 candidate = _mm256_blendv_ps(inf, v, local);
    if (j == best_chunk) {
      candidate = _mm256_blendv_ps(candidate, inf, _mm256_castsi256_ps(_mm256_cmpeq_epi32(lane, best_lane)));
    }
    second = _mm256_min_ps(candidate, second);
  }
  const float second_value = HorizontalMin(second);
  *best_index = best;
  *best_cost = c[best];  // not best_value: of +0 and -0, the one at the first index, whatever the reduction order
  if (!std::isfinite(second_value)) {
    *peak_ratio = kInf;
  } else if (best_value > 0.0f) {
    *peak_ratio = second_value / best_value;
  } else {
    *peak_ratio = second_value > 0.0f ? kInf : 1.0f;
  }
  float offset = 0.0f;
  if (subpixel && best > 0 && best < num_disp - 1 && std::isfinite(c[best - 1]) && std::isfinite(c[best + 1])) {
    const float denominator = c[best - 1] - 2.0f * c[best] + c[best + 1];
    if (denominator > 0.0f) offset = std::clamp(0.5f * (c[best - 1] - c[best + 1]) / denominator, -0.5f, 0.5f);
  }
  *disparity = static_cast<float>(dmin + best) + offset;
}

// Chunk j of a pixel's column sums; the last chunk's read stops at num_disp (masked), as what follows belongs to
// the next column, or lies past the end of the row.
CAIRN_TARGET_AVX2 inline __m256i LoadSums(const int32_t* sums, int j, int chunks, int tail, __m256i tail_mask) {
  return j + 1 < chunks || tail == 8 ? _mm256_loadu_si256(reinterpret_cast<const __m256i*>(sums + 8 * j))
                                     : _mm256_maskload_epi32(sums + 8 * j, tail_mask);
}

struct RowOutputs {
  float* disparity;
  int32_t* best_index;
  float* best_cost;
  float* peak_ratio;
  int32_t* right_best;
  uint8_t* consistent;
};

RowOutputs OutputsOfRow(int y, WtaResult* result) {
  return {result->disparity.ptr<float>(y),       result->best_index.ptr<int32_t>(y),
          result->best_cost.ptr<float>(y),       result->peak_ratio.ptr<float>(y),
          result->right_best_index.ptr<int32_t>(y), result->lr_consistent.ptr<uint8_t>(y)};
}

void ResetRightView(WtaRowScratch* scratch) {
  std::fill(scratch->right_value.begin(), scratch->right_value.end(), kInf);
  std::fill(scratch->right_index.begin(), scratch->right_index.end(), -1);
}

}  // namespace

CAIRN_TARGET_AVX2 void WinnerTakeAllRowAvx2(const float* row, int width, int num_disp, int dmin,
                                            const WtaOptions& options, int y, WtaRowScratch* scratch,
                                            WtaResult* result) {
  CAIRN_CHECK(scratch->chunks == (num_disp + 7) / 8);
  const RowOutputs out = OutputsOfRow(y, result);
  ResetRightView(scratch);
  float* c = scratch->curve;
  const std::size_t bytes = static_cast<std::size_t>(num_disp) * sizeof(float);
  for (int x = 0; x < width; ++x) {
    std::memcpy(c, row + static_cast<std::size_t>(x) * num_disp, bytes);
    const std::size_t slot = static_cast<std::size_t>(scratch->shift + width - 1 - x + dmin);
    WtaPixel(c, scratch->chunks, num_disp, dmin, options.subpixel, scratch->right_value.data() + slot,
             scratch->right_index.data() + slot, out.disparity + x, out.best_index + x, out.best_cost + x,
             out.peak_ratio + x);
  }
  LeftRightCheckRow(width, dmin, options.lr_tolerance, scratch->right_index.data() + scratch->shift, out.best_index,
                    out.right_best, out.consistent);
}

CAIRN_TARGET_AVX2 void AggregateRowAndWinnerTakeAllAvx2(const int32_t* colsum, int width, int num_disp, int dmin,
                                                        int radius, float scale, const WtaOptions& options, int y,
                                                        WtaRowScratch* scratch, float* costs, WtaResult* result) {
  CAIRN_CHECK(scratch->chunks == (num_disp + 7) / 8);
  const RowOutputs out = OutputsOfRow(y, result);
  ResetRightView(scratch);
  const int chunks = scratch->chunks;
  const int tail = num_disp - 8 * (chunks - 1);  // lanes of the last chunk that belong to the curve, 1..8
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i tail_mask = _mm256_cmpgt_epi32(_mm256_set1_epi32(tail), lane);
  const __m256 inf = _mm256_set1_ps(kInf);
  const __m256 scale_v = _mm256_set1_ps(scale);
  int32_t* acc = scratch->acc.data();
  float* c = scratch->curve;
  auto column = [&](int x) { return colsum + static_cast<std::size_t>(std::clamp(x, 0, width - 1)) * num_disp; };
  for (int j = 0; j < chunks; ++j) {
    __m256i sum = _mm256_setzero_si256();
    for (int x = -radius; x <= radius; ++x) {
      sum = _mm256_add_epi32(sum, LoadSums(column(x), j, chunks, tail, tail_mask));
    }
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(acc + 8 * j), sum);
  }
  for (int x = 0; x < width; ++x) {
    const int32_t* add = column(x + radius);
    const int32_t* sub = column(x - radius - 1);
    // Disparity index k has a match only when its right column x - dmin - k is inside the image; this also
    // makes the padding past num_disp +infinity.
    const __m256i k_lo = _mm256_set1_epi32(std::max(0, x - (width - 1) - dmin) - 1);
    const __m256i k_hi = _mm256_set1_epi32(std::min(num_disp - 1, x - dmin) + 1);
    float* o = costs + static_cast<std::size_t>(x) * num_disp;
    for (int j = 0; j < chunks; ++j) {
      __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(acc + 8 * j));
      if (x > 0) {
        a = _mm256_add_epi32(a, _mm256_sub_epi32(LoadSums(add, j, chunks, tail, tail_mask),
                                                 LoadSums(sub, j, chunks, tail, tail_mask)));
      }
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(acc + 8 * j), a);
      const __m256i k = _mm256_add_epi32(lane, _mm256_set1_epi32(8 * j));
      const __m256i valid = _mm256_and_si256(_mm256_cmpgt_epi32(k, k_lo), _mm256_cmpgt_epi32(k_hi, k));
      const __m256 v = _mm256_blendv_ps(inf, _mm256_mul_ps(_mm256_cvtepi32_ps(a), scale_v),
                                        _mm256_castsi256_ps(valid));
      _mm256_store_ps(c + 8 * j, v);
      // Masked stores are microcoded and slow on some CPUs (AMD Zen): only a partial last chunk takes one.
      if (j + 1 < chunks || tail == 8) {
        _mm256_storeu_ps(o + 8 * j, v);
      } else {
        _mm256_maskstore_ps(o + 8 * j, tail_mask, v);
      }
    }
    const std::size_t slot = static_cast<std::size_t>(scratch->shift + width - 1 - x + dmin);
    WtaPixel(c, chunks, num_disp, dmin, options.subpixel, scratch->right_value.data() + slot,
             scratch->right_index.data() + slot, out.disparity + x, out.best_index + x, out.best_cost + x,
             out.peak_ratio + x);
  }
  LeftRightCheckRow(width, dmin, options.lr_tolerance, scratch->right_index.data() + scratch->shift, out.best_index,
                    out.right_best, out.consistent);
}
#else
void WinnerTakeAllRowAvx2(const float*, int, int, int, const WtaOptions&, int, WtaRowScratch*, WtaResult*) {
  CAIRN_CHECK(false && "the AVX2 kernels are not compiled on this platform; check CpuHasAvx2() first");
}
void AggregateRowAndWinnerTakeAllAvx2(const int32_t*, int, int, int, int, float, const WtaOptions&, int,
                                      WtaRowScratch*, float*, WtaResult*) {
  CAIRN_CHECK(false && "the AVX2 kernels are not compiled on this platform; check CpuHasAvx2() first");
}
#endif

}  // namespace cairn::perception::internal
