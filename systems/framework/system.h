#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "cairn/systems/framework/context.h"
#include "cairn/systems/framework/dependency_ticket.h"
#include "cairn/systems/framework/input_port.h"
#include "cairn/systems/framework/output_port.h"

namespace cairn::systems {

class LeafSystem;

/// A leaf system and its context, as collected from a (possibly nested) diagram for event dispatch.
struct LeafAndContext {
  const LeafSystem* system;
  Context* context;
};

/// The abstract block of a block diagram. A System describes its ports, state, parameters and events; all
/// runtime values live in a Context it creates. LeafSystem is the base for user systems; Diagram composes them.
///
/// Public methods are non-virtual and validate their arguments (in particular that a context belongs to this
/// system), then call the protected Do... hooks.
class System {
 public:
  virtual ~System();
  System(const System&) = delete;
  System& operator=(const System&) = delete;

  /// The name, unique among the systems of a diagram (DiagramBuilder generates one when empty).
  const std::string& get_name() const { return name_; }
  /// Renames the system; throws std::logic_error once the system belongs to a built Diagram.
  void set_name(std::string name);
  /// "::outer::inner::name", from the outermost diagram.
  std::string GetPathName() const;
  /// A process-unique id; contexts remember the id of the system that created them.
  int64_t id() const { return id_; }

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Ports
  int num_input_ports() const { return static_cast<int>(input_ports_.size()); }
  int num_output_ports() const { return static_cast<int>(output_ports_.size()); }
  /// Throws std::out_of_range naming the valid range.
  const InputPort& get_input_port(int index) const;
  const OutputPort& get_output_port(int index) const;
  /// The only input (output) port; throws if there is not exactly one.
  const InputPort& get_input_port() const;
  const OutputPort& get_output_port() const;
  /// By name; throws std::invalid_argument listing the closest names.
  const InputPort& GetInputPort(const std::string& name) const;
  const OutputPort& GetOutputPort(const std::string& name) const;
  bool HasInputPort(const std::string& name) const;
  bool HasOutputPort(const std::string& name) const;

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Contexts and computation
  /// A context with every value at its declared default.
  std::unique_ptr<Context> CreateDefaultContext() const;
  /// Throws std::logic_error if `context` was not created by this system, saying how to get the right one.
  void ValidateContext(const Context& context) const;

  int num_continuous_states() const { return DoGetNumContinuousStates(); }
  /// Time derivatives of the continuous state; `derivatives` is resized to num_continuous_states().
  void CalcTimeDerivatives(const Context& context, Eigen::VectorXd* derivatives) const;

  /// Whether output `output` may depend on input `input` in the same instant (conservative: true unless the
  /// output's declared prerequisites exclude the input).
  bool HasDirectFeedthrough(int input, int output) const;
  bool HasAnyDirectFeedthrough() const;

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Forced events
  /// Runs every forced publish event (of every leaf, for a diagram). Throws std::runtime_error with the handler's
  /// message if one returns EventStatus::Failed (a reached termination means nothing outside a simulation).
  void ForcedPublish(const Context& context) const;
  /// Runs every forced event: unrestricted updates, then discrete updates (each computed from the state
  /// before any is applied), then publishes. Throws std::runtime_error with the handler's message if one returns
  /// EventStatus::Failed (the failed group's updates are not applied).
  void ExecuteForcedEvents(Context* context) const;

  /// Every leaf system of this system (itself, for a leaf) with its subcontext of `context`, in a stable
  /// depth-first order. For simulators and other drivers of events.
  std::vector<LeafAndContext> CollectLeafSystems(Context* context) const;

  /// A Graphviz (dot) description of the system and, for a diagram, its subsystems and connections.
  std::string GetGraphvizString() const;

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Dependency tickets (prerequisites of output ports and cache entries)
  static DependencyTicket nothing_ticket() { return DependencyTicket(internal::kNothingTicket); }
  static DependencyTicket time_ticket() { return DependencyTicket(internal::kTimeTicket); }
  static DependencyTicket xc_ticket() { return DependencyTicket(internal::kContinuousStateTicket); }
  static DependencyTicket xd_ticket() { return DependencyTicket(internal::kDiscreteStateTicket); }
  static DependencyTicket xa_ticket() { return DependencyTicket(internal::kAbstractStateTicket); }
  static DependencyTicket all_state_ticket() { return DependencyTicket(internal::kAllStateTicket); }
  static DependencyTicket numeric_parameters_ticket() { return DependencyTicket(internal::kNumericParametersTicket); }
  static DependencyTicket abstract_parameters_ticket() {
    return DependencyTicket(internal::kAbstractParametersTicket);
  }
  static DependencyTicket all_parameters_ticket() { return DependencyTicket(internal::kAllParametersTicket); }
  static DependencyTicket all_input_ports_ticket() { return DependencyTicket(internal::kAllInputPortsTicket); }
  static DependencyTicket all_sources_ticket() { return DependencyTicket(internal::kAllSourcesTicket); }
  DependencyTicket input_port_ticket(int index) const { return get_input_port(index).ticket(); }

 protected:
  System();

  /// Adds a port; called from the constructors of LeafSystem subclasses and of Diagram.
  InputPort& AddInputPort(std::string name, PortDataType data_type, int size,
                          std::unique_ptr<AbstractValue> model_value);
  OutputPort& AddOutputPort(std::string name, PortDataType data_type, int size,
                            std::unique_ptr<AbstractValue> model_value);
  /// Reserves a ticket for a state group, parameter, port or cache entry of this system.
  DependencyTicket NewTicket() { return DependencyTicket(num_tickets_++); }
  int num_tickets() const { return num_tickets_; }

  // Hooks -----------------------------------------------------------------------------------------------------
  /// Creates a context with default values, trackers wired, caches allocated.
  virtual std::unique_ptr<Context> DoAllocateContext() const = 0;
  virtual const AbstractValue& DoEvalOutput(const Context& context, int port) const = 0;
  virtual void DoCalcOutput(const Context& context, int port, AbstractValue* value) const = 0;
  virtual int DoGetNumContinuousStates() const = 0;
  virtual void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const = 0;
  virtual bool DoHasDirectFeedthrough(int input, int output) const = 0;
  virtual void DoCollectLeafSystems(Context* context, std::vector<LeafAndContext>* leaves) const = 0;
  virtual void DoGetGraphviz(std::string* dot, const std::string& indent) const;
  /// The tracker to subscribe to for changes of output `port` (for a diagram, its source leaf's).
  virtual DependencyTracker& DoGetOutputTracker(Context* context, int port) const = 0;
  /// The leaf system, context and port that actually compute output `port` (for a diagram, resolved inward).
  virtual void DoResolveOutput(const Context& context, int port, const System** leaf, const Context** leaf_context,
                               int* leaf_port) const = 0;

 private:
  friend class OutputPort;
  friend class InputPort;
  friend class Context;
  friend class DiagramBuilder;
  friend class Diagram;

  void CheckPortNameIsNew(const std::string& name, bool input) const;

  int64_t id_;
  std::string name_;
  const System* parent_{nullptr};           // The diagram this system belongs to, once built.
  const void* owner_{nullptr};              // The builder or diagram that owns this system.
  std::vector<std::unique_ptr<InputPort>> input_ports_;
  std::vector<std::unique_ptr<OutputPort>> output_ports_;
  int num_tickets_{internal::kNumBuiltInTickets};
};

}  // namespace cairn::systems
