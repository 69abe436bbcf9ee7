// `cairn friction`: friction from one image — material probabilities, the friction quantile image Q_{1-eta}, and
// statistics.

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "cairn/common/atomic_output_directory.h"
#include "cairn/common/json_writer.h"
#include "cairn/common/number_text.h"
#include "cairn/perception/friction/friction_quantile_image.h"
#include "cairn/perception/friction/make_material_segmenter.h"
#include "cairn/perception/friction/material_registry.h"
#include "cairn/perception/io/image_file.h"
#include "choice_option.h"
#include "command_registry.h"
#include "data_directory.h"
#include "report_drawing.h"
#include "file_checks.h"
#include "numeric_option.h"
#include "quiet_stderr.h"

namespace cairn::cli {
namespace {

using perception::FrictionQuantileImage;
using perception::MaterialRegistry;
using perception::QuantileMethod;

// eta is a probability in (0, 1); closer to either end than this, 1 - eta rounds (1 - 1e-300 is 1) and the
// quantile is meaningless.
constexpr double kMinEta = 1e-6;

struct FrictionArguments {
  std::string image;
  std::string segmenter{"builtin"};
  std::string registry;
  double eta{0.95};
  std::string method{"exact"};
  std::string out;
  bool json{false};
};

// The files `--out` holds; the folder is replaced as a whole (AtomicOutputDirectory).
bool IsFrictionOutput(const std::string& name) {
  return name == "materials.png" || name == "friction.png" || name == "friction.json";
}

void WritePng(AtomicOutputDirectory* out, const std::string& name, const cv::Mat& image) {
  std::vector<uchar> bytes;
  if (!cv::imencode(".png", image, bytes)) {
    throw std::runtime_error("Cannot encode '" + out->path() + "/" + name + "' as PNG.");
  }
  out->WriteFile(name, std::string(bytes.begin(), bytes.end()));
}

int Run(const FrictionArguments& args) {
  CheckInputFile("--image", args.image, "an image file");
  if (!args.registry.empty()) CheckInputFile("--registry", args.registry, "a material registry YAML file");
  const std::size_t colon = args.segmenter.find(':');
  if (colon != std::string::npos && colon + 1 < args.segmenter.size()) {
    CheckInputFile("--segmenter", args.segmenter.substr(colon + 1), "a model YAML file");
  }
  // Before the work: an --out that cannot be replaced fails now, not after it.
  AtomicOutputDirectory out(args.out, IsFrictionOutput);
  // The header's size is checked against kMaxImagePixels before anything is decoded (a small file may claim
  // gigapixels); a corrupt or truncated file is one line naming it, never a decoder's own text.
  cv::Mat image;
  {
    const QuietStderr quiet;
    image = perception::ReadImageFile(args.image, cv::IMREAD_UNCHANGED);
  }
  if (image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3)) {
    throw std::invalid_argument("The image '" + args.image + "' has " + cairn::FormatShort(image.channels()) +
                                " channel(s) of depth " + cairn::FormatShort(image.depth()) +
                                "; friction needs an 8-bit grey or colour image.");
  }
  const MaterialRegistry registry =
      args.registry.empty() ? MaterialRegistry::ThesisTable33() : MaterialRegistry::LoadYaml(args.registry);
  QuantileMethod method = QuantileMethod::kExact;
  if (args.method == "search") method = QuantileMethod::kSearch;
  if (args.method == "gaussian") method = QuantileMethod::kGaussian;
  const FrictionQuantileImage quantiles(registry, {args.eta, method, 0.02, 0});
  // "builtin" alone is the model trained by `cairn friction-train` that ships in data/models.
  const std::string specification =
      args.segmenter == "builtin" ? "builtin:" + DataDirectory() + "/models/builtin_material_segmenter.yaml"
                                  : args.segmenter;
  const auto segmenter = perception::MakeMaterialSegmenter(specification);
  std::vector<int> channel_to_registry;
  for (const std::string& label : segmenter->labels()) channel_to_registry.push_back(registry.IndexOf(label));

  const auto t0 = std::chrono::steady_clock::now();
  const cv::Mat channels = segmenter->Segment(image);
  const auto t1 = std::chrono::steady_clock::now();
  const int n = registry.size();
  cv::Mat probabilities(image.rows, image.cols, CV_32FC(n));
  cv::Mat labels(image.rows, image.cols, CV_8UC3);
  std::vector<double> label_fraction(n, 0.0);
  for (int r = 0; r < image.rows; ++r) {
    const float* in = channels.ptr<float>(r);
    float* out = probabilities.ptr<float>(r);
    for (int c = 0; c < image.cols; ++c) {
      std::fill(out + c * n, out + (c + 1) * n, 0.0f);
      int best = 0;
      for (int k = 0; k < segmenter->num_labels(); ++k) {
        out[c * n + channel_to_registry[k]] = in[c * segmenter->num_labels() + k];
        if (in[c * segmenter->num_labels() + k] > in[c * segmenter->num_labels() + best]) best = k;
      }
      const int label = channel_to_registry[best];
      labels.at<cv::Vec3b>(r, c) = MaterialColour(label);
      label_fraction[label] += 1.0;
    }
  }
  const auto t2 = std::chrono::steady_clock::now();
  const cv::Mat q = quantiles.Compute(probabilities);
  const auto t3 = std::chrono::steady_clock::now();

