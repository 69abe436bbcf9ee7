#pragma once

/// @file
/// Internal: the cell-by-cell walk of a ray through a dense grid, shared by OccupancyGrid::Traverse() and the
/// occupancy sensor models' ray integration. Installed (unlike the internal/ folders) only because the template
/// OccupancyGrid::Traverse() uses it; namespace internal: not part of the installed API's contract.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <Eigen/Core>

namespace cairn::perception::internal {

/// A 3-D DDA (Amanatides-Woo) over the cells of an axis-aligned grid of cubic cells (x fastest in the linear index)
/// for the ray origin + t direction, t in [t_begin, t_end] clipped to the grid's box.
///
/// The walk runs on fixed-point ray parameters (integer multiples of unit() = 2^-n): choosing the axis to step is
/// then an integer comparison and conditional moves, a few one-cycle instructions on the loop-carried path, where
/// floating-point compares and selects cost several times that, and a branch on the axis (which changes irregularly
/// along a ray) is mispredicted often. The unit is at most 2^-57 of the largest |t| of the walk, finer than a
/// double's own rounding of t. Each axis' boundaries are its first one plus whole multiples of its spacing, so the
/// parameter at which the ray leaves the grid through each axis is known exactly before the walk: the walk ends
/// there, and no step can leave the grid whatever the rounding.
///
/// Where the ray passes through an edge or a corner of cells (two boundaries at the same t, up to rounding), the
/// cells it would cross for at most kSliver units (at most 2^-45 of the largest |t|, well above the rounding of
/// boundaries computed from coordinates of the size of the walk's t) are stepped over without a visit: they are
/// touched at a point, and rounding alone decides whether such a sliver exists. (Far from the origin, with
/// coordinates much larger than t, boundary rounding can exceed the sliver, and such cells may be visited for
/// their rounding-sized crossing.) Ties between boundaries go to the later axis (z, then y, then x).
class GridWalk {
 public:
  /// Crossings of at most this many units are not visited (see the class comment).
  static constexpr std::int64_t kSliver = std::int64_t{1} << 12;

