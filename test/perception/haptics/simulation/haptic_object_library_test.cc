#include "cairn/perception/haptics/simulation/haptic_object_library.h"

#include <stdexcept>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

TEST(HapticObjectLibraryTest, GroundTruthFollowsFig10AndFig14) {
  const std::vector<HapticObjectKind> one = DataSet1();
  ASSERT_EQ(one.size(), 9u);
  const bool traversable[] = {false, false, false, true, true, true, true, false, false};  // (a)–(i)
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(MakeHapticObject(one[i], 3).traversable(), traversable[i]) << HapticObjectName(one[i]);
  }
  EXPECT_EQ(HapticObjectName(one[3]), "(d) shrub");
  ASSERT_EQ(DataSet2().size(), 2u);
  EXPECT_TRUE(MakeHapticObject(DataSet2()[0], 3).traversable());
  EXPECT_FALSE(MakeHapticObject(DataSet2()[1], 3).traversable());
  EXPECT_TRUE(MakeHapticObject(HapticObjectKind::kFlimsyCanes, 3).traversable());
}

TEST(HapticObjectLibraryTest, SameSeedSameObject) {
  const HapticSceneObject a = MakeHapticObject(HapticObjectKind::kShrub, 5);
  const HapticSceneObject b = MakeHapticObject(HapticObjectKind::kShrub, 5);
  const HapticSceneObject c = MakeHapticObject(HapticObjectKind::kShrub, 6);
  ASSERT_EQ(a.primitives().size(), b.primitives().size());
  for (std::size_t i = 0; i < a.primitives().size(); ++i) EXPECT_EQ(a.primitives()[i].b, b.primitives()[i].b);
  EXPECT_NE(a.primitives()[0].b, c.primitives()[0].b);
}

TEST(HapticObjectLibraryTest, NamesParseAndUnknownOnesAreListed) {
  EXPECT_EQ(ParseHapticObjectKind("vertical logs"), HapticObjectKind::kVerticalLogs);
  CAIRN_EXPECT_THROWS_WITH(ParseHapticObjectKind("tree"), std::invalid_argument, "unknown object 'tree'",
                           "'wall', 'rock'");
}

}  // namespace
}  // namespace cairn::perception
