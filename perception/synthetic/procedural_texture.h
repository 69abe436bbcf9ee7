#pragma once

/// @file
/// Deterministic procedural textures for the synthetic stereo renderer.

#include <cstdint>

namespace cairn::perception {

/// An intensity pattern over a surface's 2-D coordinates (metres), deterministic for a given seed.
struct ProceduralTexture {
  /// The pattern family.
  enum class Kind {
    /// Multi-octave value noise (well textured: good for stereo).
    kNoise,
    /// A checkerboard of `scale`-sized squares.
    kChecker,
    /// A constant intensity `mean` (textureless).
    kUniform,
  };
  /// Pattern family.
  Kind kind{Kind::kNoise};
  /// Feature size in metres (noise cell or checker square).
  double scale{0.05};
  /// Mean intensity (0..255).
  double mean{128.0};
  /// Peak deviation from the mean (0..127).
  double contrast{90.0};
  /// Seed of the noise lattice; equal seeds give identical patterns.
  std::uint32_t seed{1};

  /// Intensity at surface coordinates (u, v), in [mean - contrast, mean + contrast].
  double Evaluate(double u, double v) const;
};

}  // namespace cairn::perception
