#include "cairn/perception/haptics/simulation/haptic_object_library.h"

#include <cmath>
#include <random>
#include <stdexcept>

namespace cairn::perception {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Builder {
  explicit Builder(std::uint64_t seed) : rng(seed) {}

  double Uniform(double lo, double hi) {
    // From the raw 64-bit output, so that the objects are the same with every standard library.
    return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0));
  }
  void Sphere(const Eigen::Vector3d& c, double r, bool stiff) {
    primitives.push_back({HapticPrimitive::Shape::kSphere, c, Eigen::Vector3d::Zero(), r, stiff});
  }
  void Capsule(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r, bool stiff) {
    primitives.push_back({HapticPrimitive::Shape::kCapsule, a, b, r, stiff});
  }
  void Box(const Eigen::Vector3d& c, const Eigen::Vector3d& half, bool stiff) {
    primitives.push_back({HapticPrimitive::Shape::kBox, c, half, 0.0, stiff});
  }
  // A point in a dome of radius `radius` (x, y) and `height`, above `min_height`.
  Eigen::Vector3d InDome(double radius, double height, double min_height) {
    const double angle = Uniform(0.0, 2.0 * kPi);
    const double rho = radius * std::sqrt(Uniform(0.05, 1.0));
    const double top = height * std::sqrt(std::max(0.0, 1.0 - (rho * rho) / (radius * radius)));
    return {rho * std::cos(angle), rho * std::sin(angle), Uniform(min_height, std::max(min_height + 0.01, top))};
  }
  // Soft branches from near the base to the dome, leaves at and along their ends.
  void Bush(int branches, int leaves_per_branch, double radius, double height, double branch_radius,
            double leaf_radius) {
    for (int i = 0; i < branches; ++i) {
      const Eigen::Vector3d base(Uniform(-0.03, 0.03), Uniform(-0.03, 0.03), 0.0);
      const Eigen::Vector3d tip = InDome(radius, height, 0.4 * height);
      Capsule(base, tip, branch_radius, false);
      for (int j = 0; j < leaves_per_branch; ++j) {
        const double along = Uniform(0.55, 1.0);
        const Eigen::Vector3d jitter(Uniform(-0.03, 0.03), Uniform(-0.03, 0.03), Uniform(-0.02, 0.02));
        Sphere(base + along * (tip - base) + jitter, leaf_radius * Uniform(0.7, 1.2), false);
      }
    }
  }
  // A deep patch of `kind` of plant filling x in [0, depth], y in [-half_width, half_width].
  void Patch(double depth, double half_width, int stems, double height, double stem_radius, int leaves,
             double leaf_radius, bool stiff) {
    for (int i = 0; i < stems; ++i) {
      const Eigen::Vector3d base(Uniform(0.0, depth), Uniform(-half_width, half_width), 0.0);
      const Eigen::Vector3d tip = base + Eigen::Vector3d(Uniform(-0.08, 0.08), Uniform(-0.08, 0.08),
                                                         height * Uniform(0.7, 1.1));
      Capsule(base, tip, stem_radius, stiff);
      for (int j = 0; j < leaves; ++j) {
        Sphere(base + Uniform(0.4, 1.0) * (tip - base) +
                   Eigen::Vector3d(Uniform(-0.04, 0.04), Uniform(-0.04, 0.04), 0.0),
               leaf_radius, false);
      }
    }
  }

  std::mt19937_64 rng;
  std::vector<HapticPrimitive> primitives;
};

struct KindName {
  HapticObjectKind kind;
  const char* letter;
  const char* name;
};

