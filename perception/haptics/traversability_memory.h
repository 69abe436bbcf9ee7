#pragma once

/// @file
/// The associative memory of descriptor–traversability tuples and its k-nearest-neighbour recall (seed 000, §3.4).

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/perception/haptics/affordance_descriptor.h"

namespace cairn::perception {

/// What the memory says about an observed object (eqs. 12–15).
struct AffordanceRecall {
  /// The label of the higher confidence (eq. 14); a tie (an empty memory included) says non-traversable, the
  /// cautious answer that makes the robot touch the object.
  bool traversable{false};
  /// max(c+, c-) (eq. 15).
  double confidence{0.0};
  /// c+(o), eq. 12: the summed similarity of the traversable neighbours over k.
  double confidence_traversable{0.0};
  /// c-(o), eq. 13: the same for the non-traversable neighbours.
  double confidence_non_traversable{0.0};
  /// Neighbours found: min(k, memory size).
  int neighbours{0};
  /// Index of the nearest entry, -1 for an empty memory.
  int nearest{-1};
  /// Its global dissimilarity (eq. 11), 1 for an empty memory.
  double nearest_dissimilarity{1.0};
};

/// The memory of §3.4: every haptic interaction adds one (descriptor, traversable) tuple and none is forgotten.
/// Recall compares the observed descriptor o with every stored o' by the local dissimilarities
///   Φn = Γ(ζ |n - n'|), Φs = Γ(β |s - s'|), Φd = Γ(γ |d - d'| / d), Φm = Γ(δ |m - m'| / m)   (eqs. 7–10)
/// with Γ clamping to [0, 1], averages them over the 4 |L_H| values (eq. 11), takes the k most similar entries
/// and sums 1 - Φ over the traversable and the non-traversable ones, each divided by k (eqs. 12–13). Eqs. 9–10
/// divide by the observed object's value: when it is 0 the term is 0 if the stored value is 0 too and 1
/// otherwise (the limit of Γ).
///
/// Entries are stored contiguously and Recall allocates nothing, so a recall against 1,000 memories is 56,000
/// multiply-adds (haptics_benchmark measures it).
class TraversabilityMemory {
 public:
  /// The paper's parameters (§4.1) as defaults.
  struct Options {
    double zeta{0.5};
    double beta{0.2};
    double gamma{2.0};
    double delta{2.0};
    /// Neighbours in the recall.
    int k{5};
  };

  /// Most neighbours a recall may use.
  static constexpr int kMaxNeighbours = 64;
  /// Most entries a memory holds (about 45 MB of 16 x 14 descriptors).
  static constexpr std::int64_t kMaxEntries = 100000;
  /// Largest memory file Load reads.
  static constexpr std::int64_t kMaxFileBytes = std::int64_t{256} << 20;

  /// An empty memory of descriptors with `lines` lines. Throws std::invalid_argument for invalid options or
  /// lines outside [1, AffordanceDescriptor::kMaxBins].
  explicit TraversabilityMemory(const Options& options, int lines = 14);
  /// An empty memory with the paper's options and 16 x 14 descriptors.
  TraversabilityMemory();

  /// Throws std::invalid_argument naming the first invalid option.
  static void Validate(const Options& options);

  /// Φ(o, o') of eq. 11. Throws std::invalid_argument when the line counts differ.
  static double Dissimilarity(const AffordanceDescriptor& observed, const AffordanceDescriptor& stored,
                              const Options& options);

  /// Adds the outcome of one interaction. Throws std::invalid_argument when the descriptor's line count differs
  /// from the memory's, or std::length_error when the memory already holds kMaxEntries.
  void Add(const AffordanceDescriptor& descriptor, bool traversable);

  /// The k-NN recall of eqs. 11–15 with the memory's options. Ties in dissimilarity keep the older entry.
  /// Throws std::invalid_argument when the line count differs. Allocates nothing.
  AffordanceRecall Recall(const AffordanceDescriptor& observed) const;
  /// The same with another k (1 <= k <= kMaxNeighbours), for the leave-one-out experiments.
  AffordanceRecall Recall(const AffordanceDescriptor& observed, int k) const;

  /// Writes the memory as text (options, then one entry a line) atomically: a reader sees the old file or the
  /// new one. Throws std::runtime_error naming the path on failure.
  void Save(const std::string& path) const;
  /// Reads a file written by Save. Throws std::runtime_error naming the path, the line and the bad value for a
  /// malformed or over-sized file (limits kMaxEntries and kMaxFileBytes).
  static TraversabilityMemory Load(const std::string& path);
  /// The text Save writes.
  std::string ToText() const;
  /// Parses ToText's format; `source` names the text in messages.
  static TraversabilityMemory FromText(const std::string& text, const std::string& source);

  const Options& options() const { return options_; }
  int lines() const { return lines_; }
  int size() const { return static_cast<int>(labels_.size()); }
  bool empty() const { return labels_.empty(); }
  /// Entry i's descriptor (a copy) and label.
  AffordanceDescriptor descriptor(int i) const;
  bool traversable(int i) const { return labels_.at(static_cast<std::size_t>(i)) != 0; }

 private:
  double DissimilarityTo(const double* observed, const double* stored) const;

  Options options_;
  int lines_;
  std::vector<double> values_;  // size() x 4 lines_, entry-major
  std::vector<std::uint8_t> labels_;
};

}  // namespace cairn::perception
