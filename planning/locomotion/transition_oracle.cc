#include "cairn/planning/locomotion/transition_oracle.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <mutex>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "cairn/common/number_text.h"
#include "cairn/common/atomic_file.h"
#include "cairn/common/hash.h"
#include "cairn/common/parallel_for.h"
#include "cairn/common/internal/yaml_reader.h"

namespace cairn::planning {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kMagic = "cairn-transition-oracle 2";
constexpr const char* kMagicVersion1 = "cairn-transition-oracle 1";
constexpr int kDoublesPerEntry = 9;
static_assert(kDoublesPerEntry * 8 == TransitionOracle::kBytesPerEntry);
// Lookups match a single-valued axis, and the grid's ends, within this distance.
constexpr double kAxisTolerance = 1e-9;

void PutDouble(std::string& out, double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xffu));
}

double GetDouble(const char* in) {
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[i])) << (8 * i);
  double value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

// Cell of `x` on a strictly increasing axis: index i and weight t of node i + 1; false outside the axis.
bool LocateOnAxis(const std::vector<double>& axis, double x, std::size_t* i, double* t) {
  if (axis.size() == 1) {
    *i = 0;
    *t = 0.0;
    return std::abs(x - axis[0]) <= kAxisTolerance;
  }
  if (x < axis.front() - kAxisTolerance || x > axis.back() + kAxisTolerance) return false;
  const double clamped = std::clamp(x, axis.front(), axis.back());
  std::size_t k = static_cast<std::size_t>(std::upper_bound(axis.begin(), axis.end(), clamped) - axis.begin());
  k = std::clamp<std::size_t>(k, 1, axis.size() - 1) - 1;
  *i = k;
  *t = (clamped - axis[k]) / (axis[k + 1] - axis[k]);
  return true;
}

void ValidateAxis(const std::vector<double>& axis, const char* name, double lo, double hi, bool positive) {
  if (axis.empty()) {
    throw std::invalid_argument(std::string("OracleGrid: axis '") + name + "' is empty; give at least one value.");
  }
  for (std::size_t i = 0; i < axis.size(); ++i) {
    const double v = axis[i];
    if (!std::isfinite(v)) {
      throw std::invalid_argument(std::string("OracleGrid: axis '") + name + "' value " + cairn::FormatShort(i) +
                                  " is not finite.");
    }
    if (i > 0 && !(v > axis[i - 1])) {
      throw std::invalid_argument(std::string("OracleGrid: axis '") + name + "' is not strictly increasing at value " +
                                  FormatShort(v) + " (after " + FormatShort(axis[i - 1]) +
                                  "); sort it and remove duplicates.");
    }
    if (positive && !(v > 0.0)) {
      throw std::invalid_argument(std::string("OracleGrid: axis '") + name + "' value " + FormatShort(v) +
                                  " must be positive.");
    }
    if (v < lo - 1e-12 || v > hi + 1e-12) {
      throw std::invalid_argument(std::string("OracleGrid: axis '") + name + "' value " + FormatShort(v) +
                                  " is outside the robot's reach [" + FormatShort(lo) + ", " + FormatShort(hi) + "].");
    }
  }
}

std::string AxisLine(const char* name, const std::vector<double>& axis) {
  std::string line = std::string(name) + " " + cairn::FormatShort(axis.size());
  for (double v : axis) line += " " + FormatExact(v);
  return line + "\n";
}

// The source line of a build: the given source's, or the default's.
std::string SourceLine(const TransitionSource* source) {
  if (source == nullptr) return TransitionOracle::kSource;
  std::string line = source->Describe();
  if (line.empty() || line.find('\n') != std::string::npos || line.size() > 10000) {
    throw std::invalid_argument("TransitionOracle: the source's description '" + line.substr(0, 80) +
                                "' must be one non-empty line of at most 10000 characters");
  }
  return line;
}

// The grid's five axis lines, as headers write them.
std::string GridLines(const OracleGrid& grid) {
  return AxisLine("dx", grid.dx) + AxisLine("dy", grid.dy) + AxisLine("dz", grid.dz) +
         AxisLine("dtheta", grid.dtheta) + AxisLine("mu", grid.mu);
}

