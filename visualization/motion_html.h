#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include <cairn/multibody/model.h>
#include <cairn/multibody/pose.h>

namespace cairn::visualization {

/// A static box of the scene (terrain or obstacle), coloured by its friction.
struct SceneBox {
  std::string name;
  multibody::Pose X_WB;                      ///< pose of the box centre
  Eigen::Vector3d size{Eigen::Vector3d::Ones()};  ///< full side lengths, m
  double friction{1.0};                     ///< shown as a colour: red (ice, 0) to green (>= 1)
  /// In [0, 1]: the box is an occupied cell of perception instead, drawn dark red with this probability as its
  /// opacity (friction is then not shown). Negative (the default): a terrain box coloured by friction.
  double occupancy{-1.0};
};

/// A motion to show: configurations of a model over time among boxes.
struct MotionScene {
  std::string title;
  std::vector<SceneBox> boxes;
  std::vector<double> times;             ///< s, non-decreasing, one per configuration
  std::vector<Eigen::VectorXd> q;        ///< the model's configurations
};

/// Most frames MotionHtml() writes (an hour at 25 frames per second would be 90000): the page holds every
/// frame's shape poses, about 60 bytes per shape and frame.
inline constexpr std::size_t kMaxMotionFrames = 20000;
/// Most boxes of a scene.
inline constexpr std::size_t kMaxSceneBoxes = 10000;

/// Where three.js (Debian's libjs-three) is read from unless MotionHtml() is told otherwise.
std::string DefaultThreeJsPath();

/// One self-contained HTML page (three.js inlined, so it works offline) that animates `scene`: the robot drawn
/// from its collision shapes (boxes, spheres, cylinders, capsules; meshes are left out), each posed per frame by
/// forward kinematics computed here and embedded as JSON, and the scene's boxes coloured by friction, with a time
/// slider, a play button and a mouse-orbited camera. The page sets `data-status` on its body to "rendered" once it
/// drew the first frame, or to "error: ..." when a script error happened (for headless checks). Throws
/// std::invalid_argument for a scene with mismatched times and configurations, configurations of the wrong size,
/// times that decrease or are not finite, more than kMaxMotionFrames frames or kMaxSceneBoxes boxes, a box of
/// non-positive size or an occupancy above 1; std::runtime_error when three.js cannot be read from `three_js_path` (install libjs-three).
std::string MotionHtml(const multibody::Model& model, const MotionScene& scene,
                       const std::string& three_js_path = DefaultThreeJsPath());

}  // namespace cairn::visualization
