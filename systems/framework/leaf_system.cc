#include "cairn/systems/framework/leaf_system.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/cairn_assert.h"
#include "cairn/common/number_text.h"

namespace cairn::systems {

LeafSystem::LeafSystem() = default;

LeafSystem::~LeafSystem() = default;

// ---------------------------------------------------------------------------------------------------------------------
// Declarations

const InputPort& LeafSystem::DeclareVectorInputPort(std::string name, int size) {
  if (size < 0) {
    throw std::invalid_argument("DeclareVectorInputPort('" + name + "'): size " + cairn::FormatShort(size) +
                                " is negative.");
  }
  return AddInputPort(std::move(name), PortDataType::kVector, size,
                      std::make_unique<Value<Eigen::VectorXd>>(Eigen::VectorXd::Zero(size)));
}

const InputPort& LeafSystem::DeclareAbstractInputPort(std::string name, const AbstractValue& model_value) {
  return AddInputPort(std::move(name), PortDataType::kAbstract, 0, model_value.Clone());
}

const OutputPort& LeafSystem::DeclareVectorOutputPort(std::string name, int size, VectorCalc calc,
                                                      Prerequisites prerequisites) {
  if (size < 0) {
    throw std::invalid_argument("DeclareVectorOutputPort('" + name + "'): size " + cairn::FormatShort(size) +
                                " is negative.");
  }
  if (!calc) throw std::invalid_argument("DeclareVectorOutputPort('" + name + "'): the calc function is empty.");
  const int index = num_output_ports();
  // Wrap the vector calc so a calc that resizes its output is caught where it happens.
  AbstractCalc wrapped = [this, calc = std::move(calc), size, index](const Context& context, AbstractValue* value) {
    auto& y = value->get_mutable_value<Eigen::VectorXd>();
    calc(context, &y);
    if (y.size() != size) {
      throw std::logic_error("The calc function of the " + get_output_port(index).GetFullDescription() +
                             " resized its output to " + cairn::FormatShort(y.size()) + " (declared size " +
                             cairn::FormatShort(size) + "); write into the given vector without resizing it.");
    }
  };
  return AddCachedOutput(std::move(name), PortDataType::kVector, size, Value<Eigen::VectorXd>(Eigen::VectorXd::Zero(size)),
                         std::move(wrapped), std::move(prerequisites));
}

const OutputPort& LeafSystem::DeclareAbstractOutputPort(std::string name, const AbstractValue& model_value,
                                                        AbstractCalc calc, Prerequisites prerequisites) {
  if (!calc) throw std::invalid_argument("DeclareAbstractOutputPort('" + name + "'): the calc function is empty.");
  return AddCachedOutput(std::move(name), PortDataType::kAbstract, 0, model_value, std::move(calc),
                         std::move(prerequisites));
}

const OutputPort& LeafSystem::AddCachedOutput(std::string name, PortDataType data_type, int size,
                                              const AbstractValue& model_value, AbstractCalc calc,
                                              Prerequisites prerequisites) {
  CheckPrerequisites("output port '" + name + "' of system '" + GetPathName() + "'", prerequisites);
  const OutputPort& port = AddOutputPort(std::move(name), data_type, size, model_value.Clone());
  outputs_.push_back({port.get_name(), model_value.Clone(), std::move(calc), std::move(prerequisites), NewTicket()});
  return port;
}

void LeafSystem::DeclareContinuousState(const Eigen::VectorXd& initial_value) {
  if (has_continuous_state_) {
    throw std::logic_error("System '" + GetPathName() +
                           "' declares continuous state twice; declare it once with its full size.");
  }
  CheckFiniteInitialValue("continuous state", initial_value);
  has_continuous_state_ = true;
  xc_initial_ = initial_value;
}

int LeafSystem::DeclareDiscreteState(const Eigen::VectorXd& initial_value) {
  CheckFiniteInitialValue("discrete state", initial_value);
  xd_initial_.push_back(initial_value);
  xd_tickets_.push_back(NewTicket());
  return static_cast<int>(xd_initial_.size()) - 1;
}

int LeafSystem::DeclareAbstractState(const AbstractValue& initial_value) {
  xa_initial_.push_back(initial_value.Clone());
  xa_tickets_.push_back(NewTicket());
  return static_cast<int>(xa_initial_.size()) - 1;
}

int LeafSystem::DeclareNumericParameter(const Eigen::VectorXd& default_value) {
  pn_default_.push_back(default_value);
  pn_tickets_.push_back(NewTicket());
  return static_cast<int>(pn_default_.size()) - 1;
}

int LeafSystem::DeclareAbstractParameter(const AbstractValue& default_value) {
  pa_default_.push_back(default_value.Clone());
  pa_tickets_.push_back(NewTicket());
  return static_cast<int>(pa_default_.size()) - 1;
}

int LeafSystem::DeclareCacheEntry(std::string name, const AbstractValue& model_value, AbstractCalc calc,
                                  Prerequisites prerequisites) {
  if (!calc) throw std::invalid_argument("DeclareCacheEntry('" + name + "'): the calc function is empty.");
  CheckPrerequisites("cache entry '" + name + "' of system '" + GetPathName() + "'", prerequisites);
  cache_entries_.push_back({std::move(name), model_value.Clone(), std::move(calc), std::move(prerequisites), NewTicket()});
  return static_cast<int>(cache_entries_.size()) - 1;
}

int LeafSystem::DeclarePerContextStorage(const AbstractValue& model_value) {
  per_context_storage_models_.push_back(model_value.Clone());
  return static_cast<int>(per_context_storage_models_.size()) - 1;
}

AbstractValue& LeafSystem::MutablePerContextStorage(const Context& context, int index) const {
  ValidateContext(context);
  if (index < 0 || index >= static_cast<int>(per_context_storage_models_.size())) {
    throw std::out_of_range("System '" + GetPathName() + "' declared " +
                            cairn::FormatShort(per_context_storage_models_.size()) +
                            " per-context storage entries; index " + cairn::FormatShort(index) + " is out of range.");
  }
  return *context.per_context_storage_[index];
}

void LeafSystem::CheckFiniteInitialValue(const char* what, const Eigen::VectorXd& value) const {
  for (Eigen::Index i = 0; i < value.size(); ++i) {
    if (!std::isfinite(value[i])) {
      throw std::invalid_argument("System '" + GetPathName() + "': the initial " + what + " has element " +
                                  cairn::FormatShort(i) + " = " + FormatShort(value[i]) + "; states must be finite.");
    }
  }
}

void LeafSystem::DeclarePeriodic(double period, double offset, Event event) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("System '" + GetPathName() + "': a periodic event needs a finite period > 0; got " +
                                FormatShort(period) + ".");
  }
  if (!(offset >= 0.0) || !std::isfinite(offset)) {
    throw std::invalid_argument("System '" + GetPathName() + "': a periodic event needs a finite offset >= 0; got " +
                                FormatShort(offset) + ".");
  }
  event.periodic = PeriodicEventData{period, offset};
  DeclareEvent(TriggerType::kPeriodic, std::move(event));
}

