#include "cairn/systems/primitives/constant_vector_source.h"

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

}  // namespace
}  // namespace cairn::systems
