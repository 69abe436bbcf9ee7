#include "cairn/perception/friction/friction_quantile_image.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/common/cairn_assert.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/internal/multiversion.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CAIRN_FRICTION_QUANTILE_AVX2 1
#include <immintrin.h>
#else
#define CAIRN_FRICTION_QUANTILE_AVX2 0
#endif

namespace cairn::perception {
namespace {

constexpr double kExactStep = 1.0 / 2048.0;

// The validation's rule for a pixel's sum, shared by the fast check and the message naming the bad pixel.
inline bool SumIsOne(float sum) { return std::abs(sum - 1.0f) <= 1e-3f; }

// ---------------------------------------------------------------------------------------------------------------
// Dot products of pixels with table rows, all computed by two kernels:
// - PixelDots: one pass over a row that checks every value against [0, 1] and dots every pixel with three or four
//   vectors (the first of them ones: the pixel's sum);
// - CellDots: for a list of (pixel, cell) pairs, the pixel's dot products with the table rows at both ends of the
//   cell (a step of the searches).
// Every dot product is computed in one fixed order, the one an eight-lane vector unit follows naturally: lane k
// accumulates labels k, k + 8, k + 16, ... (a product, then products added in turn; labels past the pixel's count
// as 0), and the eight lanes are added as ((l0 + l1) + (l2 + l3)) + ((l4 + l5) + (l6 + l7)). The portable kernels
// spell this order out; the AVX2 kernels compute it with one register per lane set and the same IEEE
// multiplications and additions, so both give identical bits. (The AVX2 target does not enable fused
// multiply-adds; a build that does, with -mfma or an -march that has FMA, may contract them differently in the
// two, which the tests would report.)
// ---------------------------------------------------------------------------------------------------------------

// Returns whether every value of the row lies in [0, 1] (NaN does not); out[v][c] = pixel c's dot product with
// table row v of `vectors` (kVectors rows of `stride` floats, zeros past the n labels). Each out[v] has room for
// cols rounded up to 8. `next_row` (or null), the row to be read next, may be prefetched meanwhile. `padded`
// (portable kernels only): cols pixels of `stride` floats, zero past the first n of each, which receive the row.
using PixelDotsKernel = bool (*)(const float* row, const float* next_row, int cols, int n, const float* vectors,
                                 int stride, float* const* out, float* padded);
// f_low[k], f_high[k] = pixel[k]'s dot products with table rows cell[k] and cell[k] + 1. f_low and f_high have
// room for count rounded up to 4. `padded` (portable kernels only): the row as PixelDots left it there.
using CellDotsKernel = void (*)(const float* row, int n, const int* pixel, const int* cell, int count,
                                const float* table, int stride, float* f_low, float* f_high, float* padded);

// The dot product in the order above of a pixel held in `padded` (its labels, then zeros up to 8 * chunks floats)
// with a table row. Whole chunks, no conditions: GCC vectorises the lanes.
inline float PaddedDot(const float* padded, const float* t, int chunks) {
  float lane[8];
  for (int k = 0; k < 8; ++k) lane[k] = padded[k] * t[k];
  for (int c = 1; c < chunks; ++c) {
    for (int k = 0; k < 8; ++k) lane[k] += padded[8 * c + k] * t[8 * c + k];
  }
  return ((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7]));
}

inline bool InUnitInterval(float x) { return x >= 0.0f && x <= 1.0f; }

// The portable kernels copy the row into pixels of `stride` floats, so that every dot product runs over whole
// chunks (the searches' rounds then read these copies).
template <int kVectors>
bool PortablePixelDots(const float* row, const float* /*next_row*/, int cols, int n, const float* vectors,
                       int stride, float* const* out, float* padded) {
  const int chunks = (n + 7) / 8;
  // Over the whole row at once, branch-free (& and |: every comparison evaluated), so that it vectorises.
  int outside = 0;
  for (std::size_t i = 0; i < static_cast<std::size_t>(cols) * n; ++i) {
    outside |= !(row[i] >= 0.0f) | !(row[i] <= 1.0f);
  }
  for (int c = 0; c < cols; ++c) {
    float* pixel = padded + static_cast<std::size_t>(c) * stride;
    std::copy_n(row + static_cast<std::size_t>(c) * n, n, pixel);
    for (int v = 0; v < kVectors; ++v) out[v][c] = PaddedDot(pixel, vectors + v * stride, chunks);
  }
  return outside == 0;
}

void PortableCellDots(const float* /*row*/, int n, const int* pixel, const int* cell, int count, const float* table,
                      int stride, float* f_low, float* f_high, float* padded) {
  const int chunks = (n + 7) / 8;
  for (int k = 0; k < count; ++k) {
    const float* p = padded + static_cast<std::size_t>(pixel[k]) * stride;
    const float* t = table + static_cast<std::size_t>(cell[k]) * stride;
    f_low[k] = PaddedDot(p, t, chunks);
    f_high[k] = PaddedDot(p, t + stride, chunks);
  }
}

// The moment approximation max(0, m + z sqrt(max(s − m², 0))) from each pixel's mean m and second moment s. Kept
// with the kernels because GCC does not vectorise std::sqrt (it may set errno); the AVX2 version's square root is
// correctly rounded like std::sqrt, so the results are identical.
using GaussianKernel = void (*)(const float* mean, const float* second, int cols, float z, float* out);

void PortableGaussianQuantiles(const float* mean, const float* second, int cols, float z, float* out) {
  for (int c = 0; c < cols; ++c) {
    out[c] = std::max(0.0f, mean[c] + std::sqrt(std::max(second[c] - mean[c] * mean[c], 0.0f)) * z);
  }
}

#if CAIRN_FRICTION_QUANTILE_AVX2
#define CAIRN_TARGET_AVX2 __attribute__((target("avx2")))

// The lanes' final sums of eight registers at once: result lane m = ((x_m0 + x_m1) + (x_m2 + x_m3)) +
// ((x_m4 + x_m5) + (x_m6 + x_m7)) for register x_m. Nine instructions instead of eight separate reductions.
CAIRN_TARGET_AVX2 inline __m256 SumLanes8(const __m256* x) {
  // hadd(a, b) = [a0+a1, a2+a3, b0+b1, b2+b3 | a4+a5, a6+a7, b4+b5, b6+b7].
  const __m256 h01 = _mm256_hadd_ps(x[0], x[1]);
  const __m256 h23 = _mm256_hadd_ps(x[2], x[3]);
  const __m256 h45 = _mm256_hadd_ps(x[4], x[5]);
  const __m256 h67 = _mm256_hadd_ps(x[6], x[7]);
  // Lane m of the low half: (x_m0 + x_m1) + (x_m2 + x_m3); of the high half: (x_m4 + x_m5) + (x_m6 + x_m7).
  const __m256 q0 = _mm256_hadd_ps(h01, h23);  // registers 0-3
  const __m256 q1 = _mm256_hadd_ps(h45, h67);  // registers 4-7
  return _mm256_add_ps(_mm256_permute2f128_ps(q0, q1, 0x20), _mm256_permute2f128_ps(q0, q1, 0x31));
}

// Chunk k of a pixel's labels; the last chunk (`last`) is loaded under `mask`, so nothing past the pixel (the next
// pixel's labels, or the end of the image) is read and its missing labels are 0.
CAIRN_TARGET_AVX2 inline __m256 LoadChunk(const float* p, int k, int last, __m256i mask) {
  return k < last ? _mm256_loadu_ps(p + 8 * k) : _mm256_maskload_ps(p + 8 * k, mask);
}

// Lanes [0, count) of the last chunk hold labels.
CAIRN_TARGET_AVX2 inline __m256i ChunkMask(int count) {
  return _mm256_cmpgt_epi32(_mm256_set1_epi32(count), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}

// Lanes set where !(0 <= x <= 1), NaN included.
CAIRN_TARGET_AVX2 inline __m256 OutsideUnitInterval(__m256 x) {
  return _mm256_or_ps(_mm256_cmp_ps(x, _mm256_setzero_ps(), _CMP_NGE_UQ),
                      _mm256_cmp_ps(x, _mm256_set1_ps(1.0f), _CMP_NLE_UQ));
}

// kChunks: the number of 8-label chunks per pixel when it is a compile-time constant (loops then unroll and the
// lanes stay in registers), else 0.
template <int kVectors, int kChunks>
CAIRN_TARGET_AVX2 bool Avx2PixelDots(const float* row, const float* next_row, int cols, int n, const float* vectors,
                                     int stride, float* const* out, float* /*padded*/) {
  const int last = kChunks > 0 ? kChunks - 1 : (n - 1) / 8;
  const __m256i mask = ChunkMask(n - 8 * last);
  __m256 outside = _mm256_setzero_ps();
  // The exact search spends more time per row on its rounds than on this pass, long enough for the hardware
  // prefetcher to lose the stream: the next row is requested here, pixel by pixel, so that it is in cache when its
  // turn comes (a prefetch of `row` itself, when there is no next row, is a no-op).
  const float* ahead = next_row != nullptr ? next_row : row;
  for (int c0 = 0; c0 < cols; c0 += 8) {
    __m256 lanes[kVectors][8];
    for (int m = 0; m < 8; ++m) {
      // Past the row's end, the last pixel again: its results land in the arrays' padding.
      const float* p = row + static_cast<std::size_t>(std::min(c0 + m, cols - 1)) * n;
      _mm_prefetch(reinterpret_cast<const char*>(ahead + (p - row)), _MM_HINT_T0);
      __m256 x = LoadChunk(p, 0, last, mask);
      outside = _mm256_or_ps(outside, OutsideUnitInterval(x));
      for (int v = 0; v < kVectors; ++v) lanes[v][m] = _mm256_mul_ps(x, _mm256_load_ps(vectors + v * stride));
      for (int k = 1; k <= last; ++k) {
        x = LoadChunk(p, k, last, mask);
        outside = _mm256_or_ps(outside, OutsideUnitInterval(x));
        for (int v = 0; v < kVectors; ++v) {
          lanes[v][m] = _mm256_add_ps(lanes[v][m], _mm256_mul_ps(x, _mm256_load_ps(vectors + v * stride + 8 * k)));
        }
      }
    }
    for (int v = 0; v < kVectors; ++v) _mm256_storeu_ps(out[v] + c0, SumLanes8(lanes[v]));
  }
  return _mm256_movemask_ps(outside) == 0;
}

template <int kChunks>
CAIRN_TARGET_AVX2 void Avx2CellDots(const float* row, int n, const int* pixel, const int* cell, int count,
                                    const float* table, int stride, float* f_low, float* f_high,
                                    float* /*padded*/) {
  const int last = kChunks > 0 ? kChunks - 1 : (n - 1) / 8;
  const __m256i mask = ChunkMask(n - 8 * last);
  for (int k0 = 0; k0 < count; k0 += 4) {
    __m256 lanes[8];  // [0, 4): four pixels at their cells' left ends; [4, 8): at the right ends.
    for (int m = 0; m < 4; ++m) {
      const int k = std::min(k0 + m, count - 1);  // Past the list's end, the last pair again (into the padding).
      const float* p = row + static_cast<std::size_t>(pixel[k]) * n;
      const float* t = table + static_cast<std::size_t>(cell[k]) * stride;
      __m256 x = LoadChunk(p, 0, last, mask);
      lanes[m] = _mm256_mul_ps(x, _mm256_load_ps(t));
      lanes[m + 4] = _mm256_mul_ps(x, _mm256_load_ps(t + stride));
      for (int j = 1; j <= last; ++j) {
        x = LoadChunk(p, j, last, mask);
        lanes[m] = _mm256_add_ps(lanes[m], _mm256_mul_ps(x, _mm256_load_ps(t + 8 * j)));
        lanes[m + 4] = _mm256_add_ps(lanes[m + 4], _mm256_mul_ps(x, _mm256_load_ps(t + stride + 8 * j)));
      }
    }
    const __m256 f = SumLanes8(lanes);
    _mm_storeu_ps(f_low + k0, _mm256_castps256_ps128(f));
    _mm_storeu_ps(f_high + k0, _mm256_extractf128_ps(f, 1));
  }
}

CAIRN_TARGET_AVX2 void Avx2GaussianQuantiles(const float* mean, const float* second, int cols, float z,
                                             float* out) {
  const __m256 zero = _mm256_setzero_ps();
  const __m256 scale = _mm256_set1_ps(z);
  int c = 0;
  for (; c + 8 <= cols; c += 8) {
    const __m256 m = _mm256_loadu_ps(mean + c);
    // max_ps(a, b) = a > b ? a : b, so these are std::max(s − m², 0) and std::max(0, q) operand for operand.
    const __m256 variance = _mm256_max_ps(zero, _mm256_sub_ps(_mm256_loadu_ps(second + c), _mm256_mul_ps(m, m)));
    const __m256 q = _mm256_add_ps(m, _mm256_mul_ps(_mm256_sqrt_ps(variance), scale));
    _mm256_storeu_ps(out + c, _mm256_max_ps(q, zero));
  }
  PortableGaussianQuantiles(mean + c, second + c, cols - c, z, out + c);
}
#endif  // CAIRN_FRICTION_QUANTILE_AVX2

bool Avx2Available() {
#if CAIRN_FRICTION_QUANTILE_AVX2
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

PixelDotsKernel PixelDots(bool avx2, int num_labels, int num_vectors) {
  CAIRN_CHECK(num_vectors == 3 || num_vectors == 4);
#if CAIRN_FRICTION_QUANTILE_AVX2
  if (avx2) {
    const int chunks = (num_labels + 7) / 8;
    if (num_vectors == 3) {
      return chunks == 1 ? Avx2PixelDots<3, 1> : chunks == 2 ? Avx2PixelDots<3, 2> : Avx2PixelDots<3, 0>;
    }
    return chunks == 1 ? Avx2PixelDots<4, 1> : chunks == 2 ? Avx2PixelDots<4, 2> : Avx2PixelDots<4, 0>;
  }
#endif
  static_cast<void>(avx2);
  static_cast<void>(num_labels);
  return num_vectors == 3 ? PortablePixelDots<3> : PortablePixelDots<4>;
}

GaussianKernel GaussianQuantiles(bool avx2) {
#if CAIRN_FRICTION_QUANTILE_AVX2
  if (avx2) return Avx2GaussianQuantiles;
#endif
  static_cast<void>(avx2);
  return PortableGaussianQuantiles;
}

CellDotsKernel CellDots(bool avx2, int num_labels) {
#if CAIRN_FRICTION_QUANTILE_AVX2
  if (avx2) {
    const int chunks = (num_labels + 7) / 8;
    return chunks == 1 ? Avx2CellDots<1> : chunks == 2 ? Avx2CellDots<2> : Avx2CellDots<0>;
  }
#endif
  static_cast<void>(avx2);
  static_cast<void>(num_labels);
  return PortableCellDots;
}

// The per-pixel arithmetic that follows the dot products is the same code on every processor: element-wise
// selects over the row's arrays, no branches, so that the compiler vectorises it (and a mispredicted branch per
// pixel does not cost more than the arithmetic). Conditions combine with & and |, not && and ||, and values are
// loaded and converted unconditionally: GCC if-converts a loop only when it need not speculate a load or a float
// operation that may trap. The arrays of one call never overlap (__restrict), which spares the vectoriser
// run-time overlap checks it would otherwise give up on.

CAIRN_MULTIVERSION
bool AllSumsAreOne(const float* sum, int cols) {
  int bad = 0;
  for (int c = 0; c < cols; ++c) bad |= SumIsOne(sum[c]) ? 0 : 1;
  return bad == 0;
}

// The exact search's first cells: numerator / slope (see the constructor), clamped to the table's cells. A pixel
// without walkable mass has slope 0 and a NaN or infinite ratio, which gives an end cell (such a pixel reaches the
// target at μ = 0 and does not search anyway).
CAIRN_MULTIVERSION
void FirstCells(const float* numerator, const float* slope, int cols, int last, int* cell) {
  const float top = static_cast<float>(last - 1);
  for (int c = 0; c < cols; ++c) {
    const float x = numerator[c] / slope[c];
    cell[c] = static_cast<int>(x >= 0.0f ? (x < top ? x : top) : 0.0f);
  }
}

// One round of the exact search for `count` pixels (see ExactQuantilesOfRow()): from the tabulated CDF at both
// ends of each pixel's cell, its new bracket and next cell, whether it is done, and its quantile (final when
// done), `step` being the table spacing (a power of two, so the product is exact).
CAIRN_MULTIVERSION
void ExactSearchStep(int count, float target, int last, float step, const float* __restrict f_low,
                     const float* __restrict f_high, int* __restrict low, int* __restrict high, int* __restrict cell,
                     float* __restrict quantile, int* __restrict done) {
  const float last_point = static_cast<float>(last);
  for (int k = 0; k < count; ++k) {
    const int j = cell[k];
    const float g_low = f_low[k];
    const float g_high = f_high[k];
    const int old_low = low[k];
    const int old_high = high[k];
    const bool above = g_low >= target;  // The root is left of the cell.
    const bool below = g_high < target;  // The root is right of the cell.
    const int new_low = below ? j + 1 : old_low;
    const int new_high = above ? j : old_high;
    const float low_point = static_cast<float>(new_low);
    const float high_point = static_cast<float>(new_high);
    // Where the line through the cell's end points meets the target, in cells: the root when the cell holds it,
    // else Newton's next guess; infinite or NaN for a flat cell, which fails the bracket test.
    const float guess = static_cast<float>(j) + (target - g_low) / (g_high - g_low);
    const bool inside = (guess >= low_point) & (guess < high_point);
    const bool at_end = below & (new_low == last);  // Rounding kept G under the target up to the table's end.
    done[k] = !(above | below) | at_end ? 1 : 0;
    quantile[k] = (at_end ? last_point : guess) * step;
    low[k] = new_low;
    high[k] = new_high;
    // Newton's cell is converted from the guess clamped to the bracket (a NaN guess gives the low end), so that
    // the conversion is defined for every pixel; it is used only when the guess is inside anyway.
    const int newton = static_cast<int>(std::min(std::max(low_point, guess), high_point));
    const int middle = (new_low + new_high - 1) / 2;
    cell[k] = std::min(inside ? newton : middle, last - 1);
  }
}

// One round of Algorithm 1's scan for `count` pixels (see SearchQuantilesOfRow()).
CAIRN_MULTIVERSION
void SearchStep(int count, float target, int last, double step, const float* __restrict f_low,
                const float* __restrict f_high, int* __restrict next_point, int* __restrict cell,
                float* __restrict quantile, int* __restrict done) {
  for (int k = 0; k < count; ++k) {
    const int j = next_point[k];
    const int first_cell = cell[k];  // min(j, last - 1): when j is the last point, only the cell's right end is new.
    const bool low_exceeds = (first_cell == j) & (f_low[k] > target);
    const bool high_exceeds = f_high[k] > target;
    // The first point whose CDF exceeds the target (last + 1: none does); the answer is the point before it, or 0.
    const int first = low_exceeds ? first_cell : (high_exceeds ? first_cell + 1 : last + 1);
    quantile[k] = static_cast<float>(std::max(first - 1, 0) * step);
    done[k] = low_exceeds | high_exceeds | (first_cell + 1 == last) ? 1 : 0;
    next_point[k] = j + 2;
    cell[k] = std::min(j + 2, last - 1);
  }
}

// Writes each listed pixel's quantile to `out` (final for the pixels done) and keeps, in order, the list entries
// (`active` and the searches' `state` arrays) of the pixels not done; returns how many.
template <typename... State>
int KeepSearching(int count, const int* done, const float* quantile, float* out, int* active, State*... state) {
  int next = 0;
  for (int k = 0; k < count; ++k) {
    out[active[k]] = quantile[k];
    active[next] = active[k];
    ((state[next] = state[k]), ...);
    next += 1 - done[k];
  }
  return next;
}

}  // namespace

struct FrictionQuantileImage::Workspace {
  // Room for the kernels' padding: rows rounded up to 8 pixels.
  Workspace(int cols, int stride, bool portable)
      : dots{std::vector<float>(cols + 8), std::vector<float>(cols + 8), std::vector<float>(cols + 8),
             std::vector<float>(cols + 8)},
        padded(portable ? static_cast<std::size_t>(cols) * stride : 0, 0.0f),
        f_low(cols + 8),
        f_high(cols + 8),
        quantile(cols),
        done(cols),
        active(cols),
        low(cols),
        high(cols),
        cell(cols) {}
  std::vector<float> dots[4];  // The validation pass: each pixel's dot products with dot_vectors_.
  std::vector<float> padded;   // The portable kernels' copy of the row (see PortablePixelDots), else empty.
  // The searches' state, one entry per pixel still searching: CellDots' results, the round's outcome, the pixel,
  // its bracket and its cell.
  std::vector<float> f_low, f_high, quantile;
  std::vector<int> done, active, low, high, cell;
};

FrictionQuantileImage::FrictionQuantileImage(const MaterialRegistry& registry, const Options& options)
    : options_(options), num_labels_(registry.size()), avx2_(Avx2Available()) {
  if (!(options.eta > 0.0 && options.eta < 1.0)) {
    throw std::invalid_argument("eta (the probability that friction is at least the quantile) must be in (0, 1); "
                                "got " + FormatShort(options.eta) + ".");
  }
  if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance)) {
    throw std::invalid_argument("The quantile search step must be finite and > 0; got " +
                                FormatShort(options.tolerance) + ".");
  }
  if (num_labels_ == 0) throw std::invalid_argument("FrictionQuantileImage: the material registry is empty.");
  const double target = 1.0 - options.eta;
  target_ = static_cast<float>(target);
  blocks_ = (num_labels_ + 15) / 16;
  stride_ = 16 * blocks_;
  num_dot_vectors_ = options.method == QuantileMethod::kExact ? 4 : 3;
  dot_vectors_.assign(static_cast<std::size_t>(num_dot_vectors_) * blocks_, Block{});
  std::fill_n(DotVector(0), num_labels_, 1.0f);

