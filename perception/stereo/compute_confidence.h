#pragma once

/// @file
/// Whole-range stereo confidence C(d) (thesis eq. 4.3), computed in log space.

#include "cairn/perception/stereo/confidence_model.h"
#include "cairn/perception/stereo/disparity_volume.h"

namespace cairn::perception {

/// Computes C(d) = p(E_d | d) / sum_d' p(E_d' | d') for every pixel and disparity of `costs` under `model`.
/// The normalisation is a log-sum-exp, so costs that would underflow exp() (large SSDs with a small parameter)
/// still give a proper distribution. Infinite costs get C = 0; a pixel without any finite cost gets C = 0
/// everywhere (its curve sums to 0, not 1). `confidence` is resized like `costs` (storage reused); rows are split
/// across `num_threads` threads (0 = one per core; rule: cairn::ResolveThreadCount).
void ComputeConfidence(const DisparityVolume& costs, const ConfidenceModel& model, DisparityVolume* confidence,
                       int num_threads = 0);

}  // namespace cairn::perception
