#include "cairn/optimization/decision_variables.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cairn/optimization/mathematical_program.h"
#include "expect_throws.h"

namespace cairn::optimization {
namespace {

using ::testing::HasSubstr;

TEST(DecisionVariablesTest, SegmentsAndConcatenationKeepOrderAndProgram) {
  MathematicalProgram prog;
  const auto q = prog.NewContinuousVariables(4, "q");
  const auto v = prog.NewContinuousVariables(2, "v");
  const DecisionVariables joined = DecisionVariables::Concatenate({v, q.Segment(2, 2)});
  EXPECT_EQ(joined.indices(), (std::vector<int>{4, 5, 2, 3}));
  EXPECT_EQ(joined.description(), "(v, q[2:4])");
  EXPECT_EQ(joined.program_id(), prog.id());
  EXPECT_EQ(joined[2], 2);
  EXPECT_TRUE(DecisionVariables().empty());
  CAIRN_EXPECT_THROWS_WITH((void)joined[4], std::invalid_argument,
                           "DecisionVariables '(v, q[2:4])': position 4 is out of range; valid positions are 0..3");
}

TEST(DecisionVariablesTest, RejectsMixingPrograms) {
  MathematicalProgram a, b;
  const auto x = a.NewContinuousVariables(1, "x");
  const auto y = b.NewContinuousVariables(1, "y");
  CAIRN_EXPECT_THROWS_WITH((DecisionVariables::Concatenate({x, y})), std::invalid_argument,
                           "'y' belongs to a different MathematicalProgram than 'x'");
}

}  // namespace
}  // namespace cairn::optimization
