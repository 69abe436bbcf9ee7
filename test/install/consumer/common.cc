// Cairn::common: the version header and the helpers behind Cairn's error messages.
#include <cstdio>
#include <string>
#include <vector>

#include <cairn/common/nice_type_name.h>
#include <cairn/common/text_suggestions.h>
#include <cairn/version.h>

int main() {
  const std::string type = cairn::NiceTypeName<std::vector<int>>();
  const std::vector<std::string> closest = cairn::ClosestNames("integratr", {"gain", "integrator", "adder"}, 1);
  std::printf("consumer common: Cairn %s, %s, did you mean %s\n", CAIRN_VERSION_STRING, type.c_str(),
              closest.empty() ? "(nothing)" : closest[0].c_str());
  return closest.size() == 1 && closest[0] == "integrator" ? 0 : 1;
}
