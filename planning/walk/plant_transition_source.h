#pragma once

#include <memory>
#include <string>
#include <vector>

#include <cairn/planning/locomotion/transition_oracle.h>
#include <cairn/planning/locomotion/transition_source.h>
#include <cairn/planning/walk/plant_gait_sampler.h>

namespace cairn::planning {

/// The `plant` and `pipeline` sources of transition oracles (issue 21), both from periodic gaits of the real robot:
/// every displacement cell measures one periodic gait per pair of a double-support time and a swing time of its
/// parameter grid, and an entry at friction limit mu is the cheapest feasible gait with a measured RCOF <= mu. This
/// is the thesis' hierarchical-planner oracle (2.5.1: "hash tables ... filled offline ... the discrete
/// optimization problems are then solved") on a grid of timings; between cells the table interpolates as every
/// oracle does.
///
/// - Mode::kPlant ("plant"; thesis 2.3.3 learned its models from about 12,600 periodic gaits simulated in ODE): the
///   gait is optimised, stabilised and walked with balance feedback in the physics plant on ground of high friction
///   (PlantGaitSampler::Measure); feasible: no fall, tracked. Objectives: `ecom` (measured E_COM), `ecom_heat`
///   (E_COM plus the Joule heat of E_ele, the measured counterpart of the model's heat term) and `time`
///   (t_ds + t_sw); `torque` is refused (the plant measures no static torques).
/// - Mode::kPipeline ("pipeline"; thesis 2.5.1a, Fig. 2.13: the oracle predicts the cost at the end of the whole
///   pipeline): the gait is optimised and stabilised but not walked (PlantGaitSampler::MeasurePlanned); feasible:
///   the stabilised ZMP stays in its support polygon. Objectives: `torque` (the whole-body optimiser's squared
///   static torques over their effort limits per step, the thesis' hierarchical objective), `ecom` (of the
///   stabilised reference's COM) and `time`; `ecom_heat` is refused (no motor runs, so no heat is measured).
/// The entries' COM height is the one the walk used (the whole-body optimiser chooses the posture; the plan's
/// parameter only sets the analytic prediction, and is the middle of the model's bounds).
///
/// Cells are walked one after the other (not concurrent(): IpoptSolver serialises its solves process-wide, and the
/// whole-body solve is most of a gait's time, so threads would mostly wait); spread a build over processes instead (`mpirun -np N cairn oracle build --source plant`).
class PlantTransitionSource final : public TransitionSource {
 public:
  /// What a gait's measurement runs: the planning chain and the physics plant, or the planning chain alone.
  enum class Mode { kPlant, kPipeline };
  /// The names of the two modes, written into oracle headers.
  static constexpr const char* kName = "plant";
  static constexpr const char* kPipelineName = "pipeline";
  /// Most values of a timing axis.
  static constexpr std::size_t kMaxTimings = 100;

  /// Throws std::invalid_argument for a null sampler, or timing axes that are empty, longer than kMaxTimings,
  /// not strictly increasing or outside the sampler's walking model's parameter bounds (naming the value).
  PlantTransitionSource(std::shared_ptr<const PlantGaitSampler> sampler, std::vector<double> t_ds,
                        std::vector<double> t_sw, Mode mode = Mode::kPlant);

  /// The reduced default grid, which builds on 2 processes in minutes: level steps (dz = 0; the thesis also
  /// trained its level model apart) with dx at 0, 0.1, 0.2 and 0.3 m, dy at the reach's ends, dtheta at 0 and 15
  /// degrees, and the analytic default's friction limits.
  static OracleGrid DefaultGrid(const WalkingModel& model);
  /// The default timing axes: t_ds in {0.2, 0.5, 0.9} s and t_sw in {0.9, 1.2} s (clipped to the model's bounds).
  static std::vector<double> DefaultDoubleSupportTimes(const WalkingModel& model);
  static std::vector<double> DefaultSwingTimes(const WalkingModel& model);

  const std::vector<double>& t_ds() const { return t_ds_; }
  const std::vector<double>& t_sw() const { return t_sw_; }
  const PlantGaitSampler& sampler() const { return *sampler_; }
  Mode mode() const { return mode_; }

  /// The gaits of one displacement, t_ds outer and t_sw inner, measured as mode() says. Throws as
  /// PlantGaitSampler::Measure does.
  std::vector<GaitMeasurement> MeasureCell(const StepDisplacement& d) const;

  /// The entries at each friction limit of `mu` from a cell's measurements in `mode` (see the class comment).
  /// Throws std::invalid_argument for an objective the mode does not measure.
  static std::vector<TransitionCost> EntriesFrom(const std::vector<GaitMeasurement>& measurements,
                                                 WalkingObjective objective, const std::vector<double>& mu,
                                                 Mode mode = Mode::kPlant);

 private:
  std::string do_name() const override { return mode_ == Mode::kPlant ? kName : kPipelineName; }
  std::string do_settings() const override;
  bool do_concurrent() const override { return false; }
  std::vector<TransitionCost> DoCellEntries(const WalkingModel& model, WalkingObjective objective,
                                            const StepDisplacement& d, const std::vector<double>& mu) const override;

  std::shared_ptr<const PlantGaitSampler> sampler_;
  std::vector<double> t_ds_, t_sw_;
  double com_height_{0.0};
  Mode mode_{Mode::kPlant};
};

}  // namespace cairn::planning
