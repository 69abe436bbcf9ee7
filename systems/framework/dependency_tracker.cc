#include "cairn/systems/framework/dependency_tracker.h"

#include <atomic>

#include "cairn/systems/framework/cache_entry_value.h"

namespace cairn::systems {

void DependencyTracker::NoteValueChange(int64_t change_event) {
  // A tracker reachable through several paths (e.g. time -> all_sources and time -> an output) is visited once.
  if (last_change_event_ == change_event) return;
  last_change_event_ = change_event;
  if (cache_value_ != nullptr) cache_value_->mark_out_of_date();
  for (DependencyTracker* subscriber : subscribers_) subscriber->NoteValueChange(change_event);
}

int64_t DependencyTracker::NewChangeEvent() {
  static std::atomic<int64_t> next_event{0};
  return next_event.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace cairn::systems
