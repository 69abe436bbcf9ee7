#pragma once

// Defaults and checks of the label sets shared by the synthetic material scenes (MaterialScene and
// StereoMaterialScene): which materials exist, which may cover the ground, which may cover boxes.

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "cairn/common/text_suggestions.h"
#include "cairn/perception/synthetic/material_texture.h"

namespace cairn::perception::internal {

/// Index of `label` in `labels`; throws naming the option (`who`: the class for the message) that holds it.
inline int IndexOfLabel(const std::vector<std::string>& labels, const std::string& label, const char* who,
                        const char* option) {
  const auto it = std::find(labels.begin(), labels.end(), label);
  if (it == labels.end()) {
    throw std::invalid_argument(std::string(who) + ": " + option + " names '" + label +
                                "', which is not in Options::labels " + QuotedList(labels) +
                                "; add it to labels or remove it from " + option + ".");
  }
  return static_cast<int>(it - labels.begin());
}

/// Fills empty sets with their defaults (every textured label; the ground: all but sky; boxes: the solid
/// materials among them, else the ground's) and checks them: at most 254 labels (an 8-bit label image keeps 255
/// for "none"), every label has a texture, and the ground and box labels are among the labels.
inline void ResolveMaterialLabelSets(const char* who, std::vector<std::string>* labels,
                                     std::vector<std::string>* ground_labels, std::vector<std::string>* box_labels) {
  if (labels->empty()) *labels = MaterialTexture::SupportedLabels();
  if (labels->size() >= 255) {
    throw std::invalid_argument(std::string(who) + ": at most 254 labels fit an 8-bit label image; got " +
                                std::to_string(labels->size()) + ".");
  }
  for (const std::string& label : *labels) MaterialTexture::PatternOf(label);  // Throws for a label without texture.
  if (ground_labels->empty()) {
    for (const std::string& label : *labels) {
      if (label != "sky") ground_labels->push_back(label);
    }
    if (ground_labels->empty()) {
      throw std::invalid_argument(std::string(who) + ": Options::labels holds only 'sky'; add ground materials.");
    }
  }
  if (box_labels->empty()) {
    for (const char* label : {"wood", "metal", "marble", "rock", "ceramic", "carpet", "cloth", "paper"}) {
      if (std::find(labels->begin(), labels->end(), label) != labels->end()) box_labels->push_back(label);
    }
    if (box_labels->empty()) *box_labels = *ground_labels;
  }
  for (const std::string& label : *ground_labels) IndexOfLabel(*labels, label, who, "ground_labels");
  for (const std::string& label : *box_labels) IndexOfLabel(*labels, label, who, "box_labels");
}

}  // namespace cairn::perception::internal
