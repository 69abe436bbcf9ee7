// `cairn friction-dataset`: writes labelled renders of MaterialScene or of the synthetic stereo source
// (StereoMaterialScene) as colour image + label-index PNG pairs, for training segmentation networks outside Cairn
// (scripts/train_material_net.py).

#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/synthetic/material_scene.h"
#include "cairn/perception/synthetic/stereo_material_scene.h"
#include "choice_option.h"
#include "command_registry.h"
#include "numeric_option.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

struct FrictionDatasetState {
  std::string out;
  int images{240};
  unsigned seed{1};
  int width{160};
  int height{120};
  double noise{2.0};
  std::string source{"material"};
  bool json{false};
};

// The files `--out` holds: labels.txt and image_NNNN.png / label_NNNN.png pairs. The folder is replaced as a
// whole (AtomicOutputDirectory), so no pair of an earlier, larger dataset survives next to the new ones.
bool IsDatasetFile(const std::string& name) {
  if (name == "labels.txt") return true;
  if (name.size() < 14 || (name.compare(0, 6, "image_") != 0 && name.compare(0, 6, "label_") != 0) ||
      name.compare(name.size() - 4, 4, ".png") != 0) {
    return false;
  }
  for (std::size_t i = 6; i + 4 < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9') return false;
  }
  return true;
}

std::string Png(const cv::Mat& image, const std::string& path) {
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", image, bytes)) throw std::runtime_error("Cannot encode '" + path + "' as PNG.");
  return std::string(bytes.begin(), bytes.end());
}

int RunFrictionDataset(const FrictionDatasetState& s) {
  using cairn::perception::MaterialScene;
  using cairn::perception::StereoMaterialScene;
  std::unique_ptr<const MaterialScene> material_scene;
  std::unique_ptr<const StereoMaterialScene> stereo_scene;
  // Scene i uses seed + i: a sum past 2^32 - 1 would wrap round to seed 0 and repeat scenes.
  constexpr std::uint64_t kMaxSeed = std::numeric_limits<unsigned>::max();
  const std::uint64_t last_seed = std::uint64_t{s.seed} + static_cast<std::uint64_t>(s.images) - 1;
  if (last_seed > kMaxSeed) {
    throw UsageError("--seed " + cairn::FormatShort(s.seed) + " with --images " + cairn::FormatShort(s.images) +
                     " would use seeds up to " + cairn::FormatShort(last_seed) + ", past " + cairn::FormatShort(kMaxSeed) +
                     "; give --seed at most " + cairn::FormatShort(kMaxSeed - static_cast<std::uint64_t>(s.images) + 1));
  }
  std::vector<std::string> labels;
  if (s.source == "material") {
    MaterialScene::Options options;
    options.width = s.width;
    options.height = s.height;
    options.noise_stddev = s.noise;
    material_scene = std::make_unique<const MaterialScene>(options);
    labels = material_scene->options().labels;
  } else if (s.source == "stereo") {
    StereoMaterialScene::Options options;
    options.width = s.width;
    options.height = s.height;
    options.noise_variance = s.noise * s.noise;
    stereo_scene = std::make_unique<const StereoMaterialScene>(options);
    labels = stereo_scene->options().labels;
  } else {
    throw std::logic_error("--source '" + s.source + "' passed its check");  // AddChoiceOption refuses it
  }
  AtomicOutputDirectory out(s.out, IsDatasetFile);
  std::string label_list;
  for (const std::string& label : labels) label_list += label + "\n";
  out.WriteFile("labels.txt", label_list);
  for (int i = 0; i < s.images; ++i) {
    const unsigned seed = s.seed + static_cast<unsigned>(i);
    cv::Mat image, label_image;
    if (material_scene) {
      MaterialScene::Rendering r = material_scene->Render(seed);
      image = r.image;
      label_image = r.labels;
    } else {
      StereoMaterialScene::Rendering r = stereo_scene->Render(seed);
      image = r.image;
      label_image = r.labels;
    }
    char name[32];
    std::snprintf(name, sizeof(name), "%04d.png", i);
    const std::string image_name = std::string("image_") + name;
    const std::string label_name = std::string("label_") + name;
    out.WriteFile(image_name, Png(image, s.out + "/" + image_name));
    out.WriteFile(label_name, Png(label_image, s.out + "/" + label_name));
  }
  out.Commit();
  if (s.json) {
    JsonWriter json;
    json.BeginObject().Key("out").String(s.out).Key("images").Integer(s.images).Key("seed").Integer(s.seed);
    json.Key("width").Integer(s.width).Key("height").Integer(s.height).Key("labels").Integer(labels.size());
    std::printf("%s\n", json.EndObject().text().c_str());
  } else {
    std::printf("wrote %d image/label pairs (%dx%d, %zu labels listed in %s/labels.txt; label 255 = none) to %s\n",
                s.images, s.width, s.height, labels.size(), s.out.c_str(), s.out.c_str());
  }
  return 0;
}

}  // namespace

void RegisterFrictionDatasetCommand(CommandRegistry* registry) {
  registry->Add("friction-dataset", "Write labelled material-scene renders (image/label PNG pairs)",
                [](CLI::App& app) -> CommandAction {
                  auto s = std::make_shared<FrictionDatasetState>();
                  app.add_option("--out", s->out,
                                 "Output folder (replaced as a whole: labels.txt, image_NNNN.png, label_NNNN.png)")
                      ->required();
                  AddNumberOption(app, "--images", &s->images, "Number of image/label pairs",
                                  NumberRange::Closed(1, 100000));
                  AddNumberOption(app, "--seed", &s->seed, "Seed of the first scene (scene i uses seed + i)",
                                  NumberRange::Closed(0, 4294967295.0));
                  AddNumberOption(app, "--width", &s->width, "Image width", NumberRange::Closed(16, 4096));
                  AddNumberOption(app, "--height", &s->height, "Image height", NumberRange::Closed(16, 4096));
                  AddNumberOption(app, "--noise", &s->noise, "Gaussian noise standard deviation (0..255)",
                                  NumberRange::Closed(0.0, 255.0));
                  AddChoiceOption(app, "--source", &s->source,
                                  "Scene renderer: 'material' (MaterialScene) or 'stereo' (the synthetic stereo "
                                  "source, StereoMaterialScene)",
                                  {"material", "stereo"});
                  app.add_flag("--json", s->json, "Print one JSON object");
                  return [s] { return RunFrictionDataset(*s); };
                });
}

}  // namespace cairn::cli
