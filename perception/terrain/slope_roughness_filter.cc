#include "cairn/perception/terrain/slope_roughness_filter.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "cairn/common/number_text.h"
#include "cairn/common/parallel_for.h"
#include "cairn/perception/terrain/internal/parallel_bands.h"

namespace cairn::perception {

SlopeRoughnessFilter::SlopeRoughnessFilter(const Options& options) : options_(options) {
  if (options.window_radius < 1 || options.window_radius > kMaxWindowRadius) {
    throw std::invalid_argument("SlopeRoughnessFilter: window_radius " + FormatShort(options.window_radius) +
                                " cells must be in [1, " + FormatShort(kMaxWindowRadius) + "]");
  }
  const int window = (2 * options.window_radius + 1) * (2 * options.window_radius + 1);
  if (options.min_valid_cells < 3 || options.min_valid_cells > window) {
    throw std::invalid_argument("SlopeRoughnessFilter: min_valid_cells " + FormatShort(options.min_valid_cells) +
                                " must be in [3, " + FormatShort(window) + "] (a plane needs three heights)");
  }
  threads_ = ResolveThreadCount(options.num_threads);
}

void SlopeRoughnessFilter::Compute(GridMap* map, const std::string& elevation_layer) const {
  const int elevation = map->LayerIndex(elevation_layer);
  if (!map->HasLayer("slope")) map->AddLayer("slope");
  if (!map->HasLayer("roughness")) map->AddLayer("roughness");
  const int slope_layer = map->LayerIndex("slope");
  const int roughness_layer = map->LayerIndex("roughness");
  const std::vector<double>& z = map->layer_data(elevation);
  std::vector<double>& slope = map->layer_data(slope_layer);
  std::vector<double>& roughness = map->layer_data(roughness_layer);
  const GridMap& m = *map;
  const int nx = m.size().x();
  const int ny = m.size().y();
  const int r = options_.window_radius;
  const int min_valid = options_.min_valid_cells;
  const double res = m.resolution();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  internal::ParallelBands(nx, threads_, threads_, [&](int, int begin, int end) {
    for (int i = begin; i < end; ++i) {
      for (int j = 0; j < ny; ++j) {
        const int s = m.StorageIndex(i, j);
        const double z0 = z[s];
        if (std::isnan(z0)) {
          slope[s] = nan;
          roughness[s] = nan;
          continue;
        }
        // Normal equations of z - z0 = a dx + b dy + c in cell units (centred on the cell for conditioning).
        Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
        Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
        int count = 0;
        for (int di = -r; di <= r; ++di) {
          const int ii = i + di;
          if (ii < 0 || ii >= nx) continue;
          for (int dj = -r; dj <= r; ++dj) {
            const int jj = j + dj;
            if (jj < 0 || jj >= ny) continue;
            const double h = z[m.StorageIndex(ii, jj)];
            if (std::isnan(h)) continue;
            const Eigen::Vector3d row(di, dj, 1.0);
            A.noalias() += row * row.transpose();
            rhs += row * (h - z0);
            ++count;
          }
        }
        if (count < min_valid) {
          slope[s] = nan;
          roughness[s] = nan;
          continue;
        }
        // Collinear cells make the normal matrix singular; in cell units its determinant is count³ times the
        // spread of the cells, so a fixed relative threshold is scale-free.
        const double det = A.determinant();
        if (!(det > 1e-6 * A(2, 2) * A(2, 2) * A(2, 2))) {
          slope[s] = nan;
          roughness[s] = nan;
          continue;
        }
        const Eigen::Vector3d plane = A.ldlt().solve(rhs);
        double sum_sq = 0.0;
        for (int di = -r; di <= r; ++di) {
          const int ii = i + di;
          if (ii < 0 || ii >= nx) continue;
          for (int dj = -r; dj <= r; ++dj) {
            const int jj = j + dj;
            if (jj < 0 || jj >= ny) continue;
            const double h = z[m.StorageIndex(ii, jj)];
            if (std::isnan(h)) continue;
            const double e = (h - z0) - (plane.x() * di + plane.y() * dj + plane.z());
            sum_sq += e * e;
          }
        }
        const double gx = plane.x() / res;
        const double gy = plane.y() / res;
        slope[s] = std::atan(std::sqrt(gx * gx + gy * gy));
        roughness[s] = std::sqrt(sum_sq / count);
      }
    }
  });
}

}  // namespace cairn::perception
