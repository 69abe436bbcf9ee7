#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/footstep_planner_options.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/locomotion/step_cost_model.h>

namespace cairn::planning {

/// The graph the footstep planner searches (thesis 2.4.1): states are stances (two footholds on a lattice of
/// `lattice_resolution` positions and `orientations` yaws, plus which foot landed last), and an edge moves the
/// older foot to a foothold within reach of the newer one. An edge exists when the new sole has ground under it
/// (support within `support_tolerance` of one plane, no steeper than `max_slope`, walkable friction), the soles do
/// not overlap, the body box clears every obstacle, and the step cost model finds the step feasible under the
/// smallest friction of the three feet involved. Its cost is the model's transition cost (eq. 2.4).
///
/// The heuristic bounds the cost to go from below. Every future foothold chain starts at the newer foot and ends
/// at both goal footholds, and each of its links is a step that costs at least the model's lower bound for the
/// friction under its two ends (StepCostModel::cost_lower_bound: a fixed part plus a part per metre). So the
/// cheapest such chain in a relaxed graph -- lattice positions that carry a sole in some orientation, linked when
/// no further apart than the longest step and when no obstacle reaches the body over their midpoint -- is an
/// admissible heuristic; Dijkstra computes it once per goal foothold. It routes around walls, holes and ground too
/// slippery to step on, prices slow crossings of slippery ground, and a start it cannot connect to the goal is
/// unreachable without a search.
///
/// A second bound follows the newer foot alone: its future moves are strides, each made of two future steps
/// (the older foot's, then its own), and a stride costs at least StepCostModel::stride_cost_lower_bound() of its
/// length. The cheapest relaxed chain of strides to the newer foot's goal foothold bounds the cost to go too, and
/// more tightly on open ground, because a stride has none of the lateral zig-zag of single steps. The heuristic is
/// the larger of the two.
///
/// A third, much tighter bound is exact but for one relaxation: a backward Dijkstra search from the goal over
/// single footholds (position, yaw and side of the newer foot), linked by every step the stance graph could take
/// from that foothold, each priced by the step cost model itself. Only the friction under the older foot is
/// dropped (the step is priced under the smaller friction of its other two feet, which can only make it
/// cheaper), so on level ground of one friction it is the true cost to go of the newer foot's chain (steps up or
/// down are priced by the model's lower bound over 0.1 mm of height, MinCostOverHeights(), so that the rounding
/// of the terrain's heights does not make every slope step a new one to price). It is computed
/// once per goal, terrain and friction setting (for lattices of at most kMaxExactFootholds footholds) and makes
/// the optimal search expand little more than the optimal plan's stances. The heuristic is the largest of the
/// bounds computed; the stride bound is computed only for lattices too large for the exact one (below that size
/// it never exceeded the exact bound on the shipped scenarios, and its Dijkstra with long links is costly). The
/// exact bound is scaled by (1 - 1e-9) so that rounding differences between its sums and the search's never make
/// it overestimate.
///
/// Footholds are evaluated once and cached. Satisfies the Graph requirements of AraStar().
class StanceGraph {
 public:
  using Key = std::uint64_t;

  /// A foothold on the lattice: position (ix, iy) * resolution from the terrain's origin, yaw itheta * 2π / D.
  struct LatticeFoot {
    int ix{0};
    int iy{0};
    int itheta{0};
  };

  /// What lies under a foothold.
  struct Foothold {
    bool supported{false};
    double z{0.0};
    double friction{0.0};
    Eigen::Vector3d normal{Eigen::Vector3d::UnitZ()};
  };

  using Clock = std::chrono::steady_clock;

  /// Largest lattice (positions x yaws) for which the exact foothold-chain bound is computed: it keeps two
  /// doubles per foothold (one per side) and, while computing them, about as much again (about 130 MB at this
  /// size). Larger lattices use the relaxed bounds alone.
  static constexpr double kMaxExactFootholds = 4e6;

  /// The references must outlive the graph. Throws std::invalid_argument for a lattice the terrain cannot hold
  /// (more than 4096 positions per axis) or bad options, and TimeLimitReached when the heuristic's precomputation
  /// (every foothold of the lattice, then two Dijkstra searches) is still running at `deadline`.
  StanceGraph(const TerrainMap& terrain, const StepCostModel& cost_model, const BipedGeometry& geometry,
              const FootstepPlannerOptions& options, const StanceGoal& goal,
              Clock::time_point deadline = Clock::time_point::max());

