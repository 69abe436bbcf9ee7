#include "cairn/common/cairn_assert.h"
#include "cairn/common/number_text.h"

#include <stdexcept>
#include <string>

namespace cairn::internal {

void AssertionFailed(const char* condition, const char* function, const char* file, int line) {
  throw std::logic_error(std::string("Cairn internal check failed: '") + condition + "' in " + function + "() at " +
                         file + ":" + cairn::FormatShort(line) + ". This is a bug in Cairn; please report it.");
}

}  // namespace cairn::internal
