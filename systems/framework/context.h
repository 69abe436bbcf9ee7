#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cairn/systems/framework/cache_entry_value.h"
#include "cairn/systems/framework/dependency_ticket.h"
#include "cairn/systems/framework/dependency_tracker.h"
#include "cairn/systems/framework/discrete_values.h"
#include "cairn/systems/framework/state.h"
#include "cairn/systems/framework/value.h"

namespace cairn::systems {

class System;

/// Every runtime value of a system: time, continuous/discrete/abstract state, numeric and abstract parameters,
/// fixed input values and the cache. Systems hold no runtime values, so one system can be evaluated in many
/// contexts (e.g. one per thread, or a clone per rollout).
///
/// A context is created by its system (System::CreateDefaultContext()) and may only be used with that system;
/// the system must outlive it. A Diagram's context holds one subcontext per subsystem
/// (Diagram::GetSubsystemContext()); its continuous state is the concatenation of its subsystems', stored
/// contiguously so integrators see one vector. Discrete state, abstract state and parameters live in the leaf
/// contexts.
///
/// Mutable accessors (get_mutable_*, Set*) count as a change of that value: the cache entries that depend on it
/// are invalidated before the accessor returns.
class Context {
 public:
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  /// Returns an independent copy with the same values (state, parameters, fixed inputs, cache). Only a root
  /// context can be cloned, since a subcontext's inputs come from its siblings.
  std::unique_ptr<Context> Clone() const;

