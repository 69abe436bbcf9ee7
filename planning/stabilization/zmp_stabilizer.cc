#include <cairn/planning/stabilization/zmp_stabilizer.h>

#include <stdexcept>

#include <cairn/planning/stabilization/fft_zmp_stabilizer.h>
#include <cairn/planning/stabilization/preview_zmp_stabilizer.h>

namespace cairn::planning {

std::unique_ptr<ZmpStabilizer> MakeZmpStabilizer(const StabilizerOptions& options, double gravity) {
  ValidateStabilizerOptions(options);
  if (options.method == "fft") return std::make_unique<FftZmpStabilizer>(gravity, options.fft_padding);
  if (options.method == "preview") {
    return std::make_unique<PreviewZmpStabilizer>(gravity, options.preview_time, options.preview_q, options.preview_r);
  }
  throw std::invalid_argument("MakeZmpStabilizer: method '" + options.method +
                              "' has no stabiliser; use fft or preview");
}

}  // namespace cairn::planning