  if (options.method == QuantileMethod::kGaussian) {
    for (int i = 0; i < num_labels_; ++i) {
      const double m = registry.material(i).friction.Mean();
      DotVector(1)[i] = static_cast<float>(m);
      DotVector(2)[i] = static_cast<float>(registry.material(i).friction.Variance() + m * m);
    }
    z_ = static_cast<float>(StandardNormalQuantile(target));
    step_ = 0.0;
    num_points_ = 0;
    return;
  }

  // The mixture CDF at the largest component quantile is at least the target, so the table can stop there.
  double high = 0.0;
  for (const auto& material : registry.materials()) high = std::max(high, material.friction.Quantile(target));
  step_ = options.method == QuantileMethod::kExact ? kExactStep : options.tolerance;
  // Counted in double first: a tiny tolerance or a huge quantile must give this message, not an overflowing cast
  // and a table of gigabytes.
  const double points = std::ceil(high / step_) + 2.0;
  if (!(points <= kMaxTablePoints)) {
    throw std::invalid_argument("FrictionQuantileImage: a table up to the largest label quantile " + FormatShort(high) +
                                " in steps of " + FormatShort(step_) + " needs " + FormatShort(points) +
                                " points, more than the " + FormatShort(kMaxTablePoints) +
                                " supported; raise the tolerance");
  }
  num_points_ = static_cast<int>(points);
  table_.assign(static_cast<std::size_t>(num_points_) * blocks_, Block{});
  for (int j = 0; j < num_points_; ++j) {
    for (int i = 0; i < num_labels_; ++i) {
      TableRow(j)[i] = static_cast<float>(registry.material(i).friction.Cdf(j * step_));
    }
  }
  if (options.method == QuantileMethod::kSearch) {
    std::copy_n(TableRow(0), stride_, DotVector(1));
    std::copy_n(TableRow(1), stride_, DotVector(2));
    return;
  }
  // The exact search's first cell comes from each label's CDF linearised at its own quantile q_i (in cells),
  // F_i(x) ≈ (1 − η) + s_i (x − q_i) with s_i the slope of q_i's cell, and not-walkable labels' CDFs at 1: the
  // mixture of these lines meets the target at x = Σ_i p_i u_i / Σ_i p_i s_i, with u_i = s_i q_i for walkable
  // labels and −η for not-walkable ones (s_i = 0), two more dot products of the validation pass. Unlike the
  // probability-weighted mean of the q_i, it moves the guess with the small probabilities a segmenter leaves on
  // not-walkable labels, as they move the root. Far from q_i the lines undershoot the CDFs, so the guess is
  // typically a few cells right of the root; one Newton step from there mostly lands in the root's cell. On the
  // benchmark's segmenter-like image a searching pixel takes 2.24 cell evaluations on average (2.55 from the
  // weighted mean).
  for (int i = 0; i < num_labels_; ++i) {
    const FrictionDistribution& friction = registry.material(i).friction;
    if (!friction.walkable()) {
      DotVector(1)[i] = static_cast<float>(-options.eta);
      continue;
    }
    const double q = std::clamp(friction.Quantile(target) / step_, 0.0, num_points_ - 1.0);
    const int j = std::min(static_cast<int>(q), num_points_ - 2);
    const double slope = friction.Cdf((j + 1) * step_) - friction.Cdf(j * step_);
    DotVector(1)[i] = static_cast<float>(slope * q);
    DotVector(2)[i] = static_cast<float>(slope);
  }
  std::copy_n(TableRow(0), stride_, DotVector(3));
  for (int j = 0; j + 1 < num_points_; ++j) {
    for (int i = 0; i < num_labels_; ++i) {
      const double interpolated = 0.5 * (TableRow(j)[i] + TableRow(j + 1)[i]);
      // Point masses (not-walkable labels at 0) jump inside the first cell; they are handled exactly by the
      // F(0) >= target test before any interpolation.
      if (j == 0 && !registry.material(i).friction.walkable()) continue;
      cdf_interpolation_error_ = std::max(
          cdf_interpolation_error_, std::abs(interpolated - registry.material(i).friction.Cdf((j + 0.5) * step_)));
    }
  }
}

