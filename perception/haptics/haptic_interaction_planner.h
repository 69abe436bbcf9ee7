#pragma once

/// @file
/// Haptic interaction planning: candidate contact points, their score, confidence-based pruning and the sweep
/// order (seed 000, §3.5–3.6, eqs. 16–21).

#include <vector>

#include <Eigen/Core>

namespace cairn::perception {

/// One candidate contact point with the three criteria of §3.5 and their weighted sum.
struct InteractionPoint {
  /// The point in the sensor frame C (x right, y down, z forward).
  Eigen::Vector3d p_C{Eigen::Vector3d::Zero()};
  /// Height criterion s_h (eq. 16).
  double height_score{0.0};
  /// Centroid criterion s_c (eq. 17).
  double centroid_score{0.0};
  /// Density criterion s_d (eq. 18).
  double density_score{0.0};
  /// s(p) = θh s_h + θc s_c + θd s_d (eq. 19).
  double score{0.0};
};

/// A plan for one object.
struct InteractionPlan {
  /// The candidate set P sorted by score, highest first.
  std::vector<InteractionPoint> candidates;
  /// I (eqs. 20–21): the candidates whose score exceeds α c(o), in execution order (the robot-centric rightmost
  /// first, then always the nearest remaining one).
  std::vector<InteractionPoint> selected;
  /// The antenna targets: `selected` pushed along z_C by push_distance.
  std::vector<Eigen::Vector3d> targets_C;
  /// The score threshold α c(o) used.
  double threshold{0.0};
};

/// Plans where the antenna touches an object (§3.5–3.6). The object's points (in reach) are voxelised (4 cm);
/// candidate points are taken greedily so that no two lie within 5 cm; each is scored by
///   s_h = exp(-|y - g|² / 2σ²)                      (eq. 16, the lower the harder to bend)
///   s_c = exp(-|p - c|² / 2σ²)                      (eq. 17, c the centroid of the voxelised object)
///   s_d = min(1, N_r(p) / (2π r² / (v_w v_h)))       (eq. 18, N_r the other voxels within r)
///   s   = θh s_h + θc s_c + θd s_d                   (eq. 19)
/// The paper divides the neighbour count by the approximation of eq. 18 and reports scores in [0, 1]; a dense
/// solid can have more neighbours than the approximation, so s_d saturates at 1 to keep s within [0, 1].
///
/// Eq. 21 as printed (s(p_{m-1}) < α c < s(p_m) over a list sorted highest first) cannot hold; its stated intent —
/// "only the m points with higher score are selected", the threshold "a proportion of the memory recall
/// confidence", a higher α selecting fewer points — is what is implemented: I keeps the candidates with
/// s(p) > α c(o).
class HapticInteractionPlanner {
 public:
  /// The paper's parameters (§4.1) as defaults.
  struct Options {
    /// Voxel side of the simplification step (m).
    double voxel{0.04};
    /// Candidates lie at least this far apart (m).
    double min_candidate_spacing{0.05};
    /// g of eq. 16 (m, along y_C, which points down).
    double ground_offset{-0.1};
    /// σ of eqs. 16–17 (m).
    double sigma{0.8};
    /// r of eq. 18 (m).
    double neighbour_radius{0.1};
    double theta_height{0.3};
    double theta_centroid{0.2};
    double theta_density{0.5};
    /// α of eq. 21: how much the system trusts its memory over touching. The paper varies it (Fig. 15) and
    /// states no default; 1 keeps the candidates scoring above the recall confidence itself.
    double alpha{1.0};
    /// Targets are pushed this far along z_C, so that a sweep meets a stiff object rather than grazing it (m).
    double push_distance{0.05};
  };

  /// Most voxelised points a plan considers (the density criterion is quadratic in them).
  static constexpr int kMaxPlanPoints = 20000;

  /// Throws std::invalid_argument for invalid options (naming the value), e.g. weights that do not sum to 1.
  explicit HapticInteractionPlanner(const Options& options);
  /// The paper's parameters.
  HapticInteractionPlanner();

  /// Throws std::invalid_argument naming the first invalid option.
  static void Validate(const Options& options);

  /// The scored candidate set P, highest first (ties keep the order of the cloud). Throws std::invalid_argument
  /// for a cloud the reductions refuse or one of more than kMaxPlanPoints voxels.
  std::vector<InteractionPoint> ScoreCandidates(const Eigen::Matrix3Xd& object_C) const;

  /// The candidates whose score exceeds α `confidence` (eq. 20–21), in the given (sorted) order. Throws
  /// std::invalid_argument for a confidence outside [0, 1].
  std::vector<InteractionPoint> Prune(const std::vector<InteractionPoint>& sorted, double confidence) const;

  /// The execution order of §3.6: the point with the largest x_C (rightmost from the robot) first, then always
  /// the nearest remaining point (ties: the earlier one).
  static std::vector<InteractionPoint> ExecutionOrder(const std::vector<InteractionPoint>& points);

  /// The whole plan for an object seen with the memory's recall confidence.
  InteractionPlan Plan(const Eigen::Matrix3Xd& object_C, double confidence) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace cairn::perception
