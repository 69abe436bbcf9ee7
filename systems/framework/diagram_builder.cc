#include "cairn/common/number_text.h"
#include "cairn/systems/framework/diagram_builder.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "cairn/common/nice_type_name.h"
#include "cairn/common/text_suggestions.h"

namespace cairn::systems {
namespace {

// "cairn::systems::PassThrough" -> "pass_through".
std::string SnakeCaseTypeName(const System& system) {
  std::string name = NiceTypeName(typeid(system));
  const auto template_start = name.find('<');
  if (template_start != std::string::npos) name.resize(template_start);
  const auto scope = name.rfind("::");
  if (scope != std::string::npos) name = name.substr(scope + 2);
  std::string snake;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (std::isupper(c)) {
      if (i > 0) snake += '_';
      snake += static_cast<char>(std::tolower(c));
    } else {
      snake += static_cast<char>(c);
    }
  }
  return snake;
}

bool SameKind(const InputPort& input, const OutputPort& output) {
  if (input.get_data_type() != output.get_data_type()) return false;
  if (input.get_data_type() == PortDataType::kVector) return input.size() == output.size();
  return input.model_value().type_info() == output.model_value().type_info();
}

}  // namespace

DiagramBuilder::DiagramBuilder() = default;

DiagramBuilder::~DiagramBuilder() = default;

void DiagramBuilder::ThrowIfBuilt(const char* operation) const {
  if (built_) {
    throw std::logic_error(std::string("DiagramBuilder::") + operation +
                           "() after Build(): a builder makes one diagram; use a new DiagramBuilder.");
  }
}

std::string DiagramBuilder::UniqueName(const System& system) const {
  const std::string base = SnakeCaseTypeName(system);
  for (int k = 0;; ++k) {
    const std::string candidate = base + "_" + cairn::FormatShort(k);
    bool taken = false;
    for (const auto& other : systems_) taken = taken || other->get_name() == candidate;
    if (!taken) return candidate;
  }
}

void DiagramBuilder::AddSystemImpl(std::unique_ptr<System> system) {
  if (system == nullptr) throw std::invalid_argument("DiagramBuilder::AddSystem: the system is null.");
  if (system->owner_ != nullptr) {
    const std::string name = system->GetPathName();
    // Another builder or diagram owns this object; giving up our unique_ptr without deleting keeps its owner
    // valid.
    static_cast<void>(system.release());
    throw std::logic_error("System '" + name +
                           "' already belongs to another DiagramBuilder or Diagram; a system can be added to one "
                           "builder only. Create a separate instance for each diagram.");
  }
  ThrowIfBuilt("AddSystem");
  if (system->get_name().empty()) system->set_name(UniqueName(*system));
  system->owner_ = this;
  systems_.push_back(std::move(system));
}

std::vector<const System*> DiagramBuilder::GetSystems() const {
  std::vector<const System*> result;
  for (const auto& system : systems_) result.push_back(system.get());
  return result;
}

int DiagramBuilder::IndexOf(const System& system, const char* operation) const {
  for (std::size_t i = 0; i < systems_.size(); ++i) {
    if (systems_[i].get() == &system) return static_cast<int>(i);
  }
  throw std::logic_error(std::string("DiagramBuilder::") + operation + "(): system '" + system.GetPathName() +
                         "' has not been added to this builder; call AddSystem() first.");
}

DiagramBuilder::PortLocator DiagramBuilder::Locate(const InputPort& input, const char* operation) const {
  return {IndexOf(input.get_system(), operation), input.get_index()};
}

DiagramBuilder::PortLocator DiagramBuilder::Locate(const OutputPort& output, const char* operation) const {
  return {IndexOf(output.get_system(), operation), output.get_index()};
}

void DiagramBuilder::ThrowIfInputTaken(const InputPort& input) const {
  const PortLocator locator = Locate(input, "Connect");
  const auto connection = connections_.find(locator);
  if (connection != connections_.end()) {
    throw std::logic_error("The " + input.GetFullDescription() + " is already connected to the " +
                           systems_[connection->second.first]->get_output_port(connection->second.second)
                               .GetFullDescription() +
                           "; an input port takes one source. Add an Adder to combine signals.");
  }
  for (std::size_t i = 0; i < exported_inputs_.size(); ++i) {
    for (const auto& exported : exported_inputs_[i]) {
      if (exported == locator) {
        throw std::logic_error("The " + input.GetFullDescription() + " is already exported as diagram input '" +
                               input_names_[i] + "'; an input port takes one source.");
      }
    }
  }
  for (const auto& [fixed, value] : fixed_inputs_) {
    if (fixed == locator) {
      throw std::logic_error("The " + input.GetFullDescription() +
                             " already has a fixed value (FixInput); an input port takes one source.");
    }
  }
}

