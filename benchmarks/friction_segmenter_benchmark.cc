// Material segmentation per 640x480 frame: the built-in feature classifier (features alone, patch grid,
// full pixel probabilities), the tiny ONNX network through OpenCV dnn, and OpenCV ml's ANN_MLP (peer) classifying
// the same patch descriptors as the built-in perceptron.

#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <opencv2/ml.hpp>

#include "cairn/perception/friction/builtin_material_segmenter.h"
#include "cairn/perception/friction/material_features.h"
#include "cairn/perception/friction/onnx_material_segmenter.h"
#include "cairn/perception/synthetic/material_scene.h"
#include "cairn/perception/synthetic/material_texture.h"

namespace {

using namespace cairn::perception;

const MaterialScene::Rendering& Frame() {
  static const MaterialScene::Rendering frame = [] {
    MaterialScene::Options options;
    options.width = 640;
    options.height = 480;
    options.noise_stddev = 2.0;
    return MaterialScene(options).Render(12345);
  }();
  return frame;
}

// Timing does not depend on the weights, so a short training is enough.
const BuiltinMaterialSegmenter& Builtin() {
  static const BuiltinMaterialSegmenter segmenter = [] {
    MaterialScene::Options options;
    options.width = 160;
    options.height = 120;
    const MaterialScene scene(options);
    std::vector<cv::Mat> images, labels;
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
      MaterialScene::Rendering r = scene.Render(seed);
      images.push_back(r.image);
      labels.push_back(r.labels);
    }
    BuiltinMaterialSegmenter::TrainingOptions training;
    training.epochs = 2;
    return BuiltinMaterialSegmenter::Train(MaterialTexture::SupportedLabels(), images, labels, training);
  }();
  return segmenter;
}

void BM_MaterialFeatures(benchmark::State& state) {
  const MaterialFeatures features(15, 8);
  for (auto _ : state) benchmark::DoNotOptimize(features.Compute(Frame().image));
}
BENCHMARK(BM_MaterialFeatures)->Unit(benchmark::kMillisecond);

void BM_BuiltinSegmentGrid(benchmark::State& state) {
  const BuiltinMaterialSegmenter& segmenter = Builtin();
  for (auto _ : state) benchmark::DoNotOptimize(segmenter.SegmentGrid(Frame().image));
}
BENCHMARK(BM_BuiltinSegmentGrid)->Unit(benchmark::kMillisecond);

void BM_BuiltinSegmentPixels(benchmark::State& state) {
  const BuiltinMaterialSegmenter& segmenter = Builtin();
  for (auto _ : state) benchmark::DoNotOptimize(segmenter.Segment(Frame().image));
}
BENCHMARK(BM_BuiltinSegmentPixels)->Unit(benchmark::kMillisecond);

// Peer: OpenCV ml's multilayer perceptron with the same shape (20 -> 48 -> 14) on the same 4800 descriptors.
void BM_PeerOpenCvAnnMlpPredict(benchmark::State& state) {
  const cv::Mat descriptors = MaterialFeatures(15, 8).Compute(Frame().image);
  cv::Ptr<cv::ml::ANN_MLP> mlp = cv::ml::ANN_MLP::create();
  mlp->setLayerSizes(std::vector<int>{MaterialFeatures::kDimension, 48, 14});
  mlp->setActivationFunction(cv::ml::ANN_MLP::SIGMOID_SYM);
  mlp->setTermCriteria(cv::TermCriteria(cv::TermCriteria::MAX_ITER, 1, 0.0));
  cv::Mat responses = cv::Mat::zeros(descriptors.rows, 14, CV_32F);
  for (int i = 0; i < descriptors.rows; ++i) responses.at<float>(i, i % 14) = 1.0f;
  mlp->train(descriptors, cv::ml::ROW_SAMPLE, responses);
  cv::Mat out;
  for (auto _ : state) {
    mlp->predict(descriptors, out);
    benchmark::DoNotOptimize(out.data);
  }
}
BENCHMARK(BM_PeerOpenCvAnnMlpPredict)->Unit(benchmark::kMillisecond);

void BM_OnnxSegmentPixels(benchmark::State& state) {
  const OnnxMaterialSegmenter segmenter =
      OnnxMaterialSegmenter::Load(std::string(CAIRN_SOURCE_DIR) + "/data/models/tiny_material_net.yaml");
  for (auto _ : state) benchmark::DoNotOptimize(segmenter.Segment(Frame().image));
}
BENCHMARK(BM_OnnxSegmentPixels)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
