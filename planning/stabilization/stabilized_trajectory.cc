#include <cairn/planning/stabilization/stabilized_trajectory.h>

#include <cmath>
#include <stdexcept>

namespace cairn::planning {

std::size_t StabilizedTrajectory::SampleAt(double t) const {
  if (q.empty()) throw std::out_of_range("StabilizedTrajectory::SampleAt: the trajectory has no samples");
  if (!(t > 0.0)) return 0;
  const double k = std::round(t / period);
  if (k >= static_cast<double>(q.size() - 1)) return q.size() - 1;
  return static_cast<std::size_t>(k);
}

}  // namespace cairn::planning