  /// When set, steps ignore friction (used to tell "needs more friction" from "unreachable"); recomputes the
  /// heuristic, throwing TimeLimitReached if that is still running at `deadline` (the graph must then not be
  /// searched).
  void set_ignore_friction(bool ignore, Clock::time_point deadline = Clock::time_point::max()) {
    ignore_friction_ = ignore;
    deadline_ = deadline;
    ComputeChainDistances();
  }

  /// Evaluates again every foothold whose sole may touch a terrain cell in columns [col0, col1] and rows
  /// [row0, row1], after the terrain the graph refers to has changed there. The heuristic is not recomputed: it
  /// stays admissible when the change only raised step costs (less friction, ground or walkability removed, new
  /// obstacles), since every step cost can then only have grown; FootstepReplanner::UpdateTerrain() checks that.
  void RefreshFootholds(int col0, int row0, int col1, int row1);

  /// Whether steps ignore friction (set_ignore_friction()).
  bool ignores_friction() const { return ignore_friction_; }

  /// The nearest lattice foothold to `pose` (false when outside the lattice).
  bool Snap(const FootPose& pose, LatticeFoot* foot) const;
  FootPose PoseOf(const LatticeFoot& foot) const;
  const Foothold& EvaluateFoothold(const LatticeFoot& foot);

  Key MakeKey(const LatticeFoot& older, const LatticeFoot& newer, FootSide newer_side) const;
  void Decode(Key key, LatticeFoot* older, LatticeFoot* newer, FootSide* newer_side) const;

  double Heuristic(Key key) const;
  bool IsGoal(Key key) const;
  template <class Emit>
  void ForEachSuccessor(Key key, Emit&& emit) {
    successors_.clear();
    GenerateSuccessors(key, &successors_);
    for (const auto& [next, cost] : successors_) emit(next, cost);
  }

  /// The step from stance `from` to its successor `to`, priced again (for plan reconstruction).
  PlannedStep Transition(Key from, Key to);

  const FootstepPlanStatistics& rejections() const { return rejections_; }

  /// Cost of the cheapest relaxed foothold chain from the lattice position of `foot` to the goal foothold of
  /// `side` (infinity when none exists); see the class comment.
  double ChainDistanceToGoal(const LatticeFoot& foot, FootSide side);

  /// The exact foothold-chain bound (see the class comment) for `foot` as the newer foot of `side`: a lower
  /// bound on the cost of every plan from a stance whose newer foot it is (infinity when none exists; 0 when the
  /// lattice is too large for it).
  double FootholdChainDistance(const LatticeFoot& foot, FootSide side) const;