void FrictionQuantileImage::GaussianQuantilesOfRow(int cols, const Workspace& workspace, float* out) const {
  GaussianQuantiles(avx2_)(workspace.dots[1].data(), workspace.dots[2].data(), cols, z_, out);
}

void FrictionQuantileImage::SearchQuantilesOfRow(const float* row, int cols, Workspace* workspace,
                                                 float* out) const {
  // Algorithm 1 scans the grid from μ = 0 and stops at the first point whose CDF exceeds the target; the answer
  // is the point before it (0 if none is before it, the last point if none exceeds). Here every pixel scans two
  // points per round (one cell's ends), all pixels still scanning in the same round, so the scan visits exactly
  // Algorithm 1's points and a round's dot products are independent, not a chain. The first round's points, 0
  // and `step`, come from the validation pass. `low` holds each pixel's next point to scan.
  const CellDotsKernel cell_dots = CellDots(avx2_, num_labels_);
  int* active = workspace->active.data();
  int* next_point = workspace->low.data();
  int* cell = workspace->cell.data();
  const int last = num_points_ - 1;
  for (int c = 0; c < cols; ++c) {
    active[c] = c;
    next_point[c] = 0;
    cell[c] = 0;
  }
  const float* f_low = workspace->dots[1].data();
  const float* f_high = workspace->dots[2].data();
  int count = cols;
  while (true) {
    SearchStep(count, target_, last, step_, f_low, f_high, next_point, cell, workspace->quantile.data(),
               workspace->done.data());
    count = KeepSearching(count, workspace->done.data(), workspace->quantile.data(), out, active, next_point, cell);
    if (count == 0) break;
    cell_dots(row, num_labels_, active, cell, count, TableRow(0), stride_, workspace->f_low.data(),
              workspace->f_high.data(), workspace->padded.data());
    f_low = workspace->f_low.data();
    f_high = workspace->f_high.data();
  }
}

