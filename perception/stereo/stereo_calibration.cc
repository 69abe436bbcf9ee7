#include "cairn/perception/stereo/stereo_calibration.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/number_text.h"

namespace cairn::perception {

void StereoCalibration::Validate() const {
  auto check = [](double value, const char* name, const char* hint) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw std::invalid_argument(std::string("stereo calibration ") + name + " = " + FormatShort(value) +
                                  " must be positive and finite; " + hint);
    }
  };
  check(fx, "fx", "give the focal length in pixels");
  check(fy, "fy", "give the focal length in pixels");
  check(baseline, "baseline", "give the distance between the cameras in metres");
  for (const auto& [value, name] : {std::pair<double, const char*>{cx, "cx"}, {cy, "cy"}}) {
    if (!std::isfinite(value)) {
      throw std::invalid_argument(std::string("stereo calibration ") + name + " = " + FormatShort(value) +
                                  " must be finite; give the principal point in pixels");
    }
  }
}

}  // namespace cairn::perception