// The header lines after the magic that say what the entries depend on (and that Load checks).
std::string HeaderFields(const std::string& robot, std::uint64_t model_hash, WalkingObjective objective,
                         const std::string& source, const OracleGrid& grid) {
  std::string fields = "robot " + robot + "\n";
  fields += "model_hash " + HashHex(model_hash) + "\n";
  fields += std::string("objective ") + to_string(objective) + "\n";
  fields += "source " + source + "\n";
  return fields + GridLines(grid);
}

}  // namespace

OracleGrid OracleGrid::Default(const WalkingModel& model) {
  const StepReach& reach = model.reach();
  // Every 5 cm (k / 20.0 is the double nearest to k * 0.05, so the values print as typed).
  auto every = [&](double lo, double hi, bool keep_ends) {
    std::vector<double> axis;
    if (keep_ends) axis.push_back(lo);
    for (long k = static_cast<long>(std::ceil(lo * 20.0 - 1e-9)); k / 20.0 <= hi + 1e-9; ++k) {
      const double v = k / 20.0;
      if (keep_ends && (std::abs(v - lo) < 1e-9 || std::abs(v - hi) < 1e-9)) continue;
      if (v >= lo - 1e-9 && v <= hi + 1e-9) axis.push_back(std::clamp(v, lo, hi));
    }
    if (keep_ends && hi > lo) axis.push_back(hi);
    return axis;
  };
  OracleGrid grid;
  grid.dx = every(reach.dx_min, reach.dx_max, false);
  grid.dy = every(reach.dy_min, reach.dy_max, true);
  grid.dz = every(reach.dz_min, reach.dz_max, false);
  for (double degrees : {0.0, 15.0, 30.0}) {
    const double v = degrees * kPi / 180.0;
    if (v >= reach.dtheta_min - 1e-12 && v <= reach.dtheta_max + 1e-12) grid.dtheta.push_back(v);
  }
  if (grid.dtheta.empty()) grid.dtheta.push_back(reach.dtheta_min);
  grid.mu = {0.04, 0.05, 0.06, 0.08, 0.10, 0.12, 0.15, 0.20, 0.30, 0.45, 0.70, 1.00};
  return grid;
}

OracleGrid OracleGrid::Load(const std::string& path) {
  const internal::YamlReader yaml(path);
  yaml.CheckKeys(yaml.root(), {"dx", "dy", "dz", "dtheta", "mu"}, "the oracle grid");
  auto axis = [&](const std::string& key) {
    const YAML::Node value = yaml.Require(yaml.root(), key, "the oracle grid");
    if (!value.IsMap()) return yaml.NumberList(value, key, kMaxAxisValues);
    yaml.CheckKeys(value, {"from", "to", "step"}, key);
    const double from = yaml.Number(value, "from", key);
    const double to = yaml.Number(value, "to", key);
    const double step = yaml.Number(value, "step", key);
    if (!(step > 0.0)) yaml.Fail(value, key + ".step is " + FormatShort(step) + "; give a positive step");
    if (to < from) yaml.Fail(value, key + ".to (" + FormatShort(to) + ") is below " + key + ".from (" + FormatShort(from) + ")");
    const double count = std::floor((to - from) / step + 1e-9) + 1.0;
    if (count > static_cast<double>(kMaxAxisValues)) {
      yaml.Fail(value, key + " from " + FormatShort(from) + " to " + FormatShort(to) + " every " + FormatShort(step) +
                           " has " + FormatShort(count) + " values, more than the limit of " +
                           FormatShort(kMaxAxisValues) + "; use a larger step");
    }
    std::vector<double> values;
    for (int k = 0; k < static_cast<int>(count); ++k) values.push_back(std::min(from + k * step, to));
    return values;
  };
  OracleGrid grid;
  grid.dx = axis("dx");
  grid.dy = axis("dy");
  grid.dz = axis("dz");
  grid.dtheta = axis("dtheta");
  grid.mu = axis("mu");
  return grid;
}

