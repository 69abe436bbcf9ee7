#pragma once

#include <memory>
#include <string>

#include "cairn/perception/friction/material_segmenter.h"

namespace cairn::perception {

/// Creates a segmenter from a specification, for configuration files and the command line:
/// - "builtin:PATH": a BuiltinMaterialSegmenter saved by `cairn friction-train` (BuiltinMaterialSegmenter::Save);
/// - "onnx:PATH": an OnnxMaterialSegmenter described by the YAML file PATH.
/// Throws std::invalid_argument for an unknown kind (listing the known ones) and whatever the loaders throw for
/// missing or malformed files.
std::shared_ptr<const MaterialSegmenter> MakeMaterialSegmenter(const std::string& specification);

}  // namespace cairn::perception
