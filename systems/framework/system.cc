#include "cairn/common/number_text.h"
#include "cairn/systems/framework/system.h"

#include <atomic>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/text_suggestions.h"
#include "cairn/systems/framework/event_dispatch.h"

namespace cairn::systems {
namespace {

int64_t NextSystemId() {
  static std::atomic<int64_t> next_id{1};
  return next_id.fetch_add(1, std::memory_order_relaxed);
}

template <typename Port>
const Port& FindPort(const std::vector<std::unique_ptr<Port>>& ports, const std::string& name, const char* direction,
                     const System& system) {
  // Found by name in per-step code too (a system's named port accessors): the search allocates nothing; only the
  // error message collects the names.
  for (const auto& port : ports) {
    if (port->get_name() == name) return *port;
  }
  std::vector<std::string> names;
  for (const auto& port : ports) names.push_back(port->get_name());
  std::string message = "System '" + system.GetPathName() + "' has no " + direction + " port named '" + name + "'";
  if (names.empty()) {
    message += "; it has no " + std::string(direction) + " ports.";
  } else {
    message += "; did you mean " + QuotedList(ClosestNames(name, names)) + "? It has " + QuotedList(names) + ".";
  }
  throw std::invalid_argument(message);
}

}  // namespace

System::System() : id_(NextSystemId()) {}

System::~System() = default;

void System::set_name(std::string name) {
  if (parent_ != nullptr) {
    throw std::logic_error("Cannot rename system '" + GetPathName() +
                           "': it belongs to a built diagram. Name systems before DiagramBuilder::Build().");
  }
  name_ = std::move(name);
}

std::string System::GetPathName() const {
  const std::string own = name_.empty() ? std::string("<unnamed>") : name_;
  return parent_ == nullptr ? own : parent_->GetPathName() + "::" + own;
}

const InputPort& System::get_input_port(int index) const {
  if (index < 0 || index >= num_input_ports()) {
    throw std::out_of_range("System '" + GetPathName() + "' has " + cairn::FormatShort(num_input_ports()) +
                            " input port(s); index " + cairn::FormatShort(index) + " is out of range.");
  }
  return *input_ports_[index];
}

const OutputPort& System::get_output_port(int index) const {
  if (index < 0 || index >= num_output_ports()) {
    throw std::out_of_range("System '" + GetPathName() + "' has " + cairn::FormatShort(num_output_ports()) +
                            " output port(s); index " + cairn::FormatShort(index) + " is out of range.");
  }
  return *output_ports_[index];
}

const InputPort& System::get_input_port() const {
  if (num_input_ports() != 1) {
    throw std::logic_error("get_input_port() without an index needs exactly one input port, but system '" +
                           GetPathName() + "' has " + cairn::FormatShort(num_input_ports()) +
                           "; pass an index or a name.");
  }
  return *input_ports_[0];
}

const OutputPort& System::get_output_port() const {
  if (num_output_ports() != 1) {
    throw std::logic_error("get_output_port() without an index needs exactly one output port, but system '" +
                           GetPathName() + "' has " + cairn::FormatShort(num_output_ports()) +
                           "; pass an index or a name.");
  }
  return *output_ports_[0];
}

const InputPort& System::GetInputPort(const std::string& name) const {
  return FindPort(input_ports_, name, "input", *this);
}

const OutputPort& System::GetOutputPort(const std::string& name) const {
  return FindPort(output_ports_, name, "output", *this);
}

bool System::HasInputPort(const std::string& name) const {
  for (const auto& port : input_ports_) {
    if (port->get_name() == name) return true;
  }
  return false;
}

bool System::HasOutputPort(const std::string& name) const {
  for (const auto& port : output_ports_) {
    if (port->get_name() == name) return true;
  }
  return false;
}

void System::CheckPortNameIsNew(const std::string& name, bool input) const {
  if (input ? HasInputPort(name) : HasOutputPort(name)) {
    throw std::logic_error("System '" + GetPathName() + "' already has an " + (input ? "input" : "output") +
                           " port named '" + name + "'; port names must be unique per direction.");
  }
}

InputPort& System::AddInputPort(std::string name, PortDataType data_type, int size,
                                std::unique_ptr<AbstractValue> model_value) {
  if (name.empty()) name = "u" + cairn::FormatShort(num_input_ports());
  CheckPortNameIsNew(name, true);
  input_ports_.push_back(std::unique_ptr<InputPort>(
      new InputPort(this, num_input_ports(), std::move(name), data_type, size, std::move(model_value), NewTicket())));
  return *input_ports_.back();
}

OutputPort& System::AddOutputPort(std::string name, PortDataType data_type, int size,
                                  std::unique_ptr<AbstractValue> model_value) {
  if (name.empty()) name = "y" + cairn::FormatShort(num_output_ports());
  CheckPortNameIsNew(name, false);
  output_ports_.push_back(std::unique_ptr<OutputPort>(
      new OutputPort(this, num_output_ports(), std::move(name), data_type, size, std::move(model_value))));
  return *output_ports_.back();
}

std::unique_ptr<Context> System::CreateDefaultContext() const { return DoAllocateContext(); }

void System::ValidateContext(const Context& context) const {
  if (context.system_id() == id_) return;
  throw std::logic_error("A Context created by system '" + context.system_path_name() +
                         "' was passed to system '" + GetPathName() + "'. Create one with " +
                         "CreateDefaultContext() on this system or, for a subsystem of a diagram, use "
                         "diagram.GetSubsystemContext(subsystem, diagram_context).");
}

void System::CalcTimeDerivatives(const Context& context, Eigen::VectorXd* derivatives) const {
  ValidateContext(context);
  if (derivatives == nullptr) throw std::invalid_argument("CalcTimeDerivatives: derivatives must not be null.");
  derivatives->resize(num_continuous_states());
  DoCalcTimeDerivatives(context, *derivatives);
}

bool System::HasDirectFeedthrough(int input, int output) const {
  get_input_port(input);
  get_output_port(output);
  return DoHasDirectFeedthrough(input, output);
}

bool System::HasAnyDirectFeedthrough() const {
  for (int i = 0; i < num_input_ports(); ++i) {
    for (int o = 0; o < num_output_ports(); ++o) {
      if (DoHasDirectFeedthrough(i, o)) return true;
    }
  }
  return false;
}

std::vector<LeafAndContext> System::CollectLeafSystems(Context* context) const {
  if (context == nullptr) throw std::invalid_argument("CollectLeafSystems: context must not be null.");
  ValidateContext(*context);
  std::vector<LeafAndContext> leaves;
  DoCollectLeafSystems(context, &leaves);
  return leaves;
}

void System::ForcedPublish(const Context& context) const {
  // Publishing reads the context only; the leaves' handlers receive it as const.
  const auto leaves = CollectLeafSystems(const_cast<Context*>(&context));
  std::vector<internal::TriggeredEvent> events;
  internal::CollectEvents(leaves, TriggerType::kForced, EventKind::kPublish, &events);
  const EventStatus status = internal::DispatchPublishes(events);
  if (status.failed()) throw std::runtime_error("A forced publish failed: " + status.message());
}

void System::ExecuteForcedEvents(Context* context) const {
  const EventStatus status = internal::ExecuteAll(CollectLeafSystems(context), TriggerType::kForced);
  if (status.failed()) throw std::runtime_error("A forced event failed: " + status.message());
}

namespace {

std::string EscapeLabel(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '{' || c == '}' || c == '|' || c == '<' || c == '>' || c == '"' || c == ' ') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

void System::DoGetGraphviz(std::string* dot, const std::string& indent) const {
  // A record node: inputs on the left, the name in the middle, outputs on the right.
  std::string inputs;
  for (int i = 0; i < num_input_ports(); ++i) {
    inputs += (i > 0 ? "|" : "") + std::string("<u") + cairn::FormatShort(i) + ">" + EscapeLabel(input_ports_[i]->get_name());
  }
  std::string outputs;
  for (int i = 0; i < num_output_ports(); ++i) {
    outputs += (i > 0 ? "|" : "") + std::string("<y") + cairn::FormatShort(i) + ">" +
               EscapeLabel(output_ports_[i]->get_name());
  }
  *dot += indent + "s" + cairn::FormatShort(id_) + " [shape=record, label=\"{{" + inputs + "}|" + EscapeLabel(name_) +
          "|{" + outputs + "}}\"];\n";
}

std::string System::GetGraphvizString() const {
  std::string dot = "digraph \"" + name_ + "\" {\n  rankdir=LR;\n";
  DoGetGraphviz(&dot, "  ");
  dot += "}\n";
  return dot;
}

}  // namespace cairn::systems