void OracleGrid::Validate(const StepReach& reach) const {
  ValidateAxis(dx, "dx", reach.dx_min, reach.dx_max, false);
  ValidateAxis(dy, "dy", reach.dy_min, reach.dy_max, true);
  ValidateAxis(dz, "dz", reach.dz_min, reach.dz_max, false);
  ValidateAxis(dtheta, "dtheta", reach.dtheta_min, reach.dtheta_max, false);
  ValidateAxis(mu, "mu", 0.0, std::numeric_limits<double>::infinity(), true);
  // Counted in double: five axes of up to 10^4 values overflow no double, unlike a size_t product.
  const double entries = static_cast<double>(dx.size()) * static_cast<double>(dy.size()) *
                         static_cast<double>(dz.size()) * static_cast<double>(dtheta.size()) * static_cast<double>(mu.size());
  if (entries > kMaxEntries) {
    throw std::invalid_argument("OracleGrid: " + FormatShort(dx.size()) + " dx x " + FormatShort(dy.size()) + " dy x " +
                                FormatShort(dz.size()) + " dz x " + FormatShort(dtheta.size()) + " dtheta x " +
                                FormatShort(mu.size()) + " mu = " + FormatShort(entries) +
                                " entries, more than the limit of " + FormatShort(kMaxEntries) +
                                "; use fewer axis values");
  }
}

std::string OracleGrid::Fingerprint() const {
  return HashHex(Fnv1a64(GridLines(*this)));
}

bool operator==(const OracleGrid& a, const OracleGrid& b) {
  return a.dx == b.dx && a.dy == b.dy && a.dz == b.dz && a.dtheta == b.dtheta && a.mu == b.mu;
}

TransitionOracle TransitionOracle::Build(const WalkingModel& model, WalkingObjective objective,
                                         const OracleGrid& grid, const OracleBuildOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  TransitionOracle oracle = FromEntries(model, objective, grid,
                                        BuildCells(model, objective, grid, 0, grid.num_displacements(), options),
                                        options.source.get());
  oracle.build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return oracle;
}

std::vector<TransitionOracle::Entry> TransitionOracle::BuildCells(const WalkingModel& model, WalkingObjective objective,
                                                                  const OracleGrid& grid, std::size_t first_cell,
                                                                  std::size_t num_cells,
                                                                  const OracleBuildOptions& options) {
  grid.Validate(model.reach());
  const std::size_t all_cells = grid.num_displacements();
  if (first_cell > all_cells || num_cells > all_cells - first_cell) {
    throw std::invalid_argument("TransitionOracle::BuildCells: cells [" + cairn::FormatShort(first_cell) + ", " +
                                cairn::FormatShort(first_cell + num_cells) + ") lie outside the grid's " +
                                cairn::FormatShort(all_cells) + " displacement cells");
  }
  if (num_cells > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::invalid_argument("TransitionOracle::Build: the grid has " + cairn::FormatShort(num_cells) +
                                " step displacements, more than the " +
                                cairn::FormatShort(std::numeric_limits<int>::max()) + " supported; use fewer axis values.");
  }
  const ModelTransitionSource analytic(options.optimizer);
  const TransitionSource& source = options.source != nullptr ? *options.source : analytic;
  const int threads = source.concurrent() ? ResolveThreadCount(options.num_threads) : 1;
  const std::size_t num_mu = grid.mu.size();
  const std::size_t total = num_cells * num_mu;
  std::vector<Entry> out(total, Entry{});
  std::mutex progress_mutex;
  std::size_t done = 0;
  std::atomic<int> first_failure{std::numeric_limits<int>::max()};

  // One band per displacement, started in order by whichever thread is free (the cells' optimisations take very
  // different times). After a failure, cells above the failing one are skipped; cells below it still run, so the
  // exception rethrown is always that of the lowest failing cell.
  ParallelForBands(static_cast<int>(num_cells), static_cast<int>(num_cells), threads, [&](int band, int, int) {
    if (band > first_failure.load()) return;
    const std::size_t cell = first_cell + static_cast<std::size_t>(band);
    try {
      std::size_t rest = cell;
      const std::size_t i_th = rest % grid.dtheta.size();
      rest /= grid.dtheta.size();
      const std::size_t i_dz = rest % grid.dz.size();
      rest /= grid.dz.size();
      const std::size_t i_dy = rest % grid.dy.size();
      const std::size_t i_dx = rest / grid.dy.size();
      const StepDisplacement d{grid.dx[i_dx], grid.dy[i_dy], grid.dz[i_dz], grid.dtheta[i_th]};
      const std::vector<Entry> entries = source.CellEntries(model, objective, d, grid.mu);
      std::copy(entries.begin(), entries.end(), out.begin() + static_cast<std::ptrdiff_t>(band * num_mu));
    } catch (...) {
      int seen = first_failure.load();
      while (band < seen && !first_failure.compare_exchange_weak(seen, band)) {
      }
      throw;
    }
    std::lock_guard<std::mutex> lock(progress_mutex);
    done += num_mu;
    if (options.progress) options.progress(done, total);
  });
  return out;
}

