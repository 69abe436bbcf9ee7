#include "cairn/common/parallel_for.h"

#include <algorithm>
#include <chrono>
#include <atomic>
#include <cmath>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn {
namespace {

TEST(ParallelForTest, CoversEveryIndexOnceInDeterministicBands) {
  for (int threads : {1, 2, 3, 7, 12}) {
    std::vector<std::atomic<int>> visits(10);
    std::vector<int> band(10, -1);
    ParallelFor(10, threads, [&](int b, int begin, int end) {
      for (int r = begin; r < end; ++r) {
        ++visits[r];
        band[r] = b;
      }
    });
    for (int r = 0; r < 10; ++r) EXPECT_EQ(visits[r].load(), 1) << "threads " << threads << " index " << r;
    // Contiguous bands in order, no more bands than indices.
    EXPECT_EQ(band.front(), 0);
    EXPECT_EQ(band.back(), std::min(threads, 10) - 1);
    for (int r = 1; r < 10; ++r) EXPECT_TRUE(band[r] == band[r - 1] || band[r] == band[r - 1] + 1);
  }
}

TEST(ParallelForTest, BandsDependOnlyOnCountAndBandCount) {
  for (int threads : {1, 2, 5}) {
    std::vector<std::pair<int, int>> ranges(4);
    ParallelForBands(10, 4, threads, [&](int b, int begin, int end) { ranges[b] = {begin, end}; });
    EXPECT_EQ(ranges, (std::vector<std::pair<int, int>>{{0, 2}, {2, 5}, {5, 7}, {7, 10}})) << threads;
  }
  // More bands than indices: the extra bands are empty, and still run.
  std::atomic<int> calls{0};
  ParallelForBands(2, 5, 3, [&](int, int begin, int end) {
    EXPECT_LE(begin, end);
    ++calls;
  });
  EXPECT_EQ(calls.load(), 5);
}

// A sum made of per-band partial sums added in band order is the same for every thread count.
TEST(ParallelForTest, ResultsDoNotDependOnTheThreadCount) {
  constexpr int kCount = 10007;
  constexpr int kBands = 16;
  auto sum = [&](int threads) {
    std::vector<double> partial(kBands, 0.0);
    ParallelForBands(kCount, kBands, threads, [&](int b, int begin, int end) {
      for (int i = begin; i < end; ++i) partial[b] += std::sin(0.001 * i) / (1.0 + i);
    });
    double total = 0.0;
    for (double p : partial) total += p;
    return total;
  };
  const double one = sum(1);
  for (int threads : {2, 3, 8, 0}) EXPECT_EQ(sum(threads), one) << threads;
}

TEST(ParallelForTest, UsesNoMoreThreadsThanAskedFor) {
  // Grow the pool first, so that later calls could use more threads than they ask for.
  ParallelForBands(64, 64, 6, [](int, int, int) { std::this_thread::sleep_for(std::chrono::microseconds(50)); });
  for (int threads : {1, 2, 3}) {
    std::mutex mutex;
    std::set<std::thread::id> ids;
    ParallelForBands(200, 200, threads, [&](int, int, int) {
      std::this_thread::sleep_for(std::chrono::microseconds(20));
      std::lock_guard<std::mutex> lock(mutex);
      ids.insert(std::this_thread::get_id());
    });
    EXPECT_LE(static_cast<int>(ids.size()), threads);
  }
}

// A worker's exception once ended the process (std::terminate from the thread); it reaches the caller after every
// band has finished, the lowest band's.
TEST(ParallelForTest, ExceptionsReachTheCallerAfterEveryBandFinishes) {
  std::atomic<int> finished{0};
  CAIRN_EXPECT_THROWS_WITH(ParallelFor(9, 3,
                                       [&](int b, int, int) {
                                         if (b >= 1) throw std::runtime_error("band " + std::to_string(b));
                                         ++finished;
                                       }),
                           std::runtime_error, "band 1");
  EXPECT_EQ(finished.load(), 1);
  CAIRN_EXPECT_THROWS_WITH(ParallelFor(9, 3,
                                       [&](int b, int, int) {
                                         if (b == 0) throw std::invalid_argument("first band");
                                       }),
                           std::invalid_argument, "first band");
  // Many bands: all run, and the lowest failing band's exception wins whatever finished first.
  std::atomic<int> ran{0};
  CAIRN_EXPECT_THROWS_WITH(ParallelForBands(100, 100, 4,
                                            [&](int b, int, int) {
                                              ++ran;
                                              if (b % 10 == 7) throw std::runtime_error("band " + std::to_string(b));
                                            }),
                           std::runtime_error, "band 7");
  EXPECT_EQ(ran.load(), 100);
  // One thread: the same rule.
  CAIRN_EXPECT_THROWS_WITH(ParallelForBands(4, 4, 1,
                                            [&](int b, int, int) {
                                              if (b >= 2) throw std::runtime_error("band " + std::to_string(b));
                                            }),
                           std::runtime_error, "band 2");
}

TEST(ParallelForTest, NestedCallsRunInlineWithTheSameBands) {
  std::vector<std::vector<int>> inner(4);
  ParallelFor(4, 4, [&](int b, int, int) {
    ParallelForBands(6, 3, 4, [&](int inner_band, int begin, int end) {
      for (int i = begin; i < end; ++i) inner[b].push_back(inner_band * 10 + i);  // one thread per outer band
    });
  });
  for (const std::vector<int>& v : inner) EXPECT_EQ(v, (std::vector<int>{0, 1, 12, 13, 24, 25}));
}

TEST(ParallelForTest, CallsFromSeveralThreadsAtOnce) {
  std::vector<long long> sums(4, 0);
  std::vector<std::thread> callers;
  for (int c = 0; c < 4; ++c) {
    callers.emplace_back([&sums, c] {
      for (int repeat = 0; repeat < 20; ++repeat) {
        std::vector<long long> partial(8, 0);
        ParallelForBands(1000, 8, 3, [&](int b, int begin, int end) {
          for (int i = begin; i < end; ++i) partial[b] += i;
        });
        for (long long p : partial) sums[c] += p;
      }
    });
  }
  for (std::thread& caller : callers) caller.join();
  for (long long sum : sums) EXPECT_EQ(sum, 20LL * 999 * 1000 / 2);
}

TEST(ParallelForTest, OneThreadCountRule) {
  EXPECT_EQ(ResolveThreadCount(3), 3);
  EXPECT_EQ(ResolveThreadCount(kMaxThreads), kMaxThreads);
  const int cores = ResolveThreadCount(0);
  EXPECT_GE(cores, 1);
  EXPECT_LE(cores, kMaxThreads);
  CAIRN_EXPECT_THROWS_WITH(ResolveThreadCount(-2), std::invalid_argument, "num_threads -2 is negative",
                           "0 for one thread per core");
  CAIRN_EXPECT_THROWS_WITH(ResolveThreadCount(kMaxThreads + 1), std::invalid_argument, "num_threads 257",
                           "limit of 256");
  CAIRN_EXPECT_THROWS_WITH(ParallelFor(4, -1, [](int, int, int) {}), std::invalid_argument, "num_threads -1");
  CAIRN_EXPECT_THROWS_WITH(ParallelFor(-1, 1, [](int, int, int) {}), std::invalid_argument, "count -1 is negative");
  CAIRN_EXPECT_THROWS_WITH(ParallelForBands(4, 0, 1, [](int, int, int) {}), std::invalid_argument,
                           "num_bands 0 must be at least 1");
  bool called = false;
  ParallelFor(0, 4, [&](int, int, int) { called = true; });
  EXPECT_FALSE(called);
}

}  // namespace
}  // namespace cairn
