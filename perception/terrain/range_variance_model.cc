#include "cairn/perception/terrain/range_variance_model.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::perception {

void RangeVarianceModel::Validate() const {
  if (!(a > 0.0) || !std::isfinite(a)) {
    throw std::invalid_argument("RangeVarianceModel: a = " + FormatShort(a) +
                                " m must be positive and finite (sigma(z) = a + b (z - c)^2; D435: 0.0024)");
  }
  if (!(b >= 0.0) || !std::isfinite(b)) {
    throw std::invalid_argument("RangeVarianceModel: b = " + FormatShort(b) +
                                " 1/m must be non-negative and finite (D435: 0.0066)");
  }
  if (!std::isfinite(c)) {
    throw std::invalid_argument("RangeVarianceModel: c = " + FormatShort(c) + " m must be finite (D435: 0.77)");
  }
}

}  // namespace cairn::perception