TransitionOracle TransitionOracle::FromEntries(const WalkingModel& model, WalkingObjective objective,
                                               const OracleGrid& grid, std::vector<Entry> entries,
                                               const TransitionSource* source) {
  grid.Validate(model.reach());
  if (entries.size() != grid.num_entries()) {
    throw std::invalid_argument("TransitionOracle::FromEntries: " + cairn::FormatShort(entries.size()) +
                                " entries for a grid of " + cairn::FormatShort(grid.num_entries()) +
                                "; give one per displacement and mu value");
  }
  TransitionOracle oracle;
  oracle.grid_ = grid;
  oracle.objective_ = objective;
  oracle.robot_name_ = model.name();
  oracle.model_hash_ = model.content_hash();
  oracle.source_ = SourceLine(source);
  oracle.entries_ = std::move(entries);
  oracle.Finalize();
  return oracle;
}

std::string TransitionOracle::EncodeEntries(const std::vector<Entry>& entries) {
  std::string payload;
  payload.reserve(entries.size() * kDoublesPerEntry * 8);
  for (const Entry& e : entries) {
    PutDouble(payload, e.feasible ? 1.0 : 0.0);
    PutDouble(payload, e.cost);
    PutDouble(payload, e.parameters.t_ds);
    PutDouble(payload, e.parameters.t_sw);
    PutDouble(payload, e.parameters.com_height);
    PutDouble(payload, e.com_work);
    PutDouble(payload, e.heat);
    PutDouble(payload, e.rcof);
    PutDouble(payload, e.duration);
  }
  return payload;
}

std::vector<TransitionOracle::Entry> TransitionOracle::DecodeEntries(std::string_view bytes, std::size_t count) {
  const std::size_t per_entry = kDoublesPerEntry * 8;
  if (count > bytes.size() / per_entry || bytes.size() != count * per_entry) {
    throw std::invalid_argument("TransitionOracle::DecodeEntries: " + cairn::FormatShort(bytes.size()) +
                                " bytes do not hold " + cairn::FormatShort(count) + " entries of " +
                                cairn::FormatShort(per_entry) + " bytes");
  }
  std::vector<Entry> entries(count);
  const char* p = bytes.data();
  for (Entry& e : entries) {
    e.feasible = GetDouble(p) != 0.0;
    e.cost = GetDouble(p + 8);
    e.parameters = StepParameters{GetDouble(p + 16), GetDouble(p + 24), GetDouble(p + 32)};
    e.com_work = GetDouble(p + 40);
    e.heat = GetDouble(p + 48);
    e.rcof = GetDouble(p + 56);
    e.duration = GetDouble(p + 64);
    p += per_entry;
  }
  return entries;
}

std::uint64_t TransitionOracle::BuildKey(const WalkingModel& model, WalkingObjective objective, const OracleGrid& grid,
                                         const TransitionSource* source) {
  return Fnv1a64(HeaderFields(model.name(), model.content_hash(), objective, SourceLine(source), grid));
}

void TransitionOracle::Finalize() {
  reach_ = StepReach{grid_.dx.front(), grid_.dx.back(), grid_.dy.front(), grid_.dy.back(),
                     grid_.dz.front(), grid_.dz.back(), grid_.dtheta.front(), grid_.dtheta.back()};
  // Lower bounds cost >= per_step + per_metre * hypot(dx, dy), over all feasible entries and per mu level. An
  // interpolated lookup is a convex combination of one level's feasible entries whose (dx, dy) it reproduces, and
  // hypot is convex, so every bound holds for lookups too; a lookup at friction mu uses the floor level, whose
  // costs are at least those of any higher level, so the bound of level floor(mu) holds at every smaller mu.
  const std::size_t num_mu = grid_.mu.size();
  auto length_of = [&](std::size_t i) {
    const std::size_t rest = i / num_mu / grid_.dtheta.size() / grid_.dz.size();
    return std::hypot(grid_.dx[rest / grid_.dy.size()], grid_.dy[rest % grid_.dy.size()]);
  };
  constexpr double kInf = std::numeric_limits<double>::infinity();
  min_cost_per_metre_ = kInf;
  std::vector<double> level_per_metre(num_mu, kInf);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (!entries_[i].feasible) continue;
    const double ratio = entries_[i].cost / length_of(i);
    min_cost_per_metre_ = std::min(min_cost_per_metre_, ratio);
    level_per_metre[i % num_mu] = std::min(level_per_metre[i % num_mu], ratio);
  }
  if (!std::isfinite(min_cost_per_metre_)) min_cost_per_metre_ = 0.0;  // no feasible step: any bound is admissible
  min_cost_per_step_ = kInf;
  std::vector<double> level_per_step(num_mu, kInf);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (!entries_[i].feasible) continue;
    const double length = length_of(i);
    const std::size_t m = i % num_mu;
    min_cost_per_step_ = std::min(min_cost_per_step_, entries_[i].cost - min_cost_per_metre_ * length);
    level_per_step[m] = std::min(level_per_step[m], entries_[i].cost - level_per_metre[m] * length);
  }
  // Rounding can leave -1e-16 where a ratio was attained; the bound is then 0.
  min_cost_per_step_ = std::isfinite(min_cost_per_step_) ? std::max(0.0, min_cost_per_step_) : 0.0;
  level_bounds_.assign(num_mu, StepCostLowerBound{false, 0.0, 0.0});
  for (std::size_t m = 0; m < num_mu; ++m) {
    if (std::isfinite(level_per_metre[m])) {
      level_bounds_[m] = StepCostLowerBound{true, std::max(0.0, level_per_step[m]), level_per_metre[m]};
    }
  }
  ComputeStrideBounds();
}

