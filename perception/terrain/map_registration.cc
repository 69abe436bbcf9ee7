#include "cairn/perception/terrain/map_registration.h"

#include <cmath>
#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/terrain/internal/parallel_bands.h"
#include "cairn/perception/terrain/kalman_cell_update.h"

namespace cairn::perception {

MapRegistration::MapRegistration(std::vector<Layer> layers, int num_threads) : layers_(std::move(layers)) {
  if (layers_.empty()) throw std::invalid_argument("MapRegistration: no layers to register (give at least one)");
  if (static_cast<int>(layers_.size()) > GridMap::kMaxLayers) {
    throw std::invalid_argument("MapRegistration: " + FormatShort(static_cast<int>(layers_.size())) +
                                " layers exceed the limit of " + FormatShort(GridMap::kMaxLayers));
  }
  for (const auto& l : layers_) {
    if (l.local_layer.empty() || l.global_layer.empty()) {
      throw std::invalid_argument("MapRegistration: a layer has an empty local or global name");
    }
    if (l.variance_layer.empty() && (!(l.variance > 0.0) || !std::isfinite(l.variance))) {
      throw std::invalid_argument("MapRegistration: variance " + FormatShort(l.variance) + " of layer '" +
                                  l.local_layer + "' must be positive and finite (or name a variance layer)");
    }
  }
  threads_ = ResolveThreadCount(num_threads);
  for (const auto& l : layers_) variance_names_.push_back(l.global_layer + "_variance");
}

void MapRegistration::AddLayers(GridMap* global) const {
  for (const auto& l : layers_) {
    if (!global->HasLayer(l.global_layer)) global->AddLayer(l.global_layer);
    if (!global->HasLayer(l.global_layer + "_variance")) global->AddLayer(l.global_layer + "_variance");
  }
}

void MapRegistration::Register(const GridMap& local, GridMap* global) const {
  for (std::size_t index = 0; index < layers_.size(); ++index) {
    const Layer& l = layers_[index];
    const int src = local.LayerIndex(l.local_layer);
    const int src_var = l.variance_layer.empty() ? -1 : local.LayerIndex(l.variance_layer);
    const std::vector<double>& values = local.layer_data(src);
    const std::vector<double>* variances = src_var >= 0 ? &local.layer_data(src_var) : nullptr;
    std::vector<double>& mean = global->layer_data(global->LayerIndex(l.global_layer));
    std::vector<double>& var = global->layer_data(global->LayerIndex(variance_names_[index]));
    const double constant = l.variance;
    const GridMap& g = *global;
    internal::ParallelBands(g.size().x(), threads_, threads_, [&](int, int begin, int end) {
      for (int i = begin; i < end; ++i) {
        for (int j = 0; j < g.size().y(); ++j) {
          Eigen::Vector2i cell;
          if (!local.CellOf(g.CellCenter(Eigen::Vector2i(i, j)), &cell)) continue;
          const int ls = local.StorageIndex(cell.x(), cell.y());
          const double z = values[ls];
          if (!std::isfinite(z)) continue;
          const double v = variances != nullptr ? (*variances)[ls] : constant;
          if (!(v > 0.0) || !std::isfinite(v)) continue;
          const int gs = g.StorageIndex(i, j);
          KalmanCellUpdate(z, v, &mean[gs], &var[gs]);
        }
      }
    });
  }
}

}  // namespace cairn::perception
