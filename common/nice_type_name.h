#pragma once

#include <string>
#include <typeinfo>

namespace cairn {

/// Returns the demangled, human-readable name of a type, for error messages
/// (e.g. "Eigen::Matrix<double, -1, 1, 0, -1, 1>" becomes "Eigen::VectorXd").
std::string NiceTypeName(const std::type_info& info);

/// Returns NiceTypeName(typeid(T)).
template <typename T>
std::string NiceTypeName() {
  return NiceTypeName(typeid(T));
}

}  // namespace cairn
