#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/transition_optimizer.h>
#include <cairn/planning/locomotion/transition_source.h>
#include <cairn/planning/locomotion/model_transition_source.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>

namespace cairn::planning {

/// The displacements and friction limits an oracle table covers: the Cartesian product of the axes. Each axis
/// is strictly increasing; a single value is allowed (that coordinate is then fixed, and lookups must match it
/// within 1e-9). dy values must be positive (the bound min_cost_per_metre divides by hypot(dx, dy)) and mu
/// values positive.
struct OracleGrid {
  std::vector<double> dx, dy, dz, dtheta, mu;

  /// The default grid for `model`: dx every 5 cm over the reach, dy at the reach ends and every 5 cm between,
  /// dz every 5 cm over the reach, dtheta at 0, 15 and 30 degrees (the planner's 15-degree yaw bins) clipped to
  /// the reach, and mu in {0.04, 0.05, 0.06, 0.08, 0.10, 0.12, 0.15, 0.20, 0.30, 0.45, 0.70, 1.00}.
  static OracleGrid Default(const WalkingModel& model);

  /// Number of displacement cells (product of the four displacement axes).
  std::size_t num_displacements() const { return dx.size() * dy.size() * dz.size() * dtheta.size(); }
  /// Number of entries (displacements times mu values).
  std::size_t num_entries() const { return num_displacements() * mu.size(); }

  /// Reads a grid from YAML: the five keys dx, dy, dz, dtheta (radians) and mu, each a list of values or a range
  /// {from, to, step} (from, from + step, ... up to `to` within 1e-9; `to` need not be on the step). Throws
  /// std::invalid_argument naming the file, line and key for a missing or unknown key, a value that is not a
  /// finite number, a step that is not positive, or an axis of more than kMaxAxisValues values. The grid is
  /// not checked against a robot's reach here: Validate does that.
  static OracleGrid Load(const std::string& path);

  /// Most values an axis read by Load may hold.
  static constexpr std::size_t kMaxAxisValues = 10000;

  /// Most entries a grid may have: 2^26 (4.8 GB of entries in memory; the default grid has 8,064).
  static constexpr double kMaxEntries = 67108864.0;

  /// Throws std::invalid_argument naming the axis and the bad value if an axis is empty, not strictly
  /// increasing, non-finite, outside `reach` (mu: not positive), or dy is not positive, and naming the count if
  /// the grid has more than kMaxEntries entries.
  void Validate(const StepReach& reach) const;

  /// 16 hexadecimal digits identifying the grid's values: FNV-1a 64 (common/hash.h) of the five axis lines an
  /// oracle file's header holds (name, size and the values printed exactly, dx, dy, dz, dtheta, mu). Equal grids
  /// give equal fingerprints on every machine; the oracle cache names the files of non-default grids by it.
  std::string Fingerprint() const;
};

bool operator==(const OracleGrid& a, const OracleGrid& b);
inline bool operator!=(const OracleGrid& a, const OracleGrid& b) { return !(a == b); }

/// How an oracle table is built.
struct OracleBuildOptions {
  /// Worker threads (0 = one per core; rule: cairn::ResolveThreadCount). The table does not depend on it.
  int num_threads{0};
  /// Called from the building thread's workers, serialised, as (entries done, entries total); for a progress bar.
  std::function<void(std::size_t done, std::size_t total)> progress;
  /// Settings of each OptimizeTransition of the default source.
  TransitionOptimizerOptions optimizer;
  /// Where the entries come from; null: the analytic model (ModelTransitionSource with `optimizer`). A source that
  /// is not concurrent() is built on one thread whatever num_threads says.
  std::shared_ptr<const TransitionSource> source;
};

/// Precomputed minimum-cost transitions (thesis 2.4.1: "pre-computed versions of (2.4) for speed") over an
/// OracleGrid, for one robot and objective: a StepCostModel answering in microseconds.
///
/// Building: every displacement cell asks the build's TransitionSource for its entries at the grid's mu values
/// (by default ModelTransitionSource: OptimizeTransition from the largest mu down, warm-started along the way; see
/// there). Entries never cost more at a larger mu (a step feasible at a smaller mu is feasible at every larger one).
///
/// Lookup (Evaluate): mu is FLOORED to the largest grid value <= mu_allowed (conservative: below the smallest
/// value the step is infeasible); the displacement is interpolated multilinearly over the 16 corners of its
/// (dx, dy, dz, dtheta) cell. The step is infeasible if it lies outside the grid box or any corner with a
/// non-zero weight is infeasible; otherwise every TransitionCost field is the same weighted mean of the
/// corners' (RCOF stays <= mu_allowed, as each corner's does). The parameters are therefore interpolated too:
/// refine them with OptimizeTransition(warm_start) when the exact optimum matters.
///
/// min_cost_per_metre() is the minimum over feasible entries of cost / hypot(dx, dy). Multilinear weights
/// reproduce (dx, dy) exactly and hypot is convex, so an interpolated cost over its hypot is at least the
/// smallest corner ratio: the bound holds for every lookup.
///
/// Sources: the source's line (TransitionSource::Describe: "model" for the analytic default, or e.g. "plant ..."
/// with its settings) is part of the file header and of BuildKey, so a table is never loaded for a source, or
/// source settings, it was not built from.
///
/// File format: a text header (magic "cairn-transition-oracle 2", robot name, model content hash, objective,
/// source, the grid, payload size and its FNV-1a 64 checksum) followed by the binary payload (little-endian
/// doubles, 9 per entry); written atomically. Files of format 1 (no source line) are reported as stale.
///
/// Building in pieces: BuildCells computes the entries of a run of displacement cells, independently of every
/// other cell, and FromEntries assembles a table from all of them, so a table built from pieces (by several
/// processes: OracleShardBuilder) is the same, byte for byte, as one built by Build.
class TransitionOracle final : public StepCostModel {
 public:
  /// One stored entry.
  using Entry = TransitionCost;

