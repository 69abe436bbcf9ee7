#pragma once

/// @file
/// HierarchicalTraversability: Algorithm 1 of seed 001 — collapsibility, else semantics, else geometry.

#include <string>
#include <vector>

#include "cairn/perception/terrain/grid_map.h"

namespace cairn::perception {

/// The traversability t in [0, 1] of every cell by seed 001's hierarchical rule (Algorithm 1):
///   1. collapsibility C known (layer "collapsibility" not NaN) → t = 1 − C;
///   2. else, a semantic class present (layer "semantic_<class>" at least semantic_threshold; the most probable
///      class if several) → that class's fixed value (plants 0.8, water 0.3 in the paper);
///   3. else geometry: t = 1 − w_s · slope / slope_crit − w_r · roughness / roughness_crit, clamped to [0, 1];
///      a slope or roughness at or above its critical value makes the cell untraversable (t = 0) whatever the
///      other, as in Wermelinger et al. 2016, which the paper follows;
///   4. else (no geometry either) NaN: unknown.
/// Missing layers count as unknown everywhere (a map without collapsibility uses steps 2–4).
class HierarchicalTraversability {
 public:
  /// A semantic class and the traversability it gives a cell.
  struct SemanticValue {
    std::string name;
    double traversability{0.0};
  };

  struct Options {
    /// The classes and their fixed values (seed 001 §4.1).
    std::vector<SemanticValue> semantic_values{{"plants", 0.8}, {"water", 0.3}};
    /// Fused class probability from which a cell counts as of that class.
    double semantic_threshold{0.5};
    double slope_weight{0.5};
    double roughness_weight{0.5};
    /// Critical slope, rad (30°, a quadruped's usual limit).
    double critical_slope{0.5235987755982988};
    /// Critical roughness, m (about half a quadruped's step-height margin).
    double critical_roughness{0.05};
    /// Measurement variance of a cell's traversability by the level of the rule that set it, for registering a
    /// local traversability map into a global one (seed 001 §4.2: constants for probing and semantics, probing
    /// the smaller because touch identifies the ground; the sensor model for geometry).
    double probe_variance{0.0025};
    double semantic_variance{0.04};
    /// Geometry: at least this, more where the heights are uncertain. With an "elevation_variance" layer the
    /// variance is propagated from the heights' to first order through the roughness term (height noise of
    /// standard deviation sigma adds about sigma to a window's roughness): var(t) = max(geometry_variance,
    /// (roughness_weight / critical_roughness)^2 * elevation_variance). The floor keeps a well-fused height map
    /// (whose posterior variance shrinks with every point) from outweighing a probe: the geometric rule is a
    /// model of traversability, not a measurement of it, whatever the heights' precision.
    double geometry_variance{0.01};
    /// Threads (0 = one per core).
    int num_threads{0};
  };

  /// Most semantic classes.
  static constexpr int kMaxClasses = 16;

  /// Throws std::invalid_argument for a class value outside [0, 1], an empty or repeated class, more than
  /// kMaxClasses, a threshold outside (0, 1], negative or non-finite weights (or both zero), or non-positive
  /// critical values or variances.
  explicit HierarchicalTraversability(const Options& options);
  HierarchicalTraversability() : HierarchicalTraversability(Options{}) {}

  const Options& options() const { return options_; }

  /// The rule for one cell: `semantic` holds the classes' probabilities in the order of semantic_values (NaN =
  /// unknown), or is null when there are none.
  double CellValue(double collapsibility, const double* semantic, double slope, double roughness) const;

  /// Which level of the rule decides a cell (kUnknown where CellValue is NaN).
  enum class Source { kCollapsibility, kSemantics, kGeometry, kUnknown };
  /// The level CellValue() uses for these inputs.
  Source CellSource(double collapsibility, const double* semantic, double slope, double roughness) const;

  /// Writes layers "traversability" and "traversability_variance" of `map` (added if missing) from its layers: the
  /// value by CellValue(), its measurement variance by the level that set it (Options; NaN where unknown), ready
  /// for MapRegistration with variance_layer "traversability_variance".
  void Compute(GridMap* map) const;

 private:
  // The class step 2 picks, or -1.
  int MostProbableClass(const double* semantic) const;

  Options options_;
  std::vector<std::string> layer_names_;  // "semantic_<class>", named once
  int threads_{1};
};

}  // namespace cairn::perception
