#include "cairn/perception/stereo/cost_volume_options.h"

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
  EXPECT_NO_THROW(options.Validate(640));
  options.window = 8;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640), std::invalid_argument, "window 8", "odd", "use e.g. 9");
  // Window sums are exact int32: an SSD window of 183 could overflow (183^2 * 255^2 > 2^31); BTSAD's can be larger.
  options.cost = CostFunction::kSsd;
  options.window = 183;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640), std::invalid_argument, "window 183 is larger than 181", "ssd");
  options.window = 181;
  EXPECT_NO_THROW(options.Validate(640));
  options.cost = CostFunction::kBtSad;
  options.window = 183;
  EXPECT_NO_THROW(options.Validate(640));
  options.window = 9;
  options.max_disparity = 700;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640), std::invalid_argument, "wider than the image (640 px)");
  options.max_disparity = 63;
  options.prefilter_size = 11;
  CAIRN_EXPECT_THROWS_WITH(options.Validate(640), std::invalid_argument, "size 11", "use 3, 5, 7 or 9");
}

}  // namespace
}  // namespace cairn::perception
