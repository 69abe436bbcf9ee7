// Cairn::perception_haptics_simulation: a simulated depth frame of a rock, its descriptor, and the antenna's touch.
#include <cstdio>

#include <cairn/perception/haptics/affordance_descriptor.h>
#include <cairn/perception/haptics/simulation/haptic_affordance_experiment.h>

int main() {
  using namespace cairn::perception;
  const HapticAffordanceExperiment experiment;
  const Eigen::Matrix3Xd points = experiment.Observe(HapticObjectKind::kRock, 0);
  const AffordanceDescriptor descriptor = experiment.Describe(points);
  int planned = 0;
  const AntennaInteraction touch = experiment.Touch(HapticObjectKind::kRock, 0, points, 0.0, &planned);
  std::printf("consumer perception_haptics_simulation: %d points, %d descriptor values, %d targets, blocked %d\n",
              static_cast<int>(points.cols()), static_cast<int>(descriptor.values().size()), planned, touch.blocked);
  return points.cols() > 0 && descriptor.values().size() == 56 && planned > 0 && touch.blocked ? 0 : 1;
}