void TransitionOracle::ComputeStrideBounds() {
  // For each mu level: every ordered pair of feasible entries is a possible pair of consecutive steps (the other
  // foot lands at d1 beside this one, then this foot lands at d2 beside it, mirrored). A lookup interpolates
  // entries of one level at the planner's on-grid yaw steps, so a pair of lookups is a convex combination of
  // entry pairs with the same yaws, whose stride vectors it reproduces; the stride length is convex in them, and
  // the bound below is convex and non-decreasing, so it holds for lookups too.
  const std::size_t num_mu = grid_.mu.size();
  const std::size_t per_cell = num_mu;
  struct Step {
    double dx, dy, dtheta, cost;
  };
  constexpr double kBin = 0.01;  // m
  stride_bounds_.assign(num_mu, StrideCostLowerBound{false, {}, {}});
  for (std::size_t m = 0; m < num_mu; ++m) {
    std::vector<Step> steps;
    for (std::size_t i = m; i < entries_.size(); i += per_cell) {
      if (!entries_[i].feasible) continue;
      std::size_t rest = i / num_mu;
      const std::size_t i_theta = rest % grid_.dtheta.size();
      rest /= grid_.dtheta.size();
      rest /= grid_.dz.size();
      const std::size_t i_dy = rest % grid_.dy.size();
      const std::size_t i_dx = rest / grid_.dy.size();
      steps.push_back(Step{grid_.dx[i_dx], grid_.dy[i_dy], grid_.dtheta[i_theta], entries_[i].cost});
    }
    if (steps.empty()) continue;
    // Cheapest pair per 1 cm stride bin.
    const double longest = 2.0 * std::hypot(std::max(std::abs(grid_.dx.front()), std::abs(grid_.dx.back())), grid_.dy.back());
    const std::size_t bins = static_cast<std::size_t>(std::ceil(longest / kBin)) + 2;
    std::vector<double> cheapest(bins, std::numeric_limits<double>::infinity());
    for (const Step& a : steps) {
      // The other foot lands at (a.dx, a.dy) turned by a.dtheta; this foot lands beside it on the other side.
      const double c = std::cos(a.dtheta), s = std::sin(a.dtheta);
      for (const Step& b : steps) {
        const double x = a.dx + c * b.dx + s * b.dy;
        const double y = a.dy + s * b.dx - c * b.dy;
        const std::size_t bin = std::min(bins - 1, static_cast<std::size_t>(std::hypot(x, y) / kBin));
        cheapest[bin] = std::min(cheapest[bin], a.cost + b.cost);
      }
    }
    // G(s) = cheapest pair with stride >= s is non-decreasing and, on [j kBin, (j+1) kBin], at least the suffix
    // minimum from bin j; the points ((j+1) kBin, suffix_j) and (0, suffix_0) therefore lie below G, and so does
    // their lower convex hull.
    for (std::size_t j = bins - 1; j-- > 0;) cheapest[j] = std::min(cheapest[j], cheapest[j + 1]);
    std::vector<double> xs = {0.0}, ys = {cheapest[0]};
    std::size_t last = bins - 1;
    while (last > 0 && !std::isfinite(cheapest[last])) --last;
    for (std::size_t j = 0; j <= last; ++j) {
      xs.push_back((j + 1) * kBin);
      ys.push_back(cheapest[j]);
    }
    StrideCostLowerBound& hull = stride_bounds_[m];
    hull.any_feasible = true;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      while (hull.stride.size() >= 2) {
        const std::size_t n = hull.stride.size();
        const double cross = (hull.stride[n - 1] - hull.stride[n - 2]) * (ys[k] - hull.cost[n - 2]) -
                             (hull.cost[n - 1] - hull.cost[n - 2]) * (xs[k] - hull.stride[n - 2]);
        if (cross > 0.0) break;  // a left turn keeps the hull convex from below
        hull.stride.pop_back();
        hull.cost.pop_back();
      }
      hull.stride.push_back(xs[k]);
      hull.cost.push_back(ys[k]);
    }
  }
}