constexpr KindName kNames[] = {
    {HapticObjectKind::kWall, "(a)", "wall"},
    {HapticObjectKind::kRock, "(b)", "rock"},
    {HapticObjectKind::kBigPlant, "(c)", "big plant"},
    {HapticObjectKind::kShrub, "(d)", "shrub"},
    {HapticObjectKind::kSmallShrub, "(e)", "small shrub"},
    {HapticObjectKind::kTallPlants, "(f)", "tall plants"},
    {HapticObjectKind::kTallPlant, "(g)", "tall plant"},
    {HapticObjectKind::kVerticalLogs, "(h)", "vertical logs"},
    {HapticObjectKind::kHorizontalLogs, "(i)", "horizontal logs"},
    {HapticObjectKind::kNovelGrass, "(1)", "novel grass"},
    {HapticObjectKind::kNovelStump, "(2)", "novel stump"},
    {HapticObjectKind::kShrubPatch, "(A)", "shrub patch"},
    {HapticObjectKind::kFlimsyCanes, "(B)", "flimsy canes"},
    {HapticObjectKind::kTwigs, "(C)", "twigs"},
};

}  // namespace

std::string HapticObjectName(HapticObjectKind kind) {
  for (const KindName& k : kNames) {
    if (k.kind == kind) return std::string(k.letter) + " " + k.name;
  }
  throw std::invalid_argument("unknown haptic object kind");
}

HapticObjectKind ParseHapticObjectKind(const std::string& name) {
  std::string known;
  for (const KindName& k : kNames) {
    if (name == k.name) return k.kind;
    known += std::string(known.empty() ? "" : ", ") + "'" + k.name + "'";
  }
  throw std::invalid_argument("unknown object '" + name + "'; the objects are " + known);
}

std::vector<HapticObjectKind> DataSet1() {
  return {HapticObjectKind::kWall,       HapticObjectKind::kRock,       HapticObjectKind::kBigPlant,
          HapticObjectKind::kShrub,      HapticObjectKind::kSmallShrub, HapticObjectKind::kTallPlants,
          HapticObjectKind::kTallPlant,  HapticObjectKind::kVerticalLogs, HapticObjectKind::kHorizontalLogs};
}

std::vector<HapticObjectKind> DataSet2() { return {HapticObjectKind::kNovelGrass, HapticObjectKind::kNovelStump}; }

