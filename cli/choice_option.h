#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace cairn::cli {

/// Checks that `text`, given for `option`, is one of `choices`; throws UsageError (exit 2) otherwise, listing the
/// choices and suggesting the closest ("--model 'merel' is not one of 'matthies', 'merrell', ...; did you mean
/// 'merrell'?").
void CheckChoice(const std::string& option, const std::string& text, const std::vector<std::string>& choices);

/// Declares the option `name` on `app` whose value must be one of `choices` (checked with CheckChoice), stored in
/// `*value` when given. --help lists the choices and shows the default.
CLI::Option* AddChoiceOption(CLI::App& app, const std::string& name, std::string* value,
                             const std::string& description, const std::vector<std::string>& choices);

}  // namespace cairn::cli
