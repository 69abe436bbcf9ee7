#include "cairn/common/number_text.h"
#include "cairn/perception/stereo/cost_volume_options.h"

#include <cstdint>
#include <stdexcept>
#include <utility>

#include "cairn/common/parallel_for.h"
#include "cairn/common/text_suggestions.h"
#include "cairn/perception/io/image_file.h"

namespace cairn::perception {
namespace {

std::string Suggest(const std::string& name, const std::vector<std::string>& choices) {
  const auto close = ClosestNames(name, choices, 1);
  std::string message = "; expected one of " + QuotedList(choices);
  if (!close.empty() && EditDistance(name, close.front()) <= 2) message += " (did you mean '" + close.front() + "'?)";
  return message;
}

}  // namespace

CostFunction ParseCostFunction(const std::string& name) {
  if (name == "ssd") return CostFunction::kSsd;
  if (name == "btsad") return CostFunction::kBtSad;
  throw std::invalid_argument("unknown stereo cost function '" + name + "'" + Suggest(name, {"ssd", "btsad"}));
}

std::string CostFunctionName(CostFunction cost) { return cost == CostFunction::kSsd ? "ssd" : "btsad"; }

Prefilter ParsePrefilter(const std::string& name) {
  if (name == "sobel") return Prefilter::kSobel;
  if (name == "none") return Prefilter::kNone;
  throw std::invalid_argument("unknown stereo prefilter '" + name + "'" + Suggest(name, {"sobel", "none"}));
}

std::string PrefilterName(Prefilter prefilter) { return prefilter == Prefilter::kSobel ? "sobel" : "none"; }

void CostVolumeOptions::Validate(int image_width, int image_height) const {
  if (window < 1 || window % 2 == 0) {
    throw std::invalid_argument("stereo window " + cairn::FormatShort(window) +
                                " must be odd and positive (the pixel sits at its centre); use e.g. " +
                                cairn::FormatShort(window < 1 ? 5 : window + 1));
  }
  // Window sums are exact 32-bit integers: window^2 times the largest pixel cost (SSD 255^2, BTSAD 510 in doubled
  // units) must stay below 2^31.
  const int max_window = cost == CostFunction::kSsd ? 181 : 2051;
  if (window > max_window) {
    throw std::invalid_argument("stereo window " + cairn::FormatShort(window) + " is larger than " +
                                cairn::FormatShort(max_window) + ", beyond which " + CostFunctionName(cost) +
                                " window sums overflow; use a smaller window");
  }
  for (const auto& [side, name] : {std::pair<int, const char*>{image_width, "wide"}, {image_height, "tall"}}) {
    if (side != kUnknownImageSize && window > side) {
      throw std::invalid_argument("stereo window " + cairn::FormatShort(window) + " is larger than the image, which is " +
                                  cairn::FormatShort(side) + " px " + name + "; use a window of at most " +
                                  cairn::FormatShort(side % 2 == 1 ? side : side - 1));
    }
  }
  if (max_disparity < min_disparity) {
    throw std::invalid_argument("max disparity " + cairn::FormatShort(max_disparity) + " is below min disparity " +
                                cairn::FormatShort(min_disparity) + "; swap them");
  }
  // In 64 bits: -min_disparity overflows for the smallest int.
  if (image_width != kUnknownImageSize &&
      (max_disparity >= image_width || -static_cast<std::int64_t>(min_disparity) >= image_width)) {
    throw std::invalid_argument("disparity range [" + cairn::FormatShort(min_disparity) + ", " +
                                cairn::FormatShort(max_disparity) + "] is wider than the image (" +
                                cairn::FormatShort(image_width) + " px); use a max disparity below " +
                                cairn::FormatShort(image_width));
  }
  // Without a width, the range is bounded by the largest image a file may hold (kMaxImagePixels on one row).
  if (static_cast<std::int64_t>(max_disparity) - min_disparity + 1 > kMaxImagePixels) {
    throw std::invalid_argument("disparity range [" + cairn::FormatShort(min_disparity) + ", " +
                                cairn::FormatShort(max_disparity) + "] has more than " +
                                cairn::FormatShort(kMaxImagePixels) + " disparities; no image is that wide");
  }
  if (prefilter == Prefilter::kSobel) {
    if (prefilter_size != 3 && prefilter_size != 5 && prefilter_size != 7 && prefilter_size != 9) {
      throw std::invalid_argument("Sobel prefilter size " + cairn::FormatShort(prefilter_size) +
                                  " is not supported; use 3, 5, 7 or 9");
    }
    if (prefilter_cap < 1 || prefilter_cap > 63) {
      throw std::invalid_argument("Sobel prefilter cap " + cairn::FormatShort(prefilter_cap) +
                                  " is outside 1..63; OpenCV's default is 31");
    }
  }
  ResolveThreadCount(num_threads);  // the one thread-count rule: throws for a negative or too large count
}

}  // namespace cairn::perception
