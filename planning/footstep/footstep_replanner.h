#pragma once

#include <memory>

#include <cairn/planning/footstep/biped_geometry.h>
#include <cairn/planning/footstep/foot_pose.h>
#include <cairn/planning/footstep/footstep_plan.h>
#include <cairn/planning/footstep/footstep_planner_options.h>
#include <cairn/planning/footstep/stance_graph.h>
#include <cairn/planning/footstep/terrain_map.h>
#include <cairn/planning/locomotion/step_cost_model.h>

namespace cairn::planning {

/// Footstep planning to one goal over one terrain from a start that changes as the robot walks. The heuristic's
/// precomputation (every foothold of the lattice and the exact foothold-chain bound, StanceGraph) depends on the
/// goal and the terrain but not on the start, so it is done by the first Plan() and reused by every later one,
/// which then costs only the search (a few milliseconds to tens of them on the shipped scenarios, against a few
/// hundred for PlanFootsteps()). Each Plan() returns what PlanFootsteps() returns for the same input, and its
/// time limit covers that call alone (the first one including the precomputation). When the terrain or the goal
/// changes, make a new replanner.
class FootstepReplanner {
 public:
  /// Keeps a copy of `terrain`. Throws std::invalid_argument for a null cost model, a goal stance that cannot
  /// stand, or a non-positive time limit; the graph's own checks (lattice size, options) come with the first Plan().
  FootstepReplanner(const TerrainMap& terrain, const StanceGoal& goal, std::shared_ptr<const StepCostModel> cost_model,
                    const BipedGeometry& geometry, const FootstepPlannerOptions& options);
  FootstepReplanner(const FootstepReplanner&) = delete;
  FootstepReplanner& operator=(const FootstepReplanner&) = delete;

  /// The best plan from `start`, as PlanFootsteps(terrain, start, goal, ...) would return it. Throws
  /// std::invalid_argument as PlanFootsteps() does.
  FootstepPlan Plan(const Stance& start);

  /// Replaces the terrain (same grid: origin, size and resolution, else std::invalid_argument). When the change
  /// can only raise step costs -- cells lost friction, ground or walkability, and obstacles were only added -- the
  /// precomputed heuristic stays admissible and is kept (the footholds around the changed cells are evaluated
  /// again), so the next Plan() costs only its search, which is still optimal, though it expands more where the
  /// terrain changed; returns true. Any other change, including any change to the occupied voxels, discards the
  /// precomputation (false): the next Plan() computes it again.
  bool UpdateTerrain(const TerrainMap& terrain);

  /// Whether the heuristic's precomputation is done (after the first Plan() that had time for it).
  bool prepared() const { return graph_ != nullptr; }

 private:
  TerrainMap terrain_;
  StanceGoal goal_;
  std::shared_ptr<const StepCostModel> cost_model_;
  BipedGeometry geometry_;
  FootstepPlannerOptions options_;
  std::unique_ptr<StanceGraph> graph_;  // refers to the members above
};

}  // namespace cairn::planning
