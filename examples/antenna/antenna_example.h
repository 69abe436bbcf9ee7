#pragma once

/// @file
/// The antenna example (seed 000): a robot approaches a row of simulated objects, describes each view, recalls
/// its memory, touches what it is unsure about and learns.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cairn/perception/haptics/simulation/haptic_object_library.h"
#include "cairn/systems/framework/diagram.h"

namespace cairn::examples {

/// Settings of the antenna example.
struct AntennaExampleOptions {
  /// The row, in order.
  std::vector<perception::HapticObjectKind> objects{
      perception::HapticObjectKind::kShrub, perception::HapticObjectKind::kRock,
      perception::HapticObjectKind::kTallPlant, perception::HapticObjectKind::kVerticalLogs};
  int frames_per_object{4};
  /// Times the robot drives the row.
  int passes{2};
  double frame_period{0.5};  ///< s
  std::uint64_t seed{1};
};

/// The diagram:
///   row (RowApproach) ─X_WC─► camera (SimulatedDepthCamera) ─points_C─► descriptor (ObjectDescriptor)
///   descriptor.descriptor ─► memory (AffordanceMemory) ─recall─► planner (InteractionPlanner) ◄─object_C─ descriptor
///   planner.plan, descriptor.descriptor, row.X_WC ─► antenna (AntennaProbe) ─outcome─► memory
///   camera.points_C ─► change (ChangeDetector)
/// The camera renders at k T, the antenna acts at k T + T/4 on that frame, the memory learns at k T + T/2.
std::unique_ptr<systems::Diagram> BuildAntennaDiagram(const AntennaExampleOptions& options);

/// One frame of a run.
struct AntennaFrame {
  std::string object;
  bool traversable{false};
  double confidence{0.0};
  bool classified_traversable{false};
  /// Targets the antenna touched after this frame (0: the memory was confident enough).
  int touched_points{0};
};

/// What a run produced.
struct AntennaRun {
  std::vector<AntennaFrame> frames;
  int interactions{0};
  int memory_size{0};
};

/// Builds the diagram and simulates every frame. Throws std::invalid_argument for invalid options.
AntennaRun RunAntennaExample(const AntennaExampleOptions& options);

}  // namespace cairn::examples
