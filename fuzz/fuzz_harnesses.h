#pragma once

/// @file
/// The fuzz harnesses: one entry point per parser of user files, shared by the libFuzzer targets (fuzz/, built
/// with CAIRN_FUZZ=ON) and by the regression test (test/fuzz/), so that a crashing input found by a fuzzer is
/// replayed through exactly the code that found it.
///
/// Each entry point feeds `input` to its parser (through a scratch file when the parser takes a path) and then
/// uses what was parsed a little, the way the parser's callers do, so that an input the parser accepts but
/// should have refused shows up too. A harness returns normally for a valid input and lets the parser's
/// std::exception through for an invalid one; anything else (a sanitizer report, a signal, an exception not
/// derived from std::exception, a hang, an allocation beyond the fuzzer's limit) is a bug.

#include <string>
#include <string_view>
#include <vector>

namespace cairn::fuzz {

/// URDF text through multibody::ParseUrdfString, with a fixed and with a floating base (packages and meshes
/// resolved against data/robots/), then forward kinematics and the centre of mass at the neutral configuration.
void FuzzUrdf(std::string_view input);

/// A footstep scenario YAML through planning::FootstepScenario::Load.
void FuzzFootstepScenario(std::string_view input);

/// An occupancy scenario YAML through perception::OccupancyScenario::FromYaml.
void FuzzOccupancyScenario(std::string_view input);

/// A walking model YAML through planning::WalkingModel::Load; its folder holds the humanoid's URDF as
/// cairn_humanoid.urdf, so the shipped model's relative `urdf` key resolves.
void FuzzWalkingModel(std::string_view input);

/// A material registry YAML through perception::MaterialRegistry::LoadYaml, then a lookup of each label.
void FuzzMaterialRegistry(std::string_view input);

/// A builtin segmenter model (YAML) through perception::BuiltinMaterialSegmenter::Load, then Segment() on a
/// small image.
void FuzzBuiltinSegmenter(std::string_view input);

/// An ONNX segmenter description (YAML) through perception::OnnxMaterialSegmenter::Load; its folder holds the
/// shipped network as tiny_material_net.onnx. (The .onnx file itself is parsed by OpenCV, not by Cairn.)
void FuzzOnnxSegmenter(std::string_view input);

/// A transition oracle file through planning::TransitionOracle::Load for the humanoid's walking model, the
/// ecom_heat objective and a fixed 8-entry grid (dx {0, 0.1}, dy {0.2, 0.25}, dz {0}, dtheta {0}, mu {0.5, 1}),
/// then a few lookups and bounds. Before loading, the harness rewrites the
/// header's checksum line (when there is one) to the checksum of the bytes after the header's "end" line:
/// otherwise all but one payload mutation in 2^64 would stop at the checksum and the payload's decoding would go
/// untested. The checksum check itself is covered by the unit tests.
void FuzzTransitionOracle(std::string_view input);

/// A ground-truth disparity PNG through perception::LoadDisparityImage (scale 8, as for Middlebury), then the
/// occlusion check of the map against itself, as MiddleburyPair::Load does with a pair's two maps.
void FuzzDisparityPng(std::string_view input);

/// A starting input of a fuzzer: a file the project ships (or generates) that its parser accepts.
struct FuzzSeed {
  /// File name for the corpus folder.
  std::string name;
  std::string contents;
};

/// One fuzz target: its name (the fuzzer is cairn_fuzz_<name>; its hand-written extra seeds, dictionary and
/// crashing inputs live in fuzz/corpus/<name>/, fuzz/dict/<name>.dict and fuzz/regressions/<name>/), its entry
/// point, and its seeds from the repository (and shared/data).
struct FuzzTarget {
  std::string name;
  void (*run)(std::string_view input);
  /// Reads (or builds) the seeds; throws std::runtime_error naming a shipped file that is missing.
  std::vector<FuzzSeed> (*seeds)();
};

/// Every target, in a fixed order.
const std::vector<FuzzTarget>& FuzzTargets();

}  // namespace cairn::fuzz
