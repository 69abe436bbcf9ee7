#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace cairn::planning {

/// Pose of the next foot f_{j+1} relative to the stance foot f_j (thesis 2.3.3), expressed in f_j's sole frame
/// (x forward, y left, z up) and mirrored so that it always reads as a left foot placed beside a right foot:
/// `dy > 0` is the outward (lateral) distance between the sole centres and `dtheta > 0` turns the new foot
/// outward. A right foot placed beside a left foot has its y and yaw negated before the lookup.
struct StepDisplacement {
  double dx{0.0};      ///< forward, m
  double dy{0.0};      ///< outward, m
  double dz{0.0};      ///< up, m
  double dtheta{0.0};  ///< outward yaw, rad
};

/// The free parameters p of one step (thesis 2.4.1): double-support time, swing time, and the COM height above
/// the ground under the ZMP, which stands in for the thesis' knee-flexion angles.
struct StepParameters {
  double t_ds{0.0};        ///< s
  double t_sw{0.0};        ///< s
  double com_height{0.0};  ///< m
};

/// Reachability box of a step in StepDisplacement coordinates (thesis 2.3.3, scaled to the robot).
struct StepReach {
  double dx_min{0.0}, dx_max{0.0};
  double dy_min{0.0}, dy_max{0.0};
  double dz_min{0.0}, dz_max{0.0};
  double dtheta_min{0.0}, dtheta_max{0.0};

  bool Contains(const StepDisplacement& d) const {
    return d.dx >= dx_min && d.dx <= dx_max && d.dy >= dy_min && d.dy <= dy_max && d.dz >= dz_min &&
           d.dz <= dz_max && d.dtheta >= dtheta_min && d.dtheta <= dtheta_max;
  }
};

/// The minimum-cost transition between two stances (thesis eq. 2.4) and what it predicts.
struct TransitionCost {
  bool feasible{false};
  /// Objective value in the objective's unit (J for the energies, s for travel time, N^2 m^2 s for torque).
  double cost{std::numeric_limits<double>::infinity()};
  StepParameters parameters;
  double com_work{0.0};  ///< E_COM of eq. 2.1, J
  double heat{0.0};      ///< motor heat, the second term of eq. 2.6, J
  double rcof{0.0};      ///< eq. 2.2
  double duration{0.0};  ///< t_ds + t_sw, s
};

/// A lower bound on the cost of every step the model accepts under one friction limit:
/// cost >= per_step + per_metre * hypot(dx, dy).
struct StepCostLowerBound {
  bool any_feasible{true};  ///< false: no step at all is feasible under that friction
  double per_step{0.0};
  double per_metre{0.0};
};

/// A lower bound on the cost of two consecutive steps -- the other foot's, then this foot's -- as a function of
/// how far this foot moves over them (its "stride"), for steps under one friction limit. Convex, non-decreasing
/// and piecewise linear through the points (stride[i], cost[i]), stride[0] = 0; no pair of steps moves a foot
/// further than stride.back().
struct StrideCostLowerBound {
  bool any_feasible{true};
  std::vector<double> stride;
  std::vector<double> cost;

  /// The bound at stride `s` (infinity beyond the last point or when nothing is feasible).
  double operator()(double s) const {
    if (!any_feasible || stride.empty() || s > stride.back()) return std::numeric_limits<double>::infinity();
    std::size_t i = 1;
    while (i + 1 < stride.size() && stride[i] < s) ++i;
    if (stride.size() == 1) return cost[0];
    const double t = (s - stride[i - 1]) / (stride[i] - stride[i - 1]);
    return cost[i - 1] + std::max(0.0, std::min(1.0, t)) * (cost[i] - cost[i - 1]);
  }
};

/// What a footstep planner needs to know about walking: the cost of a step under a friction limit, a lower
/// bound on the cost per metre for an admissible heuristic (eq. 2.5), and the reachable steps.
///
/// Implementations must be thread-compatible: const methods may be called concurrently.
class StepCostModel {
 public:
  virtual ~StepCostModel() = default;

  /// Minimum-cost step with displacement `d` whose RCOF stays at or below `mu_allowed`. An infeasible step
  /// (out of reach, or no parameters meet the friction limit) returns `feasible == false`.
  TransitionCost Evaluate(const StepDisplacement& d, double mu_allowed) const { return DoEvaluate(d, mu_allowed); }

