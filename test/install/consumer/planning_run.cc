// Cairn::planning_run: the main diagram's head camera -- its intrinsics and where it looks from over a stance.
#include <cmath>
#include <cstdio>

#include <cairn/planning/run/scenario_stereo_scene.h>

int main() {
  using namespace cairn::planning;
  Stance start;
  start.left = FootPose{0.0, 0.1, 0.0, 0.0};
  start.right = FootPose{0.0, -0.1, 0.0, 0.0};
  const SyntheticCamera camera;
  const auto calibration = camera.Calibration();
  const Eigen::Isometry3d X_WC = ScenarioCameraPose(start, camera.head);
  const Eigen::Vector3d axis = X_WC.linear().col(2);  // the optical axis: ahead (+x) and down
  std::printf("consumer planning_run: fx %.1f px, camera at z = %.2f m looking (%.2f, %.2f, %.2f)\n", calibration.fx,
              X_WC.translation().z(), axis.x(), axis.y(), axis.z());
  return axis.x() > 0.0 && axis.z() < 0.0 && std::abs(X_WC.translation().z() - 1.3) < 1e-12 ? 0 : 1;
}