void LeafSystem::DeclareEvent(TriggerType trigger, Event event) {
  const bool has_handler = (event.kind == EventKind::kPublish && event.publish) ||
                           (event.kind == EventKind::kDiscreteUpdate && event.discrete_update) ||
                           (event.kind == EventKind::kUnrestrictedUpdate && event.unrestricted_update);
  if (!has_handler) throw std::invalid_argument("System '" + GetPathName() + "': an event handler is empty.");
  event.trigger = trigger;
  events_.push_back(std::move(event));
}

void LeafSystem::CheckPrerequisites(const std::string& what, const Prerequisites& prerequisites) const {
  if (prerequisites.empty()) {
    throw std::invalid_argument("The " + what + " has no prerequisites; pass {nothing_ticket()} for a constant, or "
                                "list what it depends on.");
  }
  for (DependencyTicket ticket : prerequisites) {
    // Only tickets handed out before this declaration are valid, which also rules out dependency cycles.
    if (!ticket.is_valid() || ticket.index() >= num_tickets()) {
      throw std::invalid_argument("The " + what + " lists prerequisite ticket " + cairn::FormatShort(ticket.index()) +
                                  ", which this system has not declared (yet); declare what it depends on first.");
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------------
// Tickets

namespace {
DependencyTicket TicketAt(const std::vector<DependencyTicket>& tickets, int index, const char* what,
                          const std::string& system) {
  if (index < 0 || index >= static_cast<int>(tickets.size())) {
    throw std::out_of_range("System '" + system + "' has " + cairn::FormatShort(tickets.size()) + " " + what +
                            "(s); index " + cairn::FormatShort(index) + " is out of range.");
  }
  return tickets[index];
}
}  // namespace

DependencyTicket LeafSystem::discrete_state_ticket(int group) const {
  return TicketAt(xd_tickets_, group, "discrete state group", GetPathName());
}
DependencyTicket LeafSystem::abstract_state_ticket(int index) const {
  return TicketAt(xa_tickets_, index, "abstract state", GetPathName());
}
DependencyTicket LeafSystem::numeric_parameter_ticket(int index) const {
  return TicketAt(pn_tickets_, index, "numeric parameter", GetPathName());
}
DependencyTicket LeafSystem::abstract_parameter_ticket(int index) const {
  return TicketAt(pa_tickets_, index, "abstract parameter", GetPathName());
}
DependencyTicket LeafSystem::output_port_ticket(int port) const {
  get_output_port(port);
  return outputs_[port].ticket;
}
DependencyTicket LeafSystem::cache_entry_ticket(int index) const {
  if (index < 0 || index >= static_cast<int>(cache_entries_.size())) {
    throw std::out_of_range("System '" + GetPathName() + "' has " + cairn::FormatShort(cache_entries_.size()) +
                            " cache entries; index " + cairn::FormatShort(index) + " is out of range.");
  }
  return cache_entries_[index].ticket;
}

// ---------------------------------------------------------------------------------------------------------------------
// Context allocation and evaluation

std::unique_ptr<Context> LeafSystem::DoAllocateContext() const {
  std::unique_ptr<Context> context(new Context(this, num_tickets()));
  Context& c = *context;
  auto subscribe = [&c](DependencyTicket subscriber, int prerequisite) {
    c.trackers_[subscriber.index()].SubscribeTo(&c.trackers_[prerequisite]);
  };

  c.xc_size_ = static_cast<int>(xc_initial_.size());
  c.owned_xc_ = xc_initial_;
  c.xd_ = DiscreteValues(xd_initial_);
  for (std::size_t i = 0; i < xd_tickets_.size(); ++i) {
    c.xd_tickets_.push_back(xd_tickets_[i].index());
    subscribe(DependencyTicket(internal::kDiscreteStateTicket), xd_tickets_[i].index());
  }
  for (std::size_t i = 0; i < xa_initial_.size(); ++i) {
    c.xa_.push_back(xa_initial_[i]->Clone());
    c.xa_tickets_.push_back(xa_tickets_[i].index());
    subscribe(DependencyTicket(internal::kAbstractStateTicket), xa_tickets_[i].index());
  }
  for (std::size_t i = 0; i < pn_default_.size(); ++i) {
    c.pn_.push_back(pn_default_[i]);
    c.pn_tickets_.push_back(pn_tickets_[i].index());
    subscribe(DependencyTicket(internal::kNumericParametersTicket), pn_tickets_[i].index());
  }
  for (std::size_t i = 0; i < pa_default_.size(); ++i) {
    c.pa_.push_back(pa_default_[i]->Clone());
    c.pa_tickets_.push_back(pa_tickets_[i].index());
    subscribe(DependencyTicket(internal::kAbstractParametersTicket), pa_tickets_[i].index());
  }
  c.inputs_.resize(num_input_ports());
  for (int i = 0; i < num_input_ports(); ++i) {
    subscribe(DependencyTicket(internal::kAllInputPortsTicket), get_input_port(i).ticket().index());
  }
  auto add_cached = [&](const CachedComputation& computation) {
    const int ticket = computation.ticket.index();
    c.cache_[ticket] = CacheEntryValue(computation.model_value->Clone());
    c.trackers_[ticket].set_cache_value(&c.cache_[ticket]);
    for (DependencyTicket prerequisite : computation.prerequisites) {
      subscribe(computation.ticket, prerequisite.index());
    }
  };
  for (const auto& computation : cache_entries_) add_cached(computation);
  for (const auto& computation : outputs_) add_cached(computation);
  for (const auto& model : per_context_storage_models_) c.per_context_storage_.push_back(model->Clone());
  return context;
}

const AbstractValue& LeafSystem::EvalCached(const Context& context, const CachedComputation& computation) const {
  CacheEntryValue& entry = context.cache_[computation.ticket.index()];
  if (entry.is_up_to_date() && context.caching_enabled_) return entry.value();
  computation.calc(context, &entry.mutable_value());
  entry.count_calculation();
  entry.mark_up_to_date();
  return entry.value();
}

const AbstractValue& LeafSystem::DoEvalOutput(const Context& context, int port) const {
  return EvalCached(context, outputs_[port]);
}

void LeafSystem::DoCalcOutput(const Context& context, int port, AbstractValue* value) const {
  outputs_[port].calc(context, value);
}

const AbstractValue& LeafSystem::EvalCacheEntry(const Context& context, int index) const {
  ValidateContext(context);
  cache_entry_ticket(index);
  return EvalCached(context, cache_entries_[index]);
}

void LeafSystem::DoCalcTimeDerivatives(const Context&, Eigen::Ref<Eigen::VectorXd> derivatives) const {
  if (derivatives.size() == 0) return;
  throw std::logic_error("System '" + GetPathName() +
                         "' declares continuous state but does not override DoCalcTimeDerivatives().");
}

const LeafSystem::CachedComputation* LeafSystem::FindCachedComputation(DependencyTicket ticket) const {
  for (const auto& entry : cache_entries_) {
    if (entry.ticket == ticket) return &entry;
  }
  for (const auto& entry : outputs_) {
    if (entry.ticket == ticket) return &entry;
  }
  return nullptr;
}

bool LeafSystem::DependsOnInput(const Prerequisites& prerequisites, DependencyTicket input, int depth) const {
  CAIRN_CHECK(depth < 1000);  // Prerequisites only name earlier tickets, so chains are finite.
  for (DependencyTicket ticket : prerequisites) {
    if (ticket == input || ticket == all_input_ports_ticket() || ticket == all_sources_ticket()) return true;
    if (const CachedComputation* computation = FindCachedComputation(ticket)) {
      if (DependsOnInput(computation->prerequisites, input, depth + 1)) return true;
    }
  }
  return false;
}

bool LeafSystem::DoHasDirectFeedthrough(int input, int output) const {
  return DependsOnInput(outputs_[output].prerequisites, get_input_port(input).ticket(), 0);
}

void LeafSystem::DoCollectLeafSystems(Context* context, std::vector<LeafAndContext>* leaves) const {
  leaves->push_back({this, context});
}

DependencyTracker& LeafSystem::DoGetOutputTracker(Context* context, int port) const {
  return context->tracker(outputs_[port].ticket.index());
}

void LeafSystem::DoResolveOutput(const Context& context, int port, const System** leaf, const Context** leaf_context,
                                 int* leaf_port) const {
  *leaf = this;
  *leaf_context = &context;
  *leaf_port = port;
}

const OutputPort& LeafSystem::DeclareStateOutputPort(std::string name, int group) {
  if (group < 0 || group >= static_cast<int>(xd_initial_.size())) {
    throw std::invalid_argument("DeclareStateOutputPort('" + name + "'): discrete state group " + cairn::FormatShort(group) +
                                " is not declared (this system has " + cairn::FormatShort(xd_initial_.size()) +
                                "); declare it with DeclareDiscreteState first.");
  }
  const int size = static_cast<int>(xd_initial_[static_cast<std::size_t>(group)].size());
  return DeclareVectorOutputPort(
      std::move(name), size,
      [group](const Context& context, Eigen::VectorXd* y) { *y = context.get_discrete_state(group); },
      {discrete_state_ticket(group)});
}

}  // namespace cairn::systems
