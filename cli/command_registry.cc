#include "command_registry.h"

#include <stdexcept>
#include <utility>

namespace cairn::cli {

void CommandRegistry::Add(const std::string& name, const std::string& summary, Setup setup) {
  for (const Entry& entry : entries_) {
    if (entry.name == name) throw std::logic_error("cairn subcommand '" + name + "' is registered twice.");
  }
  entries_.push_back(Entry{name, summary, std::move(setup)});
}

std::vector<CommandRegistry::Bound> CommandRegistry::BindTo(CLI::App& app) const {
  std::vector<Bound> bound;
  bound.reserve(entries_.size());
  for (const Entry& entry : entries_) {
    CLI::App* sub = app.add_subcommand(entry.name, entry.summary);
    bound.push_back(Bound{sub, entry.setup(*sub)});
  }
  return bound;
}

std::vector<std::string> CommandRegistry::names() const {
  std::vector<std::string> result;
  for (const Entry& entry : entries_) result.push_back(entry.name);
  return result;
}

}  // namespace cairn::cli