void DiagramBuilder::Connect(const OutputPort& source, const InputPort& destination) {
  ThrowIfBuilt("Connect");
  const PortLocator output = Locate(source, "Connect");
  const PortLocator input = Locate(destination, "Connect");
  if (!SameKind(destination, source)) {
    throw std::logic_error("Cannot connect the " + source.GetFullDescription() + " (" + source.GetTypeDescription() +
                           ") to the " + destination.GetFullDescription() + " (" +
                           destination.GetTypeDescription() + "): the ports carry different types.");
  }
  ThrowIfInputTaken(destination);
  connections_[input] = output;
}

void DiagramBuilder::Connect(const System& source, const System& destination) {
  Connect(source.get_output_port(), destination.get_input_port());
}

int DiagramBuilder::ExportInput(const InputPort& input, const std::string& name) {
  ThrowIfBuilt("ExportInput");
  const PortLocator locator = Locate(input, "ExportInput");
  ThrowIfInputTaken(input);
  const std::string port_name = name.empty() ? input.get_system().get_name() + "_" + input.get_name() : name;
  if (std::find(input_names_.begin(), input_names_.end(), port_name) != input_names_.end()) {
    throw std::logic_error("The diagram already has an input named '" + port_name +
                           "'; to feed another subsystem input from it, use ConnectInput('" + port_name +
                           "', port).");
  }
  input_names_.push_back(port_name);
  exported_inputs_.push_back({locator});
  return static_cast<int>(exported_inputs_.size()) - 1;
}

void DiagramBuilder::ConnectInput(int diagram_input, const InputPort& input) {
  ThrowIfBuilt("ConnectInput");
  if (diagram_input < 0 || diagram_input >= static_cast<int>(exported_inputs_.size())) {
    throw std::out_of_range("ConnectInput: the diagram has " + cairn::FormatShort(exported_inputs_.size()) +
                            " exported input(s); index " + cairn::FormatShort(diagram_input) + " is out of range.");
  }
  const PortLocator locator = Locate(input, "ConnectInput");
  const PortLocator first = exported_inputs_[diagram_input].front();
  const InputPort& model = systems_[first.first]->get_input_port(first.second);
  if (model.get_data_type() != input.get_data_type() || model.size() != input.size() ||
      model.model_value().type_info() != input.model_value().type_info()) {
    throw std::logic_error("Cannot feed the " + input.GetFullDescription() + " (" + input.GetTypeDescription() +
                           ") from diagram input '" + input_names_[diagram_input] + "' (" +
                           model.GetTypeDescription() + "): the ports carry different types.");
  }
  ThrowIfInputTaken(input);
  exported_inputs_[diagram_input].push_back(locator);
}

void DiagramBuilder::ConnectInput(const std::string& diagram_input_name, const InputPort& input) {
  const auto it = std::find(input_names_.begin(), input_names_.end(), diagram_input_name);
  if (it == input_names_.end()) {
    throw std::invalid_argument("ConnectInput: the diagram has no exported input named '" + diagram_input_name +
                                "'; it has " + QuotedList(input_names_) + ". Export one with ExportInput() first.");
  }
  ConnectInput(static_cast<int>(it - input_names_.begin()), input);
}

int DiagramBuilder::ExportOutput(const OutputPort& output, const std::string& name) {
  ThrowIfBuilt("ExportOutput");
  const PortLocator locator = Locate(output, "ExportOutput");
  const std::string port_name = name.empty() ? output.get_system().get_name() + "_" + output.get_name() : name;
  if (std::find(output_names_.begin(), output_names_.end(), port_name) != output_names_.end()) {
    throw std::logic_error("The diagram already has an output named '" + port_name + "'; choose another name.");
  }
  output_names_.push_back(port_name);
  exported_outputs_.push_back(locator);
  return static_cast<int>(exported_outputs_.size()) - 1;
}

void DiagramBuilder::FixInputValue(const InputPort& input, const AbstractValue& value) {
  ThrowIfBuilt("FixInput");
  const PortLocator locator = Locate(input, "FixInput");
  input.ValidateValue(value);
  ThrowIfInputTaken(input);
  fixed_inputs_.emplace_back(locator, value.Clone());
}

bool DiagramBuilder::IsConnectedOrExported(const InputPort& input) const {
  const PortLocator locator = Locate(input, "IsConnectedOrExported");
  if (connections_.count(locator) > 0) return true;
  for (const auto& exported : exported_inputs_) {
    if (std::find(exported.begin(), exported.end(), locator) != exported.end()) return true;
  }
  for (const auto& [fixed, value] : fixed_inputs_) {
    if (fixed == locator) return true;
  }
  return false;
}

std::string DiagramBuilder::PortLabel(PortLocator locator, bool input) const {
  const System& system = *systems_[locator.first];
  return system.get_name() + "." +
         (input ? system.get_input_port(locator.second).get_name() : system.get_output_port(locator.second).get_name());
}