StrideCostLowerBound TransitionOracle::do_stride_cost_lower_bound(double mu_allowed) const {
  const auto above = std::upper_bound(grid_.mu.begin(), grid_.mu.end(), mu_allowed + 1e-12);
  if (above == grid_.mu.begin()) return StrideCostLowerBound{false, {}, {}};
  return stride_bounds_[static_cast<std::size_t>(above - grid_.mu.begin()) - 1];
}

StepCostLowerBound TransitionOracle::do_cost_lower_bound(double mu_allowed) const {
  const auto above = std::upper_bound(grid_.mu.begin(), grid_.mu.end(), mu_allowed + 1e-12);
  if (above == grid_.mu.begin()) return StepCostLowerBound{false, 0.0, 0.0};
  return level_bounds_[static_cast<std::size_t>(above - grid_.mu.begin()) - 1];
}

const TransitionOracle::Entry& TransitionOracle::entry(std::size_t i_dx, std::size_t i_dy, std::size_t i_dz,
                                                       std::size_t i_dtheta, std::size_t i_mu) const {
  if (i_dx >= grid_.dx.size() || i_dy >= grid_.dy.size() || i_dz >= grid_.dz.size() ||
      i_dtheta >= grid_.dtheta.size() || i_mu >= grid_.mu.size()) {
    throw std::out_of_range("TransitionOracle::entry: index outside the grid.");
  }
  const std::size_t cell = ((i_dx * grid_.dy.size() + i_dy) * grid_.dz.size() + i_dz) * grid_.dtheta.size() + i_dtheta;
  return entries_[cell * grid_.mu.size() + i_mu];
}

std::size_t TransitionOracle::num_feasible() const {
  return static_cast<std::size_t>(
      std::count_if(entries_.begin(), entries_.end(), [](const Entry& e) { return e.feasible; }));
}

TransitionCost TransitionOracle::DoEvaluate(const StepDisplacement& d, double mu_allowed) const {
  if (!(mu_allowed >= 0.0)) {
    throw std::invalid_argument("TransitionOracle: mu_allowed is " + FormatShort(mu_allowed) +
                                "; it must be a friction coefficient >= 0 (0 means not walkable).");
  }
  if (!std::isfinite(d.dx) || !std::isfinite(d.dy) || !std::isfinite(d.dz) || !std::isfinite(d.dtheta)) {
    throw std::invalid_argument("TransitionOracle: the step displacement is not finite.");
  }
  TransitionCost result;
  // Floor in mu.
  const auto above = std::upper_bound(grid_.mu.begin(), grid_.mu.end(), mu_allowed + 1e-12);
  if (above == grid_.mu.begin()) return result;
  const std::size_t i_mu = static_cast<std::size_t>(above - grid_.mu.begin()) - 1;

  std::size_t index[4];
  double t[4];
  if (!LocateOnAxis(grid_.dx, d.dx, &index[0], &t[0]) || !LocateOnAxis(grid_.dy, d.dy, &index[1], &t[1]) ||
      !LocateOnAxis(grid_.dz, d.dz, &index[2], &t[2]) || !LocateOnAxis(grid_.dtheta, d.dtheta, &index[3], &t[3])) {
    return result;
  }
  const std::size_t sizes[4] = {grid_.dx.size(), grid_.dy.size(), grid_.dz.size(), grid_.dtheta.size()};
  double sum[kDoublesPerEntry - 1] = {0.0};
  for (int corner = 0; corner < 16; ++corner) {
    double weight = 1.0;
    std::size_t cell = 0;
    for (int axis = 0; axis < 4; ++axis) {
      const bool upper = (corner >> axis) & 1;
      weight *= upper ? t[axis] : 1.0 - t[axis];
      cell = cell * sizes[axis] + (upper ? std::min(index[axis] + 1, sizes[axis] - 1) : index[axis]);
    }
    if (weight == 0.0) continue;
    const Entry& e = entries_[cell * grid_.mu.size() + i_mu];
    if (!e.feasible) return TransitionCost{};
    const double values[kDoublesPerEntry - 1] = {e.cost,     e.parameters.t_ds, e.parameters.t_sw, e.parameters.com_height,
                                                 e.com_work, e.heat,            e.rcof,            e.duration};
    for (int k = 0; k < kDoublesPerEntry - 1; ++k) sum[k] += weight * values[k];
  }
  result.feasible = true;
  result.cost = sum[0];
  result.parameters = StepParameters{sum[1], sum[2], sum[3]};
  result.com_work = sum[4];
  result.heat = sum[5];
  result.rcof = sum[6];
  result.duration = sum[7];
  return result;
}

