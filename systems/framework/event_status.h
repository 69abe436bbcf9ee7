#pragma once

#include <string>
#include <utility>

namespace cairn::systems {

/// What an event handler reports (Drake's EventStatus): it did nothing, it succeeded, it reached a termination
/// condition (the Simulator stops after applying this step's updates and returns the message), or it failed (the
/// Simulator stops without applying the failed step's updates and returns the message). Handlers that return
/// void count as succeeded.
class EventStatus {
 public:
  /// In increasing severity; when several handlers run at once, the most severe status wins (the first of equals).
  enum class Severity { kDidNothing = 0, kSucceeded = 1, kReachedTermination = 2, kFailed = 3 };

  /// The handler had nothing to do.
  static EventStatus DidNothing() { return EventStatus(Severity::kDidNothing, ""); }
  /// The handler did its work.
  static EventStatus Succeeded() { return EventStatus(Severity::kSucceeded, ""); }
  /// The simulation should end normally, for `message` (e.g. "the robot fell: base 0.3 m above the soles").
  static EventStatus ReachedTermination(std::string message) {
    return EventStatus(Severity::kReachedTermination, std::move(message));
  }
  /// The handler could not do its work, for `message`; the simulation cannot go on.
  static EventStatus Failed(std::string message) { return EventStatus(Severity::kFailed, std::move(message)); }

  /// How severe the status is.
  Severity severity() const { return severity_; }
  /// The handler's message ("" for did-nothing and succeeded); the dispatcher prefixes the system's path name.
  const std::string& message() const { return message_; }
  /// True for kReachedTermination and kFailed: the Simulator stops.
  bool stops() const { return severity_ >= Severity::kReachedTermination; }
  /// True for kFailed.
  bool failed() const { return severity_ == Severity::kFailed; }

  /// Keeps the more severe of this status and `other` (this one on a tie).
  void KeepMoreSevere(const EventStatus& other) {
    if (other.severity_ > severity_) *this = other;
  }

 private:
  EventStatus(Severity severity, std::string message) : severity_(severity), message_(std::move(message)) {}

  Severity severity_;
  std::string message_;
};

}  // namespace cairn::systems
