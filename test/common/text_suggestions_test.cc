#include "cairn/common/text_suggestions.h"

#include <gtest/gtest.h>

namespace cairn {
namespace {

TEST(TextSuggestionsTest, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(EditDistance("", ""), 0);
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3);
  EXPECT_EQ(EditDistance("abc", ""), 3);
  EXPECT_EQ(EditDistance("l_knee", "l_knee"), 0);
}

TEST(TextSuggestionsTest, ClosestNamesAreSortedByDistanceAndStable) {
  const std::vector<std::string> joints = {"l_leg_kny", "r_leg_kny", "l_arm_elx", "back_bkz"};
  EXPECT_EQ(ClosestNames("l_leg_knee", joints, 2), (std::vector<std::string>{"l_leg_kny", "r_leg_kny"}));
  EXPECT_TRUE(ClosestNames("x", {}, 3).empty());
}

TEST(TextSuggestionsTest, QuotedListQuotesEveryItem) {
  EXPECT_EQ(QuotedList({"a", "b"}), "'a', 'b'");
  EXPECT_EQ(QuotedList({}), "");
}

}  // namespace
}  // namespace cairn
