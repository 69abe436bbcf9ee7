#pragma once

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cairn/systems/framework/system.h"

namespace cairn::systems {

/// A system made of subsystems connected output-to-input; built by DiagramBuilder. A Diagram is itself a System,
/// so diagrams nest. Its input ports are subsystem inputs it exports; its outputs are subsystem outputs it
/// exports. Its context holds one subcontext per subsystem.
class Diagram : public System {
 public:
  /// (subsystem index, port index) within this diagram.
  using PortLocator = std::pair<int, int>;

  ~Diagram() override;

  int num_subsystems() const { return static_cast<int>(systems_.size()); }
  /// The subsystems in the order they were added.
  std::vector<const System*> GetSystems() const;
  /// A direct subsystem by name; throws std::invalid_argument listing the closest names.
  const System& GetSubsystemByName(const std::string& name) const;

  /// The context of `subsystem` (a direct or nested subsystem of this diagram) within this diagram's `context`.
  const Context& GetSubsystemContext(const System& subsystem, const Context& context) const;
  Context& GetMutableSubsystemContext(const System& subsystem, Context* context) const;

  /// Input-to-output connections between subsystems, keyed by input, in a stable order.
  const std::map<PortLocator, PortLocator>& connections() const { return connections_; }

 private:
  friend class DiagramBuilder;

  struct Blueprint {
    std::vector<std::unique_ptr<System>> systems;
    std::map<PortLocator, PortLocator> connections;
    std::vector<std::string> input_names;
    std::vector<std::vector<PortLocator>> exported_inputs;
    std::vector<std::string> output_names;
    std::vector<PortLocator> exported_outputs;
    std::vector<std::pair<PortLocator, std::unique_ptr<AbstractValue>>> fixed_inputs;
  };
  explicit Diagram(Blueprint blueprint);

  int IndexOf(const System& subsystem) const;  // -1 if not a direct subsystem.
  void WireSubcontexts(Context* context) const;
  void ComputeFeedthrough();
  std::string GraphvizEndpoint(int system, int port, bool input) const;

  std::unique_ptr<Context> DoAllocateContext() const final;
  const AbstractValue& DoEvalOutput(const Context& context, int port) const final;
  void DoCalcOutput(const Context& context, int port, AbstractValue* value) const final;
  int DoGetNumContinuousStates() const final { return xc_size_; }
  void DoCalcTimeDerivatives(const Context& context, Eigen::Ref<Eigen::VectorXd> derivatives) const final;
  bool DoHasDirectFeedthrough(int input, int output) const final { return feedthrough_[input][output]; }
  void DoCollectLeafSystems(Context* context, std::vector<LeafAndContext>* leaves) const final;
  void DoGetGraphviz(std::string* dot, const std::string& indent) const final;
  DependencyTracker& DoGetOutputTracker(Context* context, int port) const final;
  void DoResolveOutput(const Context& context, int port, const System** leaf, const Context** leaf_context,
                       int* leaf_port) const final;

  std::vector<std::unique_ptr<System>> systems_;
  std::map<PortLocator, PortLocator> connections_;
  std::vector<std::vector<PortLocator>> exported_inputs_;
  std::vector<PortLocator> exported_outputs_;
  std::vector<std::pair<PortLocator, std::unique_ptr<AbstractValue>>> fixed_inputs_;
  std::vector<int> xc_offsets_;
  int xc_size_{0};
  std::vector<std::vector<bool>> feedthrough_;  // [input][output]
};

}  // namespace cairn::systems
