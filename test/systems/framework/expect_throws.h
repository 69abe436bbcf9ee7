#pragma once

#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

/// Expects `statement` to throw `exception_type` whose what() contains every one of the given substrings.
#define CAIRN_EXPECT_THROWS_WITH(statement, exception_type, ...)                         \
  do {                                                                                   \
    try {                                                                                \
      statement;                                                                         \
      ADD_FAILURE() << "Expected " #statement " to throw " #exception_type;              \
    } catch (const exception_type& cairn_caught) {                                       \
      for (const std::string& cairn_part : {__VA_ARGS__}) {                              \
        EXPECT_THAT(std::string(cairn_caught.what()), ::testing::HasSubstr(cairn_part)); \
      }                                                                                  \
    }                                                                                    \
  } while (0)
