#pragma once

#include "cairn/systems/framework/diagram_builder.h"
#include "cairn/systems/framework/leaf_system.h"
#include "cairn/systems/primitives/vector_log.h"

namespace cairn::systems {

/// Records its input over time, in the context (so each context — each simulation — has its own log).
///
/// | port | type | meaning |
/// |---|---|---|
/// | input `data` | vector of size n | signal to record |
///
/// With publish_period = 0 it records at initialization and after every simulator step; otherwise at
/// t = 0, period, 2 period, ... Each context's log holds at most `capacity` samples (VectorLog); recording one
/// more fails the simulation with a message naming the capacity.
class VectorLogSink final : public LeafSystem {
 public:
  /// Throws std::invalid_argument unless size >= 1, publish_period is finite and >= 0, and capacity >= 1.
  explicit VectorLogSink(int size, double publish_period = 0.0, int capacity = VectorLog::kDefaultCapacity);

  const VectorLog& GetLog(const Context& context) const;
  VectorLog& GetMutableLog(const Context& context) const;

 private:
  void WriteToLog(const Context& context) const;
  int log_index_{-1};
};

/// Adds a VectorLogSink recording `port` (publish_period and capacity as in VectorLogSink) and returns it.
VectorLogSink* LogVectorOutput(const OutputPort& port, DiagramBuilder* builder, double publish_period = 0.0,
                               int capacity = VectorLog::kDefaultCapacity);

}  // namespace cairn::systems
