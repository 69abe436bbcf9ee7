#include "cairn/perception/terrain/semantic_fusion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/terrain/internal/parallel_bands.h"
#include "cairn/perception/terrain/kalman_cell_update.h"

namespace cairn::perception {

SemanticFusion::SemanticFusion(const Options& options) : options_(options) {
  const int k = static_cast<int>(options.classes.size());
  if (k < 1 || k > kMaxClasses) {
    throw std::invalid_argument("SemanticFusion: " + FormatShort(k) + " classes; give between 1 and " +
                                FormatShort(kMaxClasses));
  }
  for (int a = 0; a < k; ++a) {
    if (options.classes[a].empty()) throw std::invalid_argument("SemanticFusion: class " + FormatShort(a) +
                                                                " has an empty name");
    for (int b = 0; b < a; ++b) {
      if (options.classes[a] == options.classes[b]) {
        throw std::invalid_argument("SemanticFusion: class '" + options.classes[a] + "' is listed twice");
      }
    }
  }
  if (!(options.measurement_variance > 0.0) || !std::isfinite(options.measurement_variance)) {
    throw std::invalid_argument("SemanticFusion: measurement_variance " + FormatShort(options.measurement_variance) +
                                " must be positive and finite (e.g. 0.04)");
  }
  threads_ = ResolveThreadCount(options.num_threads);
  if (options.input_labels.empty()) {
    if (!options.class_labels.empty()) {
      throw std::invalid_argument("SemanticFusion: class_labels is given without input_labels; set input_labels to "
                                  "the segmenter's labels (MaterialSegmenter::labels()) or leave class_labels empty");
    }
    for (int c = 0; c < k; ++c) row_class_.push_back(c);
  } else {
    const auto& labels = options.input_labels;
    for (std::size_t a = 0; a < labels.size(); ++a) {
      if (labels[a].empty()) throw std::invalid_argument("SemanticFusion: input label " + FormatShort(a) +
                                                         " is empty");
      for (std::size_t b = 0; b < a; ++b) {
        if (labels[a] == labels[b]) {
          throw std::invalid_argument("SemanticFusion: input label '" + labels[a] + "' is listed twice");
        }
      }
    }
    row_class_.assign(labels.size(), -1);
    for (const auto& [name, members] : options.class_labels) {
      const auto c = std::find(options.classes.begin(), options.classes.end(), name);
      if (c == options.classes.end()) {
        throw std::invalid_argument("SemanticFusion: class_labels names class '" + name +
                                    "', which is not one of the classes; add it to classes or remove it");
      }
      for (const auto& label : members) {
        const auto row = std::find(labels.begin(), labels.end(), label);
        if (row == labels.end()) {
          throw std::invalid_argument("SemanticFusion: class '" + name + "' is made of label '" + label +
                                      "', which is not an input label; use one of the segmenter's labels");
        }
        int& owner = row_class_[static_cast<std::size_t>(row - labels.begin())];
        if (owner >= 0) {
          throw std::invalid_argument("SemanticFusion: label '" + label + "' belongs to classes '" +
                                      options.classes[owner] + "' and '" + name + "'; give it to one class");
        }
        owner = static_cast<int>(c - options.classes.begin());
      }
    }
    for (int c = 0; c < k; ++c) {
      if (std::find(row_class_.begin(), row_class_.end(), c) == row_class_.end()) {
        throw std::invalid_argument("SemanticFusion: class '" + options.classes[c] +
                                    "' has no input label; map it in class_labels (e.g. plants: [grass])");
      }
    }
  }
  for (const auto& c : options.classes) {
    layer_names_.push_back(LayerName(c));
    variance_names_.push_back(LayerName(c) + "_variance");
  }
}

void SemanticFusion::AddLayers(GridMap* map) const {
  for (const auto& c : options_.classes) {
    if (!map->HasLayer(LayerName(c))) map->AddLayer(LayerName(c));
    if (!map->HasLayer(LayerName(c) + "_variance")) map->AddLayer(LayerName(c) + "_variance");
  }
}

void SemanticFusion::Integrate(const Eigen::Matrix3Xd& points_W, const Eigen::MatrixXd& probabilities,
                               GridMap* map) {
  const int k = static_cast<int>(options_.classes.size());
  if (points_W.cols() > kMaxPoints) {
    throw std::invalid_argument("SemanticFusion: " + FormatShort(static_cast<long long>(points_W.cols())) +
                                " points exceed the limit of " + FormatShort(static_cast<long long>(kMaxPoints)));
  }
  const int rows = num_input_rows();
  const bool labelled = !options_.input_labels.empty();
  if (probabilities.rows() != rows || probabilities.cols() != points_W.cols()) {
    throw std::invalid_argument("SemanticFusion: probabilities are " + FormatShort(static_cast<long>(probabilities.rows())) +
                                " x " + FormatShort(static_cast<long>(probabilities.cols())) + "; expected " +
                                FormatShort(rows) + (labelled ? " input labels" : " classes") + " x " +
                                FormatShort(static_cast<long>(points_W.cols())) + " points");
  }
  const int n = static_cast<int>(points_W.cols());
  // A class's labels are summed: a little above 1 is the rounding of a float32 segmenter's many outputs, more is
  // not a distribution.
  constexpr double kSumTolerance = 1e-5;
  double class_sum[kMaxClasses];
  for (int p = 0; p < n; ++p) {
    std::fill(class_sum, class_sum + k, 0.0);
    for (int r = 0; r < rows; ++r) {
      const double v = probabilities(r, p);
      if (!(v >= 0.0 && v <= 1.0)) {
        throw std::invalid_argument("SemanticFusion: probability " + FormatShort(v) + " of " +
                                    (labelled ? "label '" + options_.input_labels[r]
                                              : "class '" + options_.classes[r]) +
                                    "' at point " + FormatShort(p) + " is not in [0, 1]");
      }
      if (row_class_[r] >= 0) class_sum[row_class_[r]] += v;
    }
    for (int c = 0; c < k; ++c) {
      if (class_sum[c] > 1.0 + kSumTolerance) {
        throw std::invalid_argument("SemanticFusion: the labels of class '" + options_.classes[c] + "' sum to " +
                                    FormatShort(class_sum[c]) + " (1 + " + FormatShort(class_sum[c] - 1.0) +
                                    ") at point " + FormatShort(p) + "; a segmenter's probabilities sum to at most 1");
      }
    }
  }
  const std::int64_t cells = map->num_cells();
  if (static_cast<int>(cell_of_point_.size()) < n) cell_of_point_.resize(n);
  if (static_cast<std::int64_t>(counts_.size()) != cells) {
    counts_.assign(cells, 0);
    sums_.assign(cells * k, 0.0);
  }
  int layer_index[kMaxClasses];
  int variance_index[kMaxClasses];
  for (int c = 0; c < k; ++c) {
    layer_index[c] = map->LayerIndex(layer_names_[c]);
    variance_index[c] = map->LayerIndex(variance_names_[c]);
  }
  internal::ParallelBands(n, threads_, threads_, [&](int, int begin, int end) {
    for (int p = begin; p < end; ++p) {
      Eigen::Vector2i cell;
      cell_of_point_[p] = points_W.col(p).allFinite() && map->CellOf(points_W.col(p).head<2>(), &cell)
                              ? map->StorageIndex(cell.x(), cell.y())
                              : -1;
    }
  });
  const int columns = map->size().y();
  const double var_m = options_.measurement_variance;
  internal::ParallelBands(map->size().x(), threads_, threads_, [&](int, int row_begin, int row_end) {
    const int lo = row_begin * columns;
    const int hi = row_end * columns;
    std::fill(counts_.begin() + lo, counts_.begin() + hi, 0);
    std::fill(sums_.begin() + static_cast<std::ptrdiff_t>(lo) * k, sums_.begin() + static_cast<std::ptrdiff_t>(hi) * k,
              0.0);
    for (int p = 0; p < n; ++p) {
      const int s = cell_of_point_[p];
      if (s < lo || s >= hi) continue;
      ++counts_[s];
      for (int r = 0; r < rows; ++r) {
        if (row_class_[r] >= 0) sums_[static_cast<std::size_t>(s) * k + row_class_[r]] += probabilities(r, p);
      }
    }
    for (int s = lo; s < hi; ++s) {
      if (counts_[s] == 0) continue;
      for (int c = 0; c < k; ++c) {
        // Sums of labels were checked to within kSumTolerance of 1; the rest is rounding.
        const double z = std::min(1.0, sums_[static_cast<std::size_t>(s) * k + c] / counts_[s]);
        KalmanCellUpdate(z, var_m, &map->layer_data(layer_index[c])[s], &map->layer_data(variance_index[c])[s]);
      }
    }
  });
}

}  // namespace cairn::perception
