#include "examples/antenna/antenna_example.h"

#include <stdexcept>

#include "expect_throws.h"

namespace cairn::examples {
namespace {

TEST(AntennaExampleTest, TheRobotTouchesUnknownObjectsAndLearns) {
  AntennaExampleOptions options;
  options.frames_per_object = 3;
  const AntennaRun run = RunAntennaExample(options);
  ASSERT_EQ(run.frames.size(), 2u * 3u * 4u);
  EXPECT_EQ(run.frames[0].confidence, 0.0);  // nothing known yet
  EXPECT_GT(run.frames[0].touched_points, 0);
  EXPECT_EQ(run.memory_size, run.interactions);  // every interaction is learnt once
  EXPECT_GT(run.interactions, 0);
  // The second pass meets the objects it has learnt: more confident on average than the first.
  double first = 0.0, second = 0.0;
  for (std::size_t i = 0; i < 12; ++i) {
    first += run.frames[i].confidence;
    second += run.frames[i + 12].confidence;
  }
  EXPECT_GT(second, first);
  EXPECT_EQ(run.frames[3].object, "(b) rock");
  EXPECT_FALSE(run.frames[3].traversable);
}

TEST(AntennaExampleTest, BadOptionsAreRefused) {
  AntennaExampleOptions options;
  options.objects.clear();
  CAIRN_EXPECT_THROWS_WITH(RunAntennaExample(options), std::invalid_argument, "needs 1 to 100 objects; got 0");
}

}  // namespace
}  // namespace cairn::examples
