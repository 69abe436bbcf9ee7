#pragma once

/// @file
/// Deterministic colour procedural textures of the registry's materials, for rendering labelled training scenes.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace cairn::perception {

/// A colour (BGR) pattern over a surface's 2-D coordinates (metres) that looks like one material: wood grain,
/// ceramic tile with grout, cloth weave, grass, asphalt speckle, brushed metal, carpet, marble veins, rock, water,
/// sand, snow, paper, sky.
///
/// One label has many instances: Make(label, seed) draws the instance's feature scale, hue, brightness and
/// orientation from the seed, so that a classifier must learn the family and not one picture. Evaluate() depends
/// only on the instance's parameters: equal parameters give identical colours.
class MaterialTexture {
 public:
  /// The pattern families; one per material label.
  enum class Pattern {
    kAsphalt, kGrass, kRock, kCarpet, kCeramic, kMarble, kMetal, kWood,
    kSand, kSky, kSnow, kWater, kCloth, kPaper,
  };

  /// The parameters of one instance; Make() draws them, tests may set them directly.
  struct Parameters {
    /// Multiplies every feature size (grain, tile, weave, ...); > 0.
    double scale{1.0};
    /// Rotation of the pattern's main direction (wood grain, brushing, weave), radians.
    double orientation{0.0};
    /// Base colour, BGR in [0, 255].
    Eigen::Vector3d base_bgr{128.0, 128.0, 128.0};
    /// Secondary colour (grout, veins, dark grains, ...), BGR in [0, 255].
    Eigen::Vector3d accent_bgr{64.0, 64.0, 64.0};
    /// Seed of the noise lattice.
    std::uint32_t seed{1};
  };

  /// An instance with explicit parameters. Throws std::invalid_argument for a non-positive scale.
  MaterialTexture(Pattern pattern, const Parameters& parameters);

  /// An instance of `label`'s pattern with scale (x0.7..1.4), hue and brightness jitter and orientation drawn from
  /// `seed`. Throws std::invalid_argument for an unknown label, listing the closest supported labels.
  static MaterialTexture Make(const std::string& label, std::uint32_t seed);

  /// The labels Make() accepts, in the order of Pattern (that of MaterialRegistry::ThesisTable33()).
  static const std::vector<std::string>& SupportedLabels();
  /// The pattern of `label`; throws std::invalid_argument like Make().
  static Pattern PatternOf(const std::string& label);
  /// The label of `pattern`.
  static const std::string& LabelOf(Pattern pattern);

  /// Colour (BGR, each in [0, 255]) at surface coordinates (u, v) in metres.
  Eigen::Vector3d Evaluate(double u, double v) const;

  Pattern pattern() const { return pattern_; }
  const Parameters& parameters() const { return parameters_; }
  const std::string& label() const { return LabelOf(pattern_); }

 private:
  Pattern pattern_;
  Parameters parameters_;
  // The rotation of parameters_.orientation, cached because Evaluate() runs once per pixel.
  double cos_{1.0};
  double sin_{0.0};
};

}  // namespace cairn::perception