void DiagramBuilder::CheckUniqueNames() const {
  std::set<std::string> seen;
  for (const auto& system : systems_) {
    if (!seen.insert(system->get_name()).second) {
      throw std::logic_error("Two systems in the diagram are named '" + system->get_name() +
                             "'; give each a unique name (set_name() or AddNamedSystem()) before Build().");
    }
  }
}

void DiagramBuilder::CheckAllInputsHaveValues() const {
  std::vector<std::string> missing;
  for (std::size_t s = 0; s < systems_.size(); ++s) {
    for (int p = 0; p < systems_[s]->num_input_ports(); ++p) {
      if (!IsConnectedOrExported(systems_[s]->get_input_port(p))) {
        missing.push_back(PortLabel({static_cast<int>(s), p}, true));
      }
    }
  }
  if (missing.empty()) return;
  throw std::logic_error("The diagram has input ports with no source: " + QuotedList(missing) +
                         ". Connect each (Connect), export it as a diagram input (ExportInput), or give it a "
                         "constant value (FixInput).");
}

void DiagramBuilder::CheckNoAlgebraicLoops() const {
  // Nodes are ports; edges run from an output to the inputs it is connected to, and from an input to the outputs
  // of the same system that depend on it directly. A cycle is an algebraic loop.
  struct Node {
    PortLocator locator;
    bool input;
    bool operator<(const Node& other) const {
      return std::tie(locator, input) < std::tie(other.locator, other.input);
    }
  };
  std::map<PortLocator, std::vector<PortLocator>> fed_inputs;
  for (const auto& [input, output] : connections_) fed_inputs[output].push_back(input);
  auto successors = [&](const Node& node) {
    std::vector<Node> next;
    if (node.input) {
      const System& system = *systems_[node.locator.first];
      for (int p = 0; p < system.num_output_ports(); ++p) {
        if (system.DoHasDirectFeedthrough(node.locator.second, p)) next.push_back({{node.locator.first, p}, false});
      }
    } else {
      const auto it = fed_inputs.find(node.locator);
      if (it != fed_inputs.end()) {
        for (const PortLocator& input : it->second) next.push_back({input, true});
      }
    }
    return next;
  };

  enum class Mark { kUnvisited, kOnPath, kDone };
  std::map<Node, Mark> marks;
  std::vector<Node> path;
  std::function<bool(const Node&)> visit = [&](const Node& node) -> bool {
    marks[node] = Mark::kOnPath;
    path.push_back(node);
    for (const Node& next : successors(node)) {
      const Mark mark = marks.count(next) ? marks[next] : Mark::kUnvisited;
      if (mark == Mark::kOnPath) {
        path.push_back(next);
        return true;
      }
      if (mark == Mark::kUnvisited && visit(next)) return true;
    }
    path.pop_back();
    marks[node] = Mark::kDone;
    return false;
  };
  for (std::size_t s = 0; s < systems_.size(); ++s) {
    for (int p = 0; p < systems_[s]->num_output_ports(); ++p) {
      const Node start{{static_cast<int>(s), p}, false};
      if (marks.count(start) || !visit(start)) continue;
      // path = [..., loop start, ..., loop start]; print from the first occurrence of the repeated node.
      const Node repeated = path.back();
      auto first = std::find_if(path.begin(), path.end(), [&](const Node& n) {
        return !(n < repeated) && !(repeated < n);
      });
      std::string loop;
      for (auto it = first; it != path.end(); ++it) {
        loop += (it == first ? "" : " -> ") + PortLabel(it->locator, it->input);
      }
      throw std::logic_error("The diagram has an algebraic loop: " + loop +
                             ". Break it with a system that has no direct feedthrough, e.g. a ZeroOrderHold on one "
                             "of these connections, or declare narrower prerequisites for an output that does not "
                             "depend on its input.");
    }
  }
}

std::unique_ptr<Diagram> DiagramBuilder::Build() {
  ThrowIfBuilt("Build");
  if (systems_.empty()) throw std::logic_error("DiagramBuilder::Build(): no systems were added.");
  CheckUniqueNames();
  CheckAllInputsHaveValues();
  CheckNoAlgebraicLoops();
  built_ = true;
  Diagram::Blueprint blueprint;
  blueprint.systems = std::move(systems_);
  blueprint.connections = std::move(connections_);
  blueprint.input_names = std::move(input_names_);
  blueprint.exported_inputs = std::move(exported_inputs_);
  blueprint.output_names = std::move(output_names_);
  blueprint.exported_outputs = std::move(exported_outputs_);
  blueprint.fixed_inputs = std::move(fixed_inputs_);
  std::unique_ptr<Diagram> diagram(new Diagram(std::move(blueprint)));
  diagram->set_name("diagram");
  return diagram;
}

}  // namespace cairn::systems
