#pragma once

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "cairn/systems/framework/discrete_values.h"
#include "cairn/systems/framework/event.h"
#include "cairn/systems/framework/state.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems {

/// Base class of user systems. A leaf system declares everything in its constructor — ports, state, parameters,
/// cache entries and events — and overrides DoCalcTimeDerivatives() if it has continuous state.
///
/// Output ports are cached: Eval() recomputes only when one of the port's prerequisites changed. The default
/// prerequisite is all_sources_ticket() (time, state, parameters and every input); declaring narrower
/// prerequisites both saves work and tells DiagramBuilder which inputs an output does not depend on (direct
/// feedthrough), which is what lets feedback loops through the system build.
///
/// Handlers may be member functions of the subclass (`&MySystem::CalcY`) or any callable.
class LeafSystem : public System {
 public:
  ~LeafSystem() override;

  /// Events declared by this system, in declaration order.
  const std::vector<Event>& declared_events() const { return events_; }

  DependencyTicket discrete_state_ticket(int group) const;
  DependencyTicket abstract_state_ticket(int index) const;
  DependencyTicket numeric_parameter_ticket(int index) const;
  DependencyTicket abstract_parameter_ticket(int index) const;
  /// Ticket of output port `port`'s cached value (usable as a prerequisite of other outputs).
  DependencyTicket output_port_ticket(int port) const;
  /// Ticket of a cache entry declared with DeclareCacheEntry().
  DependencyTicket cache_entry_ticket(int index) const;

  /// Value of cache entry `index` in `context`, recomputed if out of date.
  const AbstractValue& EvalCacheEntry(const Context& context, int index) const;
  template <typename T>
  const T& EvalCacheEntry(const Context& context, int index) const {
    return EvalCacheEntry(context, index).get_value<T>();
  }

 protected:
  LeafSystem();

  using VectorCalc = std::function<void(const Context&, Eigen::VectorXd*)>;
  using AbstractCalc = std::function<void(const Context&, AbstractValue*)>;
  using Prerequisites = std::set<DependencyTicket>;

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Ports. Names must be unique per direction; an empty name becomes "u<i>" / "y<i>".
  const InputPort& DeclareVectorInputPort(std::string name, int size);
  const InputPort& DeclareAbstractInputPort(std::string name, const AbstractValue& model_value);

  /// A vector output of `size`; `calc(context, y)` gets y already sized and must not resize it.
  const OutputPort& DeclareVectorOutputPort(std::string name, int size, VectorCalc calc,
                                            Prerequisites prerequisites = {all_sources_ticket()});
  template <class MySystem>
  const OutputPort& DeclareVectorOutputPort(std::string name, int size,
                                            void (MySystem::*calc)(const Context&, Eigen::VectorXd*) const,
                                            Prerequisites prerequisites = {all_sources_ticket()}) {
    const auto* self = static_cast<const MySystem*>(this);
    return DeclareVectorOutputPort(std::move(name), size, [self, calc](const Context& c, Eigen::VectorXd* y) {
      (self->*calc)(c, y);
    }, std::move(prerequisites));
  }

  /// An abstract output holding a T (copy of `model_value` initially); `calc(context, T*)` fills it.
  const OutputPort& DeclareAbstractOutputPort(std::string name, const AbstractValue& model_value, AbstractCalc calc,
                                              Prerequisites prerequisites = {all_sources_ticket()});
  template <class MySystem, typename T>
  const OutputPort& DeclareAbstractOutputPort(std::string name, const T& model_value,
                                              void (MySystem::*calc)(const Context&, T*) const,
                                              Prerequisites prerequisites = {all_sources_ticket()}) {
    const auto* self = static_cast<const MySystem*>(this);
    return DeclareAbstractOutputPort(std::move(name), Value<T>(model_value),
                                     [self, calc](const Context& c, AbstractValue* v) {
                                       (self->*calc)(c, &v->get_mutable_value<T>());
                                     },
                                     std::move(prerequisites));
  }

  /// A vector output that is discrete state group `group` itself (declare the group first): the usual output of a
  /// discrete-time plant, depending on that state only (no direct feedthrough). Throws std::invalid_argument for
  /// an undeclared group.
  const OutputPort& DeclareStateOutputPort(std::string name, int group);