double TransitionOracle::DoMinCostOverHeights(const StepDisplacement& d, double dz_lo, double dz_hi,
                                              double mu_allowed) const {
  double best = std::numeric_limits<double>::infinity();
  StepDisplacement at = d;
  auto consider = [&](double dz) {
    at.dz = dz;
    const TransitionCost cost = DoEvaluate(at, mu_allowed);
    if (cost.feasible) best = std::min(best, cost.cost);
  };
  consider(dz_lo);
  if (dz_hi > dz_lo) {
    consider(dz_hi);
    for (double knot : grid_.dz) {
      if (knot > dz_lo && knot < dz_hi) consider(knot);
    }
  }
  return best;
}

std::string TransitionOracle::do_description() const {
  return "transition oracle for " + robot_name_ + ", objective " + to_string(objective_) + ", " +
         cairn::FormatShort(entries_.size()) + " entries (" + cairn::FormatShort(num_feasible()) + " feasible) over " +
         cairn::FormatShort(grid_.dx.size()) + " dx x " + cairn::FormatShort(grid_.dy.size()) + " dy x " +
         cairn::FormatShort(grid_.dz.size()) + " dz x " + cairn::FormatShort(grid_.dtheta.size()) + " dtheta x " +
         cairn::FormatShort(grid_.mu.size()) + " mu, source " + source_;
}

std::string TransitionOracle::Serialize() const {
  const std::string payload = EncodeEntries(entries_);
  std::string header = std::string(kMagic) + "\n";
  header += HeaderFields(robot_name_, model_hash_, objective_, source_, grid_);
  header += "entries " + cairn::FormatShort(entries_.size()) + "\n";
  header += "payload_bytes " + cairn::FormatShort(payload.size()) + "\n";
  header += "checksum " + HashHex(Fnv1a64(payload)) + "\n";
  header += "end\n";
  return header + payload;
}

void TransitionOracle::Save(const std::string& path) const { WriteFileAtomically(path, Serialize()); }

