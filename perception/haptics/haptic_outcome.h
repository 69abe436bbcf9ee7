#pragma once

/// @file
/// The outcome of one haptic interaction, as it travels from the antenna to the memory in a diagram.

#include "cairn/perception/haptics/affordance_descriptor.h"

namespace cairn::perception {

/// What the antenna learnt about the object whose descriptor it carries. `sequence` counts interactions from 0
/// (-1: none yet), so a memory adds each outcome once however often it samples its input.
struct HapticOutcome {
  int sequence{-1};
  bool traversable{false};
  AffordanceDescriptor descriptor;
};

}  // namespace cairn::perception
