#include "cairn/perception/synthetic/material_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>

#include "cairn/common/text_suggestions.h"
#include "cairn/perception/synthetic/internal/material_label_sets.h"
#include "cairn/perception/synthetic/material_texture.h"

namespace cairn::perception {
namespace {

constexpr double kPi = 3.141592653589793;

int IndexIn(const std::vector<std::string>& labels, const std::string& label, const char* option) {
  return internal::IndexOfLabel(labels, label, "MaterialScene", option);
}

struct Region {
  Eigen::Vector2d site;
  int label;
  MaterialTexture texture;
};

struct Box {
  Eigen::Vector3d lower;
  Eigen::Vector3d upper;
  int label;
  MaterialTexture texture;
};

// Surface hit by a ray: colour before lighting, label, and the Lambertian shading factor.
struct Hit {
  Eigen::Vector3d colour;
  int label;
  double shading;
};

}  // namespace

MaterialScene::MaterialScene(Options options) : options_(std::move(options)) {
  Options& o = options_;
  if (o.width <= 0 || o.height <= 0) {
    throw std::invalid_argument("MaterialScene: the image size must be positive; got " + std::to_string(o.width) +
                                "x" + std::to_string(o.height) + ".");
  }
  if (!(o.field_of_view_deg > 10.0 && o.field_of_view_deg < 150.0)) {
    throw std::invalid_argument("MaterialScene: field_of_view_deg must be in (10, 150); got " +
                                std::to_string(o.field_of_view_deg) + ".");
  }
  if (o.num_regions < 1) {
    throw std::invalid_argument("MaterialScene: num_regions must be at least 1; got " +
                                std::to_string(o.num_regions) + ".");
  }
  if (o.num_boxes < 0) {
    throw std::invalid_argument("MaterialScene: num_boxes must be >= 0; got " + std::to_string(o.num_boxes) + ".");
  }
  if (!(o.noise_stddev >= 0.0) || !std::isfinite(o.noise_stddev)) {
    throw std::invalid_argument("MaterialScene: noise_stddev must be >= 0; got " + std::to_string(o.noise_stddev) +
                                ". Use 0 for noiseless renders.");
  }
  if (o.samples_per_axis < 1 || o.samples_per_axis > 8) {
    throw std::invalid_argument("MaterialScene: samples_per_axis must be in [1, 8]; got " +
                                std::to_string(o.samples_per_axis) + ".");
  }
  internal::ResolveMaterialLabelSets("MaterialScene", &o.labels, &o.ground_labels, &o.box_labels);
}

MaterialScene::Rendering MaterialScene::Render(std::uint32_t seed) const {
  const Options& o = options_;
  std::mt19937 rng(seed * 747796405u + 2891336453u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };

  // Camera: height, pitch below the horizon, yaw, small roll. World z is up; the camera looks along +x at yaw 0.
  const double height = uniform(0.5, 1.6);
  const double pitch = uniform(20.0, 75.0) * kPi / 180.0;
  const double yaw = uniform(-kPi, kPi);
  const double roll = uniform(-6.0, 6.0) * kPi / 180.0;
  const Eigen::Vector3d eye(0.0, 0.0, height);
  const Eigen::Vector3d forward(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), -std::sin(pitch));
  const Eigen::Vector3d right0(std::sin(yaw), -std::cos(yaw), 0.0);
  const Eigen::Vector3d down0 = forward.cross(right0);
  const Eigen::Vector3d right = std::cos(roll) * right0 + std::sin(roll) * down0;
  const Eigen::Vector3d down = -std::sin(roll) * right0 + std::cos(roll) * down0;
  const double focal = 0.5 * o.width / std::tan(0.5 * o.field_of_view_deg * kPi / 180.0);
  const double cx = 0.5 * o.width;
  const double cy = 0.5 * o.height;

