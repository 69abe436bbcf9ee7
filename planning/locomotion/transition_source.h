#pragma once

#include <string>
#include <vector>

#include <cairn/planning/locomotion/step_cost_model.h>
#include <cairn/planning/locomotion/walking_model.h>
#include <cairn/planning/locomotion/walking_objective.h>

namespace cairn::planning {

/// Where a transition oracle's entries come from (issue 21): for one step displacement, the minimum-cost transition
/// (thesis eq. 2.4) at each friction limit of a grid. TransitionOracle builds its table cell by cell from a source
/// and writes the source's name and settings into its file, so a table is never used for a source it was not built
/// from.
///
/// Sources: ModelTransitionSource ("model": the analytic walking model, the default and the fastest),
/// PlantTransitionSource (planning/walk, "plant": periodic gaits walked in the physics plant, thesis 2.3.3).
///
/// Public methods are non-virtual and check their arguments; implementations override the protected hooks.
class TransitionSource {
 public:
  virtual ~TransitionSource() = default;

  /// The name written into an oracle's header: a word of lower-case letters ("model", "plant").
  std::string name() const { return do_name(); }
  /// One line with every setting the entries depend on besides the robot, the objective and the grid ("" when
  /// there is none); written after the name, so two tables of one source but other settings are told apart.
  std::string settings() const { return do_settings(); }
  /// The header's source line: the name, then the settings when there are any.
  std::string Describe() const {
    const std::string s = settings();
    return s.empty() ? name() : name() + " " + s;
  }
  /// True when CellEntries may run on several threads at once.
  bool concurrent() const { return do_concurrent(); }

  /// The entries of displacement `d` for each friction limit of `mu` (strictly increasing, > 0), in mu's order.
  /// An entry's cost must not grow with mu (a step feasible under a smaller limit is feasible under a larger
  /// one). Throws std::invalid_argument for an empty, non-increasing or non-positive mu, an objective the source
  /// cannot measure, and as the implementation does.
  std::vector<TransitionCost> CellEntries(const WalkingModel& model, WalkingObjective objective,
                                          const StepDisplacement& d, const std::vector<double>& mu) const;

 protected:
  TransitionSource() = default;
  virtual std::string do_name() const = 0;
  virtual std::string do_settings() const { return ""; }
  virtual bool do_concurrent() const { return true; }
  virtual std::vector<TransitionCost> DoCellEntries(const WalkingModel& model, WalkingObjective objective,
                                                    const StepDisplacement& d,
                                                    const std::vector<double>& mu) const = 0;
};

}  // namespace cairn::planning