void FrictionQuantileImage::ExactQuantilesOfRow(const float* row, int cols, Workspace* workspace,
                                                float* out) const {
  // The root of the piecewise-linear tabulated CDF G of each pixel, found in rounds over the pixels still
  // searching ("wavefronts"): a round evaluates G at both ends of one cell per pixel (CellDots), then updates
  // every pixel's search (ExactSearchStep) and drops the finished ones from the list. Pixels are independent,
  // so a round's dot products have no dependency chain from one pixel to the next, and its decisions are selects
  // that vectorise.
  //
  // Per pixel, invariant G(low) < target <= G(high) (point indices; G at the table's last point is only known to
  // reach the target up to rounding). A cell with G(cell) < target <= G(cell + 1) holds the root, which linear
  // interpolation then gives exactly; otherwise the cell's end points move `low` or `high` past the cell, so
  // every pixel finishes. The next cell is Newton's guess with the cell's slope when that stays inside the
  // bracket, else the bracket's middle cell (bisection). The first cell (see the constructor) and G(0), which
  // decides whether a pixel searches at all, come from the validation pass.
  const CellDotsKernel cell_dots = CellDots(avx2_, num_labels_);
  int* active = workspace->active.data();
  int* low = workspace->low.data();
  int* high = workspace->high.data();
  int* cell = workspace->cell.data();
  const float* g0 = workspace->dots[3].data();
  const int last = num_points_ - 1;
  FirstCells(workspace->dots[1].data(), workspace->dots[2].data(), cols, last, cell);
  int count = 0;
  for (int c = 0; c < cols; ++c) {
    out[c] = 0.0f;  // Final for pixels whose mixture reaches the target at μ = 0 (mostly not-walkable ones).
    active[count] = c;
    low[count] = 0;
    high[count] = last;
    cell[count] = cell[c];
    count += g0[c] < target_ ? 1 : 0;
  }
  while (count > 0) {
    cell_dots(row, num_labels_, active, cell, count, TableRow(0), stride_, workspace->f_low.data(),
              workspace->f_high.data(), workspace->padded.data());
    ExactSearchStep(count, target_, last, static_cast<float>(step_), workspace->f_low.data(),
                    workspace->f_high.data(), low, high, cell, workspace->quantile.data(), workspace->done.data());
    count = KeepSearching(count, workspace->done.data(), workspace->quantile.data(), out, active, low, high, cell);
  }
}

