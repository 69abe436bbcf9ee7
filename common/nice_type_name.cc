#include "cairn/common/nice_type_name.h"

#include <cxxabi.h>

#include <cstdlib>
#include <memory>
#include <utility>

namespace cairn {
namespace {

void ReplaceAll(std::string* text, const std::string& from, const std::string& to) {
  for (std::size_t pos = text->find(from); pos != std::string::npos; pos = text->find(from, pos + to.size())) {
    text->replace(pos, from.size(), to);
  }
}

}  // namespace

std::string NiceTypeName(const std::type_info& info) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> demangled(abi::__cxa_demangle(info.name(), nullptr, nullptr, &status),
                                                   std::free);
  std::string name = (status == 0 && demangled) ? demangled.get() : info.name();
  // Spell the types users write, not what the compiler expands them to.
  const std::pair<const char*, const char*> kAliases[] = {
      {"Eigen::Matrix<double, -1, 1, 0, -1, 1>", "Eigen::VectorXd"},
      {"Eigen::Matrix<double, -1, -1, 0, -1, -1>", "Eigen::MatrixXd"},
      {"std::__cxx11::basic_string<char, std::char_traits<char>, std::allocator<char> >", "std::string"},
      {"std::__cxx11::", "std::"},
  };
  for (const auto& [from, to] : kAliases) ReplaceAll(&name, from, to);
  return name;
}

}  // namespace cairn
