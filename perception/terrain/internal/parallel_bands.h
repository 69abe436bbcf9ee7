#pragma once

/// @file
/// ParallelForBands without a heap allocation per call, for the per-update paths of the terrain maps.

#include "cairn/common/parallel_for.h"

namespace cairn::perception::internal {

/// Calls cairn::ParallelForBands with `body` wrapped in a lambda that holds only a reference to it: small and
/// trivially copyable, so that std::function keeps it in place instead of allocating a copy of a lambda with many
/// captures (the terrain updates run at camera rate and promise not to allocate).
template <typename Body>
void ParallelBands(int count, int num_bands, int num_threads, const Body& body) {
  ParallelForBands(count, num_bands, num_threads, [&body](int band, int begin, int end) { body(band, begin, end); });
}

}  // namespace cairn::perception::internal
