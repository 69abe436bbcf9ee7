#include "cairn/perception/friction/friction_estimator.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// A test double with a real rule: bright pixels are ceramic, dark ones wood, with a logistic transition, so the
// probabilities are soft and sum to 1 as a segmenter's would.
class BrightnessSegmenter final : public MaterialSegmenter {
 public:
  BrightnessSegmenter() : MaterialSegmenter({"wood", "ceramic"}) {}
  int calls() const { return calls_; }

 private:
  cv::Mat DoSegment(const cv::Mat& image) const override {
    ++calls_;
    cv::Mat grey;
    if (image.channels() == 3) {
      cv::Mat channels[3];
      cv::split(image, channels);
      grey = channels[1];
    } else {
      grey = image;
    }
    cv::Mat out(image.rows, image.cols, CV_32FC2);
    for (int r = 0; r < image.rows; ++r) {
      for (int c = 0; c < image.cols; ++c) {
        const float ceramic = 1.0f / (1.0f + std::exp(-(grey.at<uchar>(r, c) - 128.0f) / 10.0f));
        out.at<cv::Vec2f>(r, c) = cv::Vec2f(1.0f - ceramic, ceramic);
      }
    }
    return out;
  }
  mutable int calls_{0};
};

cv::Mat HalfBrightImage() {
  cv::Mat image(4, 6, CV_8UC1, cv::Scalar(30));
  image.colRange(3, 6).setTo(cv::Scalar(230));
  return image;
}

TEST(FrictionEstimatorTest, OutputsProbabilitiesAndQuantilesInRegistryOrder) {
  auto segmenter = std::make_shared<BrightnessSegmenter>();
  const auto registry = MaterialRegistry::ThesisTable33();
  FrictionEstimator estimator(registry, segmenter, {});
  auto context = estimator.CreateDefaultContext();
  estimator.GetInputPort("image").FixValue(context.get(), HalfBrightImage());
  const cv::Mat& p = estimator.GetOutputPort("material_probabilities").Eval<cv::Mat>(*context);
  ASSERT_EQ(p.channels(), 14);
  EXPECT_NEAR(p.ptr<float>(0)[0 * 14 + registry.IndexOf("wood")], 1.0, 1e-4);
  EXPECT_NEAR(p.ptr<float>(0)[5 * 14 + registry.IndexOf("ceramic")], 1.0, 1e-4);
  const cv::Mat& q = estimator.GetOutputPort("friction_quantile").Eval<cv::Mat>(*context);
  EXPECT_NEAR(q.at<float>(0, 0), 0.88 - 0.12 * 1.6448536, 1e-3);  // wood
  EXPECT_NEAR(q.at<float>(0, 5), 0.97 - 0.05 * 1.6448536, 1e-3);  // ceramic
  EXPECT_EQ(segmenter->calls(), 1);  // Both outputs share one segmentation.

  // η and the registry are parameters: changing η recomputes the quantiles, not the segmentation.
  estimator.SetEta(context.get(), 0.5);
  EXPECT_NEAR(estimator.GetOutputPort("friction_quantile").Eval<cv::Mat>(*context).at<float>(0, 0), 0.88, 1e-3);
  EXPECT_EQ(segmenter->calls(), 1);
  CAIRN_EXPECT_THROWS_WITH(estimator.SetEta(context.get(), 0.0), std::invalid_argument, "(0, 1)");
}

TEST(FrictionEstimatorTest, LearnedRegistryCanBeSwappedIn) {
  auto segmenter = std::make_shared<BrightnessSegmenter>();
  FrictionEstimator estimator(MaterialRegistry::ThesisTable33(), segmenter, {});
  auto context = estimator.CreateDefaultContext();
  estimator.GetInputPort("image").FixValue(context.get(), HalfBrightImage());
  const float before = estimator.GetOutputPort("friction_quantile").Eval<cv::Mat>(*context).at<float>(0, 5);
  auto& registry = context->get_mutable_abstract_parameter<MaterialRegistry>(estimator.registry_parameter());
  Eigen::VectorXd ceramic = Eigen::VectorXd::Zero(registry.size());
  ceramic[registry.IndexOf("ceramic")] = 1.0;
  registry.UpdateFromContact(ceramic, ContactObservation::Slipped(0.6));
  const float after = estimator.GetOutputPort("friction_quantile").Eval<cv::Mat>(*context).at<float>(0, 5);
  EXPECT_GT(before, 0.85f);
  EXPECT_LT(after, 0.6f);
}

