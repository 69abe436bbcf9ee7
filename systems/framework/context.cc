#include "cairn/systems/framework/context.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "cairn/common/cairn_assert.h"
#include "cairn/common/number_text.h"
#include "cairn/systems/framework/system.h"

namespace cairn::systems {

using internal::BuiltInTicket;

namespace {

// States that users set must be finite: a NaN or infinite state only produces NaN downstream.
void CheckFinite(const Eigen::Ref<const Eigen::VectorXd>& x, const std::string& what) {
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw std::invalid_argument(what + ": element " + cairn::FormatShort(i) + " is " + FormatShort(x[i]) +
                                  "; states must be finite.");
    }
  }
}

}  // namespace

Context::Context(const System* system, int num_tickets)
    : system_(system),
      system_id_(system->id()),
      system_path_name_(system->GetPathName()),
      cache_(num_tickets),
      trackers_(num_tickets) {
  // The built-in tickets form a small hierarchy: a change of any one state group reaches every computation that
  // depends on "all state", and everything reaches "all sources".
  auto subscribe = [this](int subscriber, int prerequisite) {
    trackers_[subscriber].SubscribeTo(&trackers_[prerequisite]);
  };
  subscribe(internal::kAllStateTicket, internal::kContinuousStateTicket);
  subscribe(internal::kAllStateTicket, internal::kDiscreteStateTicket);
  subscribe(internal::kAllStateTicket, internal::kAbstractStateTicket);
  subscribe(internal::kAllParametersTicket, internal::kNumericParametersTicket);
  subscribe(internal::kAllParametersTicket, internal::kAbstractParametersTicket);
  subscribe(internal::kAllSourcesTicket, internal::kTimeTicket);
  subscribe(internal::kAllSourcesTicket, internal::kAllStateTicket);
  subscribe(internal::kAllSourcesTicket, internal::kAllParametersTicket);
  subscribe(internal::kAllSourcesTicket, internal::kAllInputPortsTicket);
}

Context::~Context() = default;

std::unique_ptr<Context> Context::Clone() const {
  if (!is_root()) {
    throw std::logic_error("Clone() was called on the subcontext of '" + system_path_name_ +
                           "'; clone the root (diagram) context instead, since a subcontext's inputs come from its "
                           "siblings.");
  }
  std::unique_ptr<Context> clone = system_->DoAllocateContext();
  clone->CopyValuesFrom(*this);
  return clone;
}

void Context::SetFrom(const Context& source) {
  if (source.system_id_ != system_id_) {
    throw std::invalid_argument("Context::SetFrom: the source context belongs to system '" +
                                source.system_path_name_ + "', this one to '" + system_path_name_ +
                                "'; copy between contexts of the same system.");
  }
  if (!is_root()) {
    throw std::logic_error("SetFrom() was called on the subcontext of '" + system_path_name_ +
                           "'; set the root (diagram) context instead.");
  }
  CopyValuesFrom(source);
}

void Context::CopyValuesFrom(const Context& source) {
  CAIRN_CHECK(source.system_id_ == system_id_);
  time_ = source.time_;
  if (children_.empty() && xc_size_ > 0) {
    xc_storage_->segment(xc_offset_, xc_size_) = source.xc_storage_->segment(source.xc_offset_, xc_size_);
  }
  xd_.SetFrom(source.xd_);
  // A fresh copy, not SetFrom(): this context's value may be shared with a State cloned from it.
  for (std::size_t i = 0; i < xa_.size(); ++i) xa_[i] = source.xa_[i]->Clone();
  for (std::size_t i = 0; i < pn_.size(); ++i) pn_[i] = source.pn_[i];
  for (std::size_t i = 0; i < pa_.size(); ++i) pa_[i]->SetFrom(*source.pa_[i]);
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    const auto& fixed = source.inputs_[i].fixed_value;
    inputs_[i].fixed_value = fixed ? fixed->Clone() : nullptr;
  }
  // Copying the cache with its validity is consistent because every value it was computed from is copied too.
  for (std::size_t i = 0; i < cache_.size(); ++i) {
    if (!source.cache_[i].has_value()) continue;
    cache_[i].SetFrom(source.cache_[i]);
  }
  for (std::size_t i = 0; i < per_context_storage_.size(); ++i) {
    per_context_storage_[i]->SetFrom(*source.per_context_storage_[i]);
  }
  caching_enabled_ = source.caching_enabled_;
  for (std::size_t i = 0; i < children_.size(); ++i) children_[i]->CopyValuesFrom(*source.children_[i]);
}

void Context::NoteChange(int ticket) { NoteChange(ticket, DependencyTracker::NewChangeEvent()); }

