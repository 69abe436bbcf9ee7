#include <cairn/multibody/plant/joint_trajectory.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <cairn/common/number_text.h>

namespace cairn::multibody {
namespace {

std::vector<std::string> SplitCommas(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) {
    const auto begin = field.find_first_not_of(" \t\r");
    const auto end = field.find_last_not_of(" \t\r");
    fields.push_back(begin == std::string::npos ? std::string() : field.substr(begin, end - begin + 1));
  }
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

JointTrajectory JointTrajectory::LoadCsv(const Model& model, const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw std::invalid_argument("Joint trajectory '" + path + "' does not exist or is not a file");
  }
  const auto bytes = std::filesystem::file_size(path, error);
  if (error || bytes > static_cast<std::uintmax_t>(kMaxFileBytes)) {
    throw std::invalid_argument("Joint trajectory '" + path + "' is larger than the limit of " +
                                FormatShort(kMaxFileBytes) + " bytes");
  }
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("Cannot read joint trajectory '" + path + "'");
  auto fail = [&](long long line, const std::string& message) {
    throw std::invalid_argument("In '" + path + "' line " + FormatShort(line) + ": " + message);
  };
  std::string line;
  long long line_number = 1;
  if (!std::getline(in, line)) fail(1, "the file is empty; the first line must be 'time,<joint>,...'");
  const std::vector<std::string> header = SplitCommas(line);
  if (header.empty() || header[0] != "time") fail(1, "the header must start with 'time'");
  if (header.size() < 2) fail(1, "the header names no joint");
  JointTrajectory trajectory;
  trajectory.nv_ = model.nv();
  std::set<std::string> seen;
  std::vector<const Joint*> joints;
  for (std::size_t c = 1; c < header.size(); ++c) {
    const std::string& name = header[c];
    if (!model.HasJoint(name)) fail(1, "column " + FormatShort(c + 1) + " names '" + name + "', not a joint of '" +
                                           model.name() + "'");
    const Joint& joint = model.joint(model.GetJointIndex(name));
    if (joint.type != JointType::kRevolute && joint.type != JointType::kPrismatic) {
      fail(1, "joint '" + name + "' is not revolute or prismatic");
    }
    if (!seen.insert(name).second) fail(1, "joint '" + name + "' appears twice");
    joints.push_back(&joint);
    trajectory.q_index_.push_back(joint.idx_q);
    trajectory.v_index_.push_back(joint.idx_v);
  }
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (trajectory.times_.size() >= kMaxRows) {
      fail(line_number, "more than the limit of " + FormatShort(kMaxRows) + " rows");
    }
    const std::vector<std::string> fields = SplitCommas(line);
    if (fields.size() != header.size()) {
      fail(line_number, FormatShort(fields.size()) + " fields, but the header has " + FormatShort(header.size()));
    }
    Eigen::VectorXd values(static_cast<Eigen::Index>(joints.size()));
    double time = 0.0;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      errno = 0;
      char* end = nullptr;
      const double value = std::strtod(fields[c].c_str(), &end);
      if (fields[c].empty() || end != fields[c].c_str() + fields[c].size() || errno == ERANGE || !std::isfinite(value)) {
        fail(line_number, "field " + FormatShort(c + 1) + " ('" + fields[c].substr(0, 40) + "') is not a finite number");
      }
      if (c == 0) {
        time = value;
        continue;
      }
      const Joint& joint = *joints[c - 1];
      if (value < joint.lower_limit || value > joint.upper_limit) {
        fail(line_number, "joint '" + joint.name + "' at " + FormatShort(value) + " is outside its limits [" +
                              FormatShort(joint.lower_limit) + ", " + FormatShort(joint.upper_limit) + "]");
      }
      values[static_cast<Eigen::Index>(c - 1)] = value;
    }
    if (time < 0.0) fail(line_number, "time " + FormatShort(time) + " is negative");
    if (!trajectory.times_.empty() && !(time > trajectory.times_.back())) {
      fail(line_number, "time " + FormatShort(time) + " does not increase (previous " +
                            FormatShort(trajectory.times_.back()) + ")");
    }
    trajectory.times_.push_back(time);
    trajectory.values_.push_back(values);
  }
  if (trajectory.times_.empty()) fail(line_number, "the file has no rows after the header");
  return trajectory;
}

void JointTrajectory::Evaluate(double t, const Eigen::VectorXd& q_base, Eigen::VectorXd* q, Eigen::VectorXd* v) const {
  *q = q_base;
  *v = Eigen::VectorXd::Zero(nv_);
  Eigen::VectorXd value, rate = Eigen::VectorXd::Zero(values_.front().size());
  if (t <= times_.front()) {
    value = values_.front();
  } else if (t >= times_.back()) {
    value = values_.back();
  } else {
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin());
    const double t0 = times_[k - 1], t1 = times_[k];
    rate = (values_[k] - values_[k - 1]) / (t1 - t0);
    value = values_[k - 1] + (t - t0) * rate;
  }
  for (std::size_t j = 0; j < q_index_.size(); ++j) {
    (*q)[q_index_[j]] = value[static_cast<Eigen::Index>(j)];
    (*v)[v_index_[j]] = rate[static_cast<Eigen::Index>(j)];
  }
}

}  // namespace cairn::multibody
