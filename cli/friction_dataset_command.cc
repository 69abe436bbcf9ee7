// `cairn friction-dataset`: writes labelled renders of MaterialScene or of the synthetic stereo source
// (StereoMaterialScene) as colour image + label-index PNG pairs, for training segmentation networks outside Cairn
// (scripts/train_material_net.py).

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "cairn/common/atomic_file.h"
#include "cairn/perception/synthetic/material_scene.h"
#include "cairn/perception/synthetic/stereo_material_scene.h"
#include "command_registry.h"

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

int RunFrictionDataset(const FrictionDatasetState& s) {
  using cairn::perception::MaterialScene;
  using cairn::perception::StereoMaterialScene;
  if (s.images < 1) {
    throw std::invalid_argument("--images must be >= 1; got " + std::to_string(s.images) + ".");
  }
  std::unique_ptr<const MaterialScene> material_scene;
  std::unique_ptr<const StereoMaterialScene> stereo_scene;
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
    throw std::invalid_argument("--source must be 'material' (MaterialScene renders) or 'stereo' (the synthetic "
                                "stereo source's renders); got '" + s.source + "'.");
  }
  std::error_code error;
  std::filesystem::create_directories(s.out, error);
  if (error) throw std::runtime_error("cannot create --out folder '" + s.out + "': " + error.message());
  std::string label_list;
  for (const std::string& label : labels) label_list += label + "\n";
  WriteFileAtomically(s.out + "/labels.txt", label_list);
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
    const std::string image_path = s.out + "/image_" + name;
    const std::string label_path = s.out + "/label_" + name;
    if (!cv::imwrite(image_path, image) || !cv::imwrite(label_path, label_image)) {
      throw std::runtime_error("cannot write '" + image_path + "' or '" + label_path + "'; check --out.");
    }
  }
  if (s.json) {
    std::printf("{\"out\": \"%s\", \"images\": %d, \"seed\": %u, \"width\": %d, \"height\": %d, \"labels\": %zu}\n",
                s.out.c_str(), s.images, s.seed, s.width, s.height, labels.size());
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
                  app.add_option("--out", s->out, "Output folder")->required();
                  app.add_option("--images", s->images, "Number of image/label pairs")->capture_default_str();
                  app.add_option("--seed", s->seed, "Seed of the first scene (scene i uses seed + i)")
                      ->capture_default_str();
                  app.add_option("--width", s->width, "Image width")->capture_default_str();
                  app.add_option("--height", s->height, "Image height")->capture_default_str();
                  app.add_option("--noise", s->noise, "Gaussian noise standard deviation (0..255)")
                      ->capture_default_str();
                  app.add_option("--source", s->source,
                                 "Scene renderer: 'material' (MaterialScene) or 'stereo' (the synthetic stereo "
                                 "source, StereoMaterialScene)")
                      ->capture_default_str();
                  app.add_flag("--json", s->json, "Print one JSON object");
                  return [s] { return RunFrictionDataset(*s); };
                });
}

}  // namespace cairn::cli
