#include "cairn/perception/synthetic/material_texture.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "cairn/common/text_suggestions.h"

namespace cairn::perception {
namespace {

constexpr double kTwoPi = 6.283185307179586;

// Integer lattice hash (a variant of the "lowbias32" mixer): cheap, well distributed, platform independent.
std::uint32_t Hash(std::int64_t x, std::int64_t y, std::uint32_t seed) {
  std::uint32_t h = seed * 0x9E3779B9u ^ static_cast<std::uint32_t>(x) * 0x85EBCA6Bu ^
                    static_cast<std::uint32_t>(y) * 0xC2B2AE35u;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return h;
}

double Unit(std::int64_t x, std::int64_t y, std::uint32_t seed) { return Hash(x, y, seed) * (1.0 / 4294967296.0); }

// Smooth value noise in [0, 1] with unit lattice spacing.
double ValueNoise(double u, double v, std::uint32_t seed) {
  const double fu = std::floor(u);
  const double fv = std::floor(v);
  const auto iu = static_cast<std::int64_t>(fu);
  const auto iv = static_cast<std::int64_t>(fv);
  double tu = u - fu;
  double tv = v - fv;
  tu = tu * tu * (3.0 - 2.0 * tu);
  tv = tv * tv * (3.0 - 2.0 * tv);
  const double a = Unit(iu, iv, seed);
  const double b = Unit(iu + 1, iv, seed);
  const double c = Unit(iu, iv + 1, seed);
  const double d = Unit(iu + 1, iv + 1, seed);
  return (a + (b - a) * tu) + ((c + (d - c) * tu) - (a + (b - a) * tu)) * tv;
}

// Fractal sum of `octaves` value-noise layers, normalised to [0, 1].
double Fbm(double u, double v, std::uint32_t seed, int octaves) {
  double sum = 0.0;
  double weight = 0.5;
  double total = 0.0;
  for (int o = 0; o < octaves; ++o) {
    sum += weight * ValueNoise(u, v, seed + 101u * static_cast<std::uint32_t>(o));
    total += weight;
    weight *= 0.5;
    u *= 2.03;
    v *= 2.03;
  }
  return sum / total;
}

Eigen::Vector3d Mix(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t) { return a + (b - a) * t; }

double SmoothStep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

struct Palette {
  // Nominal base and accent colours, RGB (written RGB because that is how colours are usually quoted).
  Eigen::Vector3d base_rgb;
  Eigen::Vector3d accent_rgb;
  // Per-instance hue spread: the base colour is blended towards a random colour by up to this much.
  double hue_jitter;
};

Palette PaletteOf(MaterialTexture::Pattern pattern) {
  using P = MaterialTexture::Pattern;
  switch (pattern) {
    case P::kAsphalt: return {{70, 70, 72}, {150, 150, 150}, 0.05};
    case P::kGrass: return {{70, 125, 40}, {150, 160, 60}, 0.10};
    case P::kRock: return {{120, 110, 100}, {60, 55, 50}, 0.10};
    case P::kCarpet: return {{150, 60, 60}, {90, 40, 40}, 0.60};
    case P::kCeramic: return {{215, 210, 200}, {110, 105, 100}, 0.25};
    case P::kMarble: return {{225, 220, 210}, {110, 110, 115}, 0.10};
    case P::kMetal: return {{165, 170, 178}, {120, 125, 132}, 0.05};
    case P::kWood: return {{160, 110, 65}, {105, 65, 35}, 0.10};
    case P::kSand: return {{215, 190, 140}, {175, 150, 105}, 0.08};
    case P::kSky: return {{120, 170, 230}, {245, 245, 250}, 0.08};
    case P::kSnow: return {{240, 243, 250}, {205, 215, 235}, 0.03};
    case P::kWater: return {{40, 90, 120}, {170, 200, 215}, 0.12};
    case P::kCloth: return {{60, 80, 150}, {30, 40, 90}, 0.70};
    case P::kPaper: return {{235, 233, 225}, {205, 203, 198}, 0.04};
  }
  return {{128, 128, 128}, {64, 64, 64}, 0.0};
}

}  // namespace

const std::vector<std::string>& MaterialTexture::SupportedLabels() {
  static const std::vector<std::string> labels{"asphalt", "grass", "rock",  "carpet", "ceramic", "marble", "metal",
                                               "wood",    "sand",  "sky",   "snow",   "water",   "cloth",  "paper"};
  return labels;
}

MaterialTexture::Pattern MaterialTexture::PatternOf(const std::string& label) {
  const auto& labels = SupportedLabels();
  const auto it = std::find(labels.begin(), labels.end(), label);
  if (it == labels.end()) {
    throw std::invalid_argument("MaterialTexture: no texture for label '" + label + "'; did you mean " +
                                QuotedList(ClosestNames(label, labels)) + "? Supported: " + QuotedList(labels) + ".");
  }
  return static_cast<Pattern>(it - labels.begin());
}

const std::string& MaterialTexture::LabelOf(Pattern pattern) {
  return SupportedLabels().at(static_cast<std::size_t>(pattern));
}

MaterialTexture::MaterialTexture(Pattern pattern, const Parameters& parameters)
    : pattern_(pattern), parameters_(parameters) {
  if (!(parameters.scale > 0.0) || !std::isfinite(parameters.scale)) {
    throw std::invalid_argument("MaterialTexture: scale must be positive and finite; got " +
                                std::to_string(parameters.scale) + ". Use 1 for the nominal feature size.");
  }
  cos_ = std::cos(parameters.orientation);
  sin_ = std::sin(parameters.orientation);
}

MaterialTexture MaterialTexture::Make(const std::string& label, std::uint32_t seed) {
  const Pattern pattern = PatternOf(label);
  std::mt19937 rng(seed * 2654435761u + static_cast<std::uint32_t>(pattern) * 97u + 13u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Palette palette = PaletteOf(pattern);
  Parameters p;
  p.scale = 0.7 * std::pow(2.0, unit(rng));  // 0.7 .. 1.4
  p.orientation = kTwoPi * unit(rng);
  // Hue jitter: blend towards a random colour; brightness jitter: a common gain.
  const Eigen::Vector3d random_rgb(255.0 * unit(rng), 255.0 * unit(rng), 255.0 * unit(rng));
  const double blend = palette.hue_jitter * unit(rng);
  const double gain = 0.85 + 0.3 * unit(rng);
  const Eigen::Vector3d base = (Mix(palette.base_rgb, random_rgb, blend) * gain).cwiseMin(255.0);
  const Eigen::Vector3d accent = (Mix(palette.accent_rgb, random_rgb, 0.5 * blend) * gain).cwiseMin(255.0);
  p.base_bgr = Eigen::Vector3d(base.z(), base.y(), base.x());
  p.accent_bgr = Eigen::Vector3d(accent.z(), accent.y(), accent.x());
  p.seed = static_cast<std::uint32_t>(rng());
  return MaterialTexture(pattern, p);
}

Eigen::Vector3d MaterialTexture::Evaluate(double u, double v) const {
  const Parameters& p = parameters_;
  const std::uint32_t seed = p.seed;
  // Pattern frame: s along the main direction (grain, brushing), t across it, in units of the instance's scale.
  const double s = (cos_ * u + sin_ * v) / p.scale;
  const double t = (-sin_ * u + cos_ * v) / p.scale;
  const Eigen::Vector3d& base = p.base_bgr;
  const Eigen::Vector3d& accent = p.accent_bgr;
  Eigen::Vector3d colour = base;
  switch (pattern_) {
    case Pattern::kAsphalt: {
      // Dark binder with light and dark aggregate grains of a few millimetres.
      const double grain = Unit(static_cast<std::int64_t>(std::floor(s * 180.0)),
                                static_cast<std::int64_t>(std::floor(t * 180.0)), seed);
      const double blotch = Fbm(s * 6.0, t * 6.0, seed + 7u, 3);
      colour = base * (0.8 + 0.4 * blotch);
      if (grain > 0.88) colour = Mix(colour, accent, 0.8);
      if (grain < 0.10) colour *= 0.55;
      break;
    }
    case Pattern::kGrass: {
      // Blades: noise stretched along the blade direction, light tips on dark ground.
      const double blades = Fbm(s * 25.0, t * 220.0, seed, 3);
      const double patches = Fbm(s * 2.0, t * 2.0, seed + 3u, 2);
      colour = Mix(base * 0.55, accent, SmoothStep(0.35, 0.75, blades)) * (0.8 + 0.4 * patches);
      break;
    }
    case Pattern::kRock: {
      // Multi-octave relief with dark cracks where a ridged noise is near zero.
      const double relief = Fbm(s * 8.0, t * 8.0, seed, 5);
      const double ridge = std::abs(Fbm(s * 4.0, t * 4.0, seed + 11u, 3) - 0.5);
      colour = Mix(accent, base, relief) * (0.7 + 0.6 * relief);
      colour *= 0.45 + 0.55 * SmoothStep(0.0, 0.04, ridge);
      break;
    }
    case Pattern::kCarpet: {
      // Dense fuzzy pile: fine isotropic noise at low contrast over a saturated colour.
      const double pile = Fbm(s * 300.0, t * 300.0, seed, 2);
      const double tufts = Fbm(s * 40.0, t * 40.0, seed + 5u, 2);
      colour = Mix(accent, base, 0.55 + 0.3 * pile + 0.15 * tufts);
      break;
    }
    case Pattern::kCeramic: {
      // Square tiles of 0.3 m with 1 cm grout, a slight colour change per tile and a faint glaze mottling.
      const double size = 0.3;
      const double a = s / size;
      const double b = t / size;
      const double fa = a - std::floor(a);
      const double fb = b - std::floor(b);
      const double grout = 0.012 / size;
      const bool in_grout = fa < grout || fb < grout;
      const double tile = Unit(static_cast<std::int64_t>(std::floor(a)), static_cast<std::int64_t>(std::floor(b)),
                               seed);
      const double mottle = Fbm(s * 30.0, t * 30.0, seed + 9u, 2);
      colour = in_grout ? accent : base * (0.93 + 0.1 * tile + 0.05 * mottle);
      break;
    }
    case Pattern::kMarble: {
      // Turbulent sine veins on a pale ground.
      const double turbulence = Fbm(s * 3.0, t * 3.0, seed, 5);
      const double vein = std::abs(std::sin((s * 4.0 + 9.0 * turbulence) * 3.14159));
      const double cloud = Fbm(s * 10.0, t * 10.0, seed + 4u, 3);
      colour = Mix(accent, base * (0.92 + 0.08 * cloud), SmoothStep(0.0, 0.35, vein));
      break;
    }
    case Pattern::kMetal: {
      // Brushed: noise stretched a hundredfold along the brushing direction, low contrast, slow sheen.
      const double brush = Fbm(s * 4.0, t * 500.0, seed, 3);
      const double sheen = 0.5 + 0.5 * std::sin(s * 2.0 + Fbm(s, t, seed + 2u, 2) * 3.0);
      colour = Mix(accent, base, 0.45 + 0.4 * brush) * (0.9 + 0.2 * sheen);
      break;
    }
    case Pattern::kWood: {
      // Growth rings across the grain, wobbling along it, plus fine fibres along the grain; planks of 0.15 m.
      const double plank = std::floor(t / 0.15);
      const double shift = Unit(static_cast<std::int64_t>(plank), 0, seed) * 10.0;
      const double wobble = Fbm(s * 1.5 + shift, t * 0.5, seed + 1u, 3);
      const double rings = t * 40.0 + 6.0 * wobble + shift;
      const double ring = 0.5 + 0.5 * std::sin(rings * kTwoPi * 0.25);
      const double fibre = Fbm(s * 8.0, t * 300.0, seed + 2u, 2);
      const double gap = t / 0.15 - plank;
      colour = Mix(accent, base, 0.25 + 0.55 * ring + 0.2 * fibre);
      if (gap < 0.03) colour *= 0.45;
      break;
    }
    case Pattern::kSand: {
      // Fine grains on gentle wind ripples.
      const double grains = Unit(static_cast<std::int64_t>(std::floor(s * 400.0)),
                                 static_cast<std::int64_t>(std::floor(t * 400.0)), seed);
      const double ripple = 0.5 + 0.5 * std::sin((t * 12.0 + 2.0 * Fbm(s * 2.0, t * 2.0, seed + 1u, 2)) * kTwoPi);
      colour = Mix(accent, base, 0.35 + 0.35 * ripple + 0.3 * grains);
      break;
    }
    case Pattern::kSky: {
      // Soft clouds.
      const double cloud = Fbm(s * 0.8, t * 0.8, seed, 5);
      colour = Mix(base, accent, SmoothStep(0.45, 0.8, cloud));
      break;
    }
    case Pattern::kSnow: {
      // Nearly uniform white with soft blue shadows in the hollows and rare sparkles.
      const double drift = Fbm(s * 3.0, t * 3.0, seed, 4);
      const double sparkle = Unit(static_cast<std::int64_t>(std::floor(s * 250.0)),
                                  static_cast<std::int64_t>(std::floor(t * 250.0)), seed + 3u);
      colour = Mix(accent, base, SmoothStep(0.3, 0.7, drift));
      if (sparkle > 0.985) colour = Eigen::Vector3d(255.0, 255.0, 255.0);
      break;
    }
    case Pattern::kWater: {
      // Smooth low-frequency waves with bright glints on their crests.
      const double wave = Fbm(s * 2.0 + 0.5 * std::sin(t * 3.0), t * 6.0, seed, 4);
      const double glint = SmoothStep(0.68, 0.78, wave);
      colour = Mix(base * (0.8 + 0.4 * wave), accent, glint);
      break;
    }
    case Pattern::kCloth: {
      // Plain weave: warp and weft threads of ~4 mm alternating over and under.
      const double period = 0.004;
      const double a = s / period;
      const double b = t / period;
      const bool warp_on_top = ((static_cast<std::int64_t>(std::floor(a)) + static_cast<std::int64_t>(std::floor(b))) & 1) == 0;
      const double thread = warp_on_top ? std::sin((b - std::floor(b)) * 3.14159)
                                        : std::sin((a - std::floor(a)) * 3.14159);
      const double fold = Fbm(s * 3.0, t * 3.0, seed, 2);
      colour = Mix(accent, base, 0.3 + 0.7 * thread) * (0.75 + 0.5 * fold);
      break;
    }
    case Pattern::kPaper: {
      // Sheets of A-size with faint fibres; a sheet edge shadow every 0.3 m.
      const double fibres = Fbm(s * 150.0, t * 150.0, seed, 2);
      const double sheet = s / 0.297 - std::floor(s / 0.297);
      colour = Mix(accent, base, 0.8 + 0.2 * fibres);
      if (sheet < 0.01) colour *= 0.8;
      break;
    }
  }
  return colour.cwiseMax(0.0).cwiseMin(255.0);
}

}  // namespace cairn::perception