TransitionOracle TransitionOracle::Load(const std::string& path, const WalkingModel& model, WalkingObjective objective,
                                        const OracleGrid& grid, const TransitionSource* source) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the transition oracle file.");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  auto fail = [&](const std::string& why) -> void { throw std::runtime_error(path + ": " + why); };

  std::size_t position = 0;
  auto next_line = [&]() {
    const std::size_t end = bytes.find('\n', position);
    if (end == std::string::npos || end - position > 100000) fail("corrupt header (truncated).");
    std::string line = bytes.substr(position, end - position);
    position = end + 1;
    return line;
  };
  auto field = [&](const std::string& key) {
    const std::string line = next_line();
    if (line.compare(0, key.size() + 1, key + " ") != 0) fail("corrupt header: expected '" + key + "'.");
    return line.substr(key.size() + 1);
  };
  const std::string magic = next_line();
  if (magic == kMagicVersion1) fail("written in format 1 (before oracle sources were recorded); build it again.");
  if (magic != kMagic) fail("not a transition oracle file (bad magic line).");
  const std::string robot = field("robot");
  if (robot != model.name()) fail("made for robot '" + robot + "', not '" + model.name() + "'.");
  const std::string hash = field("model_hash");
  if (hash != HashHex(model.content_hash())) {
    fail("made for another version of the walking model (model hash " + hash + ", current " +
         HashHex(model.content_hash()) + ").");
  }
  const std::string stored_objective = field("objective");
  if (stored_objective != to_string(objective)) {
    fail("made for objective '" + stored_objective + "', not '" + to_string(objective) + "'.");
  }
  const std::string stored_source = field("source");
  const std::string wanted_source = SourceLine(source);
  if (stored_source != wanted_source) {
    fail("built from source '" + stored_source + "', not '" + wanted_source + "'.");
  }
  OracleGrid stored;
  for (auto [name, axis] : {std::pair<const char*, std::vector<double>*>{"dx", &stored.dx},
                            {"dy", &stored.dy}, {"dz", &stored.dz}, {"dtheta", &stored.dtheta}, {"mu", &stored.mu}}) {
    std::istringstream values(field(name));
    std::size_t count = 0;
    if (!(values >> count) || count > 100000) fail(std::string("corrupt header: bad '") + name + "' axis.");
    axis->resize(count);
    for (double& v : *axis) {
      std::string token;
      if (!(values >> token)) fail(std::string("corrupt header: bad '") + name + "' axis.");
      v = std::strtod(token.c_str(), nullptr);
    }
  }
  if (stored != grid) fail("made for a different grid (" + cairn::FormatShort(stored.num_entries()) + " entries vs " +
                           cairn::FormatShort(grid.num_entries()) + " requested, or different axis values).");
  const std::size_t entries = std::strtoull(field("entries").c_str(), nullptr, 10);
  const std::size_t payload_bytes = std::strtoull(field("payload_bytes").c_str(), nullptr, 10);
  const std::string checksum = field("checksum");
  if (next_line() != "end") fail("corrupt header: missing 'end'.");
  if (entries != grid.num_entries() || payload_bytes != entries * kDoublesPerEntry * 8) {
    fail("corrupt header: entry count or payload size does not match the grid.");
  }
  if (bytes.size() - position != payload_bytes) {
    fail("corrupt: the payload has " + cairn::FormatShort(bytes.size() - position) + " bytes, the header says " +
         cairn::FormatShort(payload_bytes) + ".");
  }
  if (HashHex(Fnv1a64(std::string_view(bytes).substr(position, payload_bytes))) != checksum) {
    fail("corrupt: payload checksum mismatch.");
  }

  return FromEntries(model, objective, grid, DecodeEntries(std::string_view(bytes).substr(position), entries), source);
}

TransitionOracle TransitionOracle::LoadOrBuild(const std::string& path, const WalkingModel& model,
                                               WalkingObjective objective, const OracleGrid& grid,
                                               const OracleBuildOptions& options, std::ostream* log) {
  grid.Validate(model.reach());
  std::string reason;
  std::error_code exists_error;
  if (std::filesystem::exists(path, exists_error)) {
    try {
      TransitionOracle oracle = Load(path, model, objective, grid, options.source.get());
      if (log != nullptr) *log << "Loaded transition oracle " << path << " (" << oracle.num_entries() << " entries)\n";
      return oracle;
    } catch (const std::runtime_error& error) {
      reason = error.what();
    }
  }
  if (log != nullptr) {
    if (reason.empty()) {
      *log << "Building transition oracle " << path << " (" << grid.num_entries() << " entries, objective "
           << to_string(objective) << ")\n";
    } else {
      *log << "Rebuilding transition oracle: " << reason << "\n";
    }
  }
  TransitionOracle oracle = Build(model, objective, grid, options);
  // The cache is an optimisation: a folder that cannot be created or written costs the next run a rebuild, not
  // this run its table.
  std::string problem;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code folder_error;
  if (!folder.empty()) std::filesystem::create_directories(folder, folder_error);
  if (folder_error) {
    problem = "cannot create the folder '" + folder.string() + "' (" + folder_error.message() + ")";
  } else {
    try {
      oracle.Save(path);
    } catch (const std::exception& error) {
      problem = error.what();
    }
  }
  if (!problem.empty()) {
    std::ostream& warning = log != nullptr ? *log : std::cerr;
    warning << "Warning: the transition oracle is not cached: " << problem
            << "; continuing with the table in memory (it will be built again next time; choose a writable cache "
               "folder to keep it)\n";
  }
  return oracle;
}

}  // namespace cairn::planning
