#include "cairn/perception/occupancy/internal/fast_log.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace cairn::perception {
namespace {

// The logarithm of the occupancy update's log-odds against std::log, over the probability clamps' range and more.
TEST(FastLogTest, MatchesStdLogOverTheProbabilityRange) {
  double worst = 0.0;
  for (float x = 1e-4f; x < 1e4f; x *= 1.0007f) {
    worst = std::max(worst, std::abs(internal::LogPositive(x) - std::log(static_cast<double>(x))));
  }
  EXPECT_LT(worst, 2e-6);
  EXPECT_EQ(internal::LogPositive(1.0f), 0.0f);
}

}  // namespace
}  // namespace cairn::perception
