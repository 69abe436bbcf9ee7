#pragma once

#include <string>

#include <gtest/gtest.h>

namespace cairn::optimization::test {

/// Runs `f`, expects it to throw `Exception`, and returns what(); records a test failure (and returns "") if it
/// throws nothing or something else, so EXPECT_THAT(MessageOf<...>(...), HasSubstr(...)) cannot pass vacuously.
template <typename Exception, typename F>
std::string MessageOf(F&& f) {
  try {
    f();
  } catch (const Exception& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw a different exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "did not throw";
  return "";
}

}  // namespace cairn::optimization::test
