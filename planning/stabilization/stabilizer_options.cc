#include <cairn/planning/stabilization/stabilizer_options.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
void CheckRange(const char* name, double value, double lo, double hi, bool open_lo, const char* unit) {
  const bool ok = std::isfinite(value) && (open_lo ? value > lo : value >= lo) && value <= hi;
  if (!ok) {
    throw std::invalid_argument(std::string("StabilizerOptions: ") + name + " " + FormatShort(value) + unit +
                                " must be in " + (open_lo ? "(" : "[") + FormatShort(lo) + ", " + FormatShort(hi) +
                                "]");
  }
}
}  // namespace

StabilizerOptions WalkingStabilizerOptions(const std::string& method) {
  StabilizerOptions options;
  options.method = method;
  options.contact_timing = true;
  options.waist_orientation = "upright";
  options.cart_table_start = true;
  options.crouch = 0.06;
  options.landing_height = 0.01;
  options.landing_time = 0.15;
  return options;
}

void ValidateStabilizerOptions(const StabilizerOptions& o) {
  if (o.method != "fft" && o.method != "preview" && o.method != "none") {
    throw std::invalid_argument("StabilizerOptions: method '" + o.method + "' is unknown; use fft, preview or none");
  }
  if (o.interpolation != "hermite" && o.interpolation != "spline") {
    throw std::invalid_argument("StabilizerOptions: interpolation '" + o.interpolation +
                                "' is unknown; use hermite or spline");
  }
  if (o.waist_orientation != "interpolated" && o.waist_orientation != "upright") {
    throw std::invalid_argument("StabilizerOptions: waist_orientation '" + o.waist_orientation +
                                "' is unknown; use upright or interpolated");
  }
  CheckRange("control_period", o.control_period, 1e-4, 0.05, false, " s");
  if (o.max_iterations < 1 || o.max_iterations > 100) {
    throw std::invalid_argument("StabilizerOptions: max_iterations " + std::to_string(o.max_iterations) +
                                " must be in [1, 100]");
  }
  CheckRange("step_fraction", o.step_fraction, 0.0, 1.0, true, "");
  CheckRange("tolerance", o.tolerance, 0.0, 1.0, true, " m");
  if (!(o.min_improvement >= 0.0 && o.min_improvement < 1.0)) {
    throw std::invalid_argument("StabilizerOptions: min_improvement " + FormatShort(o.min_improvement) +
                                " must be in [0, 1)");
  }
  CheckRange("preview_time", o.preview_time, 0.0, 5.0, true, " s");
  CheckRange("preview_q", o.preview_q, 0.0, 1e12, true, "");
  CheckRange("preview_r", o.preview_r, 0.0, 1e12, true, "");
  CheckRange("crouch", o.crouch, 0.0, 0.3, false, " m");
  CheckRange("landing_height", o.landing_height, 0.0, 0.1, false, " m");
  CheckRange("landing_time", o.landing_time, 0.0, 1.0, false, " s");
  if (o.landing_height > 0.0 && !o.contact_timing) {
    throw std::invalid_argument("StabilizerOptions: landing_height " + FormatShort(o.landing_height) +
                                " m needs contact_timing (the landing shapes the contact-timed swing path); set "
                                "contact_timing or landing_height 0");
  }
  if ((o.landing_height > 0.0) != (o.landing_time > 0.0)) {
    throw std::invalid_argument("StabilizerOptions: landing_height " + FormatShort(o.landing_height) +
                                " m and landing_time " + FormatShort(o.landing_time) +
                                " s must be both 0 (no landing phase) or both > 0");
  }
  CheckRange("fft_padding", o.fft_padding, 0.0, 10.0, false, " s");
  CheckRange("sole_length", o.sole_length, 0.0, 2.0, true, " m");
  CheckRange("sole_width", o.sole_width, 0.0, 2.0, true, " m");
  if (o.left_sole_frame.empty() || o.right_sole_frame.empty() || o.waist_frame.empty()) {
    throw std::invalid_argument("StabilizerOptions: left_sole_frame, right_sole_frame and waist_frame must be named");
  }
}

}  // namespace cairn::planning
