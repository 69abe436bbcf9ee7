#pragma once

/// @file
/// SemanticFusion: per-point class probabilities projected onto semantic layers of a grid map.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/perception/terrain/grid_map.h"

namespace cairn::perception {

/// Projects a segmenter's per-point class probabilities (the points being the segmented image's pixels in the
/// world frame) onto one layer per semantic class, "semantic_<class>", holding the fused probability that the cell
/// is of that class, with its variance in "semantic_<class>_variance". Each update averages the probabilities of
/// the points that fall in a cell and fuses that average with the one-dimensional Kalman update at a constant
/// measurement variance (seed 001 §4.2: semantics are registered like the other layers, to damp false
/// segmentations from the projection and the model). Deterministic for every thread count; no allocation per
/// update once the scratch has grown to the map and cloud sizes.
class SemanticFusion {
 public:
  /// Most classes, and most points per update.
  static constexpr int kMaxClasses = 16;
  static constexpr std::int64_t kMaxPoints = std::int64_t{1} << 24;

  struct Options {
    /// The semantic classes (seed 001: plants and water): the probability rows Integrate() receives, in this
    /// order, unless input_labels is set.
    std::vector<std::string> classes{"plants", "water"};
    /// The labels of the rows Integrate() receives when they come straight from a material segmenter
    /// (MaterialSegmenter::labels()), or empty when the rows are `classes`.
    std::vector<std::string> input_labels;
    /// With input_labels: the labels that make up each class, e.g. {"plants", {"grass"}} and {"water", {"water"}}
    /// for the built-in segmenter. A class's probability at a point is the sum of its labels'; a label belongs to
    /// at most one class, and labels of no class are ignored.
    std::map<std::string, std::vector<std::string>> class_labels;
    /// Measurement variance of one update's average probability.
    double measurement_variance{0.04};
    /// Threads (0 = one per core).
    int num_threads{0};
  };

  /// Throws std::invalid_argument for no classes, more than kMaxClasses, an empty or repeated class name, a
  /// non-positive variance or a bad thread count; with input_labels, for a repeated label, a class without labels,
  /// a label that is not an input label or belongs to two classes, or class_labels naming an unknown class (each
  /// message names the value). class_labels without input_labels is refused too.
  explicit SemanticFusion(const Options& options);
  SemanticFusion() : SemanticFusion(Options{}) {}

  const Options& options() const { return options_; }
  /// "semantic_<name>".
  static std::string LayerName(const std::string& class_name) { return "semantic_" + class_name; }

  /// Adds the class layers and their variance layers to `map` where missing.
  void AddLayers(GridMap* map) const;

  /// Rows Integrate() expects: input_labels' size, or the number of classes.
  int num_input_rows() const { return static_cast<int>(row_class_.size()); }

  /// Fuses `probabilities` (num_input_rows() x N, each in [0, 1]) of the points (3 x N, world frame) into `map`.
  /// Non-finite points and points outside the map are skipped. Throws std::invalid_argument for a row count other
  /// than num_input_rows(), a column count other than the points', more than kMaxPoints points, a probability
  /// outside [0, 1] (naming the point and the row's class or label), or a class's summed labels above 1.
  void Integrate(const Eigen::Matrix3Xd& points_W, const Eigen::MatrixXd& probabilities, GridMap* map);

 private:
  Options options_;
  int threads_{1};
  std::vector<std::string> layer_names_;
  std::vector<std::string> variance_names_;
  // The class of each input row, or -1 for a label of no class.
  std::vector<int> row_class_;
  std::vector<int> cell_of_point_;
  std::vector<double> sums_;  // cells x classes
  std::vector<int> counts_;
};

}  // namespace cairn::perception
