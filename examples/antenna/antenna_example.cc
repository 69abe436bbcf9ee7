#include "examples/antenna/antenna_example.h"

#include <stdexcept>

#include "cairn/common/number_text.h"
#include "cairn/perception/haptics/affordance_memory.h"
#include "cairn/perception/haptics/change_detector.h"
#include "cairn/perception/haptics/interaction_planner.h"
#include "cairn/perception/haptics/object_descriptor.h"
#include "cairn/perception/haptics/simulation/antenna_probe.h"
#include "cairn/perception/haptics/simulation/haptic_affordance_experiment.h"
#include "cairn/perception/haptics/simulation/simulated_depth_camera.h"
#include "cairn/systems/analysis/simulator.h"
#include "cairn/systems/framework/diagram_builder.h"
#include "examples/antenna/row_approach.h"

namespace cairn::examples {

using namespace cairn::perception;

namespace {

constexpr double kSpacing = 2.5;

std::vector<HapticSceneObject> Row(const AntennaExampleOptions& options) {
  std::vector<HapticSceneObject> row;
  for (std::size_t i = 0; i < options.objects.size(); ++i) {
    row.push_back(MakeHapticObject(options.objects[i], options.seed + static_cast<std::uint64_t>(options.objects[i]))
                      .Translated({kSpacing * static_cast<double>(i), 0.0, 0.0}));
  }
  return row;
}

void Check(const AntennaExampleOptions& options) {
  if (options.objects.empty() || options.objects.size() > 100) {
    throw std::invalid_argument("the antenna example needs 1 to 100 objects; got " +
                                FormatShort(options.objects.size()));
  }
  if (options.frames_per_object < 1 || options.frames_per_object > 1000 || options.passes < 1 ||
      options.passes > 100) {
    throw std::invalid_argument("frames_per_object " + FormatShort(options.frames_per_object) + " and passes " +
                                FormatShort(options.passes) + " must lie in [1, 1000] and [1, 100]");
  }
}

}  // namespace

std::unique_ptr<systems::Diagram> BuildAntennaDiagram(const AntennaExampleOptions& options) {
  Check(options);
  const HapticAffordanceExperiment::Options robot;  // sensor, antenna mount and the paper's parameters
  AffordanceDescriptor::Options descriptor_options = robot.descriptor;
  descriptor_options.reach_center_C = robot.X_CA.translation();
  const double T = options.frame_period;
  systems::DiagramBuilder builder;
  auto* row = builder.AddNamedSystem<RowApproach>("row", static_cast<int>(options.objects.size()),
                                                  options.frames_per_object, kSpacing, robot.sensor_height, T);
  auto* camera = builder.AddNamedSystem<SimulatedDepthCamera>("camera", robot.sensor, Row(options), T, options.seed);
  auto* descriptor = builder.AddNamedSystem<ObjectDescriptor>("descriptor", descriptor_options);
  auto* memory = builder.AddNamedSystem<AffordanceMemory>(
      "memory", TraversabilityMemory(robot.memory, descriptor_options.lines), T, T / 2);
  auto* planner = builder.AddNamedSystem<InteractionPlanner>("planner", robot.planner);
  auto* antenna = builder.AddNamedSystem<AntennaProbe>("antenna", robot.antenna, Row(options), robot.X_CA,
                                                       descriptor_options.lines, T, T / 4);
  auto* change = builder.AddNamedSystem<ChangeDetector>("change", GistChangeDetector::Options{}, T);
  builder.Connect(row->get_pose_output_port(), camera->get_pose_input_port());
  builder.Connect(camera->get_points_output_port(), descriptor->get_points_input_port());
  builder.Connect(descriptor->get_descriptor_output_port(), memory->get_descriptor_input_port());
  builder.Connect(antenna->get_outcome_output_port(), memory->get_outcome_input_port());
  builder.Connect(descriptor->get_object_output_port(), planner->get_object_input_port());
  builder.Connect(memory->get_recall_output_port(), planner->get_recall_input_port());
  builder.Connect(planner->get_plan_output_port(), antenna->get_plan_input_port());
  builder.Connect(descriptor->get_descriptor_output_port(), antenna->get_descriptor_input_port());
  builder.Connect(row->get_pose_output_port(), antenna->get_pose_input_port());
  builder.Connect(camera->get_points_output_port(), change->get_points_input_port());
  auto diagram = builder.Build();
  diagram->set_name("antenna");
  return diagram;
}

AntennaRun RunAntennaExample(const AntennaExampleOptions& options) {
  auto diagram = BuildAntennaDiagram(options);
  const auto& row = static_cast<const RowApproach&>(diagram->GetSubsystemByName("row"));
  const auto& memory = static_cast<const AffordanceMemory&>(diagram->GetSubsystemByName("memory"));
  const auto& antenna = static_cast<const AntennaProbe&>(diagram->GetSubsystemByName("antenna"));
  systems::Simulator simulator(*diagram);
  const double T = options.frame_period;
  AntennaRun run;
  const int frames = options.passes * options.frames_per_object * static_cast<int>(options.objects.size());
  for (int k = 0; k < frames; ++k) {
    // Just after the camera's update (k T) and before the antenna's (k T + T/4): the recall the plan uses.
    simulator.AdvanceTo(k * T + 0.1 * T);
    const systems::Context& context = simulator.get_context();
    const AffordanceRecall recall = memory.get_recall_output_port().Eval<AffordanceRecall>(
        diagram->GetSubsystemContext(memory, context));
    const double before = antenna.get_interactions_output_port().Eval<Eigen::VectorXd>(
        diagram->GetSubsystemContext(antenna, context))[0];
    simulator.AdvanceTo(k * T + 0.4 * T);
    const Eigen::VectorXd counts = antenna.get_interactions_output_port().Eval<Eigen::VectorXd>(
        diagram->GetSubsystemContext(antenna, simulator.get_context()));
    const HapticObjectKind kind = options.objects[static_cast<std::size_t>(row.ObjectAt(k * T + 0.1 * T))];
    AntennaFrame frame;
    frame.object = HapticObjectName(kind);
    frame.traversable = MakeHapticObject(kind, options.seed + static_cast<std::uint64_t>(kind)).traversable();
    frame.confidence = recall.confidence;
    frame.classified_traversable = recall.traversable;
    frame.touched_points = counts[0] > before ? static_cast<int>(counts[1]) : 0;
    run.frames.push_back(frame);
  }
  simulator.AdvanceTo(frames * T);
  run.interactions = static_cast<int>(antenna.get_interactions_output_port().Eval<Eigen::VectorXd>(
      diagram->GetSubsystemContext(antenna, simulator.get_context()))[0]);
  run.memory_size = memory.get_memory_output_port()
                        .Eval<TraversabilityMemory>(diagram->GetSubsystemContext(memory, simulator.get_context()))
                        .size();
  return run;
}

}  // namespace cairn::examples
