#include "cairn/perception/haptics/simulation/haptic_affordance_experiment.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/gist_change_detector.h"
#include "cairn/perception/haptics/point_cloud_reduction.h"

namespace cairn::perception {
namespace {

// A deterministic value in [0, 1) from a seed and two integers (splitmix64), so that each approach has its own
// view whatever order the experiments run in.
double Hash01(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (a + 1) + 0xBF58476D1CE4E5B9ULL * (b + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z = z ^ (z >> 31);
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

std::uint64_t Mix(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
  return static_cast<std::uint64_t>(Hash01(seed, a, b) * 9007199254740992.0);
}

HapticAffordanceExperiment::Options Checked(HapticAffordanceExperiment::Options options) {
  if (!(options.sensor_height > 0.0) || !std::isfinite(options.sensor_height)) {
    throw std::invalid_argument("sensor_height is " + FormatShort(options.sensor_height) + " m; it must be positive");
  }
  if (!(options.min_distance > 0.0) || !(options.max_distance >= options.min_distance) ||
      !std::isfinite(options.max_distance)) {
    throw std::invalid_argument("the approach distances [" + FormatShort(options.min_distance) + ", " +
                                FormatShort(options.max_distance) + "] m must be finite with 0 < min <= max");
  }
  if (!(options.max_heading >= 0.0) || !(options.max_heading < 1.5)) {
    throw std::invalid_argument("max_heading is " + FormatShort(options.max_heading) + " rad; it must lie in [0, 1.5)");
  }
  if (options.samples_per_object < 1 || options.samples_per_object > HapticAffordanceExperiment::kMaxSamples) {
    throw std::invalid_argument("samples_per_object is " + FormatShort(options.samples_per_object) +
                                "; it must be between 1 and " + FormatShort(HapticAffordanceExperiment::kMaxSamples));
  }
  options.descriptor.reach_center_C = options.X_CA.translation();
  AffordanceDescriptor::Validate(options.descriptor);
  TraversabilityMemory::Validate(options.memory);
  HapticInteractionPlanner::Validate(options.planner);
  return options;
}

void CheckCount(int n, const char* what) {
  if (n < 0 || n > HapticAffordanceExperiment::kMaxSamples) {
    throw std::invalid_argument(std::string(what) + " is " + FormatShort(n) + "; it must be between 0 and " +
                                FormatShort(HapticAffordanceExperiment::kMaxSamples));
  }
}

}  // namespace

double TraversabilityConfusion::accuracy() const {
  const int n = total();
  return n == 0 ? 0.0 : static_cast<double>(counts[0][0] + counts[1][1]) / n;
}

void TraversabilityConfusion::Add(bool actual_traversable, bool predicted_traversable) {
  ++counts[actual_traversable ? 0 : 1][predicted_traversable ? 0 : 1];
}

HapticAffordanceExperiment::HapticAffordanceExperiment() : HapticAffordanceExperiment(Options{}) {}

HapticAffordanceExperiment::HapticAffordanceExperiment(const Options& options)
    : options_(Checked(options)), sensor_(options.sensor), antenna_(options.antenna) {}

Eigen::Isometry3d HapticAffordanceExperiment::SensorPose(HapticObjectKind kind, int approach) const {
  const auto k = static_cast<std::uint64_t>(kind);
  const auto a = static_cast<std::uint64_t>(static_cast<std::int64_t>(approach) + (std::int64_t{1} << 32));
  const double distance =
      options_.min_distance + (options_.max_distance - options_.min_distance) * Hash01(options_.seed, k, 2 * a);
  const double heading = options_.max_heading * (2.0 * Hash01(options_.seed, k, 2 * a + 1) - 1.0);
  const Eigen::Vector3d position(-distance * std::cos(heading), -distance * std::sin(heading),
                                 options_.sensor_height);
  return SimulatedDepthSensor::LookingAlong(position, heading);
}

Eigen::Matrix3Xd HapticAffordanceExperiment::Observe(HapticObjectKind kind, int approach) const {
  const std::vector<HapticSceneObject> objects{MakeHapticObject(kind, options_.seed + static_cast<std::uint64_t>(kind))};
  return sensor_.Render(objects, SensorPose(kind, approach),
                        Mix(options_.seed, static_cast<std::uint64_t>(kind) + 100, static_cast<std::uint64_t>(approach)));
}

AffordanceDescriptor HapticAffordanceExperiment::Describe(const Eigen::Matrix3Xd& points_C) const {
  return AffordanceDescriptor::Compute(points_C, options_.descriptor);
}

AntennaInteraction HapticAffordanceExperiment::Touch(HapticObjectKind kind, int approach,
                                                     const Eigen::Matrix3Xd& points_C, double confidence,
                                                     int* interaction_points) const {
  const Eigen::Matrix3Xd object_C =
      KeepWithinReach(DownsampleByMinDistance(points_C, options_.descriptor.min_point_distance),
                      options_.descriptor.reach_center_C, options_.descriptor.reach_radius);
  const HapticInteractionPlanner planner(options_.planner);
  const InteractionPlan plan = planner.Plan(object_C, confidence);
  if (interaction_points) *interaction_points = static_cast<int>(plan.selected.size());
  const Eigen::Isometry3d X_AC = options_.X_CA.inverse();
  std::vector<Eigen::Vector3d> targets_A;
  targets_A.reserve(plan.targets_C.size());
  for (const Eigen::Vector3d& t : plan.targets_C) targets_A.push_back(X_AC * t);
  const std::vector<HapticSceneObject> objects{MakeHapticObject(kind, options_.seed + static_cast<std::uint64_t>(kind))};
  return antenna_.Probe(targets_A, objects, SensorPose(kind, approach) * options_.X_CA);
}

TraversabilityConfusion HapticAffordanceExperiment::LeaveOneOut(const std::vector<HapticObjectKind>& kinds,
                                                                int k) const {
  const int samples = options_.samples_per_object;
  std::vector<std::vector<AffordanceDescriptor>> descriptors(kinds.size());
  std::vector<bool> truth(kinds.size());
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    truth[i] = MakeHapticObject(kinds[i], options_.seed + static_cast<std::uint64_t>(kinds[i])).traversable();
    for (int s = 0; s < samples; ++s) descriptors[i].push_back(Describe(Observe(kinds[i], s)));
  }
  TraversabilityConfusion confusion;
  for (std::size_t out = 0; out < kinds.size(); ++out) {
    TraversabilityMemory memory(options_.memory, options_.descriptor.lines);
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      if (i == out) continue;
      for (const AffordanceDescriptor& d : descriptors[i]) memory.Add(d, truth[i]);
    }
    for (const AffordanceDescriptor& d : descriptors[out]) confusion.Add(truth[out], memory.Recall(d, k).traversable);
  }
  return confusion;
}

std::vector<HapticEncounter> HapticAffordanceExperiment::Incremental(const std::vector<HapticObjectKind>& kinds,
                                                                     int encounters,
                                                                     TraversabilityMemory* memory) const {
  CheckCount(encounters, "encounters");
  if (memory == nullptr) throw std::invalid_argument("Incremental needs a memory to learn into");
  std::vector<HapticEncounter> result;
  for (const HapticObjectKind kind : kinds) {
    const bool truth = MakeHapticObject(kind, options_.seed + static_cast<std::uint64_t>(kind)).traversable();
    for (int e = 0; e < encounters; ++e) {
      // Approaches 1000 + e: different views from the samples of the other experiments.
      const int approach = 1000 + e;
      const Eigen::Matrix3Xd points = Observe(kind, approach);
      const AffordanceDescriptor d = Describe(points);
      HapticEncounter encounter;
      encounter.kind = kind;
      encounter.traversable = truth;
      encounter.recall = memory->Recall(d);
      const AntennaInteraction touch = Touch(kind, approach, points, encounter.recall.confidence,
                                             &encounter.interaction_points);
      encounter.touched = encounter.interaction_points > 0;
      encounter.blocked = touch.blocked;
      // With no point to touch the memory's answer stands and nothing new is learnt.
      if (encounter.touched) memory->Add(d, !touch.blocked);
      result.push_back(encounter);
    }
  }
  return result;
}

std::vector<std::vector<int>> HapticAffordanceExperiment::AlphaSweep(HapticObjectKind kind,
                                                                     const std::vector<double>& alphas,
                                                                     int max_memory) const {
  CheckCount(max_memory, "max_memory");
  const bool truth = MakeHapticObject(kind, options_.seed + static_cast<std::uint64_t>(kind)).traversable();
  const int probe = 5000;  // the fresh sample
  const Eigen::Matrix3Xd points = Observe(kind, probe);
  const AffordanceDescriptor observed = Describe(points);
  const Eigen::Matrix3Xd object_C =
      KeepWithinReach(DownsampleByMinDistance(points, options_.descriptor.min_point_distance),
                      options_.descriptor.reach_center_C, options_.descriptor.reach_radius);
  const std::vector<InteractionPoint> candidates = HapticInteractionPlanner(options_.planner).ScoreCandidates(object_C);
  std::vector<std::vector<int>> result(alphas.size(), std::vector<int>(static_cast<std::size_t>(max_memory) + 1));
  TraversabilityMemory memory(options_.memory, options_.descriptor.lines);
  for (int n = 0; n <= max_memory; ++n) {
    if (n > 0) memory.Add(Describe(Observe(kind, 2000 + n)), truth);
    const double confidence = memory.Recall(observed).confidence;
    for (std::size_t a = 0; a < alphas.size(); ++a) {
      HapticInteractionPlanner::Options planner = options_.planner;
      planner.alpha = alphas[a];
      result[a][static_cast<std::size_t>(n)] =
          static_cast<int>(HapticInteractionPlanner(planner).Prune(candidates, confidence).size());
    }
  }
  return result;
}

std::vector<HapticEncounter> HapticAffordanceExperiment::Transfer(const std::vector<HapticObjectKind>& memory_kinds,
                                                                  const std::vector<HapticObjectKind>& test_kinds,
                                                                  int k) const {
  TraversabilityMemory memory(options_.memory, options_.descriptor.lines);
  for (const HapticObjectKind kind : memory_kinds) {
    for (int s = 0; s < options_.samples_per_object; ++s) {
      const int approach = 3000 + s;
      const Eigen::Matrix3Xd points = Observe(kind, approach);
      const AntennaInteraction touch = Touch(kind, approach, points, 0.0, nullptr);
      memory.Add(Describe(points), !touch.blocked);
    }
  }
  std::vector<HapticEncounter> result;
  for (const HapticObjectKind kind : test_kinds) {
    const bool truth = MakeHapticObject(kind, options_.seed + static_cast<std::uint64_t>(kind)).traversable();
    for (int s = 0; s < options_.samples_per_object; ++s) {
      HapticEncounter encounter;
      encounter.kind = kind;
      encounter.traversable = truth;
      encounter.recall = memory.Recall(Describe(Observe(kind, s)), k);
      result.push_back(encounter);
    }
  }
  return result;
}

std::vector<HapticAffordanceExperiment::ChangeRun> HapticAffordanceExperiment::ChangeDetection(double omega,
                                                                                               double voxel) const {
  GistChangeDetector::Options detector_options;
  detector_options.omega = omega;
  detector_options.voxel = voxel;
  SimulatedDepthSensor::Options sensor_options = options_.sensor;
  sensor_options.render_ground = true;
  const SimulatedDepthSensor sensor(sensor_options);
  struct Scenario {
    const char* name;
    HapticObjectKind kind;
    double depth;
    bool wall;
    bool stuck;
  };
  const Scenario scenarios[] = {{"A-1", HapticObjectKind::kShrubPatch, 2.0, false, false},
                                {"A-2", HapticObjectKind::kShrubPatch, 2.0, true, false},
                                {"B", HapticObjectKind::kFlimsyCanes, 0.9, false, true},
                                {"C", HapticObjectKind::kTwigs, 1.0, false, false}};
  std::vector<ChangeRun> runs;
  int index = 0;
  for (const Scenario& s : scenarios) {
    std::vector<HapticSceneObject> objects{MakeHapticObject(s.kind, options_.seed + static_cast<std::uint64_t>(s.kind))};
    if (s.wall) objects.push_back(MakeHapticObject(HapticObjectKind::kWall, options_.seed).Translated({s.depth + 0.9, 0.0, 0.0}));
    GistChangeDetector detector(detector_options);
    ChangeRun run;
    run.name = s.name;
    // The robot meets the patch 0.1 m inside it (it has been judged traversable) and takes the reference there;
    // then it drives 0.25 m per step until 0.3 m past the patch, or stays where it is when stuck.
    double x = 0.1;
    int frame = 0;
    const auto render = [&](double at) {
      return sensor.Render(objects, SimulatedDepthSensor::LookingAlong({at, 0.0, options_.sensor_height}, 0.0),
                           Mix(options_.seed, 7000 + static_cast<std::uint64_t>(index), static_cast<std::uint64_t>(frame++)));
    };
    detector.SetReference(render(x));
    const int steps = s.stuck ? 3 : static_cast<int>(std::ceil((s.depth + 0.3 - x) / 0.25));
    for (int step = 0; step < steps; ++step) {
      if (!s.stuck) x += 0.25;
      if (!s.stuck && x > s.depth && run.exit_step < 0) run.exit_step = step;
      const GistChangeDetector::Result r = detector.Compare(render(x));
      run.differences.push_back(r.difference);
      if (r.changed) {
        run.detected = true;
        break;  // the robot stops and checks anew
      }
    }
    runs.push_back(run);
    ++index;
  }
  return runs;
}

}  // namespace cairn::perception