void Context::NoteChange(int ticket, int64_t change_event) { trackers_[ticket].NoteValueChange(change_event); }

void Context::SetTime(double time) {
  if (!is_root()) {
    throw std::logic_error("SetTime() was called on the subcontext of '" + system_path_name_ +
                           "'; set the time of the root (diagram) context, which all subcontexts share.");
  }
  if (!std::isfinite(time)) {
    throw std::invalid_argument("SetTime(" + FormatShort(time) + ") on the context of '" + system_path_name_ +
                                "': the time must be finite.");
  }
  SetTimeRecursive(time, DependencyTracker::NewChangeEvent());
}

void Context::SetTimeRecursive(double time, int64_t change_event) {
  time_ = time;
  NoteChange(internal::kTimeTicket, change_event);
  for (auto& child : children_) child->SetTimeRecursive(time, change_event);
}

Eigen::VectorBlock<const Eigen::VectorXd> Context::get_continuous_state_vector() const {
  const Eigen::VectorXd& storage = *xc_storage_;
  return storage.segment(xc_offset_, xc_size_);
}

Eigen::VectorBlock<Eigen::VectorXd> Context::get_mutable_continuous_state_vector() {
  NoteContinuousStateChange(DependencyTracker::NewChangeEvent());
  return xc_storage_->segment(xc_offset_, xc_size_);
}

void Context::SetContinuousState(const Eigen::Ref<const Eigen::VectorXd>& x) {
  if (x.size() != xc_size_) {
    throw std::invalid_argument("The continuous state of '" + system_path_name_ + "' has size " +
                                cairn::FormatShort(xc_size_) + " but was given a vector of size " +
                                cairn::FormatShort(x.size()) + ".");
  }
  CheckFinite(x, "SetContinuousState on the context of '" + system_path_name_ + "'");
  get_mutable_continuous_state_vector() = x;
}

void Context::NoteContinuousStateChange(int64_t change_event) {
  NoteChange(internal::kContinuousStateTicket, change_event);
  for (auto& child : children_) {
    if (child->xc_size_ > 0) child->NoteContinuousStateChange(change_event);
  }
}

void Context::BindContinuousStorage(Eigen::VectorXd* storage, int offset) {
  if (xc_size_ > 0) storage->segment(offset, xc_size_) = get_continuous_state_vector();
  for (std::size_t i = 0; i < children_.size(); ++i) {
    children_[i]->BindContinuousStorage(storage, offset + child_xc_offsets_[i]);
  }
  xc_storage_ = storage;
  xc_offset_ = offset;
  if (storage != &owned_xc_) owned_xc_.resize(0);
}

void Context::ThrowIfNotLeafState(const char* what, int index, int count) const {
  if (index >= 0 && index < count) return;
  if (!children_.empty()) {
    throw std::out_of_range("The context of diagram '" + system_path_name_ + "' holds no " + what +
                            "; it lives in the subsystems' contexts: use "
                            "diagram.GetSubsystemContext(subsystem, context).");
  }
  throw std::out_of_range("System '" + system_path_name_ + "' has " + cairn::FormatShort(count) + " " + what +
                          " entr" + (count == 1 ? "y" : "ies") + "; index " + cairn::FormatShort(index) +
                          " is out of range.");
}

const Eigen::VectorXd& Context::get_discrete_state(int group) const {
  ThrowIfNotLeafState("discrete state", group, xd_.num_groups());
  return xd_.value(group);
}

Eigen::VectorXd& Context::get_mutable_discrete_state(int group) {
  ThrowIfNotLeafState("discrete state", group, xd_.num_groups());
  NoteChange(xd_tickets_[group]);
  return xd_.get_mutable_value(group);
}

void Context::SetDiscreteState(int group, const Eigen::Ref<const Eigen::VectorXd>& value) {
  ThrowIfNotLeafState("discrete state", group, xd_.num_groups());
  CheckFinite(value, "SetDiscreteState(" + cairn::FormatShort(group) + ") on the context of '" + system_path_name_ + "'");
  xd_.set_value(group, value);
  NoteChange(xd_tickets_[group]);
}

void Context::SetDiscreteState(const DiscreteValues& values) {
  xd_.SetFrom(values);
  const int64_t change_event = DependencyTracker::NewChangeEvent();
  for (int ticket : xd_tickets_) NoteChange(ticket, change_event);
}

State Context::CloneState() const {
  if (!children_.empty()) {
    throw std::logic_error("CloneState() applies to leaf contexts; '" + system_path_name_ +
                           "' is a diagram. Use diagram.GetSubsystemContext(subsystem, context).");
  }
  return State(get_continuous_state_vector(), xd_, xa_);  // abstract values shared copy-on-write
}