TEST(FrictionEstimatorTest, AnnotatesWorldPointsFromDepth) {
  auto segmenter = std::make_shared<BrightnessSegmenter>();
  FrictionEstimator::Options options;
  options.with_geometry = true;
  options.camera = StereoCalibration{100.0, 100.0, 3.0, 2.0, 0.1};
  FrictionEstimator estimator(MaterialRegistry::ThesisTable33(), segmenter, options);
  auto context = estimator.CreateDefaultContext();
  estimator.GetInputPort("image").FixValue(context.get(), HalfBrightImage());
  cv::Mat depth(4, 6, CV_32F, cv::Scalar(2.0f));
  depth.at<float>(0, 0) = 0.0f;  // No depth: no point.
  estimator.GetInputPort("depth").FixValue(context.get(), depth);
  Eigen::Isometry3d X_WC = Eigen::Isometry3d::Identity();
  X_WC.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  estimator.GetInputPort("X_WC").FixValue(context.get(), X_WC);
  const auto& cloud = estimator.GetOutputPort("friction_points").Eval<FrictionPointCloud>(*context);
  ASSERT_EQ(cloud.size(), 23);
  // Pixel (row 2, col 3) is on the optical axis: 2 m ahead of a camera 1 m up its z axis.
  const int axis = 2 * 6 + 3 - 1;  // Minus the skipped pixel (0, 0).
  EXPECT_TRUE(cloud.points_W[axis].isApprox(Eigen::Vector3d(0.0, 0.0, 3.0)));
  EXPECT_EQ(cloud.weights.cols(), 14);
  EXPECT_FLOAT_EQ(cloud.quantiles[axis],
                  estimator.GetOutputPort("friction_quantile").Eval<cv::Mat>(*context).at<float>(2, 3));
  estimator.GetInputPort("depth").FixValue(context.get(), cv::Mat(2, 2, CV_32F, cv::Scalar(1.0f)));
  CAIRN_EXPECT_THROWS_WITH(estimator.GetOutputPort("friction_points").Eval<FrictionPointCloud>(*context),
                           std::invalid_argument, "depth image must be CV_32F (metres) of the image's size 6x4");
}

TEST(FrictionEstimatorTest, RejectsLabelsTheRegistryLacksAndBadImages) {
  class Unknown final : public MaterialSegmenter {
   public:
    Unknown() : MaterialSegmenter({"wood", "lava"}) {}
    cv::Mat DoSegment(const cv::Mat& image) const override { return cv::Mat(image.size(), CV_32FC2); }
  };
  CAIRN_EXPECT_THROWS_WITH(FrictionEstimator(MaterialRegistry::ThesisTable33(), std::make_shared<Unknown>(), {}),
                           std::invalid_argument, "label 'lava' is not in the material registry", "'asphalt'");
  FrictionEstimator estimator(MaterialRegistry::ThesisTable33(), std::make_shared<BrightnessSegmenter>(), {});
  auto context = estimator.CreateDefaultContext();
  estimator.GetInputPort("image").FixValue(context.get(), cv::Mat(2, 2, CV_32FC1, cv::Scalar(0.5f)));
  CAIRN_EXPECT_THROWS_WITH(estimator.GetOutputPort("friction_quantile").Eval<cv::Mat>(*context), std::invalid_argument,
                           "8-bit image with 1 or 3 channels");
  FrictionEstimator::Options bad;
  bad.eta = 1.2;
  CAIRN_EXPECT_THROWS_WITH(FrictionEstimator(MaterialRegistry::ThesisTable33(), std::make_shared<BrightnessSegmenter>(), bad),
                           std::invalid_argument, "got 1.2");
}

}  // namespace
}  // namespace cairn::perception