  // ---------------------------------------------------------------------------------------------------------------
  /// @name State and parameters; each returns the index of what it declared.
  /// Declares the continuous state (once per system) with its initial value, which must be finite (throws
  /// std::invalid_argument naming the element otherwise).
  void DeclareContinuousState(const Eigen::VectorXd& initial_value);
  /// Declares a discrete state group with its initial value, which must be finite.
  int DeclareDiscreteState(const Eigen::VectorXd& initial_value);
  int DeclareAbstractState(const AbstractValue& initial_value);
  int DeclareNumericParameter(const Eigen::VectorXd& default_value);
  int DeclareAbstractParameter(const AbstractValue& default_value);

  /// A cached computation other outputs can share (list its ticket among their prerequisites).
  int DeclareCacheEntry(std::string name, const AbstractValue& model_value, AbstractCalc calc,
                        Prerequisites prerequisites = {all_sources_ticket()});

  /// Storage that lives in each context but is neither state nor cache: written by publish events (e.g. a
  /// logger's log), read by user code, never by outputs, so it takes no part in dependency tracking. It is
  /// copied when the context is cloned.
  int DeclarePerContextStorage(const AbstractValue& model_value);
  template <typename T>
  T& GetMutablePerContextStorage(const Context& context, int index) const {
    return MutablePerContextStorage(context, index).get_mutable_value<T>();
  }
  template <typename T>
  const T& GetPerContextStorage(const Context& context, int index) const {
    return MutablePerContextStorage(context, index).get_value<T>();
  }

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Events. Handlers: publish `void(const Context&)`, discrete update `void(const Context&,
  /// DiscreteValues* next)`, unrestricted update `void(const Context&, State* next)`; `next` starts as a copy of
  /// the current values. A handler may return an EventStatus instead of void, to end a simulation
  /// (EventStatus::ReachedTermination) or report a failure (EventStatus::Failed) with a message.
  template <typename Handler>
  void DeclarePeriodicPublishEvent(double period, double offset, Handler handler) {
    DeclarePeriodic(period, offset, MakePublish(handler));
  }
  template <typename Handler>
  void DeclarePeriodicDiscreteUpdateEvent(double period, double offset, Handler handler) {
    DeclarePeriodic(period, offset, MakeDiscrete(handler));
  }
  template <typename Handler>
  void DeclarePeriodicUnrestrictedUpdateEvent(double period, double offset, Handler handler) {
    DeclarePeriodic(period, offset, MakeUnrestricted(handler));
  }
  template <typename Handler>
  void DeclarePerStepPublishEvent(Handler handler) {
    DeclareEvent(TriggerType::kPerStep, MakePublish(handler));
  }
  template <typename Handler>
  void DeclarePerStepDiscreteUpdateEvent(Handler handler) {
    DeclareEvent(TriggerType::kPerStep, MakeDiscrete(handler));
  }
  template <typename Handler>
  void DeclarePerStepUnrestrictedUpdateEvent(Handler handler) {
    DeclareEvent(TriggerType::kPerStep, MakeUnrestricted(handler));
  }
  template <typename Handler>
  void DeclareInitializationPublishEvent(Handler handler) {
    DeclareEvent(TriggerType::kInitialization, MakePublish(handler));
  }
  template <typename Handler>
  void DeclareInitializationDiscreteUpdateEvent(Handler handler) {
    DeclareEvent(TriggerType::kInitialization, MakeDiscrete(handler));
  }
  template <typename Handler>
  void DeclareInitializationUnrestrictedUpdateEvent(Handler handler) {
    DeclareEvent(TriggerType::kInitialization, MakeUnrestricted(handler));
  }
  template <typename Handler>
  void DeclareForcedPublishEvent(Handler handler) {
    DeclareEvent(TriggerType::kForced, MakePublish(handler));
  }
  template <typename Handler>
  void DeclareForcedDiscreteUpdateEvent(Handler handler) {
    DeclareEvent(TriggerType::kForced, MakeDiscrete(handler));
  }
  template <typename Handler>
  void DeclareForcedUnrestrictedUpdateEvent(Handler handler) {
    DeclareEvent(TriggerType::kForced, MakeUnrestricted(handler));
  }

  /// Override when the system declares continuous state. The default throws (the state would never change).
  void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const override;

 private:
  struct CachedComputation {
    std::string name;
    std::unique_ptr<AbstractValue> model_value;
    AbstractCalc calc;
    Prerequisites prerequisites;
    DependencyTicket ticket;
  };

