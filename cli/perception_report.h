#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cairn/perception/friction/material_registry.h"
#include "cairn/planning/run/main_diagram.h"
#include "cairn/visualization/motion_html.h"

namespace cairn::cli {

/// The first frame's perception as one picture (`cairn run --out`'s perception.png), each panel titled: the camera
/// image; the material segmentation (each pixel's most probable label, with a legend of the labels covering at
/// least 1 % of the image); the friction quantile Q_{1-eta} (colour bar 0..1); the occupancy grid seen from above
/// (each column's highest probability, x right and y up, metric ticks) and a vertical x-z slice through the grid
/// row holding the most occupied cells (the obstacles, if any), both on a free-unknown-occupied colour bar.
/// Throws std::invalid_argument if the record holds no perception (a run that stopped before perceiving) or its
/// probabilities do not have one channel per registry label, std::runtime_error if encoding fails.
std::string PerceptionReportPng(const planning::MainRecord& record, const perception::MaterialRegistry& registry,
                                double eta);

/// The perceived terrain as boxes of the 3-D viewer: each row's runs of ground cells of one friction (within 0.005)
/// and height (within 2 mm) as one box 1 cm thick under the surface, coloured by friction, and the occupied voxels
/// as cubes whose opacity is their probability. When they would be more than `max_boxes`, the least probable
/// voxels are left out (the ground never is; throws std::invalid_argument if the ground alone exceeds it).
std::vector<visualization::SceneBox> PerceivedTerrainBoxes(const planning::TerrainMap& terrain,
                                                           std::size_t max_boxes = visualization::kMaxSceneBoxes);

}  // namespace cairn::cli
