#include <cairn/planning/walk/scenario_terrain_boxes.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include <cairn/common/number_text.h>
#include <cairn/multibody/plant/bullet_plant.h>

namespace cairn::planning {
namespace {

struct Rectangle {
  double x0, x1, y0, y1;
  std::size_t region;
  bool Empty() const { return !(x1 - x0 > 1e-9) || !(y1 - y0 > 1e-9); }
};

// The region's polygon as an axis-aligned rectangle, or an error naming it.
Rectangle RegionRectangle(const FootstepScenario::Region& region, std::size_t index, const std::string& path) {
  const auto& p = region.polygon;
  Rectangle r{0, 0, 0, 0, index};
  bool ok = p.size() == 4;
  if (ok) {
    r.x0 = r.x1 = p[0].x();
    r.y0 = r.y1 = p[0].y();
    for (const Eigen::Vector2d& v : p) {
      r.x0 = std::min(r.x0, v.x());
      r.x1 = std::max(r.x1, v.x());
      r.y0 = std::min(r.y0, v.y());
      r.y1 = std::max(r.y1, v.y());
    }
    for (const Eigen::Vector2d& v : p) {
      const bool on_x = std::abs(v.x() - r.x0) < 1e-9 || std::abs(v.x() - r.x1) < 1e-9;
      const bool on_y = std::abs(v.y() - r.y0) < 1e-9 || std::abs(v.y() - r.y1) < 1e-9;
      ok = ok && on_x && on_y;
    }
    ok = ok && !r.Empty();
  }
  if (!ok) {
    throw std::invalid_argument(path + ": region '" + region.name + "' is a " + FormatShort(p.size()) +
                                "-gon that is not an axis-aligned rectangle; the physics plant's terrain is made of "
                                "boxes, so walk scenarios need `box:` regions");
  }
  return r;
}

// `a` less `b`: up to four rectangles.
void Subtract(const Rectangle& a, const Rectangle& b, std::vector<Rectangle>* out) {
  const double x0 = std::max(a.x0, b.x0), x1 = std::min(a.x1, b.x1);
  const double y0 = std::max(a.y0, b.y0), y1 = std::min(a.y1, b.y1);
  if (!(x1 - x0 > 1e-9) || !(y1 - y0 > 1e-9)) {
    out->push_back(a);
    return;
  }
  for (const Rectangle& piece : {Rectangle{a.x0, x0, a.y0, a.y1, a.region}, Rectangle{x1, a.x1, a.y0, a.y1, a.region},
                                 Rectangle{x0, x1, a.y0, y0, a.region}, Rectangle{x0, x1, y1, a.y1, a.region}}) {
    if (!piece.Empty()) out->push_back(piece);
  }
}

}  // namespace

std::vector<multibody::TerrainBox> ScenarioTerrainBoxes(const FootstepScenario& scenario) {
  std::vector<Rectangle> pieces;
  const auto& regions = scenario.regions();
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const Rectangle r = RegionRectangle(regions[i], i, scenario.path());
    std::vector<Rectangle> kept;
    for (const Rectangle& piece : pieces) Subtract(piece, r, &kept);
    kept.push_back(r);
    if (kept.size() + scenario.obstacles().size() > static_cast<std::size_t>(multibody::BulletPlant::kMaxTerrainBoxes)) {
      throw std::invalid_argument(scenario.path() + ": the regions cut into more than " +
                                  FormatShort(multibody::BulletPlant::kMaxTerrainBoxes) +
                                  " terrain boxes, the physics plant's limit; use fewer overlapping regions");
    }
    pieces = std::move(kept);
  }
  // Pieces in region order, then by position, so the boxes' names and order do not depend on the cutting order.
  std::stable_sort(pieces.begin(), pieces.end(), [](const Rectangle& a, const Rectangle& b) {
    if (a.region != b.region) return a.region < b.region;
    if (a.x0 != b.x0) return a.x0 < b.x0;
    return a.y0 < b.y0;
  });
  std::vector<multibody::TerrainBox> boxes;
  std::vector<int> count(regions.size(), 0);
  for (const Rectangle& piece : pieces) {
    const FootstepScenario::Region& region = regions[piece.region];
    const Eigen::Vector2d centre(0.5 * (piece.x0 + piece.x1), 0.5 * (piece.y0 + piece.y1));
    const Eigen::Vector3d n = region.Normal().normalized();
    // A box tilted about a horizontal axis that is neither x nor y would not have an axis-aligned footprint, and
    // the cut pieces would leave gaps or overlap.
    if (std::abs(n.x()) > 1e-9 && std::abs(n.y()) > 1e-9) {
      throw std::invalid_argument(scenario.path() + ": region '" + region.name +
                                  "' slopes neither along x nor along y (uphill " +
                                  FormatShort(std::atan2(-n.y(), -n.x()) * 180.0 / M_PI) +
                                  " deg); the plant's boxes need uphill_deg 0, 90, 180 or 270");
    }
    const Eigen::Matrix3d R = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), n).toRotationMatrix();
    // The box's x and y axes lean out of the horizontal plane; stretch them so their footprint spans the piece.
    const double cx = std::max(1e-6, std::hypot(R(0, 0), R(1, 0)));
    const double cy = std::max(1e-6, std::hypot(R(0, 1), R(1, 1)));
    multibody::TerrainBox box;
    box.name = region.name + (count[piece.region]++ == 0 ? "" : " " + FormatShort(count[piece.region]));
    box.size = Eigen::Vector3d((piece.x1 - piece.x0) / cx, (piece.y1 - piece.y0) / cy, kScenarioTerrainThickness);
    const Eigen::Vector3d top(centre.x(), centre.y(), region.HeightAt(centre));
    box.X_WB = multibody::Pose(R, top - 0.5 * kScenarioTerrainThickness * n);
    box.friction = region.friction.Mean();
    boxes.push_back(box);
  }
  for (const TerrainMap::Obstacle& obstacle : scenario.obstacles()) {
    multibody::TerrainBox box;
    box.name = obstacle.name;
    box.size = 2.0 * obstacle.half_extents;
    box.X_WB = multibody::Pose(Eigen::AngleAxisd(obstacle.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                               obstacle.center);
    box.friction = kScenarioObstacleFriction;
    boxes.push_back(box);
  }
  return boxes;
}

}  // namespace cairn::planning
