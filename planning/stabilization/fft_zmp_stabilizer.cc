#include <cairn/planning/stabilization/fft_zmp_stabilizer.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include <unsupported/Eigen/FFT>

#include <cairn/common/number_text.h>

namespace cairn::planning {

namespace {
constexpr double kPi = 3.141592653589793;

void CheckOffsetInput(const char* caller, const Eigen::VectorXd& error, double period, double com_height) {
  if (error.size() == 0 || !error.allFinite()) {
    throw std::invalid_argument(std::string(caller) + ": the ZMP error must be non-empty and finite");
  }
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument(std::string(caller) + ": period " + FormatShort(period) + " s must be positive");
  }
  if (!(com_height > 0.0) || !std::isfinite(com_height)) {
    throw std::invalid_argument(std::string(caller) + ": COM height " + FormatShort(com_height) +
                                " m must be positive and finite");
  }
}
}  // namespace

FftZmpStabilizer::FftZmpStabilizer(double gravity, double padding) : gravity_(gravity), padding_(padding) {
  if (!(gravity > 0.0) || !std::isfinite(gravity)) {
    throw std::invalid_argument("FftZmpStabilizer: gravity " + FormatShort(gravity) + " m/s^2 must be positive");
  }
  if (!(padding >= 0.0 && padding <= 10.0)) {
    throw std::invalid_argument("FftZmpStabilizer: padding " + FormatShort(padding) + " s must be in [0, 10]");
  }
}

Eigen::VectorXd FftZmpStabilizer::ComOffsets(const Eigen::VectorXd& error, double period, double com_height) const {
  CheckOffsetInput("FftZmpStabilizer::ComOffsets", error, period, com_height);
  const auto n = static_cast<long long>(error.size());
  const auto pad = static_cast<long long>(std::ceil(padding_ / period));
  long long size = 1;
  while (size < n + 2 * pad) size *= 2;
  if (size > kMaxTransformSize) {
    throw std::invalid_argument("FftZmpStabilizer::ComOffsets: " + std::to_string(n) + " samples with " +
                                FormatShort(padding_) + " s padding need a transform of " + std::to_string(size) +
                                " samples, more than the limit of " + std::to_string(kMaxTransformSize) +
                                "; lengthen the period or shorten the trajectory");
  }
  std::vector<double> signal(static_cast<std::size_t>(size), 0.0);
  const long long offset = (size - n) / 2;
  for (long long k = 0; k < n; ++k) signal[static_cast<std::size_t>(offset + k)] = error[k];
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, signal);
  const double gain = com_height / gravity_;
  const double base = 2.0 * kPi / (static_cast<double>(size) * period);
  for (long long i = 0; i < static_cast<long long>(spectrum.size()); ++i) {
    const long long index = i <= size / 2 ? i : i - size;
    const double w = base * static_cast<double>(index);
    spectrum[static_cast<std::size_t>(i)] /= (1.0 + gain * w * w);
  }
  std::vector<double> result;
  fft.inv(result, spectrum);
  Eigen::VectorXd offsets(n);
  for (long long k = 0; k < n; ++k) offsets[k] = result[static_cast<std::size_t>(offset + k)];
  return offsets;
}

}  // namespace cairn::planning
