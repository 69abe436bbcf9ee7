#pragma once

#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/pose.h>

namespace cairn::planning {

/// The convex hull (counter-clockwise, Andrew's monotone chain) of the horizontal projections of sole rectangles
/// (length x width, centred on each sole frame, turned by the frame's yaw). Empty for no soles.
std::vector<Eigen::Vector2d> SupportPolygon(const std::vector<multibody::Pose>& soles, double sole_length,
                                            double sole_width);

/// Signed distance of p to the edge of a convex counter-clockwise polygon: positive inside (distance to the
/// nearest edge), negative outside (minus the distance to the polygon). -infinity for an empty polygon.
double SupportMargin(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace cairn::planning