 private:
  // A step the lattice allows from a stance foot of one yaw: the target's offset in lattice positions, its yaw
  // bins turned (outward, >= 0), and the displacement in the stance foot's frame (dz filled in per step).
  struct StepClass {
    int dix{0};
    int diy{0};
    int k{0};
    StepDisplacement d;
  };
  // The steps into a target: class `index` of forward_classes_[stance yaw][moving side].
  struct IncomingStep {
    int stance_itheta{0};
    int index{0};
  };
  void BuildStepClasses();
  void ComputeFootholdChainDistances();
  // Cost of the relaxed step from foothold `from` (the newer foot) by `step` under the friction of the two
  // footholds, or infinity when the step does not exist.
  double RelaxedStepCost(const LatticeFoot& from, int moving, int class_index, const StepClass& step);
  std::size_t FootholdIndex(const LatticeFoot& foot) const {
    return (static_cast<std::size_t>(foot.iy) * lattice_cols_ + foot.ix) * options_.orientations + foot.itheta;
  }
  void GenerateSuccessors(Key key, std::vector<std::pair<Key, double>>* out);
  // Prices the move of the older foot to `target`; false when the edge does not exist.
  // The body box at `center` with `yaw` hits a box obstacle, or is free of the occupied voxels with less than
  // options_.min_body_free_probability.
  bool BodyBlocked(const Eigen::Vector3d& center, double yaw) const;
  // The height of a step from a foothold at `from_z` onto one at `to_z` as the cost model sees it: zero within
  // options.level_step_tolerance. The search, the relaxed step costs and the heuristic's chains all use it, so
  // the heuristic stays a lower bound of what the search prices.
  double StepHeight(double from_z, double to_z) const {
    const double dz = to_z - from_z;
    return std::abs(dz) <= options_.level_step_tolerance ? 0.0 : dz;
  }
  // Box obstacles or occupied voxels exist (else the body needs no check).
  bool HasBodyChecks() const { return !terrain_.obstacles().empty() || !terrain_.occupied_voxels().empty(); }
  bool EvaluateStep(const LatticeFoot& older, const LatticeFoot& newer, FootSide newer_side, const LatticeFoot& target,
                    PlannedStep* step, bool count_rejections);
  Eigen::Vector2d Position(const LatticeFoot& foot) const;
  void ComputeChainDistances();
  // Throws TimeLimitReached when deadline_ has passed, saying that `what` was being computed.
  void CheckDeadline(const char* what) const;
  void ComputeStrideDistances(const std::vector<char>& usable, const std::vector<float>& friction);
  // Dijkstra from each goal foothold over usable lattice positions, with links up to `max_link` long costing
  // link_cost(i, j, p_i, p_j, length) (infinity: no link).
  template <class LinkCost>
  void RelaxedDistances(const std::vector<char>& usable, double max_link, LinkCost&& link_cost,
                        std::vector<double> distances[2]) const;
  double ChainDistance(const LatticeFoot& foot, int goal_side) const {
    return chain_distance_[goal_side][static_cast<std::size_t>(foot.iy) * lattice_cols_ + foot.ix];
  }
  double Yaw(int itheta) const;
  // Signed difference b - a of two yaw bins, in bins within [-D/2, D/2).
  int BinDelta(int a, int b) const {
    const int d = options_.orientations;
    return ((b - a) % d + d + d / 2) % d - d / 2;
  }

  const TerrainMap& terrain_;
  const StepCostModel& cost_model_;
  BipedGeometry geometry_;
  FootstepPlannerOptions options_;
  StanceGoal goal_;
  double min_cost_per_metre_;
  double min_cost_per_step_;
  double max_step_length_;
  int lattice_cols_;
  int lattice_rows_;
  bool ignore_friction_{false};
  Clock::time_point deadline_;
  // Every foothold of the lattice, indexed by FootholdIndex(), evaluated on first use.
  std::vector<Foothold> footholds_;
  std::vector<char> foothold_evaluated_;
  // forward_classes_[itheta * 2 + moving side]: the steps from a stance foot of that yaw (side 0: left moves).
  std::vector<std::vector<StepClass>> forward_classes_;
  // incoming_[itheta * 2 + moving side]: the steps landing with that yaw.
  std::vector<std::vector<IncomingStep>> incoming_;
  // Memoised costs of steps with dz == 0: per friction value seen, one entry per step class (NaN: not yet).
  std::vector<double> memo_friction_;
  std::vector<std::vector<double>> memo_cost_;
  // Memoised lower bounds of other steps, per (class, friction, height bucket); see RelaxedStepCost().
  std::unordered_map<std::uint64_t, double> memo_height_cost_;
  // Per friction value and class: the last height bucket looked up and its bound.
  std::vector<std::vector<std::pair<double, double>>> memo_last_height_;
  std::vector<std::size_t> class_offset_;  // first memo slot of forward_classes_[i]
  // Per foothold index * 2 + side: the exact foothold-chain bound; empty when the lattice is too large.
  std::vector<double> foothold_distance_;
  // Per lattice position, for the left (0) and right (1) goal foothold; filled by ComputeChainDistances().
  std::vector<double> chain_distance_[2];
  // Per lattice position: cost of the cheapest relaxed chain of strides of one foot to its goal foothold (0 when
  // the exact foothold-chain bound replaces it).
  std::vector<double> stride_distance_[2];
  // cos and sin of yaw at half-bin steps: index 2 * itheta (+1 for the half bin after it).
  std::vector<double> half_bin_cos_;
  std::vector<double> half_bin_sin_;
  std::vector<std::pair<Key, double>> successors_;
  FootstepPlanStatistics rejections_;
};

}  // namespace cairn::planning