  /// Prepares the walk; false when the clipped interval is empty. `direction` must not be zero.
  bool Start(const Eigen::Vector3d& min_corner, double resolution, const Eigen::Vector3i& dims,
             const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double t_begin, double t_end) {
    // Clip [t_begin, t_end] to the grid's box (slabs).
    double t0 = t_begin;
    double t1 = t_end;
    for (int a = 0; a < 3; ++a) {
      const double lo = min_corner[a];
      const double hi = min_corner[a] + dims[a] * resolution;
      if (direction[a] == 0.0) {
        if (origin[a] < lo || origin[a] >= hi) return false;
        continue;
      }
      double ta = (lo - origin[a]) / direction[a];
      double tb = (hi - origin[a]) / direction[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
    if (!(t0 < t1)) return false;
    t_begin_ = t0;
    t_end_ = t1;
    // max |t| < 2^exponent (kept above -900 so that the scale stays finite)
    const int exponent = std::max(BinaryExponent(std::max(std::abs(t0), std::abs(t1))), -900);
    scale_ = PowerOfTwo(kFractionBits - exponent);
    unit_ = PowerOfTwo(exponent - kFractionBits);
    // If t1 is the largest |t|, t1 * scale_ >= 2^(kFractionBits - 1) > 2^53 is an integer: end * unit_ == t1.
    std::int64_t end = static_cast<std::int64_t>(t1 * scale_);
    position_ = static_cast<std::int64_t>(t0 * scale_) * 4;
    const Eigen::Vector3d start = origin + t0 * direction;
    const std::ptrdiff_t axis_stride[3] = {1, dims.x(), static_cast<std::ptrdiff_t>(dims.x()) * dims.y()};
    index_ = 0;
    for (int a = 0; a < 3; ++a) {
      const int cell = std::min(dims[a] - 1, std::max(0, static_cast<int>((start[a] - min_corner[a]) / resolution)));
      index_ += cell * axis_stride[a];
      const int code = 2 - a;
      if (direction[a] == 0.0) {
        next_[a] = kNever * 4 + code;
        spacing_[a] = 0;
        stride_[code] = 0;
        continue;
      }
      const bool up = direction[a] > 0.0;
      // A start on a cell boundary may be assigned the cell whose computed boundary lies a rounding error behind
      // it; with a nearly parallel direction that boundary's t is then far negative. It is crossed at the start.
      const std::int64_t next =
          std::max(ToFixedSaturated((min_corner[a] + (cell + (up ? 1 : 0)) * resolution - origin[a]) / direction[a]),
                   position_ / 4);
      const std::int64_t spacing = ToFixedSaturated(resolution / std::abs(direction[a]));
      next_[a] = next * 4 + code;
      spacing_[a] = spacing * 4;
      stride_[code] = up ? axis_stride[a] : -axis_stride[a];
      // The ray leaves the grid at this axis' boundary after its last cell.
      const std::int64_t steps_left = up ? dims[a] - 1 - cell : cell;
      if (static_cast<double>(next) + static_cast<double>(steps_left) * static_cast<double>(spacing) <
          static_cast<double>(kNever)) {
        end = std::min(end, next + steps_left * spacing);
      }
    }
    end_ = end * 4;
    return position_ < end_;
  }

  /// Visits the cells whose entry is before `until` (fixed point), in order: visit(index, exit) with the cell's
  /// linear index and the fixed-point parameter at which the ray leaves it (its entry is the previous exit, or
  /// position() for the first). Returns false once the walk is over: the end is reached or visit returned false.
  template <typename Visit>
  bool Walk(std::int64_t until, const Visit& visit) {
    std::int64_t x = next_[0], y = next_[1], z = next_[2];
    const std::int64_t x_spacing = spacing_[0], y_spacing = spacing_[1], z_spacing = spacing_[2];
    std::int64_t position = position_;
    std::ptrdiff_t index = index_;
    const std::int64_t end = end_;
    const std::int64_t limit = until < kNever ? std::min(until * 4, end) : end;
    bool stopped = false;
    while (position < limit) {
      // The next exit is the smallest of the three boundaries, and its code the axis to step. An axis steps when
      // its boundary is below the other two (the codes make the three distinct): against their minimum, computed
      // beside it, which keeps the loop-carried path to a minimum, a compare and a conditional move.
      const std::int64_t yz = std::min(y, z);
      const std::int64_t xz = std::min(x, z);
      const std::int64_t xy = std::min(x, y);
      const std::int64_t first = std::min(x, yz);
      const std::int64_t exit = std::min(first, end);
      const std::ptrdiff_t stride = stride_[first & 3];
      if (exit - position > kSliver * 4 && !visit(static_cast<std::size_t>(index), exit >> 2)) {
        stopped = true;
        break;
      }
      position = exit;
      x = x < yz ? x + x_spacing : x;
      y = y < xz ? y + y_spacing : y;
      z = z < xy ? z + z_spacing : z;
      index += stride;
    }
    next_[0] = x;
    next_[1] = y;
    next_[2] = z;
    position_ = position;
    index_ = index;
    return !stopped && position < end_;
  }

  /// Fixed-point value of a parameter (rounded toward zero), saturated to [-kNever, kNever] (beyond any walk).
  std::int64_t ToFixedSaturated(double t) const {
    const double scaled = t * scale_;
    if (!(scaled < static_cast<double>(kNever))) return kNever;  // NaN too
    return scaled > -static_cast<double>(kNever) ? static_cast<std::int64_t>(scaled) : -kNever;
  }
  /// The parameter t of one fixed-point unit.
  double unit() const { return unit_; }
  /// Units per unit of t (1 / unit()).
  double scale() const { return scale_; }
  /// Entry of the next cell to visit (fixed point).
  std::int64_t position() const { return position_ >> 2; }
  /// The clipped interval, exactly as given or computed in double.
  double t_begin() const { return t_begin_; }
  double t_end() const { return t_end_; }

 private:
  // The e with 2^(e - 1) <= x < 2^e of a positive normal x (frexp's exponent, without the library call).
  static int BinaryExponent(double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof(bits));
    return static_cast<int>((bits >> 52) & 0x7ff) - 1022;
  }
  // 2^n for -1022 <= n <= 1023.
  static double PowerOfTwo(int n) {
    const std::uint64_t bits = static_cast<std::uint64_t>(n + 1023) << 52;
    double x;
    std::memcpy(&x, &bits, sizeof(x));
    return x;
  }

  // Fixed-point parameters have kFractionBits bits below the largest |t| of the walk, and are stored times 4 plus
  // a code of their axis (x 2, y 1, z 0): the three next boundaries are then distinct, the smallest one is the
  // next exit and its code the axis to step, and ties go to the later axis (z before y before x).
  static constexpr int kFractionBits = 58;
  // Beyond the end of any walk (whose parameters are below 2^58); times 4 plus a spacing, cannot overflow.
  static constexpr std::int64_t kNever = std::int64_t{1} << 59;

  double t_begin_{0.0};
  double t_end_{0.0};
  double scale_{1.0};
  double unit_{1.0};
  // Stored times 4 (with the axis code in the low bits for the boundaries).
  std::int64_t position_{0};
  std::int64_t end_{0};
  std::int64_t next_[3]{};      // the next boundary of each axis x, y, z
  std::int64_t spacing_[3]{};   // between an axis' boundaries
  std::ptrdiff_t stride_[4]{};  // linear-index step across a boundary, by axis code
  std::ptrdiff_t index_{0};
};

}  // namespace cairn::perception::internal
