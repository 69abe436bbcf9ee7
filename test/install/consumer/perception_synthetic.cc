// Cairn::perception_synthetic: renders the first frame of the thesis' bars scenario.
#include <cmath>
#include <cstdio>

#include <cairn/perception/synthetic/bars_scenario.h>
#include <cairn/perception/synthetic/synthetic_stereo_renderer.h>

int main() {
  using namespace cairn::perception;
  const BarsScenario scenario = BarsScenario::Make(1);
  const SyntheticStereoRenderer renderer(scenario.calibration, scenario.width, scenario.height, 0.0, 1);
  const SyntheticStereoFrame frame = renderer.Render(scenario.scene, scenario.trajectory[0], 0);
  int bar_pixels = 0, bad_depth = 0;
  for (int y = 0; y < frame.labels.rows; ++y) {
    for (int x = 0; x < frame.labels.cols; ++x) {
      if (frame.labels.at<int>(y, x) != 1) continue;
      ++bar_pixels;
      const float z = frame.depth.at<float>(y, x);
      if (!(std::isfinite(z) && z > 0.0f)) ++bad_depth;
    }
  }
  std::printf("consumer perception_synthetic: %d x %d frame, %d bar pixels\n", frame.left.cols, frame.left.rows,
              bar_pixels);
  const bool right = frame.left.cols == scenario.width && frame.left.rows == scenario.height &&
                     frame.right.size() == frame.left.size() && bar_pixels > 0 && bad_depth == 0;
  return right ? 0 : 1;
}