  /// Copies every value from `source`, a context of the same system (e.g. a clone made earlier).
  void SetFrom(const Context& source);

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Time
  double get_time() const { return time_; }
  /// Sets the time of this context and all its subcontexts; throws std::invalid_argument unless `time` is finite.
  void SetTime(double time);

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Continuous state (for a diagram: all subsystems' continuous states, concatenated)
  int num_continuous_states() const { return xc_size_; }
  Eigen::VectorBlock<const Eigen::VectorXd> get_continuous_state_vector() const;
  /// Returns the state for writing; counts as a change of it.
  Eigen::VectorBlock<Eigen::VectorXd> get_mutable_continuous_state_vector();
  /// Throws std::invalid_argument if the size differs or an element is NaN or infinite (naming it).
  void SetContinuousState(const Eigen::Ref<const Eigen::VectorXd>& x);

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Discrete state (leaf systems)
  int num_discrete_state_groups() const { return xd_.num_groups(); }
  const DiscreteValues& get_discrete_state() const { return xd_; }
  const Eigen::VectorXd& get_discrete_state(int group) const;
  Eigen::VectorXd& get_mutable_discrete_state(int group);
  /// Sets group `group`; throws std::invalid_argument if the size differs or an element is NaN or infinite.
  void SetDiscreteState(int group, const Eigen::Ref<const Eigen::VectorXd>& value);
  /// Sets every group (e.g. from a discrete update's result). Values are not checked for finiteness: updates
  /// compute them, and a diverging one shows in the continuous state, which the integrators check.
  void SetDiscreteState(const DiscreteValues& values);

  /// A copy of this leaf context's whole state (as unrestricted update events receive it).
  State CloneState() const;
  /// Sets this leaf context's whole state; `state` must have the structure CloneState() gives. An abstract value
  /// `state` still shares with this context (cloned and not written since) is left as it is, so what depends only
  /// on it keeps its cached values.
  void SetState(const State& state);

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Abstract state (leaf systems)
  int num_abstract_states() const { return static_cast<int>(xa_.size()); }
  const AbstractValue& get_abstract_state_value(int index) const;
  AbstractValue& get_mutable_abstract_state_value(int index);
  template <typename T>
  const T& get_abstract_state(int index) const {
    return get_abstract_state_value(index).get_value<T>();
  }
  template <typename T>
  T& get_mutable_abstract_state(int index) {
    return get_mutable_abstract_state_value(index).get_mutable_value<T>();
  }

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Parameters (leaf systems)
  int num_numeric_parameter_groups() const { return static_cast<int>(pn_.size()); }
  const Eigen::VectorXd& get_numeric_parameter(int index) const;
  Eigen::VectorXd& get_mutable_numeric_parameter(int index);
  int num_abstract_parameters() const { return static_cast<int>(pa_.size()); }
  const AbstractValue& get_abstract_parameter_value(int index) const;
  AbstractValue& get_mutable_abstract_parameter_value(int index);
  template <typename T>
  const T& get_abstract_parameter(int index) const {
    return get_abstract_parameter_value(index).get_value<T>();
  }
  template <typename T>
  T& get_mutable_abstract_parameter(int index) {
    return get_mutable_abstract_parameter_value(index).get_mutable_value<T>();
  }

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Caching
  /// With caching off every Eval recomputes; results are identical either way. Applies to all subcontexts.
  void DisableCaching();
  /// Turns caching back on; every cached value is marked out of date first.
  void EnableCaching();
  bool is_caching_enabled() const { return caching_enabled_; }
  /// Number of times cached computation `ticket` (an output port's or cache entry's) ran in this context.
  int64_t num_calculations(DependencyTicket ticket) const;

  // ---------------------------------------------------------------------------------------------------------------
  /// @name Structure
  bool is_root() const { return parent_ == nullptr; }
  int num_subcontexts() const { return static_cast<int>(children_.size()); }
  const Context& subcontext(int index) const;
  Context& mutable_subcontext(int index);
  /// Id of the system that created this context (System::id()).
  int64_t system_id() const { return system_id_; }
  /// Path name of the system that created this context, for messages.
  const std::string& system_path_name() const { return system_path_name_; }

 private:
  friend class System;
  friend class LeafSystem;
  friend class Diagram;
  friend class InputPort;

  // Where an input port's value comes from when it is not fixed.
  struct InputSlot {
    std::unique_ptr<AbstractValue> fixed_value;
    const System* source_system{nullptr};  // Leaf system owning the connected output, resolved through diagrams.
    const Context* source_context{nullptr};
    int source_port{-1};
    int parent_port{-1};  // >= 0: exported as this input of the parent diagram.
    std::string source_description;  // For messages about connected ports.
  };

  Context(const System* system, int num_tickets);

  void NoteChange(int ticket);
  void NoteChange(int ticket, int64_t change_event);
  void NoteContinuousStateChange(int64_t change_event);
  void SetTimeRecursive(double time, int64_t change_event);
  void SetCachingRecursive(bool enabled);
  void BindContinuousStorage(Eigen::VectorXd* storage, int offset);
  void CopyValuesFrom(const Context& source);
  void ThrowIfNotLeafState(const char* what, int index, int count) const;
  const AbstractValue& EvalInput(int port) const;
  DependencyTracker& tracker(int ticket) { return trackers_[ticket]; }

  const System* system_{nullptr};
  int64_t system_id_{-1};
  std::string system_path_name_;
  Context* parent_{nullptr};
  double time_{0.0};

  Eigen::VectorXd owned_xc_;
  Eigen::VectorXd* xc_storage_{&owned_xc_};
  int xc_offset_{0};
  int xc_size_{0};
  std::vector<int> child_xc_offsets_;

  DiscreteValues xd_;
  std::vector<int> xd_tickets_;
  // Shared copy-on-write with States cloned from this context (see State); never with another context, so a
  // context and its clones stay independent across threads.
  std::vector<std::shared_ptr<AbstractValue>> xa_;
  std::vector<int> xa_tickets_;
  std::vector<Eigen::VectorXd> pn_;
  std::vector<int> pn_tickets_;
  std::vector<std::unique_ptr<AbstractValue>> pa_;
  std::vector<int> pa_tickets_;

  std::vector<InputSlot> inputs_;

  // Indexed by ticket; only tickets of cached computations have a value.
  mutable std::vector<CacheEntryValue> cache_;
  // Per-context storage written by publish events (loggers); not state, not cache (LeafSystem docs).
  mutable std::vector<std::unique_ptr<AbstractValue>> per_context_storage_;
  bool caching_enabled_{true};

  std::vector<DependencyTracker> trackers_;
  std::vector<std::unique_ptr<Context>> children_;
};

}  // namespace cairn::systems