  /// Builds the table (see class comment). Throws std::invalid_argument for a bad grid.
  static TransitionOracle Build(const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
                                const OracleBuildOptions& options = OracleBuildOptions());

  /// The default source's name written into the header: "model".
  static constexpr const char* kSource = ModelTransitionSource::kName;

  /// The entries of displacement cells [first_cell, first_cell + num_cells) (cells in entries() order, each
  /// with its grid.mu.size() entries, mu fastest), computed as Build computes them; progress counts these
  /// cells' entries. Throws std::invalid_argument for a bad grid or a range outside [0, num_displacements()].
  static std::vector<Entry> BuildCells(const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
                                       std::size_t first_cell, std::size_t num_cells,
                                       const OracleBuildOptions& options = OracleBuildOptions());

  /// The table of `entries` (all of the grid's, in entries() order) from `source` (null: the default "model").
  /// Throws std::invalid_argument for a bad grid or a count other than grid.num_entries().
  static TransitionOracle FromEntries(const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
                                      std::vector<Entry> entries, const TransitionSource* source = nullptr);

  /// Bytes of one stored entry (9 little-endian doubles).
  static constexpr std::size_t kBytesPerEntry = 72;
  /// Entries as the payload stores them (9 little-endian doubles each).
  static std::string EncodeEntries(const std::vector<Entry>& entries);
  /// The inverse of EncodeEntries; throws std::invalid_argument unless bytes holds exactly `count` entries.
  static std::vector<Entry> DecodeEntries(std::string_view bytes, std::size_t count);

  /// A 64-bit key of what a table's entries depend on: the robot's name and content hash, the objective, the
  /// source and the grid (the header fields Load checks). Pieces of a build carry it.
  static std::uint64_t BuildKey(const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
                                const TransitionSource* source = nullptr);

  /// Reads a table written by Save and checks it against `model` (robot name and content hash), `objective`,
  /// `grid` and `source`'s line (null: the default "model"). Throws std::runtime_error whose message names the file
  /// and says what differs or that it is corrupt (bad magic, truncated, checksum mismatch).
  static TransitionOracle Load(const std::string& path, const WalkingModel& model, WalkingObjective objective,
                               const OracleGrid& grid, const TransitionSource* source = nullptr);

  /// Load (for options.source), or Build and Save when the file is missing, stale or corrupt; writes one line
  /// saying which (and why it rebuilt) to `log` if not null. Creates the file's folder when missing. When the
  /// folder cannot be created or the file cannot be written, warns once (one line to `log`, or to std::cerr when
  /// `log` is null) and returns the table it built: the cache is an optimisation, never a reason to fail.
  static TransitionOracle LoadOrBuild(const std::string& path, const WalkingModel& model, WalkingObjective objective,
                                      const OracleGrid& grid, const OracleBuildOptions& options,
                                      std::ostream* log);

  /// Writes the table atomically (cairn::WriteFileAtomically). Throws std::runtime_error on I/O failure.
  void Save(const std::string& path) const;
  /// The file contents Save writes.
  std::string Serialize() const;

  const OracleGrid& grid() const { return grid_; }
  WalkingObjective objective() const { return objective_; }
  const std::string& robot_name() const { return robot_name_; }
  std::uint64_t model_hash() const { return model_hash_; }
  /// The source's line the entries came from (TransitionSource::Describe; "model" for the default).
  const std::string& source() const { return source_; }
  std::size_t num_entries() const { return entries_.size(); }
  /// Entry at grid indices (dx, dy, dz, dtheta, mu).
  const Entry& entry(std::size_t i_dx, std::size_t i_dy, std::size_t i_dz, std::size_t i_dtheta,
                     std::size_t i_mu) const;
  /// All entries, mu fastest, then dtheta, dz, dy, dx.
  const std::vector<Entry>& entries() const { return entries_; }
  /// Number of feasible entries.
  std::size_t num_feasible() const;
  /// Wall time of Build, s (0 for a loaded table).
  double build_seconds() const { return build_seconds_; }

 private:
  TransitionOracle() = default;
  TransitionCost DoEvaluate(const StepDisplacement& d, double mu_allowed) const override;
  // Exact: the interpolation is linear in dz between grid values, so the minimum lies at an end or a grid value.
  double DoMinCostOverHeights(const StepDisplacement& d, double dz_lo, double dz_hi, double mu_allowed) const override;
  double do_min_cost_per_metre() const override { return min_cost_per_metre_; }
  double do_min_cost_per_step() const override { return min_cost_per_step_; }
  StepCostLowerBound do_cost_lower_bound(double mu_allowed) const override;
  StrideCostLowerBound do_stride_cost_lower_bound(double mu_allowed) const override;
  void ComputeStrideBounds();
  const StepReach& do_reach() const override { return reach_; }
  std::string do_description() const override;
  void Finalize();

  OracleGrid grid_;
  WalkingObjective objective_{WalkingObjective::kComWorkPlusHeat};
  std::string robot_name_;
  std::uint64_t model_hash_{0};
  std::string source_{kSource};
  StepReach reach_;
  std::vector<Entry> entries_;
  double min_cost_per_step_{0.0};
  // Per mu value of the grid: the line bound over that level's feasible entries (see Finalize()).
  std::vector<StepCostLowerBound> level_bounds_;
  // Per mu value of the grid: the stride bound over pairs of that level's feasible entries.
  std::vector<StrideCostLowerBound> stride_bounds_;
  double min_cost_per_metre_{0.0};
  double build_seconds_{0.0};
};

}  // namespace cairn::planning
