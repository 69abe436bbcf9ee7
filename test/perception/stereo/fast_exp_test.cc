#include "cairn/perception/stereo/internal/fast_exp.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace cairn::perception {
namespace {

// The vectorisable exp used by ComputeConfidence() against std::exp over its whole domain.
TEST(FastExpTest, MatchesStdExpOverItsWholeDomain) {
  double worst = 0.0;
  for (float x = 0.0f; x > -87.0f; x -= 0.001237f) {
    const double reference = std::exp(static_cast<double>(x));
    worst = std::max(worst, std::abs(internal::ExpNonPositive(x) - reference) / reference);
  }
  EXPECT_LT(worst, 5e-7);
  EXPECT_EQ(internal::ExpNonPositive(0.0f), 1.0f);
  EXPECT_LT(internal::ExpNonPositive(-1.0e6f), 1e-37f);
  EXPECT_LT(internal::ExpNonPositive(std::numeric_limits<float>::quiet_NaN()), 1e-37f);
}

}  // namespace
}  // namespace cairn::perception
