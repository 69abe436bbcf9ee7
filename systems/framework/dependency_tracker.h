#pragma once

#include <cstdint>
#include <vector>

namespace cairn::systems {

class CacheEntryValue;

/// One node of a context's dependency graph. When the value it tracks changes, NoteValueChange() marks its cache
/// entry (if any) out of date and notifies its subscribers, once per change event however many paths reach it.
/// Trackers are owned by contexts and never move after the context is built, so subscribers hold plain pointers.
class DependencyTracker {
 public:
  DependencyTracker() = default;

  /// Makes this tracker a subscriber of `prerequisite`.
  void SubscribeTo(DependencyTracker* prerequisite) { prerequisite->subscribers_.push_back(this); }

  /// Associates the cache entry this tracker invalidates.
  void set_cache_value(CacheEntryValue* value) { cache_value_ = value; }

  /// Propagates a change. `change_event` identifies one user-visible change (NewChangeEvent()).
  void NoteValueChange(int64_t change_event);

  /// Returns a fresh change-event id (process-wide, thread-safe).
  static int64_t NewChangeEvent();

 private:
  std::vector<DependencyTracker*> subscribers_;
  CacheEntryValue* cache_value_{nullptr};
  int64_t last_change_event_{-1};
};

}  // namespace cairn::systems
