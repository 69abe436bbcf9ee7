#include "cairn/perception/synthetic/material_texture.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::perception {
namespace {

// Mean colour of a texture over a 1 m square, sampled on a 2 mm grid.
Eigen::Vector3d MeanColour(const MaterialTexture& texture) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) {
      sum += texture.Evaluate(0.0101 * i, 0.0097 * j);
      ++n;
    }
  }
  return sum / n;
}

TEST(MaterialTextureTest, EveryLabelHasATextureInRangeAndDeterministic) {
  ASSERT_EQ(MaterialTexture::SupportedLabels().size(), 14u);
  for (const std::string& label : MaterialTexture::SupportedLabels()) {
    const MaterialTexture a = MaterialTexture::Make(label, 5);
    const MaterialTexture b = MaterialTexture::Make(label, 5);
    EXPECT_EQ(a.label(), label);
    EXPECT_EQ(MaterialTexture::LabelOf(MaterialTexture::PatternOf(label)), label);
    for (int i = 0; i < 200; ++i) {
      const double u = 0.37 * i - 11.0;
      const double v = 0.21 * i + 3.0;
      const Eigen::Vector3d colour = a.Evaluate(u, v);
      EXPECT_EQ(colour, b.Evaluate(u, v)) << label;
      EXPECT_GE(colour.minCoeff(), 0.0) << label;
      EXPECT_LE(colour.maxCoeff(), 255.0) << label;
    }
  }
}

TEST(MaterialTextureTest, SeedsVaryScaleOrientationAndColourWithinBounds) {
  for (const std::string& label : MaterialTexture::SupportedLabels()) {
    double min_scale = 10.0;
    double max_scale = 0.0;
    int distinct_colours = 0;
    const MaterialTexture first = MaterialTexture::Make(label, 0);
    for (std::uint32_t seed = 0; seed < 30; ++seed) {
      const MaterialTexture t = MaterialTexture::Make(label, seed);
      min_scale = std::min(min_scale, t.parameters().scale);
      max_scale = std::max(max_scale, t.parameters().scale);
      if ((t.parameters().base_bgr - first.parameters().base_bgr).norm() > 1.0) ++distinct_colours;
    }
    EXPECT_GE(min_scale, 0.7) << label;
    EXPECT_LE(max_scale, 1.4) << label;
    EXPECT_GT(max_scale - min_scale, 0.3) << label;
    EXPECT_GE(distinct_colours, 25) << label;
  }
}

TEST(MaterialTextureTest, MaterialsHaveTheirCharacteristicColours) {
  // BGR: grass is green, water and sky are blue-ish, sand is yellow, snow and paper are bright, asphalt is dark.
  for (std::uint32_t seed = 0; seed < 5; ++seed) {
    const Eigen::Vector3d grass = MeanColour(MaterialTexture::Make("grass", seed));
    EXPECT_GT(grass[1], grass[2]);
    EXPECT_GT(grass[1], grass[0]);
    const Eigen::Vector3d sky = MeanColour(MaterialTexture::Make("sky", seed));
    EXPECT_GT(sky[0], sky[2]);
    const Eigen::Vector3d sand = MeanColour(MaterialTexture::Make("sand", seed));
    EXPECT_GT(sand[2], sand[0]);
    EXPECT_GT(MaterialTexture::Make("snow", seed).Evaluate(0.3, 0.4).mean(), 150.0);
    EXPECT_LT(MeanColour(MaterialTexture::Make("asphalt", seed)).mean(), 110.0);
  }
}

TEST(MaterialTextureTest, TexturedMaterialsVaryAndSmoothOnesDoNot) {
  auto spread = [](const MaterialTexture& t) {
    double sum = 0.0;
    double sum2 = 0.0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
      const double g = t.Evaluate(0.0013 * i, 0.0007 * i + 0.1).mean();
      sum += g;
      sum2 += g * g;
    }
    return std::sqrt(sum2 / n - (sum / n) * (sum / n));
  };
  EXPECT_GT(spread(MaterialTexture::Make("wood", 3)), 2.0 * spread(MaterialTexture::Make("paper", 3)));
  EXPECT_GT(spread(MaterialTexture::Make("rock", 3)), 2.0 * spread(MaterialTexture::Make("paper", 3)));
}

TEST(MaterialTextureTest, ErrorsNameTheBadValue) {
  CAIRN_EXPECT_THROWS_WITH(MaterialTexture::Make("wod", 1), std::invalid_argument, "'wod'", "did you mean 'wood'");
  CAIRN_EXPECT_THROWS_WITH(MaterialTexture::PatternOf("Grass"), std::invalid_argument, "'Grass'", "'grass'");
  MaterialTexture::Parameters parameters;
  parameters.scale = 0.0;
  CAIRN_EXPECT_THROWS_WITH(MaterialTexture(MaterialTexture::Pattern::kWood, parameters), std::invalid_argument,
                           "scale must be positive", "got 0");
}

}  // namespace
}  // namespace cairn::perception
