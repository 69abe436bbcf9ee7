#pragma once

namespace cairn::systems {

/// Names one source of values a computation may depend on (time, a state group, an input port, a cache
/// entry, ...). Output ports and cache entries declare their prerequisites as tickets; the context keeps one
/// DependencyTracker per ticket, so a change invalidates exactly the computations that depend on it.
class DependencyTicket {
 public:
  constexpr DependencyTicket() = default;
  constexpr explicit DependencyTicket(int index) : index_(index) {}
  constexpr int index() const { return index_; }
  constexpr bool is_valid() const { return index_ >= 0; }
  constexpr bool operator==(DependencyTicket other) const { return index_ == other.index_; }
  constexpr bool operator!=(DependencyTicket other) const { return index_ != other.index_; }
  constexpr bool operator<(DependencyTicket other) const { return index_ < other.index_; }

 private:
  int index_{-1};
};

namespace internal {
// Tickets every context has, in this order; a system's own tickets (state groups, ports, cache entries) follow.
enum BuiltInTicket : int {
  kNothingTicket = 0,
  kTimeTicket,
  kContinuousStateTicket,
  kDiscreteStateTicket,
  kAbstractStateTicket,
  kAllStateTicket,
  kNumericParametersTicket,
  kAbstractParametersTicket,
  kAllParametersTicket,
  kAllInputPortsTicket,
  kAllSourcesTicket,
  kNumBuiltInTickets
};
}  // namespace internal

}  // namespace cairn::systems
