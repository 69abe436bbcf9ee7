#include "whole_body_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/multibody/data.h"
#include "cairn/multibody/kinematics.h"
#include "cairn/multibody/urdf_parser.h"
#include "cairn/planning/trajectory/environment_from_obstacles.h"
#include "cairn/planning/trajectory/optimize_whole_body_trajectory.h"
#include "data_directory.h"

namespace cairn::cli {
namespace {
constexpr double kPixelsPerMetre = 300.0;
constexpr double kMaxExtent = 50.0;  // m

// The scenario's terrain is exact: the swing feet keep their clearance from its slopes and treads.
planning::TrajectoryOptimizerOptions WholeBodyOptions() {
  planning::TrajectoryOptimizerOptions options;
  options.ground_follows_terrain = true;
  return options;
}
}  // namespace

std::string WholeBodyTrajectoryJson(const planning::WholeBodyTrajectory& t) {
  JsonWriter json;
  json.BeginObject().Key("found").Bool(t.found);
  const planning::TrajectorySolveReport& r = t.report;
  json.Key("report").BeginObject();
  json.Key("success").Bool(r.success).Key("status").String(r.status).Key("solver").String(r.solver);
  json.Key("message").String(r.message).Key("violations").BeginArray();
  for (const std::string& v : r.violations) json.String(v);
  json.EndArray();
  json.Key("max_violation").Number(r.max_violation).Key("iterations").Integer(r.iterations);
  json.Key("windows").Integer(r.windows).Key("seconds").Number(r.seconds).Key("objective").Number(r.objective);
  json.Key("variables").Integer(r.num_variables).Key("constraints").Integer(r.num_constraints);
  json.Key("jacobian_nonzeros").Integer(r.jacobian_nonzeros).Key("hessian").String(r.hessian);
  json.EndObject();
  json.Key("coordinates").BeginArray();
  for (const std::string& name : t.coordinate_names) json.String(name);
  json.EndArray();
  json.Key("waypoints").BeginArray();
  for (const planning::WholeBodyWaypoint& w : t.waypoints) {
    json.BreakLine(2).BeginObject().Key("time").Number(w.time).Key("stance").Integer(w.stance);
    json.Key("label").String(w.label).Key("single_support").Bool(w.single_support);
    json.Key("contacts").BeginArray();
    for (const std::string& c : w.contacts) json.String(c);
    json.EndArray().Key("com").BeginArray();
    for (int i = 0; i < 3; ++i) json.Number(w.com(i), JsonWriter::Fixed(4));
    json.EndArray().Key("min_clearance").Number(w.min_clearance, JsonWriter::Fixed(4)).Key("q").BeginArray();
    for (Eigen::Index i = 0; i < w.q.size(); ++i) json.Number(w.q(i), JsonWriter::Fixed(6));
    json.EndArray().EndObject();
  }
  json.EndArray().EndObject();
  return json.text();
}

std::string WholeBodyTrajectoryPng(const multibody::Model& model, const planning::WholeBodyTrajectory& trajectory,
                                   const std::vector<planning::EnvironmentBox>& environment) {
  // Body origins per waypoint, and the extent of everything drawn.
  std::vector<std::vector<Eigen::Vector3d>> bodies;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(0.0), hi = Eigen::Vector3d::Constant(0.0);
  multibody::Data data(model);
  for (const planning::WholeBodyWaypoint& w : trajectory.waypoints) {
    multibody::ForwardKinematics(model, data, w.q);
    std::vector<Eigen::Vector3d> p;
    for (int b = 0; b < model.num_bodies(); ++b) {
      p.push_back(data.X_world[static_cast<std::size_t>(b)].translation());
      if (b > 0) {
        lo = lo.cwiseMin(p.back());
        hi = hi.cwiseMax(p.back());
      }
    }
    bodies.push_back(std::move(p));
  }
  for (const planning::EnvironmentBox& box : environment) {
    lo = lo.cwiseMin(box.X_WB.translation() - 0.5 * box.size);
    hi = hi.cwiseMax(box.X_WB.translation() + 0.5 * box.size);
  }
  lo -= Eigen::Vector3d::Constant(0.2);
  hi += Eigen::Vector3d::Constant(0.2);
  lo.z() = std::min(lo.z(), -0.1);
  if (!lo.allFinite() || !hi.allFinite() || (hi - lo).maxCoeff() > kMaxExtent) {
    throw std::invalid_argument("The whole-body picture would span " + FormatShort((hi - lo).maxCoeff()) +
                                " m, more than the limit of " + FormatShort(kMaxExtent) + " m.");
  }
  const int width = static_cast<int>(std::lround((hi.x() - lo.x()) * kPixelsPerMetre));
  const int side_h = static_cast<int>(std::lround((hi.z() - lo.z()) * kPixelsPerMetre));
  const int top_h = static_cast<int>(std::lround((hi.y() - lo.y()) * kPixelsPerMetre));
  cv::Mat image(side_h + top_h + 10, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto side = [&](const Eigen::Vector3d& p) {
    return cv::Point(static_cast<int>(std::lround((p.x() - lo.x()) * kPixelsPerMetre)),
                     static_cast<int>(std::lround((hi.z() - p.z()) * kPixelsPerMetre)));
  };
  const auto top = [&](const Eigen::Vector3d& p) {
    return cv::Point(static_cast<int>(std::lround((p.x() - lo.x()) * kPixelsPerMetre)),
                     side_h + 10 + static_cast<int>(std::lround((hi.y() - p.y()) * kPixelsPerMetre)));
  };
  cv::line(image, side(Eigen::Vector3d(lo.x(), 0, 0)), side(Eigen::Vector3d(hi.x(), 0, 0)), cv::Scalar(90, 90, 90), 2);
  cv::line(image, cv::Point(0, side_h + 5), cv::Point(width - 1, side_h + 5), cv::Scalar(0, 0, 0), 1);
  for (const planning::EnvironmentBox& box : environment) {
    const Eigen::Vector3d a = box.X_WB.translation() - 0.5 * box.size, b = box.X_WB.translation() + 0.5 * box.size;
    cv::rectangle(image, side(a), side(b), cv::Scalar(170, 170, 170), cv::FILLED);
    cv::rectangle(image, top(a), top(b), cv::Scalar(200, 200, 200), cv::FILLED);
  }
  const int n = static_cast<int>(bodies.size());
  for (int t = 0; t < n; ++t) {
    // Early waypoints blue, late ones red.
    const double s = n > 1 ? static_cast<double>(t) / (n - 1) : 0.0;
    const cv::Scalar colour(255 * (1.0 - s), 60, 255 * s);
    for (int b = 1; b < model.num_bodies(); ++b) {
      const int parent = model.parent(b);
      if (parent <= 0) continue;
      const Eigen::Vector3d& p = bodies[static_cast<std::size_t>(t)][static_cast<std::size_t>(b)];
      const Eigen::Vector3d& q = bodies[static_cast<std::size_t>(t)][static_cast<std::size_t>(parent)];
      cv::line(image, side(p), side(q), colour, 2, cv::LINE_AA);
      cv::line(image, top(p), top(q), colour, 1, cv::LINE_AA);
    }
    const Eigen::Vector3d& com = trajectory.waypoints[static_cast<std::size_t>(t)].com;
    cv::circle(image, side(com), 4, colour, cv::FILLED);
    cv::circle(image, top(com), 4, colour, cv::FILLED);
  }
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", image, bytes)) throw std::runtime_error("Cannot encode the whole-body picture as PNG.");
  return std::string(bytes.begin(), bytes.end());
}

int RunWholeBody(const planning::FootstepScenario& scenario, const planning::FootstepPlan& plan,
                 const planning::TerrainMap* terrain, bool quiet, AtomicOutputDirectory* out) {
  multibody::UrdfOptions urdf;
  urdf.floating_base = true;
  const auto model = std::make_shared<const multibody::Model>(
      multibody::ParseUrdfFile(DataDirectory() + "/robots/cairn_humanoid.urdf", urdf));
  const std::vector<planning::EnvironmentBox> environment = planning::EnvironmentFromObstacles(scenario.obstacles());
  const planning::WholeBodyTrajectory trajectory =
      planning::OptimizeWholeBodyTrajectory(model, plan, environment, WholeBodyOptions(), terrain);
  if (out != nullptr) {
    out->WriteFile("trajectory.json", WholeBodyTrajectoryJson(trajectory) + "\n");
    out->WriteFile("trajectory.png", WholeBodyTrajectoryPng(*model, trajectory, environment));
  }
  if (!quiet) {
    double clearance = std::numeric_limits<double>::infinity();
    for (const planning::WholeBodyWaypoint& w : trajectory.waypoints) clearance = std::min(clearance, w.min_clearance);
    std::printf("whole body %s: %zu waypoints, %d iterations, %s s, min clearance %s m%s%s\n",
                trajectory.found ? "solved" : "FAILED", trajectory.waypoints.size(), trajectory.report.iterations,
                FormatShort(trajectory.report.seconds).c_str(), FormatShort(clearance).c_str(),
                trajectory.found ? "" : "; ", trajectory.found ? "" : trajectory.report.message.c_str());
  }
  return trajectory.found ? 0 : 1;
}

}  // namespace cairn::cli
