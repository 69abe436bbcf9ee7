#include "cairn/common/number_text.h"
#include "cairn/systems/framework/diagram.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/cairn_assert.h"
#include "cairn/common/text_suggestions.h"

namespace cairn::systems {

Diagram::Diagram(Blueprint blueprint)
    : systems_(std::move(blueprint.systems)),
      connections_(std::move(blueprint.connections)),
      exported_inputs_(std::move(blueprint.exported_inputs)),
      exported_outputs_(std::move(blueprint.exported_outputs)),
      fixed_inputs_(std::move(blueprint.fixed_inputs)) {
  for (auto& system : systems_) {
    system->parent_ = this;
    system->owner_ = this;
  }
  for (std::size_t i = 0; i < exported_inputs_.size(); ++i) {
    const auto [s, p] = exported_inputs_[i].front();
    const InputPort& inner = systems_[s]->get_input_port(p);
    AddInputPort(blueprint.input_names[i], inner.get_data_type(), inner.size(), inner.model_value().Clone());
  }
  for (std::size_t i = 0; i < exported_outputs_.size(); ++i) {
    const auto [s, p] = exported_outputs_[i];
    const OutputPort& inner = systems_[s]->get_output_port(p);
    AddOutputPort(blueprint.output_names[i], inner.get_data_type(), inner.size(), inner.model_value().Clone());
  }
  for (const auto& system : systems_) {
    xc_offsets_.push_back(xc_size_);
    xc_size_ += system->num_continuous_states();
  }
  ComputeFeedthrough();
}

Diagram::~Diagram() = default;

void Diagram::ComputeFeedthrough() {
  // Which subsystem inputs each subsystem output feeds, to walk from a diagram input to the diagram outputs it
  // reaches in the same instant.
  std::map<PortLocator, std::vector<PortLocator>> fed_inputs;
  for (const auto& [input, output] : connections_) fed_inputs[output].push_back(input);
  std::map<PortLocator, std::vector<int>> exported_as;
  for (std::size_t o = 0; o < exported_outputs_.size(); ++o) exported_as[exported_outputs_[o]].push_back(o);

  feedthrough_.assign(exported_inputs_.size(), std::vector<bool>(exported_outputs_.size(), false));
  for (std::size_t i = 0; i < exported_inputs_.size(); ++i) {
    std::vector<PortLocator> frontier = exported_inputs_[i];
    std::map<PortLocator, bool> visited;
    while (!frontier.empty()) {
      const PortLocator input = frontier.back();
      frontier.pop_back();
      if (visited[input]) continue;
      visited[input] = true;
      const System& system = *systems_[input.first];
      for (int p = 0; p < system.num_output_ports(); ++p) {
        if (!system.DoHasDirectFeedthrough(input.second, p)) continue;
        const PortLocator output{input.first, p};
        for (int o : exported_as[output]) feedthrough_[i][o] = true;
        for (const PortLocator& next : fed_inputs[output]) frontier.push_back(next);
      }
    }
  }
}

std::vector<const System*> Diagram::GetSystems() const {
  std::vector<const System*> result;
  for (const auto& system : systems_) result.push_back(system.get());
  return result;
}

const System& Diagram::GetSubsystemByName(const std::string& name) const {
  std::vector<std::string> names;
  for (const auto& system : systems_) {
    if (system->get_name() == name) return *system;
    names.push_back(system->get_name());
  }
  throw std::invalid_argument("Diagram '" + GetPathName() + "' has no subsystem named '" + name + "'; did you mean " +
                              QuotedList(ClosestNames(name, names)) + "?");
}

int Diagram::IndexOf(const System& subsystem) const {
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    if (systems_[i].get() == &subsystem) return static_cast<int>(i);
  }
  return -1;
}

const Context& Diagram::GetSubsystemContext(const System& subsystem, const Context& context) const {
  ValidateContext(context);
  // Walk up from the subsystem to this diagram, then down through the matching subcontexts.
  std::vector<const System*> chain;
  for (const System* s = &subsystem; s != nullptr && s != this; s = s->parent_) chain.push_back(s);
  bool inside = !chain.empty() && chain.back()->parent_ == this;
  if (!inside) {
    throw std::invalid_argument("System '" + subsystem.GetPathName() + "' is not a subsystem of diagram '" +
                                GetPathName() + "'; pass the diagram that contains it.");
  }
  const Context* current = &context;
  const Diagram* diagram = this;
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const int index = diagram->IndexOf(**it);
    CAIRN_CHECK(index >= 0);
    current = current->children_[index].get();
    diagram = dynamic_cast<const Diagram*>(*it);
  }
  return *current;
}

Context& Diagram::GetMutableSubsystemContext(const System& subsystem, Context* context) const {
  if (context == nullptr) throw std::invalid_argument("GetMutableSubsystemContext: context must not be null.");
  return const_cast<Context&>(GetSubsystemContext(subsystem, *context));
}

std::unique_ptr<Context> Diagram::DoAllocateContext() const {
  std::unique_ptr<Context> context(new Context(this, num_tickets()));
  context->inputs_.resize(num_input_ports());
  for (int i = 0; i < num_input_ports(); ++i) {
    context->trackers_[internal::kAllInputPortsTicket].SubscribeTo(&context->trackers_[input_port_ticket(i).index()]);
  }
  for (const auto& system : systems_) {
    std::unique_ptr<Context> child = system->DoAllocateContext();
    child->parent_ = context.get();
    context->children_.push_back(std::move(child));
  }
  context->xc_size_ = xc_size_;
  context->child_xc_offsets_ = xc_offsets_;
  context->owned_xc_.resize(xc_size_);
  context->BindContinuousStorage(&context->owned_xc_, 0);
  WireSubcontexts(context.get());
  return context;
}

