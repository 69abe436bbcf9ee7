#pragma once

#include <exception>
#include <initializer_list>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

/// The one throws-with-message check of Cairn's tests: runs `statement`, expects it to throw `Exception` whose
/// what() contains every one of the given substrings. A statement that throws nothing, or throws an exception of
/// another type (named with its what()), is a test failure and the test goes on. Wrap a statement whose commas are
/// not inside parentheses (a braced list, a template argument list) in parentheses, or in a lambda called at once.
#define CAIRN_EXPECT_THROWS_WITH(statement, Exception, ...)                                          \
  do {                                                                                              \
    try {                                                                                           \
      statement;                                                                                    \
      ADD_FAILURE() << "expected " #Exception " from " #statement;                                  \
    } catch (const Exception& error) {                                                              \
      for (const std::string& part : std::initializer_list<std::string>{__VA_ARGS__}) {             \
        EXPECT_THAT(std::string(error.what()), ::testing::HasSubstr(part));                         \
      }                                                                                             \
    } catch (...) {                                                                                 \
      try {                                                                                         \
        throw;                                                                                      \
      } catch (const std::exception& other) {                                                       \
        ADD_FAILURE() << "expected " #Exception " from " #statement ", got another exception: "     \
                      << other.what();                                                              \
      } catch (...) {                                                                               \
        ADD_FAILURE() << "expected " #Exception " from " #statement ", got a non-standard exception"; \
      }                                                                                             \
    }                                                                                               \
  } while (0)
