#include "cairn/common/number_text.h"

#include <climits>
#include <cstddef>
#include <cstdint>

#include <gtest/gtest.h>

namespace cairn {
namespace {

TEST(NumberTextTest, DoublesShortAndExact) {
  EXPECT_EQ(FormatShort(0.1), "0.1");
  EXPECT_EQ(FormatShort(1234567.0), "1.23457e+06");
  EXPECT_EQ(FormatShort(-2.5), "-2.5");
  EXPECT_EQ(FormatExact(0.1), "0.10000000000000001");
  EXPECT_EQ(std::stod(FormatExact(1.0 / 3.0)), 1.0 / 3.0);
}

// Integers print every digit, never an exponent, whatever their type.
TEST(NumberTextTest, IntegersPrintEveryDigit) {
  EXPECT_EQ(FormatShort(0), "0");
  EXPECT_EQ(FormatShort(1234567), "1234567");
  EXPECT_EQ(FormatShort(-1234567), "-1234567");
  EXPECT_EQ(FormatShort(INT_MIN), "-2147483648");
  EXPECT_EQ(FormatShort(INT_MAX), "2147483647");
  EXPECT_EQ(FormatShort(123456789012L), "123456789012");
  EXPECT_EQ(FormatShort(LLONG_MIN), "-9223372036854775808");
  EXPECT_EQ(FormatShort(LLONG_MAX), "9223372036854775807");
  EXPECT_EQ(FormatShort(4000000000u), "4000000000");
  EXPECT_EQ(FormatShort(ULLONG_MAX), "18446744073709551615");
  EXPECT_EQ(FormatShort(std::size_t{50000000}), "50000000");
  EXPECT_EQ(FormatShort(std::int64_t{-9007199254740993}), "-9007199254740993");  // not representable as a double
  EXPECT_EQ(FormatShort(std::uint32_t{4294967295u}), "4294967295");
  const short small = -12;
  EXPECT_EQ(FormatShort(small), "-12");  // promotes to int
}

}  // namespace
}  // namespace cairn
