#pragma once

/// @file
/// Internal: splits an image's rows across worker threads. Not part of the installed API.

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace cairn::perception::internal {

/// Resolves a user's thread count: 0 means one thread per hardware core (at least one). Throws
/// std::invalid_argument for a negative count (it used to mean "all cores" silently).
inline int ResolveThreadCount(int requested) {
  if (requested < 0) {
    throw std::invalid_argument("num_threads " + std::to_string(requested) +
                                " is negative; use 0 for one thread per core, or a positive count");
  }
  if (requested > 0) return requested;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

/// Calls body(thread_index, row_begin, row_end) on contiguous bands of [0, rows) covering every row once, one
/// band per thread; band t covers a deterministic range, so results never depend on scheduling. An exception
/// thrown by a band (std::bad_alloc, say) reaches the caller once every band has finished; if several bands
/// throw, the lowest band's exception does.
template <typename Body>
void ParallelForRows(int rows, int num_threads, const Body& body) {
  const int threads = std::max(1, std::min(num_threads, rows));
  if (threads == 1) {
    body(0, 0, rows);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  auto run = [&body, &errors](int t, int begin, int end) {
    try {
      body(t, begin, end);
    } catch (...) {
      errors[t] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(threads - 1);
  for (int t = 1; t < threads; ++t) {
    const int begin = static_cast<int>(static_cast<long long>(rows) * t / threads);
    const int end = static_cast<int>(static_cast<long long>(rows) * (t + 1) / threads);
    workers.emplace_back(run, t, begin, end);
  }
  run(0, 0, static_cast<int>(static_cast<long long>(rows) / threads));
  for (auto& worker : workers) worker.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
}

}  // namespace cairn::perception::internal
