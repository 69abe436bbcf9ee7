#pragma once

/// @file
/// The one way Cairn splits work across threads: contiguous bands of an index range, run on a pool of worker
/// threads that is started once per process and reused by every call.

#include <functional>

namespace cairn {

/// The most threads one call may ask for. A count above it is almost certainly a mistake (a uint overflow, a
/// pixel count passed as a thread count) and would start that many threads; it is refused instead.
inline constexpr int kMaxThreads = 256;

/// The one thread-count rule: 0 means one thread per hardware core (at least one, at most kMaxThreads);
/// 1..kMaxThreads are used as given. Throws std::invalid_argument for a negative count (it once meant "all
/// cores" silently) or one above kMaxThreads, naming the value and the rule.
int ResolveThreadCount(int num_threads);

/// What a band runs: body(band, begin, end) handles the indices [begin, end) of band number `band`.
using ParallelBandBody = std::function<void(int band, int begin, int end)>;

/// Runs body(band, begin, end) over [0, count) split into min(ResolveThreadCount(num_threads), count) contiguous
/// bands, one per thread; see ParallelForBands. Does nothing when count is 0.
void ParallelFor(int count, int num_threads, const ParallelBandBody& body);

/// Runs body(b, begin, end) once for every band b in [0, num_bands), on up to ResolveThreadCount(num_threads)
/// threads (the calling thread is one of them). Band b covers [count * b / num_bands, count * (b + 1) / num_bands):
/// the bands depend only on count and num_bands, never on scheduling, so a body whose result depends only on its
/// band gives the same result for every thread count. Bands are started in increasing order, each by whichever
/// thread is free; more bands than threads balance uneven work. A band index is used by one thread at a time, so
/// per-band scratch needs no locking.
///
/// Every band runs even if some throw; the exception of the lowest band that threw then reaches the caller, once
/// every band has finished. A ParallelFor called from inside a band runs its bands one after another on that
/// thread (same bands, same results), so nesting cannot deadlock the pool. Calls from several threads at once
/// share the pool safely. Throws std::invalid_argument for a negative count, num_bands < 1, or a thread count
/// that ResolveThreadCount refuses.
void ParallelForBands(int count, int num_bands, int num_threads, const ParallelBandBody& body);

}  // namespace cairn
