#include "cairn/perception/terrain/grid_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cairn/common/cairn_assert.h"
#include "cairn/common/number_text.h"

namespace cairn::perception {

namespace {

int PositiveModulo(long long value, int modulus) {
  long long r = value % modulus;
  if (r < 0) r += modulus;
  return static_cast<int>(r);
}

}  // namespace

GridMap::GridMap(const Eigen::Vector2i& size, double resolution, const Eigen::Vector2d& center_W)
    : size_(size), resolution_(resolution), center_(center_W) {
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw std::invalid_argument("GridMap: resolution " + FormatShort(resolution) +
                                " m must be positive and finite (e.g. 0.05)");
  }
  for (int axis = 0; axis < 2; ++axis) {
    const char* name = axis == 0 ? "x" : "y";
    if (size[axis] < 1 || size[axis] > kMaxCellsPerAxis) {
      throw std::invalid_argument(std::string("GridMap: ") + name + " size " + FormatShort(size[axis]) +
                                  " cells must be in [1, " + FormatShort(kMaxCellsPerAxis) +
                                  "] (use a coarser resolution or a smaller map)");
    }
  }
  if (num_cells() > kMaxCells) {
    throw std::invalid_argument("GridMap: " + FormatShort(size.x()) + " x " + FormatShort(size.y()) + " = " +
                                FormatShort(static_cast<long long>(num_cells())) + " cells exceed the limit of " +
                                FormatShort(static_cast<long long>(kMaxCells)) +
                                " (use a coarser resolution or a smaller map)");
  }
  if (!center_W.allFinite()) {
    throw std::invalid_argument("GridMap: centre (" + FormatShort(center_W.x()) + ", " + FormatShort(center_W.y()) +
                                ") must be finite");
  }
}

int GridMap::AddLayer(const std::string& name, double fill) {
  if (name.empty()) throw std::invalid_argument("GridMap::AddLayer: the layer name is empty (give it a name)");
  if (HasLayer(name)) {
    throw std::invalid_argument("GridMap::AddLayer: a layer named '" + name +
                                "' exists already (layer names are unique)");
  }
  if (num_layers() >= kMaxLayers) {
    throw std::invalid_argument("GridMap::AddLayer: layer '" + name + "' would exceed the limit of " +
                                FormatShort(kMaxLayers) + " layers");
  }
  names_.push_back(name);
  fills_.push_back(fill);
  data_.emplace_back(static_cast<std::size_t>(num_cells()), fill);
  return num_layers() - 1;
}

bool GridMap::HasLayer(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

int GridMap::LayerIndex(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) {
    std::string known;
    for (const auto& n : names_) known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("GridMap: no layer named '" + name + "' (the map has: " +
                                (known.empty() ? std::string("no layers") : known) + ")");
  }
  return static_cast<int>(it - names_.begin());
}

bool GridMap::CellOf(const Eigen::Vector2d& p_W, Eigen::Vector2i* cell) const {
  if (!p_W.allFinite()) return false;
  const Eigen::Vector2d offset = (p_W - min_corner()) / resolution_;
  const double fx = std::floor(offset.x());
  const double fy = std::floor(offset.y());
  if (fx < 0.0 || fy < 0.0 || fx >= size_.x() || fy >= size_.y()) return false;
  *cell = Eigen::Vector2i(static_cast<int>(fx), static_cast<int>(fy));
  return true;
}

Eigen::Vector2d GridMap::CellCenter(const Eigen::Vector2i& cell) const {
  return min_corner() + (cell.cast<double>() + Eigen::Vector2d::Constant(0.5)) * resolution_;
}

Eigen::Vector2i GridMap::MapIndexOfStorage(int storage) const {
  const int si = storage / size_.y();
  const int sj = storage % size_.y();
  return Eigen::Vector2i(PositiveModulo(static_cast<long long>(si) - start_.x(), size_.x()),
                         PositiveModulo(static_cast<long long>(sj) - start_.y(), size_.y()));
}

int GridMap::CheckedLayer(int layer) const {
  if (layer < 0 || layer >= num_layers()) {
    throw std::invalid_argument("GridMap: layer index " + FormatShort(layer) + " is not in [0, " +
                                FormatShort(num_layers()) + ")");
  }
  return layer;
}

