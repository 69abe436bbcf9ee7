#include "cairn/perception/stereo/cost_volume_options.h"

#include <limits>
#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(CostVolumeOptionsTest, ParsesNamesAndSuggestsFixes) {
  EXPECT_EQ(ParseCostFunction("ssd"), CostFunction::kSsd);
  EXPECT_EQ(ParseCostFunction("btsad"), CostFunction::kBtSad);
  EXPECT_EQ(CostFunctionName(CostFunction::kBtSad), "btsad");
  EXPECT_EQ(ParsePrefilter("none"), Prefilter::kNone);
  CAIRN_EXPECT_THROWS_WITH(ParseCostFunction("bstad"), std::invalid_argument, "'bstad'", "did you mean 'btsad'");
  CAIRN_EXPECT_THROWS_WITH(ParsePrefilter("sobol"), std::invalid_argument, "did you mean 'sobel'");
}

TEST(CostVolumeOptionsTest, ValidateNamesTheBadValue) {
  CostVolumeOptions options;
  EXPECT_NO_THROW(options.Validate(640, 480));
  options.window = 8;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640, 480), std::invalid_argument, "window 8", "odd", "use e.g. 9");
  // Window sums are exact int32: an SSD window of 183 could overflow (183^2 * 255^2 > 2^31); BTSAD's can be larger.
  options.cost = CostFunction::kSsd;
  options.window = 183;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640, 480), std::invalid_argument, "window 183 is larger than 181", "ssd");
  options.window = 181;
  EXPECT_NO_THROW(options.Validate(640, 480));
  options.cost = CostFunction::kBtSad;
  options.window = 183;
  EXPECT_NO_THROW(options.Validate(640, 480));
  options.window = 9;
  options.max_disparity = 700;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640, 480), std::invalid_argument, "wider than the image (640 px)");
  options.max_disparity = 63;
  options.prefilter_size = 11;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640, 480), std::invalid_argument, "size 11", "use 3, 5, 7 or 9");
}

TEST(CostVolumeOptionsTest, RefusesWindowsLargerThanTheImageAndRangesThatOverflow) {
  CostVolumeOptions options;
  options.window = 31;
  options.max_disparity = 15;
  EXPECT_NO_THROW(options.Validate(40, 31));
  CAIRN_EXPECT_THROWS_WITH(options.Validate(40, 30), std::invalid_argument, "window 31 is larger than the image",
                           "30 px tall", "at most 29");
  CAIRN_EXPECT_THROWS_WITH(options.Validate(20, 480), std::invalid_argument, "20 px wide", "at most 19");
  // A matcher checks its options before it sees an image: only the size-independent checks apply.
  EXPECT_NO_THROW(options.Validate(CostVolumeOptions::kUnknownImageSize, CostVolumeOptions::kUnknownImageSize));
  options.window = 9;
  options.min_disparity = std::numeric_limits<int>::min();
  options.max_disparity = 0;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640, 480), std::invalid_argument, "wider than the image (640 px)");
  CAIRN_EXPECT_THROWS_WITH(
      options.Validate(CostVolumeOptions::kUnknownImageSize, CostVolumeOptions::kUnknownImageSize),
      std::invalid_argument, "disparities; no image is that wide");
}

}  // namespace
}  // namespace cairn::perception
