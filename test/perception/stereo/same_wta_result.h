#pragma once

#include <algorithm>
#include <utility>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "cairn/perception/stereo/winner_take_all.h"

namespace cairn::perception {

/// Success when every matrix of the two results has the same size, type and bytes (so NaN and infinity compare
/// too); otherwise names the first matrix that differs.
inline ::testing::AssertionResult SameWtaResult(const WtaResult& a, const WtaResult& b) {
  const std::pair<const char*, const cv::Mat WtaResult::*> matrices[] = {
      {"disparity", &WtaResult::disparity},   {"best_index", &WtaResult::best_index},
      {"best_cost", &WtaResult::best_cost},   {"peak_ratio", &WtaResult::peak_ratio},
      {"right_best_index", &WtaResult::right_best_index}, {"lr_consistent", &WtaResult::lr_consistent}};
  for (const auto& [name, member] : matrices) {
    const cv::Mat& x = a.*member;
    const cv::Mat& y = b.*member;
    if (x.size() != y.size() || x.type() != y.type() || !std::equal(x.datastart, x.dataend, y.datastart)) {
      return ::testing::AssertionFailure() << "WtaResult::" << name << " differs";
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace cairn::perception