  /// Lower bound of cost / hypot(dx, dy) over every feasible step at any friction: the cost per metre of
  /// horizontal distance between consecutive footholds (the thesis' eq. 2.5 bounds cost per metre of stance
  /// travel, which is admissible only for periodic gaits). Every foothold chain from a foot to a goal foothold
  /// is at least as long as the straight line, so this times that distance never overestimates the cost to go.
  /// Implementations that interpolate must keep the bound valid for interpolated costs.
  double min_cost_per_metre() const { return do_min_cost_per_metre(); }

  /// The largest α with cost >= α + min_cost_per_metre() * hypot(dx, dy) for every feasible step: a fixed
  /// cost every step pays. Together with the fewest steps that can cover a distance it tightens the heuristic.
  /// 0 is always valid (and the default).
  double min_cost_per_step() const { return do_min_cost_per_step(); }

  /// A lower bound on the cost of the steps feasible under friction limit `mu_allowed`: slippery ground makes
  /// steps slower or shorter, and this lets a heuristic see it. It must hold for Evaluate(d, mu_allowed) at every
  /// d; since a model's cost never decreases as the friction limit falls (a step feasible on less friction is
  /// feasible on more), it then holds for every smaller limit too. The default, valid for every model, is the
  /// friction-free bound.
  StepCostLowerBound cost_lower_bound(double mu_allowed) const { return do_cost_lower_bound(mu_allowed); }

  /// A lower bound on the cost of two consecutive steps under friction limit `mu_allowed` by the distance the
  /// second step's foot travels; pairs of steps walking straight have no lateral zig-zag in it, so it bounds the
  /// cost of progress much more tightly than cost_lower_bound(). Must hold for every pair of steps the model
  /// accepts (and so for smaller limits, as for cost_lower_bound()). The default derives it from
  /// cost_lower_bound(): two steps cost at least 2 per_step + per_metre (|d1| + |d2|) >= 2 per_step + per_metre s.
  StrideCostLowerBound stride_cost_lower_bound(double mu_allowed) const {
    return do_stride_cost_lower_bound(mu_allowed);
  }

  /// A lower bound on Evaluate(d', mu_allowed).cost over every feasible d' that equals `d` but for a height dz in
  /// [dz_lo, dz_hi] (infinity: no such d' is feasible). A heuristic can price steps whose heights differ only by
  /// the rounding of the terrain's heights once for the whole range. The default, valid for every model, is the
  /// friction bound of cost_lower_bound() at d's horizontal length.
  double MinCostOverHeights(const StepDisplacement& d, double dz_lo, double dz_hi, double mu_allowed) const {
    return DoMinCostOverHeights(d, dz_lo, dz_hi, mu_allowed);
  }

  /// The box of displacements the model can evaluate; steps outside it are infeasible.
  const StepReach& reach() const { return do_reach(); }

  /// Short description for plans and logs, e.g. "oracle table 6720 entries, objective ecom_heat".
  std::string description() const { return do_description(); }

 protected:
  virtual TransitionCost DoEvaluate(const StepDisplacement& d, double mu_allowed) const = 0;
  virtual double do_min_cost_per_metre() const = 0;
  virtual double do_min_cost_per_step() const { return 0.0; }
  virtual StepCostLowerBound do_cost_lower_bound(double /*mu_allowed*/) const {
    return StepCostLowerBound{true, min_cost_per_step(), min_cost_per_metre()};
  }
  virtual StrideCostLowerBound do_stride_cost_lower_bound(double mu_allowed) const {
    const StepCostLowerBound b = cost_lower_bound(mu_allowed);
    const StepReach& r = reach();
    const double longest = std::hypot(std::max(std::abs(r.dx_min), std::abs(r.dx_max)),
                                      std::max(std::abs(r.dy_min), std::abs(r.dy_max)));
    StrideCostLowerBound out;
    out.any_feasible = b.any_feasible;
    out.stride = {0.0, 2.0 * longest};
    out.cost = {2.0 * b.per_step, 2.0 * b.per_step + 2.0 * longest * b.per_metre};
    return out;
  }
  virtual double DoMinCostOverHeights(const StepDisplacement& d, double /*dz_lo*/, double /*dz_hi*/,
                                      double mu_allowed) const {
    const StepCostLowerBound b = cost_lower_bound(mu_allowed);
    if (!b.any_feasible) return std::numeric_limits<double>::infinity();
    return b.per_step + b.per_metre * std::hypot(d.dx, d.dy);
  }
  virtual const StepReach& do_reach() const = 0;
  virtual std::string do_description() const = 0;
};


}  // namespace cairn::planning
