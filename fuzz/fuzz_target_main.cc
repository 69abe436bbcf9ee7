// The libFuzzer entry point, compiled once per target with CAIRN_FUZZ_ENTRY naming its harness (fuzz_harnesses.h).
// A std::exception is the parser refusing the input, which is what it should do; everything else reaches libFuzzer.

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "fuzz_harnesses.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    cairn::fuzz::CAIRN_FUZZ_ENTRY(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const std::exception&) {
  }
  return 0;
}