std::string FrictionQuantileImage::DescribeFirstBadPixel(const float* row, int r, int cols) const {
  const int n = num_labels_;
  std::vector<float> padded(stride_, 0.0f);
  int c = 0;
  bool in_range = true;
  float sum = 0.0f;
  for (; c < cols; ++c) {
    const float* p = row + static_cast<std::size_t>(c) * n;
    in_range = true;
    for (int i = 0; i < n; ++i) in_range = in_range && InUnitInterval(p[i]);
    std::copy_n(p, n, padded.begin());
    sum = PaddedDot(padded.data(), DotVector(0), (n + 7) / 8);  // The validation pass's sum, in the same order.
    if (!(in_range && SumIsOne(sum))) break;
  }
  CAIRN_CHECK(c < cols);  // The validation pass rejected the row, so one of its pixels is bad.
  return "The material probabilities at pixel (" + cairn::FormatShort(r) + ", " + cairn::FormatShort(c) + ") " +
         (in_range ? "sum to " + FormatShort(sum) + ", not 1" : std::string("leave [0, 1]")) +
         "; normalise them (e.g. with a softmax).";
}

cv::Mat FrictionQuantileImage::Compute(const cv::Mat& probabilities) const {
  cv::Mat quantiles;
  Compute(probabilities, &quantiles);
  return quantiles;
}

