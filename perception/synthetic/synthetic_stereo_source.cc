#include "cairn/perception/synthetic/synthetic_stereo_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace cairn::perception {

using systems::AbstractValue;
using systems::Context;

SyntheticStereoSource::SyntheticStereoSource(SyntheticStereoScene scene, SyntheticStereoRenderer renderer,
                                             std::vector<Eigen::Isometry3d> trajectory, double period)
    : scene_(std::move(scene)), renderer_(std::move(renderer)), trajectory_(std::move(trajectory)), period_(period) {
  if (trajectory_.empty()) {
    throw std::invalid_argument("SyntheticStereoSource: the trajectory is empty; give at least one camera pose");
  }
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw std::invalid_argument("SyntheticStereoSource: period " + std::to_string(period) +
                                " s must be positive and finite (e.g. 0.1 for 10 frames/s)");
  }
  frame_cache_ = DeclareCacheEntry(
      "frame", systems::Value<SyntheticStereoFrame>(SyntheticStereoFrame()),
      [this](const Context& c, AbstractValue* v) {
        const int k = FrameIndexAt(c.get_time());
        v->get_mutable_value<SyntheticStereoFrame>() = renderer_.Render(scene_, trajectory_[k], k);
      },
      {time_ticket()});
  const auto frame = Prerequisites{cache_entry_ticket(frame_cache_)};
  auto image_output = [this, &frame](const char* name, cv::Mat SyntheticStereoFrame::*member) {
    DeclareAbstractOutputPort(
        name, systems::Value<cv::Mat>(cv::Mat()),
        [this, member](const Context& c, AbstractValue* v) {
          v->get_mutable_value<cv::Mat>() = EvalCacheEntry<SyntheticStereoFrame>(c, frame_cache_).*member;
        },
        frame);
  };
  image_output("left", &SyntheticStereoFrame::left);
  image_output("right", &SyntheticStereoFrame::right);
  image_output("depth", &SyntheticStereoFrame::depth);
  image_output("labels", &SyntheticStereoFrame::labels);
  DeclareAbstractOutputPort(
      "X_WC", systems::Value<Eigen::Isometry3d>(Eigen::Isometry3d::Identity()),
      [this](const Context& c, AbstractValue* v) {
        v->get_mutable_value<Eigen::Isometry3d>() = trajectory_[FrameIndexAt(c.get_time())];
      },
      {time_ticket()});
  image_output("left_colour", &SyntheticStereoFrame::left_colour);
  image_output("right_colour", &SyntheticStereoFrame::right_colour);
}

int SyntheticStereoSource::FrameIndexAt(double t) const {
  // A small slack so that t = k * period computed in floating point selects frame k, not k - 1.
  const double k = std::floor(t / period_ + 1e-9);
  return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(trajectory_.size() - 1)));
}

}  // namespace cairn::perception
