#include <cairn/planning/walk/plant_transition_source.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <cairn/common/number_text.h>

namespace cairn::planning {
namespace {

void CheckTimings(const std::vector<double>& axis, const char* name, double lo, double hi) {
  const std::string what = std::string("PlantTransitionSource: ") + name;
  if (axis.empty() || axis.size() > PlantTransitionSource::kMaxTimings) {
    throw std::invalid_argument(what + " has " + FormatShort(axis.size()) + " values; give 1 to " +
                                FormatShort(PlantTransitionSource::kMaxTimings));
  }
  for (std::size_t i = 0; i < axis.size(); ++i) {
    if (!(axis[i] >= lo && axis[i] <= hi)) {
      throw std::invalid_argument(what + " value " + FormatShort(axis[i]) + " s is outside the walking model's bounds [" +
                                  FormatShort(lo) + ", " + FormatShort(hi) + "] s");
    }
    if (i > 0 && !(axis[i] > axis[i - 1])) {
      throw std::invalid_argument(what + " is not strictly increasing at " + FormatShort(axis[i]) +
                                  " s; sort it and remove duplicates");
    }
  }
}

std::vector<double> Clipped(std::vector<double> values, double lo, double hi) {
  std::vector<double> out;
  for (double v : values) {
    const double c = std::clamp(v, lo, hi);
    if (out.empty() || c > out.back()) out.push_back(c);
  }
  return out;
}

std::string AxisText(const std::vector<double>& axis) {
  std::string text;
  for (double v : axis) text += (text.empty() ? "" : ",") + FormatExact(v);
  return text;
}

// Refuses an objective the mode does not measure.
void CheckMeasured(WalkingObjective objective, PlantTransitionSource::Mode mode) {
  using Mode = PlantTransitionSource::Mode;
  if (mode == Mode::kPlant && objective == WalkingObjective::kSquaredTorque) {
    throw std::invalid_argument(std::string("PlantTransitionSource: the plant measures no squared static torques "
                                            "(objective '") +
                                to_string(objective) + "'); use ecom, ecom_heat or time, or the pipeline source");
  }
  if (mode == Mode::kPipeline && objective == WalkingObjective::kComWorkPlusHeat) {
    throw std::invalid_argument(std::string("PlantTransitionSource: the pipeline source runs no motors, so it "
                                            "measures no heat (objective '") +
                                to_string(objective) + "'); use torque, ecom or time, or the plant source");
  }
}

}  // namespace

PlantTransitionSource::PlantTransitionSource(std::shared_ptr<const PlantGaitSampler> sampler,
                                             std::vector<double> t_ds, std::vector<double> t_sw, Mode mode)
    : sampler_(std::move(sampler)), t_ds_(std::move(t_ds)), t_sw_(std::move(t_sw)), mode_(mode) {
  if (sampler_ == nullptr) throw std::invalid_argument("PlantTransitionSource: the gait sampler is null");
  const WalkingModel& model = sampler_->walking_model();
  CheckTimings(t_ds_, "t_ds", model.parameter_lower().t_ds, model.parameter_upper().t_ds);
  CheckTimings(t_sw_, "t_sw", model.parameter_lower().t_sw, model.parameter_upper().t_sw);
  com_height_ = 0.5 * (model.parameter_lower().com_height + model.parameter_upper().com_height);
}

OracleGrid PlantTransitionSource::DefaultGrid(const WalkingModel& model) {
  const StepReach& reach = model.reach();
  OracleGrid grid;
  grid.dx = Clipped({0.0, 0.1, 0.2, 0.3}, reach.dx_min, reach.dx_max);
  grid.dy = {reach.dy_min, reach.dy_max};
  grid.dz = {std::clamp(0.0, reach.dz_min, reach.dz_max)};
  grid.dtheta = Clipped({0.0, 15.0 * 3.14159265358979323846 / 180.0}, reach.dtheta_min, reach.dtheta_max);
  grid.mu = OracleGrid::Default(model).mu;
  return grid;
}

std::vector<double> PlantTransitionSource::DefaultDoubleSupportTimes(const WalkingModel& model) {
  return Clipped({0.2, 0.5, 0.9}, model.parameter_lower().t_ds, model.parameter_upper().t_ds);
}

std::vector<double> PlantTransitionSource::DefaultSwingTimes(const WalkingModel& model) {
  return Clipped({0.9, 1.2}, model.parameter_lower().t_sw, model.parameter_upper().t_sw);
}

std::string PlantTransitionSource::do_settings() const {
  const PlantGaitOptions& o = sampler_->options();
  return "t_ds " + AxisText(t_ds_) + " t_sw " + AxisText(t_sw_) + " steps " + FormatShort(o.num_steps) +
         " transient " + FormatShort(o.transient_steps) + " friction " + FormatExact(o.ground_friction) +
         " tolerance " + FormatExact(o.tracking_tolerance) + " settle " + FormatExact(o.settle_time) + " stabilizer " +
         o.stabilizer.method + (mode_ == Mode::kPlant ? std::string(" feedback ") + (o.feedback ? "on" : "off")
                                                     : " margin " + FormatExact(o.min_support_margin));
}

std::vector<GaitMeasurement> PlantTransitionSource::MeasureCell(const StepDisplacement& d) const {
  std::vector<GaitMeasurement> out;
  out.reserve(t_ds_.size() * t_sw_.size());
  for (double t_ds : t_ds_) {
    for (double t_sw : t_sw_) {
      PeriodicGait gait;
      gait.displacement = d;
      gait.parameters = {t_ds, t_sw, com_height_};
      out.push_back(mode_ == Mode::kPlant ? sampler_->Measure(gait) : sampler_->MeasurePlanned(gait));
    }
  }
  return out;
}

std::vector<TransitionCost> PlantTransitionSource::EntriesFrom(const std::vector<GaitMeasurement>& measurements,
                                                               WalkingObjective objective,
                                                               const std::vector<double>& mu, Mode mode) {
  CheckMeasured(objective, mode);
  std::vector<TransitionCost> entries(mu.size());
  for (std::size_t k = 0; k < mu.size(); ++k) {
    for (const GaitMeasurement& m : measurements) {
      if (!m.feasible || !(m.rcof <= mu[k])) continue;
      const StepParameters& p = m.gait.parameters;
      double cost = 0.0;
      switch (objective) {
        case WalkingObjective::kComWork: cost = m.com_work; break;
        case WalkingObjective::kComWorkPlusHeat: cost = m.com_work + m.heat; break;
        case WalkingObjective::kSquaredTorque: cost = m.torque_cost; break;
        default: cost = p.t_ds + p.t_sw; break;
      }
      if (!std::isfinite(cost) || (entries[k].feasible && !(cost < entries[k].cost))) continue;
      TransitionCost& e = entries[k];
      e.feasible = true;
      e.cost = cost;
      e.parameters = {p.t_ds, p.t_sw, m.com_height};
      e.com_work = m.com_work;
      e.heat = mode == Mode::kPlant ? m.heat : 0.0;
      e.rcof = m.rcof;
      e.duration = p.t_ds + p.t_sw;
    }
  }
  return entries;
}

std::vector<TransitionCost> PlantTransitionSource::DoCellEntries(const WalkingModel& model,
                                                                 WalkingObjective objective,
                                                                 const StepDisplacement& d,
                                                                 const std::vector<double>& mu) const {
  if (model.content_hash() != sampler_->walking_model().content_hash()) {
    throw std::invalid_argument("PlantTransitionSource: asked for robot '" + model.name() +
                                "', but its gait sampler walks '" + sampler_->walking_model().name() +
                                "' (another walking model); build the source for the oracle's model");
  }
  // Before the first gait is measured.
  CheckMeasured(objective, mode_);
  return EntriesFrom(MeasureCell(d), objective, mu, mode_);
}

}  // namespace cairn::planning