  // Grey: white = mu 0, black = mu 1 (the thesis' convention), saturating above 1.
  cv::Mat grey(q.size(), CV_8UC1);
  double sum = 0.0, low = 1e9, high = -1e9;
  for (int r = 0; r < q.rows; ++r) {
    for (int c = 0; c < q.cols; ++c) {
      const double value = q.at<float>(r, c);
      sum += value;
      low = std::min(low, value);
      high = std::max(high, value);
      grey.at<uchar>(r, c) = cv::saturate_cast<uchar>(255.0 * (1.0 - std::min(value, 1.0)));
    }
  }
  const double pixels = static_cast<double>(q.total());
  const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  const JsonWriter::NumberFormat f6 = JsonWriter::Fixed(6);
  JsonWriter writer;
  writer.BeginObject().Key("image").String(args.image).Key("width").Integer(image.cols);
  writer.Key("height").Integer(image.rows).Key("segmenter").String(args.segmenter);
  writer.Key("eta").Number(args.eta).Key("method").String(args.method);
  writer.Key("quantile_min").Number(low, f6).Key("quantile_mean").Number(sum / pixels, f6);
  writer.Key("quantile_max").Number(high, f6);
  writer.Key("ms_segment").Number(ms(t0, t1), JsonWriter::Fixed(3));
  writer.Key("ms_quantile").Number(ms(t2, t3), JsonWriter::Fixed(3)).Key("label_fractions").BeginObject();
  for (int i = 0; i < n; ++i) writer.Key(registry.material(i).label).Number(label_fraction[i] / pixels, f6);
  writer.EndObject().Key("palette_bgr").BeginObject();
  for (int i = 0; i < n; ++i) {
    const cv::Vec3b colour = MaterialColour(i);
    writer.Key(registry.material(i).label).BeginArray();
    writer.Integer(colour[0]).Integer(colour[1]).Integer(colour[2]).EndArray();
  }
  writer.EndObject().EndObject();
  const std::string json = writer.text() + "\n";

  WritePng(&out, "materials.png", labels);
  WritePng(&out, "friction.png", grey);
  out.WriteFile("friction.json", json);
  out.Commit();
  if (args.json) {
    std::cout << json;
  } else {
    std::printf("%s: %dx%d, %s, eta %.3g (%s)\n", args.image.c_str(), image.cols, image.rows, args.segmenter.c_str(),
                args.eta, args.method.c_str());
    std::printf("  friction quantile: min %.3f, mean %.3f, max %.3f\n", low, sum / pixels, high);
    std::printf("  segmentation %.1f ms, quantiles %.1f ms\n", ms(t0, t1), ms(t2, t3));
    std::printf("  wrote %s/materials.png, friction.png (white = mu 0, black = mu 1), friction.json\n",
                args.out.c_str());
  }
  return 0;
}

}  // namespace

void RegisterFrictionCommand(CommandRegistry* registry) {
  registry->Add("friction", "Friction from one image: material probabilities and the friction quantile image",
                [](CLI::App& app) -> CommandAction {
                  auto args = std::make_shared<FrictionArguments>();
                  app.add_option("--image", args->image, "8-bit grey or colour image")->required();
                  app.add_option("--segmenter", args->segmenter,
                                 "builtin (the shipped model), builtin:MODEL.yaml or onnx:NETWORK.yaml")
                      ->capture_default_str();
                  app.add_option("--registry", args->registry,
                                 "Material registry YAML (default: the thesis' Table 3.3)");
                  AddNumberOption(app, "--eta", &args->eta, "Probability that friction is at least the quantile",
                                  NumberRange::Closed(kMinEta, 1.0 - kMinEta));
                  AddChoiceOption(app, "--method", &args->method, "Quantile method", {"exact", "search", "gaussian"});
                  app.add_option("--out", args->out,
                                 "Output folder (replaced as a whole: materials.png, friction.png, friction.json)")
                      ->required();
                  app.add_flag("--json", args->json, "Print the statistics as one JSON object");
                  return [args]() { return Run(*args); };
                });
}

}  // namespace cairn::cli
