#pragma once

/// @file
/// The simulated objects of the haptic-affordance experiments (seed 000, Fig. 10, Fig. 14, Fig. 16).

#include <cstdint>
#include <string>
#include <vector>

#include "cairn/perception/haptics/simulation/haptic_scene_object.h"

namespace cairn::perception {

/// The objects. Data set 1 is the paper's nine (a)–(i) of Fig. 10; data set 2 the two novel objects of Fig. 14;
/// the last three are the change-detection objects of Fig. 16, deep patches the robot drives through.
enum class HapticObjectKind {
  kWall,            ///< (a) non-traversable
  kRock,            ///< (b) non-traversable
  kBigPlant,        ///< (c) non-traversable: leaves around a stiff trunk
  kShrub,           ///< (d) traversable
  kSmallShrub,      ///< (e) traversable
  kTallPlants,      ///< (f) traversable
  kTallPlant,       ///< (g) traversable
  kVerticalLogs,    ///< (h) non-traversable
  kHorizontalLogs,  ///< (i) non-traversable
  kNovelGrass,      ///< data set 2, object 1: a traversable tuft of blades
  kNovelStump,      ///< data set 2, object 2: a non-traversable stump with sprouts
  kShrubPatch,      ///< Fig. 16 (A): a small shrub patch, traversable
  kFlimsyCanes,     ///< Fig. 16 (B): canes dense enough to stop the robot (the antenna bends them)
  kTwigs,           ///< Fig. 16 (C): twigs with thin leaves
};

/// The paper's name and letter of a kind, e.g. "(d) shrub".
std::string HapticObjectName(HapticObjectKind kind);

/// Parses a name as printed by HapticObjectName without the letter ("shrub", "vertical logs", ...). Throws
/// std::invalid_argument listing the names.
HapticObjectKind ParseHapticObjectKind(const std::string& name);

/// The nine objects of data set 1, (a)–(i).
std::vector<HapticObjectKind> DataSet1();
/// The two novel objects of data set 2.
std::vector<HapticObjectKind> DataSet2();

/// The object of `kind` standing on the ground at the origin of W (x forward, z up), its random details (branch
/// directions, leaf places, jitter of sizes) drawn from `seed`: the same seed gives the same object.
HapticSceneObject MakeHapticObject(HapticObjectKind kind, std::uint64_t seed);

}  // namespace cairn::perception
