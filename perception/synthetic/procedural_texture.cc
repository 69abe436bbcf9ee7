#include "cairn/perception/synthetic/procedural_texture.h"

#include <cmath>

namespace cairn::perception {
namespace {

// Integer hash to [-1, 1] (a fixed function of the lattice point and the seed: reproducible everywhere).
double Lattice(std::int64_t i, std::int64_t j, std::uint32_t seed) {
  std::uint64_t h = static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ULL ^
                    (static_cast<std::uint64_t>(j) + 0x632BE59BD9B4E019ULL) * 0xC2B2AE3D27D4EB4FULL ^
                    (static_cast<std::uint64_t>(seed) << 32);
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ULL;
  h ^= h >> 32;
  return static_cast<double>(h & 0xFFFFFF) / static_cast<double>(0xFFFFFF) * 2.0 - 1.0;
}

double ValueNoise(double u, double v, std::uint32_t seed) {
  const double fu = std::floor(u);
  const double fv = std::floor(v);
  const auto i = static_cast<std::int64_t>(fu);
  const auto j = static_cast<std::int64_t>(fv);
  double tu = u - fu;
  double tv = v - fv;
  tu = tu * tu * (3.0 - 2.0 * tu);
  tv = tv * tv * (3.0 - 2.0 * tv);
  const double a = Lattice(i, j, seed) * (1.0 - tu) + Lattice(i + 1, j, seed) * tu;
  const double b = Lattice(i, j + 1, seed) * (1.0 - tu) + Lattice(i + 1, j + 1, seed) * tu;
  return a * (1.0 - tv) + b * tv;
}

}  // namespace

double ProceduralTexture::Evaluate(double u, double v) const {
  switch (kind) {
    case Kind::kUniform:
      return mean;
    case Kind::kChecker: {
      const auto parity = (static_cast<std::int64_t>(std::floor(u / scale)) +
                           static_cast<std::int64_t>(std::floor(v / scale))) & 1;
      return mean + (parity != 0 ? contrast : -contrast);
    }
    case Kind::kNoise: {
      double value = 0.0;
      double amplitude = 0.6;
      double frequency = 1.0 / scale;
      for (int octave = 0; octave < 3; ++octave) {
        value += amplitude * ValueNoise(u * frequency, v * frequency, seed + 977u * static_cast<std::uint32_t>(octave));
        amplitude *= 0.5;
        frequency *= 2.0;
      }
      return mean + contrast * std::max(-1.0, std::min(1.0, value / 0.95));
    }
  }
  return mean;
}

}  // namespace cairn::perception