void Context::SetState(const State& state) {
  if (!children_.empty() || state.continuous_state().size() != xc_size_ ||
      state.discrete_state().num_groups() != xd_.num_groups() || state.num_abstract_states() != num_abstract_states()) {
    throw std::invalid_argument("SetState() on '" + system_path_name_ +
                                "': the state's structure differs from this context's; build it with CloneState().");
  }
  const int64_t change_event = DependencyTracker::NewChangeEvent();
  if (xc_size_ > 0) {
    xc_storage_->segment(xc_offset_, xc_size_) = state.continuous_state();
    NoteContinuousStateChange(change_event);
  }
  xd_.SetFrom(state.discrete_state());
  for (int ticket : xd_tickets_) NoteChange(ticket, change_event);
  // A value the state still shares with this context was not touched: its dependents' caches stay valid.
  for (std::size_t i = 0; i < xa_.size(); ++i) {
    if (state.abstract_[i] == xa_[i]) continue;
    xa_[i] = state.abstract_[i];  // shared copy-on-write, as CloneState() does
    NoteChange(xa_tickets_[i], change_event);
  }
}

const AbstractValue& Context::get_abstract_state_value(int index) const {
  ThrowIfNotLeafState("abstract state", index, num_abstract_states());
  return *xa_[index];
}

AbstractValue& Context::get_mutable_abstract_state_value(int index) {
  ThrowIfNotLeafState("abstract state", index, num_abstract_states());
  NoteChange(xa_tickets_[index]);
  std::shared_ptr<AbstractValue>& value = xa_[static_cast<std::size_t>(index)];
  if (value.use_count() > 1) value = value->Clone();  // still shared with a State cloned from this context
  return *value;
}

const Eigen::VectorXd& Context::get_numeric_parameter(int index) const {
  ThrowIfNotLeafState("numeric parameter", index, num_numeric_parameter_groups());
  return pn_[index];
}

Eigen::VectorXd& Context::get_mutable_numeric_parameter(int index) {
  ThrowIfNotLeafState("numeric parameter", index, num_numeric_parameter_groups());
  NoteChange(pn_tickets_[index]);
  return pn_[index];
}

const AbstractValue& Context::get_abstract_parameter_value(int index) const {
  ThrowIfNotLeafState("abstract parameter", index, num_abstract_parameters());
  return *pa_[index];
}

AbstractValue& Context::get_mutable_abstract_parameter_value(int index) {
  ThrowIfNotLeafState("abstract parameter", index, num_abstract_parameters());
  NoteChange(pa_tickets_[index]);
  return *pa_[index];
}

void Context::DisableCaching() { SetCachingRecursive(false); }

void Context::EnableCaching() { SetCachingRecursive(true); }

void Context::SetCachingRecursive(bool enabled) {
  if (enabled && !caching_enabled_) {
    for (auto& entry : cache_) entry.mark_out_of_date();
  }
  caching_enabled_ = enabled;
  for (auto& child : children_) child->SetCachingRecursive(enabled);
}

int64_t Context::num_calculations(DependencyTicket ticket) const {
  if (!ticket.is_valid() || ticket.index() >= static_cast<int>(cache_.size()) ||
      !cache_[ticket.index()].has_value()) {
    throw std::invalid_argument("Ticket " + cairn::FormatShort(ticket.index()) + " of '" + system_path_name_ +
                                "' is not a cached computation; pass an output port's or cache entry's ticket "
                                "(LeafSystem::output_port_ticket(), cache_entry_ticket()).");
  }
  return cache_[ticket.index()].num_calculations();
}

const Context& Context::subcontext(int index) const {
  if (index < 0 || index >= num_subcontexts()) {
    throw std::out_of_range("The context of '" + system_path_name_ + "' has " + cairn::FormatShort(num_subcontexts()) +
                            " subcontext(s); index " + cairn::FormatShort(index) + " is out of range.");
  }
  return *children_[index];
}

Context& Context::mutable_subcontext(int index) {
  return const_cast<Context&>(static_cast<const Context*>(this)->subcontext(index));
}

const AbstractValue& Context::EvalInput(int port) const {
  const InputSlot& slot = inputs_[port];
  if (slot.fixed_value) return *slot.fixed_value;
  if (slot.source_system != nullptr) return slot.source_system->DoEvalOutput(*slot.source_context, slot.source_port);
  if (slot.parent_port >= 0) return parent_->EvalInput(slot.parent_port);
  throw std::logic_error("The " + system_->get_input_port(port).GetFullDescription() +
                         " has no value: it is neither connected nor fixed. For a test of this system alone call "
                         "port.FixValue(&context, value); in a diagram, connect or export it.");
}

}  // namespace cairn::systems
