#pragma once

/// @file
/// Cost samples for maximum-likelihood parameters and histogram training (thesis sections 4.3.2-4.3.3).

#include <vector>

#include <opencv2/core.hpp>

#include "cairn/perception/stereo/disparity_volume.h"
#include "cairn/perception/stereo/winner_take_all.h"

namespace cairn::perception {

/// Appends to `samples` the minimum cost of every pixel whose winner-take-all disparity passes the left-right
/// check (the thesis' no-ground-truth estimation set). Returns the number appended.
std::size_t CollectConsistentWtaCosts(const DisparityVolume& costs, const WtaResult& wta, std::vector<float>* samples);

/// Appends to `samples` the cost at the ground-truth disparity (rounded to the nearest integer) of every pixel
/// where `ground_truth` (CV_32F, pixels; 0 = unknown) is known, `mask` (CV_8U, may be empty) is non-zero and the
/// disparity is inside the volume's range with a finite cost. Throws std::invalid_argument on a size or type
/// mismatch. Returns the number appended.
std::size_t CollectGroundTruthCosts(const DisparityVolume& costs, const cv::Mat& ground_truth, const cv::Mat& mask,
                                    std::vector<float>* samples);

}  // namespace cairn::perception