  // Ground regions: Voronoi cells of sites around the camera's footprint, biased forward so most are visible.
  const Eigen::Vector2d ahead(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d footprint = ahead * (height / std::tan(pitch));
  std::vector<Region> regions;
  regions.reserve(static_cast<std::size_t>(o.num_regions));
  const double spread = 1.0 + 2.5 * height / std::tan(pitch);
  for (int i = 0; i < o.num_regions; ++i) {
    const Eigen::Vector2d site = footprint + Eigen::Vector2d(uniform(-spread, spread), uniform(-spread, spread));
    const std::string& label = o.ground_labels[rng() % o.ground_labels.size()];
    regions.push_back({site, IndexIn(o.labels, label, "ground_labels"),
                       MaterialTexture::Make(label, static_cast<std::uint32_t>(rng()))});
  }
  // Boxes standing on the ground in front of the camera.
  std::vector<Box> boxes;
  for (int i = 0; i < o.num_boxes; ++i) {
    const double distance = uniform(1.5, 1.5 + 3.0 * spread);
    const double side = uniform(-0.6, 0.6) * distance;
    const Eigen::Vector2d centre = ahead * distance + Eigen::Vector2d(-ahead.y(), ahead.x()) * side;
    const Eigen::Vector2d half(uniform(0.2, 0.8), uniform(0.2, 0.8));
    const double box_height = uniform(0.2, 1.8);
    const std::string& label = o.box_labels[rng() % o.box_labels.size()];
    boxes.push_back({Eigen::Vector3d(centre.x() - half.x(), centre.y() - half.y(), 0.0),
                     Eigen::Vector3d(centre.x() + half.x(), centre.y() + half.y(), box_height),
                     IndexIn(o.labels, label, "box_labels"),
                     MaterialTexture::Make(label, static_cast<std::uint32_t>(rng()))});
  }
  const auto sky_it = std::find(o.labels.begin(), o.labels.end(), "sky");
  const int sky_label = sky_it == o.labels.end() ? kNoLabel : static_cast<int>(sky_it - o.labels.begin());
  const MaterialTexture sky = MaterialTexture::Make("sky", static_cast<std::uint32_t>(rng()));

  // Lighting: global gain, colour tint, a sun direction for box faces and an illumination gradient over the ground.
  const double gain = uniform(0.6, 1.25);
  const Eigen::Vector3d tint(uniform(0.9, 1.1), uniform(0.95, 1.05), uniform(0.9, 1.1));
  const double sun_elevation = uniform(0.3, 1.3);
  const double sun_azimuth = uniform(-kPi, kPi);
  const Eigen::Vector3d sun(std::cos(sun_elevation) * std::cos(sun_azimuth),
                            std::cos(sun_elevation) * std::sin(sun_azimuth), std::sin(sun_elevation));
  const Eigen::Vector2d gradient = Eigen::Vector2d(uniform(-1.0, 1.0), uniform(-1.0, 1.0)) * 0.04;

  auto cast = [&](const Eigen::Vector3d& direction) -> Hit {
    double best = std::numeric_limits<double>::infinity();
    Hit hit{Eigen::Vector3d::Zero(), sky_label, 1.0};
    bool found = false;
    if (direction.z() < -1e-9) {
      best = -eye.z() / direction.z();
      const Eigen::Vector3d p = eye + best * direction;
      const Eigen::Vector2d q(p.x(), p.y());
      std::size_t nearest = 0;
      double nearest_d2 = std::numeric_limits<double>::infinity();
      for (std::size_t r = 0; r < regions.size(); ++r) {
        const double d2 = (regions[r].site - q).squaredNorm();
        if (d2 < nearest_d2) {
          nearest_d2 = d2;
          nearest = r;
        }
      }
      const double light = std::clamp(1.0 + gradient.dot(q), 0.6, 1.4) * (0.55 + 0.45 * sun.z());
      hit = {regions[nearest].texture.Evaluate(p.x(), p.y()), regions[nearest].label, light};
      found = true;
    }
    for (const Box& box : boxes) {
      // Slab test; `axis` remembers which face the ray enters through.
      double t_near = 0.0;
      double t_far = best;
      int axis = -1;
      bool miss = false;
      for (int a = 0; a < 3 && !miss; ++a) {
        if (std::abs(direction[a]) < 1e-12) {
          if (eye[a] < box.lower[a] || eye[a] > box.upper[a]) miss = true;
          continue;
        }
        double t0 = (box.lower[a] - eye[a]) / direction[a];
        double t1 = (box.upper[a] - eye[a]) / direction[a];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_near) {
          t_near = t0;
          axis = a;
        }
        t_far = std::min(t_far, t1);
        if (t_near > t_far) miss = true;
      }
      if (miss || axis < 0 || t_near >= best) continue;
      best = t_near;
      const Eigen::Vector3d p = eye + best * direction;
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      normal[axis] = direction[axis] > 0.0 ? -1.0 : 1.0;
      // Texture coordinates: the face's two in-plane axes.
      const double u = axis == 0 ? p.y() : p.x();
      const double v = axis == 2 ? p.y() : p.z();
      hit = {box.texture.Evaluate(u, v), box.label, 0.55 + 0.45 * std::max(0.0, normal.dot(sun))};
      found = true;
    }
    if (!found) {
      // Sky: texture coordinates on a virtual cloud layer, brighter towards the horizon.
      const double up = std::max(direction.z() / direction.norm(), 0.02);
      hit = {sky.Evaluate(direction.x() / up * 0.5, direction.y() / up * 0.5), sky_label, 1.0};
    }
    return hit;
  };

  Rendering out;
  out.image.create(o.height, o.width, CV_8UC3);
  out.labels.create(o.height, o.width, CV_8UC1);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::mt19937 noise_rng(seed * 2246822519u + 374761393u);
  const int n = o.samples_per_axis;
  for (int y = 0; y < o.height; ++y) {
    cv::Vec3b* pixels = out.image.ptr<cv::Vec3b>(y);
    std::uint8_t* labels = out.labels.ptr<std::uint8_t>(y);
    for (int x = 0; x < o.width; ++x) {
      const Eigen::Vector3d centre_ray =
          forward + ((x + 0.5 - cx) / focal) * right + ((y + 0.5 - cy) / focal) * down;
      const Hit centre = cast(centre_ray);
      labels[x] = static_cast<std::uint8_t>(centre.label);
      Eigen::Vector3d colour = Eigen::Vector3d::Zero();
      if (n == 1) {
        colour = centre.colour * centre.shading;
      } else {
        for (int sy = 0; sy < n; ++sy) {
          for (int sx = 0; sx < n; ++sx) {
            const Hit h = cast(forward + ((x + (sx + 0.5) / n - cx) / focal) * right +
                               ((y + (sy + 0.5) / n - cy) / focal) * down);
            colour += h.colour * h.shading;
          }
        }
        colour /= static_cast<double>(n * n);
      }
      for (int c = 0; c < 3; ++c) {
        double value = colour[c] * gain * tint[c];
        if (o.noise_stddev > 0.0) value += o.noise_stddev * noise(noise_rng);
        pixels[x][c] = static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
      }
    }
  }
  return out;
}

}  // namespace cairn::perception
