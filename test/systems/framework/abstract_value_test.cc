#include "cairn/systems/framework/value.h"

#include <memory>
#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(AbstractValueTest, HoldsAndCopiesValues) {
  auto value = AbstractValue::Make<std::string>("cairn");
  EXPECT_EQ(value->get_value<std::string>(), "cairn");
  value->set_value<std::string>("stone");
  auto copy = value->Clone();
  value->get_mutable_value<std::string>() = "changed";
  EXPECT_EQ(copy->get_value<std::string>(), "stone");
  copy->SetFrom(*value);
  EXPECT_EQ(copy->get_value<std::string>(), "changed");
  EXPECT_EQ(value->GetNiceTypeName(), "std::string");
}

TEST(AbstractValueTest, WrongTypeNamesBothTypes) {
  Value<Eigen::VectorXd> vector(Eigen::VectorXd::Zero(3));
  CAIRN_EXPECT_THROWS_WITH(vector.get_value<int>(), std::logic_error, "Eigen::VectorXd", "accessed as int");
  Value<int> number(3);
  CAIRN_EXPECT_THROWS_WITH(number.SetFrom(vector), std::logic_error, "Eigen::VectorXd", "int");
}

TEST(AbstractValueTest, MoveOnlyTypesWorkUntilCloned) {
  Value<std::unique_ptr<int>> holder(std::make_unique<int>(7));
  EXPECT_EQ(*holder.get_value<std::unique_ptr<int>>(), 7);
  CAIRN_EXPECT_THROWS_WITH(holder.Clone(), std::logic_error, "move-only", "copy constructor");
}

}  // namespace
}  // namespace cairn::systems