void Diagram::WireSubcontexts(Context* context) const {
  for (const auto& [input, output] : connections_) {
    Context& input_context = *context->children_[input.first];
    Context& output_context = *context->children_[output.first];
    const System& source = *systems_[output.first];
    Context::InputSlot& slot = input_context.inputs_[input.second];
    source.DoResolveOutput(output_context, output.second, &slot.source_system, &slot.source_context,
                           &slot.source_port);
    slot.source_description = "connected to the " + source.get_output_port(output.second).GetFullDescription();
    const int ticket = systems_[input.first]->get_input_port(input.second).ticket().index();
    input_context.trackers_[ticket].SubscribeTo(&source.DoGetOutputTracker(&output_context, output.second));
  }
  for (std::size_t i = 0; i < exported_inputs_.size(); ++i) {
    for (const auto& [s, p] : exported_inputs_[i]) {
      Context& child = *context->children_[s];
      child.inputs_[p].parent_port = static_cast<int>(i);
      child.inputs_[p].source_description =
          "exported as input '" + get_input_port(i).get_name() + "' of diagram '" + GetPathName() + "'";
      child.trackers_[systems_[s]->get_input_port(p).ticket().index()].SubscribeTo(
          &context->trackers_[input_port_ticket(i).index()]);
    }
  }
  for (const auto& [locator, value] : fixed_inputs_) {
    context->children_[locator.first]->inputs_[locator.second].fixed_value = value->Clone();
  }
}

const AbstractValue& Diagram::DoEvalOutput(const Context& context, int port) const {
  const auto [s, p] = exported_outputs_[port];
  return systems_[s]->DoEvalOutput(*context.children_[s], p);
}

void Diagram::DoCalcOutput(const Context& context, int port, AbstractValue* value) const {
  const auto [s, p] = exported_outputs_[port];
  systems_[s]->DoCalcOutput(*context.children_[s], p, value);
}

void Diagram::DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const {
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    const int n = systems_[i]->num_continuous_states();
    if (n == 0) continue;
    systems_[i]->DoCalcTimeDerivatives(*context.children_[i], derivatives.segment(xc_offsets_[i], n));
  }
}

void Diagram::DoCollectLeafSystems(Context* context, std::vector<LeafAndContext>* leaves) const {
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    systems_[i]->DoCollectLeafSystems(context->children_[i].get(), leaves);
  }
}

DependencyTracker& Diagram::DoGetOutputTracker(Context* context, int port) const {
  const auto [s, p] = exported_outputs_[port];
  return systems_[s]->DoGetOutputTracker(context->children_[s].get(), p);
}

void Diagram::DoResolveOutput(const Context& context, int port, const System** leaf, const Context** leaf_context,
                              int* leaf_port) const {
  const auto [s, p] = exported_outputs_[port];
  systems_[s]->DoResolveOutput(*context.children_[s], p, leaf, leaf_context, leaf_port);
}

std::string Diagram::GraphvizEndpoint(int system, int port, bool input) const {
  const System& s = *systems_[system];
  const std::string id = "s" + cairn::FormatShort(s.id());
  const std::string suffix = (input ? "u" : "y") + cairn::FormatShort(port);
  // Leaves are record nodes with port fields; diagrams are clusters with a small node per exported port.
  if (dynamic_cast<const Diagram*>(&s) != nullptr) return id + "_" + suffix;
  return id + ":" + suffix;
}

void Diagram::DoGetGraphviz(std::string* dot, const std::string& indent) const {
  const std::string id = "s" + cairn::FormatShort(this->id());
  *dot += indent + "subgraph cluster_" + id + " {\n";
  const std::string inner = indent + "  ";
  *dot += inner + "label=\"" + get_name() + "\";\n";
  for (int i = 0; i < num_input_ports(); ++i) {
    *dot += inner + id + "_u" + cairn::FormatShort(i) + " [shape=cds, label=\"" + get_input_port(i).get_name() + "\"];\n";
  }
  for (int i = 0; i < num_output_ports(); ++i) {
    *dot += inner + id + "_y" + cairn::FormatShort(i) + " [shape=cds, label=\"" + get_output_port(i).get_name() +
            "\"];\n";
  }
  for (const auto& system : systems_) system->DoGetGraphviz(dot, inner);
  for (const auto& [input, output] : connections_) {
    *dot += inner + GraphvizEndpoint(output.first, output.second, false) + " -> " +
            GraphvizEndpoint(input.first, input.second, true) + ";\n";
  }
  for (std::size_t i = 0; i < exported_inputs_.size(); ++i) {
    for (const auto& [s, p] : exported_inputs_[i]) {
      *dot += inner + id + "_u" + cairn::FormatShort(i) + " -> " + GraphvizEndpoint(s, p, true) + ";\n";
    }
  }
  for (std::size_t i = 0; i < exported_outputs_.size(); ++i) {
    *dot += inner + GraphvizEndpoint(exported_outputs_[i].first, exported_outputs_[i].second, false) + " -> " + id +
            "_y" + cairn::FormatShort(i) + ";\n";
  }
  *dot += indent + "}\n";
}

}  // namespace cairn::systems
