#pragma once

#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "cairn/systems/framework/diagram.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems {

/// Assembles a Diagram: add systems, connect outputs to inputs, export the diagram's own ports, Build().
///
/// Mistakes are reported where they are made when possible (connecting mismatched ports, connecting an input
/// twice, adding a system that another builder owns) and otherwise by Build(): duplicate names, inputs that are
/// neither connected, exported nor fixed (all listed), and algebraic loops (printed as `a.y -> b.u -> ...`).
///
/// @code
///   DiagramBuilder builder;
///   auto* source = builder.AddSystem<ConstantVectorSource>(Eigen::Vector3d(1, 2, 3));
///   auto* gain = builder.AddNamedSystem<Gain>("gain", 2.0, 3);
///   builder.Connect(source->get_output_port(), gain->get_input_port());
///   builder.ExportOutput(gain->get_output_port(), "y");
///   std::unique_ptr<Diagram> diagram = builder.Build();
/// @endcode
class DiagramBuilder {
 public:
  DiagramBuilder();
  ~DiagramBuilder();
  DiagramBuilder(const DiagramBuilder&) = delete;
  DiagramBuilder& operator=(const DiagramBuilder&) = delete;

  /// Takes ownership of `system` and returns it. A system without a name gets a unique one from its type.
  /// Throws if the system already belongs to another builder or diagram.
  template <class S>
  S* AddSystem(std::unique_ptr<S> system) {
    static_assert(std::is_base_of_v<System, S>, "AddSystem needs a System.");
    S* raw = system.get();
    AddSystemImpl(std::unique_ptr<System>(system.release()));
    return raw;
  }
  /// Constructs an S from `args` and adds it.
  template <class S, typename... Args>
  S* AddSystem(Args&&... args) {
    return AddSystem(std::make_unique<S>(std::forward<Args>(args)...));
  }
  /// As AddSystem(), naming the system.
  template <class S>
  S* AddNamedSystem(const std::string& name, std::unique_ptr<S> system) {
    system->set_name(name);
    return AddSystem(std::move(system));
  }
  template <class S, typename... Args>
  S* AddNamedSystem(const std::string& name, Args&&... args) {
    return AddNamedSystem(name, std::make_unique<S>(std::forward<Args>(args)...));
  }

  /// Connects `source` to `destination`. Both systems must have been added; the ports must carry the same kind
  /// of value (vector sizes or abstract types equal); an input takes one source.
  void Connect(const OutputPort& source, const InputPort& destination);
  /// Connects the only output of `source` to the only input of `destination`.
  void Connect(const System& source, const System& destination);

  /// Makes `input` an input port of the diagram named `name` (default "<system>_<port>"); returns its index.
  int ExportInput(const InputPort& input, const std::string& name = "");
  /// Feeds one more subsystem input from an already exported diagram input.
  void ConnectInput(int diagram_input, const InputPort& input);
  void ConnectInput(const std::string& diagram_input_name, const InputPort& input);
  /// Makes `output` an output port of the diagram named `name` (default "<system>_<port>"); returns its index.
  int ExportOutput(const OutputPort& output, const std::string& name = "");

  /// Gives `input` a constant value in every context of the built diagram (for inputs a diagram does not
  /// drive); the value can still be changed per context with InputPort::FixValue.
  template <typename T>
  void FixInput(const InputPort& input, const T& value) {
    if constexpr (std::is_base_of_v<Eigen::EigenBase<T>, T>) {
      FixInputValue(input, Value<Eigen::VectorXd>(Eigen::VectorXd(value)));
    } else if constexpr (std::is_base_of_v<AbstractValue, T>) {
      FixInputValue(input, value);
    } else {
      FixInputValue(input, Value<T>(value));
    }
  }
  void FixInputValue(const InputPort& input, const AbstractValue& value);

  /// The systems added so far, in order.
  std::vector<const System*> GetSystems() const;
  /// True if `input` is connected, exported or fixed.
  bool IsConnectedOrExported(const InputPort& input) const;

  /// Checks the diagram and builds it; the builder cannot be used afterwards.
  std::unique_ptr<Diagram> Build();

 private:
  using PortLocator = Diagram::PortLocator;

  void AddSystemImpl(std::unique_ptr<System> system);
  void ThrowIfBuilt(const char* operation) const;
  int IndexOf(const System& system, const char* operation) const;
  PortLocator Locate(const InputPort& input, const char* operation) const;
  PortLocator Locate(const OutputPort& output, const char* operation) const;
  void ThrowIfInputTaken(const InputPort& input) const;
  std::string UniqueName(const System& system) const;
  void CheckUniqueNames() const;
  void CheckAllInputsHaveValues() const;
  void CheckNoAlgebraicLoops() const;
  std::string PortLabel(PortLocator locator, bool input) const;

  std::vector<std::unique_ptr<System>> systems_;
  std::map<PortLocator, PortLocator> connections_;
  std::vector<std::string> input_names_;
  std::vector<std::vector<PortLocator>> exported_inputs_;
  std::vector<std::string> output_names_;
  std::vector<PortLocator> exported_outputs_;
  std::vector<std::pair<PortLocator, std::unique_ptr<AbstractValue>>> fixed_inputs_;
  bool built_{false};
};

}  // namespace cairn::systems
