#include "cairn/systems/primitives/constant_vector_source.h"

#include <cmath>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::systems {
namespace {

TEST(ConstantVectorSourceTest, OutputsItsValueAndCachesIt) {
  ConstantVectorSource source(Eigen::Vector3d(1.0, 2.0, 3.0));
  auto context = source.CreateDefaultContext();
  EXPECT_EQ(source.get_output_port().Eval<Eigen::VectorXd>(*context), Eigen::Vector3d(1.0, 2.0, 3.0));
  context->SetTime(10.0);
  source.get_output_port().Eval<Eigen::VectorXd>(*context);
  EXPECT_EQ(context->num_calculations(source.output_port_ticket(0)), 1);
  source.SetValue(context.get(), Eigen::Vector3d::Zero());
  EXPECT_EQ(source.get_output_port().Eval<Eigen::VectorXd>(*context), Eigen::Vector3d::Zero());
  CAIRN_EXPECT_THROWS_WITH(source.SetValue(context.get(), Eigen::VectorXd::Zero(2)), std::invalid_argument,
                           "has size 3", "size 2");
}

TEST(ConstantVectorSourceTest, NanValuesAreRefusedAndInfinitiesKept) {
  CAIRN_EXPECT_THROWS_WITH(ConstantVectorSource(Eigen::Vector2d(1.0, std::nan(""))), std::invalid_argument,
                           "element 1 of the value is NaN");
  ConstantVectorSource limit(Eigen::VectorXd::Constant(1, HUGE_VAL));
  auto context = limit.CreateDefaultContext();
  EXPECT_EQ(limit.get_output_port().Eval<Eigen::VectorXd>(*context)[0], HUGE_VAL);
  CAIRN_EXPECT_THROWS_WITH(limit.SetValue(context.get(), Eigen::VectorXd::Constant(1, std::nan(""))),
                           std::invalid_argument, "element 0 of the value is NaN");
}

}  // namespace
}  // namespace cairn::systems
