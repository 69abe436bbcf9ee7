#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

namespace cairn::optimization {

/// Options for solvers, keyed by solver ("ipopt", "nlopt", "least_squares") and then by option name.
///
/// One SolverOptions may configure several solvers; each solver reads its own key and rejects option names it
/// does not know (with the closest valid names), and Solver::Solve rejects keys that name no solver, so a typo
/// is an error rather than a silently ignored setting. Values are typed: integers, numbers or strings; an
/// integer is accepted where a number is expected.
class SolverOptions {
 public:
  /// An option value.
  using Value = std::variant<int, double, std::string>;
  /// The options of one solver.
  using OptionMap = std::map<std::string, Value>;

  /// Sets an integer option.
  void Set(const std::string& solver, const std::string& option, int value);
  /// Sets a numeric option; throws std::invalid_argument for NaN (infinities are passed on: some options take
  /// them, and each solver checks the range of its own).
  void Set(const std::string& solver, const std::string& option, double value);
  /// Sets a string option.
  void Set(const std::string& solver, const std::string& option, const std::string& value);
  /// Sets a string option (so that string literals do not decay to bool or int).
  void Set(const std::string& solver, const std::string& option, const char* value);

  /// The options of `solver` (empty if none were set).
  const OptionMap& Get(const std::string& solver) const;

  /// Solver keys with at least one option, sorted.
  std::vector<std::string> solver_keys() const;

  /// Renders a value for messages: 3, 1e-08, 'yes'.
  static std::string ToString(const Value& value);

 private:
  std::map<std::string, OptionMap> options_;
};

}  // namespace cairn::optimization