void FrictionQuantileImage::Compute(const cv::Mat& probabilities, cv::Mat* quantiles) const {
  if (probabilities.empty() || probabilities.type() != CV_32FC(num_labels_)) {
    throw std::invalid_argument("Friction quantiles need a CV_32FC(" + cairn::FormatShort(num_labels_) +
                                ") probability image, one channel per registry label; got type " +
                                cairn::FormatShort(probabilities.type()) + " with " +
                                cairn::FormatShort(probabilities.channels()) + " channel(s).");
  }
  // The rows are read while quantiles are written: a header keeps the probabilities alive should `quantiles` be
  // the same cv::Mat, and an output sharing their pixels (a one-label image) gets a buffer of its own.
  const cv::Mat input = probabilities;
  if (quantiles->data == input.data) quantiles->release();
  quantiles->create(input.rows, input.cols, CV_32F);
  const int cols = input.cols;
  const PixelDotsKernel pixel_dots = PixelDots(avx2_, num_labels_, num_dot_vectors_);
  // A thread stops at its first bad row; its exception (a bad pixel, or an allocation failure) is rethrown here,
  // the first band's first, so the first bad pixel of the image is the one named.
  std::vector<std::exception_ptr> failures(ResolveThreadCount(options_.num_threads));
  ParallelFor(input.rows, static_cast<int>(failures.size()), [&](int thread, int row_begin, int row_end) {
    try {
      Workspace workspace(cols, stride_, !avx2_);
      float* const dots[4] = {workspace.dots[0].data(), workspace.dots[1].data(), workspace.dots[2].data(),
                              workspace.dots[3].data()};
      for (int r = row_begin; r < row_end; ++r) {
        const float* row = input.ptr<float>(r);
        float* out = quantiles->ptr<float>(r);
        // One pass validates the row and takes the dot products every method starts from; only a row that fails
        // is read again, to name its first bad pixel.
        const float* next_row = r + 1 < input.rows ? input.ptr<float>(r + 1) : nullptr;
        const bool in_range =
            pixel_dots(row, next_row, cols, num_labels_, DotVector(0), stride_, dots, workspace.padded.data());
        if (!(in_range && AllSumsAreOne(dots[0], cols))) {
          throw std::invalid_argument(DescribeFirstBadPixel(row, r, cols));
        }
        switch (options_.method) {
          case QuantileMethod::kExact:
            ExactQuantilesOfRow(row, cols, &workspace, out);
            break;
          case QuantileMethod::kSearch:
            SearchQuantilesOfRow(row, cols, &workspace, out);
            break;
          case QuantileMethod::kGaussian:
            GaussianQuantilesOfRow(cols, workspace, out);
            break;
        }
      }
    } catch (...) {
      failures[thread] = std::current_exception();
    }
  });
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

}  // namespace cairn::perception
