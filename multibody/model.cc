#include <cairn/common/number_text.h>
#include <cairn/multibody/model.h>

#include <stdexcept>

#include <cairn/common/text_suggestions.h>

namespace cairn::multibody {
namespace {

int Lookup(const std::map<std::string, int>& index, const std::string& name, const char* kind,
           const std::string& model_name) {
  const auto it = index.find(name);
  if (it != index.end()) return it->second;
  std::vector<std::string> names;
  names.reserve(index.size());
  for (const auto& entry : index) names.push_back(entry.first);
  const std::vector<std::string> closest = ClosestNames(name, names);
  std::string message = std::string("unknown ") + kind + " '" + name + "' in model '" + model_name + "'";
  if (!closest.empty()) message += "; did you mean " + QuotedList(closest) + "?";
  message += " (the model has " + cairn::FormatShort(names.size()) + " " + kind + "s)";
  throw std::invalid_argument(message);
}

}  // namespace

bool Model::IsAncestorOrSelf(int ancestor, int body) const {
  while (body > ancestor) body = parent(body);
  return body == ancestor;
}

int Model::GetBodyIndex(const std::string& name) const { return Lookup(body_index_, name, "body", name_); }
int Model::GetJointIndex(const std::string& name) const { return Lookup(joint_index_, name, "joint", name_); }
int Model::GetFrameIndex(const std::string& name) const { return Lookup(frame_index_, name, "frame", name_); }
bool Model::HasBody(const std::string& name) const { return body_index_.count(name) > 0; }
bool Model::HasJoint(const std::string& name) const { return joint_index_.count(name) > 0; }
bool Model::HasFrame(const std::string& name) const { return frame_index_.count(name) > 0; }

Model Model::WithGravity(const Eigen::Vector3d& gravity) const {
  if (!gravity.allFinite()) {
    throw std::invalid_argument("Model::WithGravity: gravity must be finite; pass e.g. (0, 0, -9.81)");
  }
  Model copy = *this;
  copy.gravity_ = gravity;
  return copy;
}

std::vector<std::string> Model::body_names() const {
  std::vector<std::string> names;
  for (const Body& body : bodies_) names.push_back(body.name);
  return names;
}

std::vector<std::string> Model::joint_names() const {
  std::vector<std::string> names;
  for (std::size_t i = 1; i < joints_.size(); ++i) names.push_back(joints_[i].name);
  return names;
}

std::vector<std::string> Model::frame_names() const {
  std::vector<std::string> names;
  for (const Frame& frame : frames_) names.push_back(frame.name);
  return names;
}

}  // namespace cairn::multibody