double GridMap::at(int layer, int i, int j) const {
  CAIRN_CHECK(Contains(Eigen::Vector2i(i, j)));
  return data_[CheckedLayer(layer)][StorageIndex(i, j)];
}

double& GridMap::at(int layer, int i, int j) {
  CAIRN_CHECK(Contains(Eigen::Vector2i(i, j)));
  return data_[CheckedLayer(layer)][StorageIndex(i, j)];
}

double GridMap::ValueAt(const std::string& name, const Eigen::Vector2d& p_W) const {
  const int layer = LayerIndex(name);
  Eigen::Vector2i cell;
  if (!CellOf(p_W, &cell)) return std::numeric_limits<double>::quiet_NaN();
  return data_[layer][StorageIndex(cell.x(), cell.y())];
}

const std::vector<double>& GridMap::layer_data(int layer) const { return data_[CheckedLayer(layer)]; }
std::vector<double>& GridMap::layer_data(int layer) { return data_[CheckedLayer(layer)]; }

void GridMap::Fill(int layer, double value) {
  auto& d = data_[CheckedLayer(layer)];
  std::fill(d.begin(), d.end(), value);
}

double GridMap::fill_value(int layer) const { return fills_[CheckedLayer(layer)]; }

void GridMap::ClearStorageRows(int first_row, int count) {
  for (int k = 0; k < count; ++k) {
    const int row = PositiveModulo(static_cast<long long>(first_row) + k, size_.x());
    for (int l = 0; l < num_layers(); ++l) {
      auto begin = data_[l].begin() + static_cast<std::ptrdiff_t>(row) * size_.y();
      std::fill(begin, begin + size_.y(), fills_[l]);
    }
  }
}

void GridMap::ClearStorageColumns(int first_column, int count) {
  for (int k = 0; k < count; ++k) {
    const int column = PositiveModulo(static_cast<long long>(first_column) + k, size_.y());
    for (int l = 0; l < num_layers(); ++l) {
      for (int row = 0; row < size_.x(); ++row) data_[l][static_cast<std::size_t>(row) * size_.y() + column] = fills_[l];
    }
  }
}

Eigen::Vector2i GridMap::Move(const Eigen::Vector2d& center_W) {
  if (!center_W.allFinite()) {
    throw std::invalid_argument("GridMap::Move: centre (" + FormatShort(center_W.x()) + ", " +
                                FormatShort(center_W.y()) + ") must be finite");
  }
  const Eigen::Vector2d cells = ((center_W - center_) / resolution_).array().round();
  if (cells.cwiseAbs().maxCoeff() > static_cast<double>(1 << 30)) {
    throw std::invalid_argument("GridMap::Move: the move to (" + FormatShort(center_W.x()) + ", " +
                                FormatShort(center_W.y()) + ") is more than 2^30 cells (is the position in metres?)");
  }
  const Eigen::Vector2i shift = cells.cast<int>();
  // Along each axis: a shift of +d drops map rows [0, d) (their storage becomes the new rows [n - d, n)); a shift
  // of -d drops rows [n - d, n). Only those rows are cleared; then the start offset moves.
  if (shift.x() != 0) {
    const int n = size_.x();
    const int d = std::min(std::abs(shift.x()), n);
    const int first = shift.x() > 0 ? start_.x() : start_.x() + n - d;
    ClearStorageRows(first, d);
    start_.x() = PositiveModulo(static_cast<long long>(start_.x()) + shift.x(), n);
  }
  if (shift.y() != 0) {
    const int n = size_.y();
    const int d = std::min(std::abs(shift.y()), n);
    const int first = shift.y() > 0 ? start_.y() : start_.y() + n - d;
    ClearStorageColumns(first, d);
    start_.y() = PositiveModulo(static_cast<long long>(start_.y()) + shift.y(), n);
  }
  center_ += shift.cast<double>() * resolution_;
  return shift;
}

bool GridMap::SameLayoutAs(const GridMap& other) const {
  return size_ == other.size_ && resolution_ == other.resolution_ && center_ == other.center_ &&
         start_ == other.start_ && names_ == other.names_;
}

}  // namespace cairn::perception
