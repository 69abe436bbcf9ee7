#include "usage_message.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include "cairn/common/text_suggestions.h"

namespace cairn::cli {
namespace {

// The long names of `app`'s options, with their dashes ("--duration").
std::vector<std::string> OptionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

std::string DidYouMean(const std::string& given, const std::vector<std::string>& candidates) {
  const std::vector<std::string> closest = ClosestNames(given, candidates, 1);
  if (closest.empty() || EditDistance(given, closest.front()) > std::max<int>(2, static_cast<int>(given.size()) / 3)) {
    return "";
  }
  return "; did you mean '" + closest.front() + "'?";
}

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// "NAME: rest" -> NAME (CLI11 starts most option messages with the option's name and a colon).
std::string LeadingName(const std::string& message) { return message.substr(0, message.find(':')); }

}  // namespace

std::string UsageMessage(const CLI::ParseError& error, const CLI::App& app) {
  const std::string message = error.what();
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr) {
    if (message.find(": At Most ") != std::string::npos) {
      for (const CLI::Option* option : app.get_options()) {
        if (option->count() > 1) {
          return option->get_name() + " is given " + std::to_string(option->count()) + " times; give it once";
        }
      }
      return LeadingName(message) + " is given more than once; give it once";
    }
    if (EndsWith(message, " missing")) return LeadingName(message) + " needs a value";
  }
  if (dynamic_cast<const CLI::ExtrasError*>(&error) != nullptr) {
    // CLI11 lists the extras in no useful order ("3 --duraton" for "--duraton 3"): an unknown option explains the
    // stray value after it, so name it first.
    const std::size_t colon = message.find(": ");
    std::istringstream extras(colon == std::string::npos ? message : message.substr(colon + 2));
    std::string first, word;
    while (extras >> word) {
      if (word.size() > 1 && word[0] == '-' && !(word[1] >= '0' && word[1] <= '9') && word[1] != '.') {
        const std::string flag = word.substr(0, word.find('='));
        return "unknown option '" + flag + "'" + DidYouMean(flag, OptionNames(app));
      }
      if (first.empty()) first = word;
    }
    return "unexpected argument '" + first + "'";
  }
  if (dynamic_cast<const CLI::ConversionError*>(&error) != nullptr) {
    // "Could not convert: --json = abc": every option but the flags is parsed by Cairn's own declarations.
    const std::string prefix = "Could not convert: ";
    if (message.compare(0, prefix.size(), prefix) == 0) {
      const std::string rest = message.substr(prefix.size());
      const std::size_t equals = rest.find(" = ");
      if (equals != std::string::npos) {
        return rest.substr(0, equals) + " is a flag and takes no value; got '" + rest.substr(equals + 3) + "'";
      }
    }
    if (message.find(": too many inputs for a flag") != std::string::npos) {
      return LeadingName(message) + " is a flag and takes no value";
    }
  }
  return message;
}

}  // namespace cairn::cli
