#include "choice_option.h"

#include <algorithm>

#include "cairn/common/text_suggestions.h"
#include "usage_error.h"

namespace cairn::cli {

void CheckChoice(const std::string& option, const std::string& text, const std::vector<std::string>& choices) {
  if (std::find(choices.begin(), choices.end(), text) != choices.end()) return;
  std::string message = option + " '" + text + "' is not one of " + QuotedList(choices);
  const std::vector<std::string> closest = ClosestNames(text, choices, 1);
  if (!closest.empty() && EditDistance(text, closest.front()) <= std::max<int>(2, static_cast<int>(text.size()) / 3)) {
    message += "; did you mean '" + closest.front() + "'?";
  }
  throw UsageError(message);
}

CLI::Option* AddChoiceOption(CLI::App& app, const std::string& name, std::string* value,
                             const std::string& description, const std::vector<std::string>& choices) {
  std::string names;
  for (const std::string& choice : choices) names += (names.empty() ? "" : ", ") + choice;
  CLI::Option* option = app.add_option_function<std::string>(
      name,
      [value, name, choices](const std::string& text) {
        CheckChoice(name, text, choices);
        *value = text;
      },
      description + "; one of " + names);
  option->type_name("TEXT");
  if (!value->empty()) option->default_str(*value);
  return option;
}

}  // namespace cairn::cli
