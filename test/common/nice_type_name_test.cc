#include "cairn/common/nice_type_name.h"

#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>

namespace cairn {
namespace {

struct LocalType {};

TEST(NiceTypeNameTest, SpellsCommonTypesAsUsersWriteThem) {
  EXPECT_EQ(NiceTypeName<Eigen::VectorXd>(), "Eigen::VectorXd");
  EXPECT_EQ(NiceTypeName<std::string>(), "std::string");
  EXPECT_EQ(NiceTypeName<int>(), "int");
  EXPECT_EQ(NiceTypeName<LocalType>(), "cairn::(anonymous namespace)::LocalType");
}

}  // namespace
}  // namespace cairn
