#pragma once

/// @file
/// Internal: splits an image's rows across worker threads. Not part of the installed API.

#include <algorithm>
#include <thread>
#include <vector>

namespace cairn::perception::internal {

/// Resolves a user's thread count: 0 means one thread per hardware core (at least one).
inline int ResolveThreadCount(int requested) {
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

/// Calls body(thread_index, row_begin, row_end) on contiguous bands of [0, rows) covering every row once, one
/// band per thread; band t covers a deterministic range, so results never depend on scheduling.
template <typename Body>
void ParallelForRows(int rows, int num_threads, const Body& body) {
  const int threads = std::max(1, std::min(num_threads, rows));
  if (threads == 1) {
    body(0, 0, rows);
    return;
  }
  std::vector<std::thread> workers;
  workers.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) {
    const int begin = static_cast<int>(static_cast<long long>(rows) * t / threads);
    const int end = static_cast<int>(static_cast<long long>(rows) * (t + 1) / threads);
    workers.emplace_back([&body, t, begin, end] { body(t, begin, end); });
  }
  body(0, 0, static_cast<int>(static_cast<long long>(rows) / threads));
  for (auto& worker : workers) worker.join();
}

}  // namespace cairn::perception::internal
