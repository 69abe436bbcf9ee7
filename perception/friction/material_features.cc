#include "cairn/common/number_text.h"
#include "cairn/perception/friction/material_features.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace cairn::perception {
namespace {

// The per-pixel maps of Compute() and their window means, kept per thread from one call to the next: an image
// stream's frames have one size, so every buffer is allocated once (about 60 MB at 640x480; allocated anew each
// frame, the page faults of memory returned to the system and taken back cost more than the features).
struct FeatureScratch {
  cv::Mat bgr, gx, gy, l1, l2, l3, cx, cy, lbp, indicator, product;
  std::vector<cv::Mat> lab;
  std::vector<cv::Mat> maps{21};
  std::vector<cv::Mat> means{21};
};

// Tables of BgrToLab.
struct LabTables {
  float linear[256];
  static constexpr int kSize = 4096;
  static constexpr float kMax = 1.1f;  // X/Xn and Z/Zn may slightly exceed 1.
  float f[kSize + 2];
  LabTables() {
    for (int v = 0; v < 256; ++v) {
      const double c = v / 255.0;
      linear[v] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    for (int i = 0; i <= kSize + 1; ++i) {
      const double t = static_cast<double>(kMax) * i / kSize;
      f[i] = static_cast<float>(t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0);
    }
  }
  float F(float t) const {
    const float x = std::clamp(t, 0.0f, kMax) * (kSize / kMax);
    const int i = static_cast<int>(x);
    return f[i] + (f[i + 1] - f[i]) * (x - static_cast<float>(i));
  }
};

// CIE L*a*b* (D65) of an 8-bit BGR image as three CV_32F planes. Written out because OpenCV 4.6's cvtColor takes
// ~20 ms for 640x480 (about half of the whole descriptor); tables for the sRGB decoding and for the cube root
// (linearly interpolated, error < 1e-4 of the L* range) make it ~10x cheaper.
void BgrToLab(const cv::Mat& bgr, std::vector<cv::Mat>* lab) {
  static const LabTables tables;
  lab->resize(3);
  for (cv::Mat& plane : *lab) plane.create(bgr.size(), CV_32F);
  for (int r = 0; r < bgr.rows; ++r) {
    const auto* in = bgr.ptr<cv::Vec3b>(r);
    float* l = (*lab)[0].ptr<float>(r);
    float* a = (*lab)[1].ptr<float>(r);
    float* b = (*lab)[2].ptr<float>(r);
    for (int c = 0; c < bgr.cols; ++c) {
      const float blue = tables.linear[in[c][0]];
      const float green = tables.linear[in[c][1]];
      const float red = tables.linear[in[c][2]];
      const float x = (0.412453f * red + 0.357580f * green + 0.180423f * blue) / 0.950456f;
      const float y = 0.212671f * red + 0.715160f * green + 0.072169f * blue;
      const float z = (0.019334f * red + 0.119193f * green + 0.950227f * blue) / 1.088754f;
      const float fx = tables.F(x);
      const float fy = tables.F(y);
      const float fz = tables.F(z);
      l[c] = 116.0f * fy - 16.0f;
      a[c] = 500.0f * (fx - fy);
      b[c] = 200.0f * (fy - fz);
    }
  }
}

}  // namespace

MaterialFeatures::MaterialFeatures(int window, int stride) : window_(window), stride_(stride) {
  if (window < 3 || window % 2 == 0 || window > kMaxWindow) {
    throw std::invalid_argument("MaterialFeatures: the window must be odd and in [3, " + cairn::FormatShort(kMaxWindow) +
                                "] pixels; got " + cairn::FormatShort(window) + ". Try 15.");
  }
  if (stride < 1 || stride > kMaxStride) {
    throw std::invalid_argument("MaterialFeatures: the stride must be in [1, " + cairn::FormatShort(kMaxStride) +
                                "] pixels; got " + cairn::FormatShort(stride) + ". Try 8.");
  }
}

cv::Size MaterialFeatures::GridSize(cv::Size image) const {
  return {(image.width + stride_ - 1) / stride_, (image.height + stride_ - 1) / stride_};
}

int MaterialFeatures::CentreOf(int i, int extent) const { return std::min(i * stride_ + stride_ / 2, extent - 1); }

cv::Mat MaterialFeatures::Compute(const cv::Mat& image) const {
  if (image.empty() || image.depth() != CV_8U || (image.channels() != 1 && image.channels() != 3)) {
    throw std::invalid_argument("MaterialFeatures: needs a non-empty 8-bit image with 1 or 3 channels; got " +
                                cairn::FormatShort(image.rows) + "x" + cairn::FormatShort(image.cols) + " with depth " +
                                cairn::FormatShort(image.depth()) + " and " + cairn::FormatShort(image.channels()) +
                                " channel(s).");
  }
  if (image.cols < window_ || image.rows < window_) {
    throw std::invalid_argument("Material segmentation: the image is " + cairn::FormatShort(image.cols) + "x" +
                                cairn::FormatShort(image.rows) + " pixels, smaller than the segmenter's " +
                                cairn::FormatShort(window_) + "x" + cairn::FormatShort(window_) +
                                " patch window; give an image at least that large or a model with a smaller window.");
  }
  thread_local FeatureScratch scratch;
  FeatureScratch& w = scratch;
  const cv::Mat* bgr = &image;
  if (image.channels() == 1) {
    cv::cvtColor(image, w.bgr, cv::COLOR_GRAY2BGR);
    bgr = &w.bgr;
  }
  BgrToLab(*bgr, &w.lab);

  // Per-pixel maps whose window means are the features (second moments give the standard deviations).
  std::vector<cv::Mat>& maps = w.maps;
  for (int k = 0; k < 3; ++k) {
    w.lab[static_cast<std::size_t>(k)].copyTo(maps[static_cast<std::size_t>(k)]);
    cv::multiply(w.lab[static_cast<std::size_t>(k)], w.lab[static_cast<std::size_t>(k)], maps[static_cast<std::size_t>(3 + k)]);
  }
  const cv::Mat& l = w.lab[0];
  cv::Sobel(l, w.gx, CV_32F, 1, 0, 3, 0.125, 0.0, cv::BORDER_REFLECT);
  cv::Sobel(l, w.gy, CV_32F, 0, 1, 3, 0.125, 0.0, cv::BORDER_REFLECT);
  cv::multiply(w.gx, w.gx, maps[6]);
  cv::multiply(w.gy, w.gy, w.product);
  cv::add(maps[6], w.product, maps[6]);  // 6: fine gradient energy
  cv::GaussianBlur(l, w.l1, cv::Size(0, 0), 1.0, 1.0, cv::BORDER_REFLECT);
  cv::GaussianBlur(l, w.l3, cv::Size(0, 0), 3.0, 3.0, cv::BORDER_REFLECT);
  cv::GaussianBlur(l, w.l2, cv::Size(0, 0), 2.0, 2.0, cv::BORDER_REFLECT);
  cv::Sobel(w.l2, w.cx, CV_32F, 1, 0, 3, 0.125, 0.0, cv::BORDER_REFLECT);
  cv::Sobel(w.l2, w.cy, CV_32F, 0, 1, 3, 0.125, 0.0, cv::BORDER_REFLECT);
  cv::multiply(w.cx, w.cx, maps[7]);
  cv::multiply(w.cy, w.cy, w.product);
  cv::add(maps[7], w.product, maps[7]);  // 7: coarse gradient energy
  cv::multiply(w.gx, w.gx, maps[8]);
  cv::multiply(w.gy, w.gy, w.product);
  cv::subtract(maps[8], w.product, maps[8]);  // 8: structure tensor Jxx - Jyy
  cv::multiply(w.gx, w.gy, maps[9], 2.0);      // 9: 2 Jxy
  cv::absdiff(l, w.l1, maps[10]);              // 10: fine band
  cv::absdiff(w.l1, w.l3, maps[11]);           // 11: coarse band
  // Rotation-invariant LBP: number of 8-neighbours brighter than the centre (by more than a small margin, so
  // flat regions and sensor noise fall in well-defined bins).
  w.lbp.create(l.size(), CV_8U);
  cv::Mat& lbp = w.lbp;
  const int rows = l.rows;
  const int cols = l.cols;
  for (int r = 0; r < rows; ++r) {
    const float* up = l.ptr<float>(std::max(r - 1, 0));
    const float* mid = l.ptr<float>(r);
    const float* dn = l.ptr<float>(std::min(r + 1, rows - 1));
    auto* out = lbp.ptr<std::uint8_t>(r);
    for (int c = 0; c < cols; ++c) {
      const int cl = std::max(c - 1, 0);
      const int cr = std::min(c + 1, cols - 1);
      const float centre = mid[c] + 0.5f;
      out[c] = static_cast<std::uint8_t>((up[cl] > centre) + (up[c] > centre) + (up[cr] > centre) +
                                         (mid[cl] > centre) + (mid[cr] > centre) + (dn[cl] > centre) +
                                         (dn[c] > centre) + (dn[cr] > centre));
    }
  }
  for (int bin = 0; bin <= 8; ++bin) {
    cv::compare(lbp, bin, w.indicator, cv::CMP_EQ);  // 0 or 255
    w.indicator.convertTo(maps[static_cast<std::size_t>(12 + bin)], CV_32F, 1.0 / 255.0);  // 12..20
  }

  // Window means, sampled at the grid centres.
  const cv::Size grid = GridSize(image.size());
  cv::Mat features(grid.area(), kDimension, CV_32F);
  std::vector<cv::Mat>& means = w.means;
  for (std::size_t k = 0; k < maps.size(); ++k) {
    cv::boxFilter(maps[k], means[k], CV_32F, cv::Size(window_, window_), cv::Point(-1, -1), true, cv::BORDER_REFLECT);
  }
  for (int gr = 0; gr < grid.height; ++gr) {
    const int r = CentreOf(gr, rows);
    for (int gc = 0; gc < grid.width; ++gc) {
      const int c = CentreOf(gc, cols);
      float* f = features.ptr<float>(gr * grid.width + gc);
      float m[21];
      for (int k = 0; k < 21; ++k) m[k] = means[static_cast<std::size_t>(k)].ptr<float>(r)[c];
      for (int k = 0; k < 3; ++k) {
        f[k] = m[k];
        f[3 + k] = std::sqrt(std::max(0.0f, m[3 + k] - m[k] * m[k]));
      }
      f[6] = std::log1p(m[6]);
      f[7] = std::log1p(m[7]);
      // Coherence of the window's structure tensor: |(Jxx - Jyy, 2 Jxy)| / (Jxx + Jyy).
      f[8] = std::sqrt(m[8] * m[8] + m[9] * m[9]) / (m[6] + 1e-3f);
      f[9] = std::log1p(m[10]);
      f[10] = std::log1p(m[11]);
      for (int k = 0; k < 9; ++k) f[11 + k] = m[12 + k];
    }
  }
  return features;
}

}  // namespace cairn::perception