HapticSceneObject MakeHapticObject(HapticObjectKind kind, std::uint64_t seed) {
  Builder b(seed);
  switch (kind) {
    case HapticObjectKind::kWall:
      b.Box({0.05, 0.0, 0.3}, {0.05, 0.6, 0.3}, true);
      break;
    case HapticObjectKind::kRock:
      b.Sphere({0.1, 0.0, 0.06}, 0.17 * b.Uniform(0.9, 1.1), true);
      b.Sphere({0.12, 0.13, 0.03}, 0.11 * b.Uniform(0.9, 1.1), true);
      b.Sphere({0.08, -0.12, 0.02}, 0.12 * b.Uniform(0.9, 1.1), true);
      break;
    case HapticObjectKind::kBigPlant: {
      b.Capsule({0.0, 0.0, 0.0}, {0.0, 0.0, 0.5}, 0.03, true);
      for (int i = 0; i < 9; ++i) {
        const double z = b.Uniform(0.12, 0.5);
        const double angle = b.Uniform(0.0, 2.0 * kPi);
        const Eigen::Vector3d tip(0.28 * std::cos(angle), 0.28 * std::sin(angle), z + b.Uniform(0.0, 0.12));
        b.Capsule({0.0, 0.0, z}, tip, 0.006, false);
        for (int j = 0; j < 4; ++j) {
          b.Sphere(Eigen::Vector3d(0.0, 0.0, z) + b.Uniform(0.35, 1.0) * (tip - Eigen::Vector3d(0.0, 0.0, z)),
                   0.045 * b.Uniform(0.8, 1.2), false);
        }
      }
      break;
    }
    case HapticObjectKind::kShrub:
      b.Bush(28, 3, 0.3, 0.45, 0.006, 0.028);
      break;
    case HapticObjectKind::kSmallShrub:
      b.Bush(14, 3, 0.18, 0.28, 0.005, 0.022);
      break;
    case HapticObjectKind::kTallPlants:
      for (int i = 0; i < 6; ++i) {
        const Eigen::Vector3d base(b.Uniform(-0.08, 0.08), b.Uniform(-0.25, 0.25), 0.0);
        const Eigen::Vector3d tip = base + Eigen::Vector3d(b.Uniform(-0.05, 0.05), b.Uniform(-0.05, 0.05),
                                                           b.Uniform(0.55, 0.65));
        b.Capsule(base, tip, 0.005, false);
        for (int j = 0; j < 4; ++j) b.Sphere(base + b.Uniform(0.5, 1.0) * (tip - base), 0.022, false);
      }
      break;
    case HapticObjectKind::kTallPlant: {
      const Eigen::Vector3d tip(b.Uniform(-0.03, 0.03), b.Uniform(-0.03, 0.03), 0.62);
      b.Capsule({0.0, 0.0, 0.0}, tip, 0.008, false);
      for (int j = 0; j < 12; ++j) {
        const double along = 0.25 + 0.06 * j;
        const double side = (j % 2 == 0 ? 1.0 : -1.0) * b.Uniform(0.04, 0.08);
        b.Sphere(along * tip + Eigen::Vector3d(b.Uniform(-0.03, 0.03), side, 0.0), 0.032, false);
      }
      break;
    }
    case HapticObjectKind::kVerticalLogs:
      for (int i = 0; i < 5; ++i) {
        const Eigen::Vector3d base(b.Uniform(-0.02, 0.02), -0.2 + 0.1 * i, 0.0);
        b.Capsule(base, base + Eigen::Vector3d(0.0, 0.0, b.Uniform(0.32, 0.42)), 0.05, true);
      }
      break;
    case HapticObjectKind::kHorizontalLogs:
      b.Capsule({-0.06, -0.3, 0.06}, {-0.06, 0.3, 0.06}, 0.06, true);
      b.Capsule({0.07, -0.28, 0.06}, {0.07, 0.32, 0.06}, 0.06, true);
      b.Capsule({0.0, -0.25, 0.17}, {0.0, 0.25 + b.Uniform(0.0, 0.05), 0.17}, 0.06, true);
      break;
    case HapticObjectKind::kNovelGrass:
      for (int i = 0; i < 45; ++i) {
        const Eigen::Vector3d base(b.Uniform(-0.04, 0.04), b.Uniform(-0.04, 0.04), 0.0);
        b.Capsule(base, b.InDome(0.25, 0.38, 0.2), 0.004, false);
      }
      break;
    case HapticObjectKind::kNovelStump:
      b.Capsule({0.0, 0.0, 0.0}, {0.0, 0.0, 0.28}, 0.14, true);
      for (int i = 0; i < 5; ++i) {
        const double angle = b.Uniform(0.0, 2.0 * kPi);
        const Eigen::Vector3d base(0.1 * std::cos(angle), 0.1 * std::sin(angle), 0.4);
        b.Capsule(base, base + Eigen::Vector3d(b.Uniform(-0.08, 0.08), b.Uniform(-0.08, 0.08), 0.15), 0.005, false);
        b.Sphere(base + Eigen::Vector3d(0.0, 0.0, 0.15), 0.025, false);
      }
      break;
    case HapticObjectKind::kShrubPatch:
      b.Patch(2.0, 0.6, 156, 0.4, 0.005, 3, 0.025, false);
      break;
    case HapticObjectKind::kFlimsyCanes:
      b.Patch(0.9, 0.6, 120, 0.6, 0.006, 0, 0.02, false);
      break;
    case HapticObjectKind::kTwigs:
      b.Patch(1.0, 0.6, 80, 0.3, 0.003, 3, 0.018, false);
      break;
  }
  return HapticSceneObject(HapticObjectName(kind), std::move(b.primitives));
}

}  // namespace cairn::perception
