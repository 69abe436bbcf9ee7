#include "cairn/perception/terrain/hierarchical_traversability.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/number_text.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/terrain/internal/parallel_bands.h"
#include "cairn/perception/terrain/semantic_fusion.h"

namespace cairn::perception {

namespace {

bool PositiveFinite(double x) { return x > 0.0 && std::isfinite(x); }

// Named once: longer than the small-string buffer, a literal would allocate on every Compute().
const std::string& VarianceLayer() {
  static const std::string name = "traversability_variance";
  return name;
}
const std::string& ElevationVarianceLayer() {
  static const std::string name = "elevation_variance";
  return name;
}

}  // namespace

HierarchicalTraversability::HierarchicalTraversability(const Options& options) : options_(options) {
  const auto& classes = options.semantic_values;
  if (static_cast<int>(classes.size()) > kMaxClasses) {
    throw std::invalid_argument("HierarchicalTraversability: " + FormatShort(static_cast<int>(classes.size())) +
                                " semantic classes exceed the limit of " + FormatShort(kMaxClasses));
  }
  for (std::size_t a = 0; a < classes.size(); ++a) {
    if (classes[a].name.empty()) throw std::invalid_argument("HierarchicalTraversability: a semantic class has an empty name");
    if (!(classes[a].traversability >= 0.0 && classes[a].traversability <= 1.0)) {
      throw std::invalid_argument("HierarchicalTraversability: traversability " +
                                  FormatShort(classes[a].traversability) + " of class '" + classes[a].name +
                                  "' must be in [0, 1] (seed 001: plants 0.8, water 0.3)");
    }
    for (std::size_t b = 0; b < a; ++b) {
      if (classes[a].name == classes[b].name) {
        throw std::invalid_argument("HierarchicalTraversability: class '" + classes[a].name + "' is listed twice");
      }
    }
  }
  if (!(options.semantic_threshold > 0.0 && options.semantic_threshold <= 1.0)) {
    throw std::invalid_argument("HierarchicalTraversability: semantic_threshold " +
                                FormatShort(options.semantic_threshold) + " must be in (0, 1] (e.g. 0.5)");
  }
  if (!(options.slope_weight >= 0.0) || !(options.roughness_weight >= 0.0) || !std::isfinite(options.slope_weight) ||
      !std::isfinite(options.roughness_weight) || options.slope_weight + options.roughness_weight <= 0.0) {
    throw std::invalid_argument("HierarchicalTraversability: weights slope " + FormatShort(options.slope_weight) +
                                ", roughness " + FormatShort(options.roughness_weight) +
                                " must be finite, non-negative and not both zero (e.g. 0.5 and 0.5)");
  }
  if (!PositiveFinite(options.critical_slope) || !PositiveFinite(options.critical_roughness)) {
    throw std::invalid_argument("HierarchicalTraversability: critical slope " + FormatShort(options.critical_slope) +
                                " rad and roughness " + FormatShort(options.critical_roughness) +
                                " m must be positive and finite");
  }
  for (const auto& [name, v] : {std::pair<const char*, double>{"probe_variance", options.probe_variance},
                                 {"semantic_variance", options.semantic_variance},
                                 {"geometry_variance", options.geometry_variance}}) {
    if (!PositiveFinite(v)) {
      throw std::invalid_argument(std::string("HierarchicalTraversability: ") + name + " " + FormatShort(v) +
                                  " must be positive and finite (defaults: probe 0.0025, semantic 0.04, geometry "
                                  "0.01)");
    }
  }
  threads_ = ResolveThreadCount(options.num_threads);
  for (const auto& c : classes) layer_names_.push_back(SemanticFusion::LayerName(c.name));
}

int HierarchicalTraversability::MostProbableClass(const double* semantic) const {
  if (semantic == nullptr) return -1;
  int best = -1;
  double best_p = options_.semantic_threshold;
  for (std::size_t c = 0; c < options_.semantic_values.size(); ++c) {
    const double p = semantic[c];
    if (p >= best_p) {  // NaN compares false: unknown classes never win
      best = static_cast<int>(c);
      best_p = p;
    }
  }
  return best;
}

HierarchicalTraversability::Source HierarchicalTraversability::CellSource(double collapsibility,
                                                                          const double* semantic, double slope,
                                                                          double roughness) const {
  if (!std::isnan(collapsibility)) return Source::kCollapsibility;
  if (MostProbableClass(semantic) >= 0) return Source::kSemantics;
  if (std::isnan(slope) || std::isnan(roughness)) return Source::kUnknown;
  return Source::kGeometry;
}

double HierarchicalTraversability::CellValue(double collapsibility, const double* semantic, double slope,
                                             double roughness) const {
  if (!std::isnan(collapsibility)) return std::clamp(1.0 - collapsibility, 0.0, 1.0);
  const int best = MostProbableClass(semantic);
  if (best >= 0) return options_.semantic_values[best].traversability;
  if (std::isnan(slope) || std::isnan(roughness)) return std::numeric_limits<double>::quiet_NaN();
  const double s = slope / options_.critical_slope;
  const double r = roughness / options_.critical_roughness;
  if (s >= 1.0 || r >= 1.0) return 0.0;
  return std::clamp(1.0 - options_.slope_weight * s - options_.roughness_weight * r, 0.0, 1.0);
}

void HierarchicalTraversability::Compute(GridMap* map) const {
  if (!map->HasLayer("traversability")) map->AddLayer("traversability");
  if (!map->HasLayer(VarianceLayer())) map->AddLayer(VarianceLayer());
  const int out = map->LayerIndex("traversability");
  const int out_variance = map->LayerIndex(VarianceLayer());
  const std::vector<double>* elevation_variance =
      map->HasLayer(ElevationVarianceLayer()) ? &map->layer_data(map->LayerIndex(ElevationVarianceLayer())) : nullptr;
  const double roughness_gain = options_.roughness_weight / options_.critical_roughness;
  const int k = static_cast<int>(options_.semantic_values.size());
  const std::vector<double>* collapsibility =
      map->HasLayer("collapsibility") ? &map->layer_data(map->LayerIndex("collapsibility")) : nullptr;
  const std::vector<double>* slope = map->HasLayer("slope") ? &map->layer_data(map->LayerIndex("slope")) : nullptr;
  const std::vector<double>* roughness =
      map->HasLayer("roughness") ? &map->layer_data(map->LayerIndex("roughness")) : nullptr;
  const std::vector<double>* semantic[kMaxClasses] = {};
  bool any_semantic = false;
  for (int c = 0; c < k; ++c) {
    const std::string& name = layer_names_[c];
    if (map->HasLayer(name)) {
      semantic[c] = &map->layer_data(map->LayerIndex(name));
      any_semantic = true;
    }
  }
  std::vector<double>& t = map->layer_data(out);
  std::vector<double>& t_variance = map->layer_data(out_variance);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  internal::ParallelBands(static_cast<int>(map->num_cells()), threads_, threads_, [&](int, int begin, int end) {
    double probabilities[kMaxClasses];
    for (int s = begin; s < end; ++s) {
      for (int c = 0; c < k; ++c) probabilities[c] = semantic[c] != nullptr ? (*semantic[c])[s] : nan;
      const double cs = collapsibility != nullptr ? (*collapsibility)[s] : nan;
      const double* ps = any_semantic ? probabilities : nullptr;
      const double ss = slope != nullptr ? (*slope)[s] : nan;
      const double rs = roughness != nullptr ? (*roughness)[s] : nan;
      t[s] = CellValue(cs, ps, ss, rs);
      switch (CellSource(cs, ps, ss, rs)) {
        case Source::kCollapsibility: t_variance[s] = options_.probe_variance; break;
        case Source::kSemantics: t_variance[s] = options_.semantic_variance; break;
        case Source::kGeometry: {
          const double ev = elevation_variance != nullptr ? (*elevation_variance)[s] : nan;
          // A cell of the filter's window without a height of its own has no variance: fall back to the constant.
          t_variance[s] = ev > 0.0 && std::isfinite(ev)
                              ? std::max(options_.geometry_variance, roughness_gain * roughness_gain * ev)
                              : options_.geometry_variance;
          break;
        }
        case Source::kUnknown: t_variance[s] = nan; break;
      }
    }
  });
}

}  // namespace cairn::perception
