#include "cairn/systems/primitives/vector_log_sink.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "cairn/common/number_text.h"

namespace cairn::systems {

VectorLogSink::VectorLogSink(int size, double publish_period, int capacity) {
  if (size < 1) throw std::invalid_argument("VectorLogSink: size must be positive; got " + std::to_string(size) + ".");
  if (!(publish_period >= 0.0) || !std::isfinite(publish_period)) {
    throw std::invalid_argument("VectorLogSink: publish_period must be >= 0 and finite (0 = every step); got " +
                                FormatShort(publish_period) + ".");
  }
  if (capacity < 1) {
    throw std::invalid_argument("VectorLogSink: capacity must be >= 1 sample; got " + std::to_string(capacity) + ".");
  }
  DeclareVectorInputPort("data", size);
  log_index_ = DeclarePerContextStorage(Value<VectorLog>(VectorLog(size, capacity)));
  if (publish_period > 0.0) {
    DeclarePeriodicPublishEvent(publish_period, 0.0, &VectorLogSink::WriteToLog);
  } else {
    DeclarePerStepPublishEvent(&VectorLogSink::WriteToLog);
  }
  DeclareForcedPublishEvent(&VectorLogSink::WriteToLog);
}

const VectorLog& VectorLogSink::GetLog(const Context& context) const {
  return GetPerContextStorage<VectorLog>(context, log_index_);
}

VectorLog& VectorLogSink::GetMutableLog(const Context& context) const {
  return GetMutablePerContextStorage<VectorLog>(context, log_index_);
}

void VectorLogSink::WriteToLog(const Context& context) const {
  GetMutableLog(context).AddData(context.get_time(), get_input_port().Eval<Eigen::VectorXd>(context));
}

VectorLogSink* LogVectorOutput(const OutputPort& port, DiagramBuilder* builder, double publish_period,
                               int capacity) {
  if (builder == nullptr) throw std::invalid_argument("LogVectorOutput: builder must not be null.");
  if (port.get_data_type() != PortDataType::kVector) {
    throw std::invalid_argument("LogVectorOutput: the " + port.GetFullDescription() + " carries an " +
                                port.GetTypeDescription() + "; only vector ports can be logged.");
  }
  auto* sink = builder->AddSystem<VectorLogSink>(port.size(), publish_period, capacity);
  builder->Connect(port, sink->get_input_port());
  return sink;
}

}  // namespace cairn::systems