  // A handler is a member function of the subclass (bound to this system) or any callable, returning void
  // (succeeded) or an EventStatus.
  template <typename... Args, typename Handler>
  std::function<EventStatus(Args...)> BindHandler(Handler handler) const {
    if constexpr (std::is_member_function_pointer_v<Handler>) {
      return [this, handler](Args... args) {
        return AsStatus([&] { return (static_cast<const OwnerOf<Handler>*>(this)->*handler)(args...); });
      };
    } else {
      return [handler = std::move(handler)](Args... args) mutable {
        return AsStatus([&] { return handler(args...); });
      };
    }
  }
  template <typename Call>
  static EventStatus AsStatus(Call call) {
    if constexpr (std::is_void_v<decltype(call())>) {
      call();
      return EventStatus::Succeeded();
    } else {
      static_assert(std::is_same_v<decltype(call()), EventStatus>,
                    "An event handler must return void or cairn::systems::EventStatus");
      return call();
    }
  }
  template <typename Handler>
  Event MakePublish(Handler handler) {
    Event event;
    event.kind = EventKind::kPublish;
    event.publish = BindHandler<const Context&>(std::move(handler));
    return event;
  }
  template <typename Handler>
  Event MakeDiscrete(Handler handler) {
    Event event;
    event.kind = EventKind::kDiscreteUpdate;
    event.discrete_update = BindHandler<const Context&, DiscreteValues*>(std::move(handler));
    return event;
  }
  template <typename Handler>
  Event MakeUnrestricted(Handler handler) {
    Event event;
    event.kind = EventKind::kUnrestrictedUpdate;
    event.unrestricted_update = BindHandler<const Context&, State*>(std::move(handler));
    return event;
  }
  template <typename MemberPointer>
  struct OwnerOfImpl;
  template <typename Class, typename Signature>
  struct OwnerOfImpl<Signature Class::*> {
    using type = Class;
  };
  template <typename MemberPointer>
  using OwnerOf = typename OwnerOfImpl<MemberPointer>::type;

  const OutputPort& AddCachedOutput(std::string name, PortDataType data_type, int size,
                                    const AbstractValue& model_value, AbstractCalc calc, Prerequisites prerequisites);
  void DeclarePeriodic(double period, double offset, Event event);
  void DeclareEvent(TriggerType trigger, Event event);
  DependencyTicket AddCachedComputation(std::string name, const AbstractValue& model_value, AbstractCalc calc,
                                        Prerequisites prerequisites);
  AbstractValue& MutablePerContextStorage(const Context& context, int index) const;
  void CheckPrerequisites(const std::string& what, const Prerequisites& prerequisites) const;
  void CheckFiniteInitialValue(const char* what, const Eigen::VectorXd& value) const;
  bool DependsOnInput(const Prerequisites& prerequisites, DependencyTicket input, int depth) const;
  const CachedComputation* FindCachedComputation(DependencyTicket ticket) const;

  // System hooks.
  std::unique_ptr<Context> DoAllocateContext() const final;
  const AbstractValue& DoEvalOutput(const Context& context, int port) const final;
  void DoCalcOutput(const Context& context, int port, AbstractValue* value) const final;
  int DoGetNumContinuousStates() const final { return static_cast<int>(xc_initial_.size()); }
  bool DoHasDirectFeedthrough(int input, int output) const final;
  void DoCollectLeafSystems(Context* context, std::vector<LeafAndContext>* leaves) const final;
  DependencyTracker& DoGetOutputTracker(Context* context, int port) const final;
  void DoResolveOutput(const Context& context, int port, const System** leaf, const Context** leaf_context,
                       int* leaf_port) const final;

  const AbstractValue& EvalCached(const Context& context, const CachedComputation& computation) const;

  Eigen::VectorXd xc_initial_;
  bool has_continuous_state_{false};
  std::vector<Eigen::VectorXd> xd_initial_;
  std::vector<DependencyTicket> xd_tickets_;
  std::vector<std::unique_ptr<AbstractValue>> xa_initial_;
  std::vector<DependencyTicket> xa_tickets_;
  std::vector<Eigen::VectorXd> pn_default_;
  std::vector<DependencyTicket> pn_tickets_;
  std::vector<std::unique_ptr<AbstractValue>> pa_default_;
  std::vector<DependencyTicket> pa_tickets_;
  std::vector<CachedComputation> outputs_;       // One per output port.
  std::vector<CachedComputation> cache_entries_;  // Declared with DeclareCacheEntry().
  std::vector<std::unique_ptr<AbstractValue>> per_context_storage_models_;
  std::vector<Event> events_;
};

}  // namespace cairn::systems
