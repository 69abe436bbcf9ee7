#pragma once

/// @file
/// A scene of textured planes and boxes for the synthetic stereo renderer.

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "cairn/perception/synthetic/procedural_texture.h"

namespace cairn::perception {

/// An immutable-after-construction set of textured, labelled objects: infinite planes and oriented boxes. Every
/// object carries an integer material label (rendered as ground truth for material recognition). Texture
/// coordinates are the object's own (box faces: the face's two in-plane box axes from the box centre; planes: an
/// orthonormal basis from the plane's anchor point), so identical boxes with one texture look identical
/// (which is how the repetitive-bars scene is built).
class SyntheticStereoScene {
 public:
  /// The first surface a ray meets.
  struct Hit {
    /// Ray parameter: the hit point is origin + t * direction.
    double t;
    /// Index of the object hit (order of the Add calls).
    int object;
    /// The object's material label.
    int label;
    /// Texture intensity at the hit point (0..255).
    double intensity;
  };

  /// Adds an infinite plane through `point` with normal `normal` (need not be unit; must be non-zero).
  /// Returns the object index. Throws std::invalid_argument for a zero normal.
  int AddPlane(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, const ProceduralTexture& texture,
               int label);
  /// Adds a box with pose X_WB (its centre and axes in the world) and positive half extents. Returns the object
  /// index. Throws std::invalid_argument naming a non-positive half extent.
  int AddBox(const Eigen::Isometry3d& X_WB, const Eigen::Vector3d& half_extents, const ProceduralTexture& texture,
             int label);

  /// A colour pattern (BGR, each in [0, 255]) over an object's texture coordinates (metres), e.g. a
  /// perception::MaterialTexture's Evaluate().
  using ColourTexture = std::function<Eigen::Vector3d(double u, double v)>;

  /// Gives object `object` a colour texture (optional: objects without one are grey, their ProceduralTexture's
  /// intensity on all channels). SyntheticStereoRenderer renders colour images when any object has one.
  /// Throws std::invalid_argument for an object index out of range or an empty function.
  void SetColourTexture(int object, ColourTexture texture);
  /// Whether any object has a colour texture.
  bool has_colour_textures() const { return num_colour_textures_ > 0; }
  /// Colour (BGR) of `hit`, the result of Intersect(origin, direction): the object's colour texture at the hit's
  /// texture coordinates, or its intensity on all channels when it has none.
  Eigen::Vector3d ColourOf(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Hit& hit) const;

  /// The nearest surface hit by the ray origin + t direction, t > 0, or nothing.
  std::optional<Hit> Intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) const;

  /// Whether the point is inside a box or within `tolerance` of a plane: the scene's ground-truth occupancy.
  bool Occupies(const Eigen::Vector3d& p_W, double tolerance = 0.0) const;

  /// Whether the axis-aligned cube centred at `center` with side `size` overlaps any object (exact, by the
  /// separating-axis theorem; touching counts), used to rasterise ground-truth grids of thin objects.
  bool OccupiesCube(const Eigen::Vector3d& center, double size) const;

  /// Number of objects.
  int num_objects() const { return static_cast<int>(objects_.size()); }

 private:
  struct Object {
    bool is_box;
    Eigen::Isometry3d X_WB;        // box pose, or plane frame (z = normal) at its anchor
    Eigen::Isometry3d X_BW;        // its inverse, kept because Intersect() runs per pixel and object
    Eigen::Vector3d half_extents;  // boxes only
    ProceduralTexture texture;
    int label;
  };
  std::vector<Object> objects_;
  // Per object, possibly empty; sized lazily by SetColourTexture() so grey scenes carry nothing.
  std::vector<ColourTexture> colour_textures_;
  int num_colour_textures_{0};
};

}  // namespace cairn::perception
