#include "cairn/perception/friction/make_material_segmenter.h"

#include <stdexcept>

#include "cairn/perception/friction/builtin_material_segmenter.h"
#include "cairn/perception/friction/onnx_material_segmenter.h"

namespace cairn::perception {

std::shared_ptr<const MaterialSegmenter> MakeMaterialSegmenter(const std::string& specification) {
  const auto colon = specification.find(':');
  const std::string kind = specification.substr(0, colon);
  const std::string path = colon == std::string::npos ? std::string() : specification.substr(colon + 1);
  if ((kind == "builtin" || kind == "onnx") && path.empty()) {
    throw std::invalid_argument("The segmenter '" + specification + "' needs a file: write " + kind + ":PATH.");
  }
  if (kind == "builtin") return std::make_shared<BuiltinMaterialSegmenter>(BuiltinMaterialSegmenter::Load(path));
  if (kind == "onnx") return std::make_shared<OnnxMaterialSegmenter>(OnnxMaterialSegmenter::Load(path));
  throw std::invalid_argument("Unknown segmenter '" + specification +
                              "'; use builtin:MODEL.yaml (from cairn friction-train) or onnx:NETWORK.yaml.");
}

}  // namespace cairn::perception
