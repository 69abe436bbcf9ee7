// perception/internal/parallel_rows.h, which the stereo, occupancy and friction kernels split their rows with.

#include <algorithm>
#include <atomic>
#include <string>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "cairn/perception/internal/parallel_rows.h"
#include "cairn/perception/stereo/winner_take_all.h"
#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(ParallelRowsTest, CoversEveryRowOnceInDeterministicBands) {
  for (int threads : {1, 2, 3, 7, 12}) {
    std::vector<std::atomic<int>> visits(10);
    std::vector<int> band(10, -1);
    internal::ParallelForRows(10, threads, [&](int t, int begin, int end) {
      for (int r = begin; r < end; ++r) {
        ++visits[r];
        band[r] = t;
      }
    });
    for (int r = 0; r < 10; ++r) EXPECT_EQ(visits[r].load(), 1) << "threads " << threads << " row " << r;
    // Contiguous bands in thread order, no more bands than rows, the first on the calling thread's index 0.
    EXPECT_EQ(band.front(), 0);
    EXPECT_EQ(band.back(), std::min(threads, 10) - 1);
    for (int r = 1; r < 10; ++r) EXPECT_TRUE(band[r] == band[r - 1] || band[r] == band[r - 1] + 1);
  }
}

// A worker's exception used to end the process (std::terminate from the thread); it now reaches the caller after
// every band has finished, the lowest band's first.
TEST(ParallelRowsTest, ExceptionsReachTheCallerAfterEveryBandFinishes) {
  std::atomic<int> finished{0};
  CAIRN_EXPECT_THROWS_WITH(internal::ParallelForRows(9, 3,
                                                     [&](int t, int, int) {
                                                       if (t >= 1) throw std::runtime_error("band " + std::to_string(t));
                                                       ++finished;
                                                     }),
                           std::runtime_error, "band 1");
  EXPECT_EQ(finished.load(), 1);
  CAIRN_EXPECT_THROWS_WITH(internal::ParallelForRows(9, 3,
                                                     [&](int t, int, int) {
                                                       if (t == 0) throw std::invalid_argument("caller's band");
                                                     }),
                           std::invalid_argument, "caller's band");
}

TEST(ParallelRowsTest, ANegativeThreadCountIsAnError) {
  EXPECT_EQ(internal::ResolveThreadCount(3), 3);
  EXPECT_GE(internal::ResolveThreadCount(0), 1);
  CAIRN_EXPECT_THROWS_WITH(internal::ResolveThreadCount(-2), std::invalid_argument, "num_threads -2 is negative");
  // Through a public entry point that used to read -1 as "all cores".
  DisparityVolume costs(2, 4, 0, 1);
  WtaOptions options;
  options.num_threads = -1;
  WtaResult result;
  CAIRN_EXPECT_THROWS_WITH(ComputeWinnerTakeAll(costs, options, &result), std::invalid_argument,
                           "num_threads -1 is negative");
}

}  // namespace
}  // namespace cairn::perception
