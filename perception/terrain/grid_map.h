#pragma once

/// @file
/// GridMap: a 2-D map of named layers that moves with the robot over a circular buffer.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::perception {

/// A square-celled 2-D grid with any number of named layers of doubles (NaN = unknown), centred on a point of the
/// world's x-y plane, in the style of grid_map: moving the map with the robot (Move) changes only an index offset,
/// so no cell is copied; the cells that leave the map are reset to their layer's fill value and reappear on the
/// other side as the newly entered cells.
///
/// Cells are addressed by a map index (i, j): i along world x, j along world y, (0, 0) at the map's minimum corner.
/// Storage is one contiguous vector per layer, row-major over the *storage* index, which is the map index shifted
/// by start_index() modulo the size. Per-cell loops that do not care about the map index (fusion, traversability)
/// run directly over the storage.
class GridMap {
 public:
  /// Most cells a map may hold per axis, and in all (2^24 = a 200 m square at 5 cm, 128 MiB per layer).
  static constexpr int kMaxCellsPerAxis = 1 << 14;
  static constexpr std::int64_t kMaxCells = std::int64_t{1} << 24;
  /// Most layers a map may hold.
  static constexpr int kMaxLayers = 64;

  /// A map of `size` cells (x, y) of side `resolution` metres, centred on `center_W`, with no layers. Throws
  /// std::invalid_argument for a non-positive or non-finite resolution, a non-positive size, more than
  /// kMaxCellsPerAxis cells on an axis or kMaxCells in all, or a non-finite centre.
  GridMap(const Eigen::Vector2i& size, double resolution, const Eigen::Vector2d& center_W);

  /// Adds a layer whose cells all hold `fill` (also the value of cells that enter the map on Move) and returns its
  /// index. Throws std::invalid_argument for an empty name, a name already used, or more than kMaxLayers layers.
  int AddLayer(const std::string& name, double fill = std::numeric_limits<double>::quiet_NaN());
  /// Whether a layer of that name exists.
  bool HasLayer(const std::string& name) const;
  /// The index of layer `name`. Throws std::invalid_argument naming the layer and the layers there are.
  int LayerIndex(const std::string& name) const;
  /// The layers' names, in the order they were added.
  const std::vector<std::string>& layer_names() const { return names_; }
  int num_layers() const { return static_cast<int>(names_.size()); }

  const Eigen::Vector2i& size() const { return size_; }
  double resolution() const { return resolution_; }
  /// The centre of the map in the world (moves with Move, always by whole cells).
  const Eigen::Vector2d& center() const { return center_; }
  /// The map's side lengths in metres.
  Eigen::Vector2d length() const { return size_.cast<double>() * resolution_; }
  /// The world position of the map's minimum corner.
  Eigen::Vector2d min_corner() const { return center_ - 0.5 * length(); }
  /// The storage offset of map index (0, 0).
  const Eigen::Vector2i& start_index() const { return start_; }
  std::int64_t num_cells() const { return static_cast<std::int64_t>(size_.x()) * size_.y(); }

  /// The map index of the cell containing p_W; false (and `cell` untouched) outside the map.
  bool CellOf(const Eigen::Vector2d& p_W, Eigen::Vector2i* cell) const;
  /// The world position of the centre of map cell `cell` (which need not be inside the map).
  Eigen::Vector2d CellCenter(const Eigen::Vector2i& cell) const;
  /// Whether `cell` is a map index inside the map.
  bool Contains(const Eigen::Vector2i& cell) const {
    return cell.x() >= 0 && cell.y() >= 0 && cell.x() < size_.x() && cell.y() < size_.y();
  }
  /// The storage position (into layer_data()) of map cell (i, j), which must be inside the map.
  int StorageIndex(int i, int j) const {
    int si = i + start_.x();
    if (si >= size_.x()) si -= size_.x();
    int sj = j + start_.y();
    if (sj >= size_.y()) sj -= size_.y();
    return si * size_.y() + sj;
  }
  /// The map index of storage position `storage`.
  Eigen::Vector2i MapIndexOfStorage(int storage) const;

  /// Value of layer `layer` at map cell (i, j), inside the map (checked).
  double at(int layer, int i, int j) const;
  double& at(int layer, int i, int j);
  /// Value of layer `name` at the cell containing p_W; NaN outside the map.
  double ValueAt(const std::string& name, const Eigen::Vector2d& p_W) const;

  /// The storage of a layer (num_cells() values, in storage order).
  const std::vector<double>& layer_data(int layer) const;
  std::vector<double>& layer_data(int layer);
  /// Sets every cell of `layer` to `value`.
  void Fill(int layer, double value);
  /// The value layer `layer` was created with.
  double fill_value(int layer) const;

  /// Moves the map so that its centre is the cell corner-aligned position closest to `center_W` (a whole number of
  /// cells from the current centre). Only the cells that leave the map are touched: they are reset to their
  /// layers' fill values and become the entering cells. Returns the shift in cells. Throws std::invalid_argument
  /// for a non-finite centre or one so far away that the shift overflows (more than 2^30 cells).
  Eigen::Vector2i Move(const Eigen::Vector2d& center_W);

  /// Whether two maps have the same geometry (size, resolution, centre, start index) and layer names.
  bool SameLayoutAs(const GridMap& other) const;

 private:
  int CheckedLayer(int layer) const;
  void ClearStorageRows(int first_row, int count);
  void ClearStorageColumns(int first_column, int count);

  Eigen::Vector2i size_;
  double resolution_;
  Eigen::Vector2d center_;
  Eigen::Vector2i start_{0, 0};
  std::vector<std::string> names_;
  std::vector<double> fills_;
  std::vector<std::vector<double>> data_;
};

}  // namespace cairn::perception
