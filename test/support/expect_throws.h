#pragma once

#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

/// Runs `statement`, expects it to throw `Exception` whose what() contains every one of the given substrings.
#define CAIRN_EXPECT_THROWS_WITH(statement, Exception, ...)                                  \
  do {                                                                                      \
    try {                                                                                   \
      statement;                                                                            \
      ADD_FAILURE() << "expected " #Exception " from " #statement;                          \
    } catch (const Exception& error) {                                                      \
      for (const std::string& part : std::initializer_list<std::string>{__VA_ARGS__}) {     \
        EXPECT_THAT(std::string(error.what()), ::testing::HasSubstr(part));                 \
      }                                                                                     \
    }                                                                                       \
  } while (0)
