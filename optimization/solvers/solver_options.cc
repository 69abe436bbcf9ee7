#include "cairn/optimization/solvers/solver_options.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "cairn/common/number_text.h"

namespace cairn::optimization {

namespace {

void CheckNames(const std::string& solver, const std::string& option) {
  if (solver.empty() || option.empty()) {
    throw std::invalid_argument("SolverOptions::Set('" + solver + "', '" + option +
                                "'): both the solver key (e.g. 'ipopt') and the option name must be non-empty.");
  }
}

}  // namespace

void SolverOptions::Set(const std::string& solver, const std::string& option, int value) {
  CheckNames(solver, option);
  options_[solver][option] = value;
}

void SolverOptions::Set(const std::string& solver, const std::string& option, double value) {
  CheckNames(solver, option);
  if (std::isnan(value)) {
    throw std::invalid_argument("SolverOptions::Set('" + solver + "', '" + option +
                                "'): the value is NaN, which no option accepts; give a number.");
  }
  options_[solver][option] = value;
}

void SolverOptions::Set(const std::string& solver, const std::string& option, const std::string& value) {
  CheckNames(solver, option);
  options_[solver][option] = value;
}

void SolverOptions::Set(const std::string& solver, const std::string& option, const char* value) {
  Set(solver, option, std::string(value == nullptr ? "" : value));
}

const SolverOptions::OptionMap& SolverOptions::Get(const std::string& solver) const {
  static const OptionMap kEmpty;
  const auto it = options_.find(solver);
  return it == options_.end() ? kEmpty : it->second;
}

std::vector<std::string> SolverOptions::solver_keys() const {
  std::vector<std::string> keys;
  for (const auto& entry : options_) keys.push_back(entry.first);
  return keys;
}

std::string SolverOptions::ToString(const Value& value) {
  std::ostringstream out;
  if (const int* i = std::get_if<int>(&value)) {
    out << *i;
  } else if (const double* d = std::get_if<double>(&value)) {
    out << FormatShort(*d);
  } else {
    out << "'" << std::get<std::string>(value) << "'";
  }
  return out.str();
}

}  // namespace cairn::optimization
