#pragma once

// Reading planning YAML files with errors that name the file, the line and the key. Internal: included only
// from .cc files, so yaml-cpp stays out of Cairn's public headers.

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include <cairn/common/text_suggestions.h>

namespace cairn::planning::internal {

class YamlReader {
 public:
  /// Parses `path`; throws std::invalid_argument naming the file (unreadable) or the line (malformed).
  explicit YamlReader(std::string path) : path_(std::move(path)) {
    try {
      root_ = YAML::LoadFile(path_);
    } catch (const YAML::BadFile&) {
      throw std::invalid_argument("Cannot read '" + path_ + "'; check that the file exists and is readable.");
    } catch (const YAML::Exception& error) {
      throw std::invalid_argument("Malformed YAML in '" + path_ + "' at line " + std::to_string(error.mark.line + 1) +
                                  ": " + error.msg);
    }
    if (!root_.IsMap()) throw std::invalid_argument("'" + path_ + "' must hold a YAML mapping at the top level.");
  }

  const YAML::Node& root() const { return root_; }
  const std::string& path() const { return path_; }
  /// The folder holding the file, with a trailing slash ("" for the current folder).
  std::string folder() const {
    const auto slash = path_.find_last_of('/');
    return slash == std::string::npos ? std::string() : path_.substr(0, slash + 1);
  }
  /// `relative` resolved against the file's folder (absolute paths are kept).
  std::string Resolve(const std::string& relative) const {
    return !relative.empty() && relative[0] == '/' ? relative : folder() + relative;
  }

  std::invalid_argument Error(const YAML::Node& node, const std::string& message) const {
    return std::invalid_argument("In '" + path_ + "' line " + std::to_string(node.Mark().line + 1) + ": " + message);
  }

  /// Throws when `node` (a mapping called `where`) has a key outside `allowed`, suggesting the closest.
  void CheckKeys(const YAML::Node& node, const std::vector<std::string>& allowed, const std::string& where) const {
    if (!node.IsMap()) throw Error(node, where + " must be a mapping of keys to values.");
    for (const auto& entry : node) {
      const std::string key = entry.first.as<std::string>();
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      std::string message = "unknown key '" + key + "' in " + where + ".";
      const std::vector<std::string> close = ClosestNames(key, allowed, 1);
      if (!close.empty() && EditDistance(key, close.front()) <= 3) message += " Did you mean '" + close.front() + "'?";
      message += " Allowed keys: " + QuotedList(allowed) + ".";
      throw Error(entry.first, message);
    }
  }

  YAML::Node Require(const YAML::Node& node, const std::string& key, const std::string& where) const {
    const YAML::Node child = node[key];
    if (!child) throw Error(node, "missing key '" + key + "' in " + where + ".");
    return child;
  }

  double Number(const YAML::Node& node, const std::string& key, const std::string& where) const {
    return AsNumber(Require(node, key, where), key);
  }
  double Number(const YAML::Node& node, const std::string& key, const std::string& /*where*/, double fallback) const {
    const YAML::Node child = node[key];
    return child ? AsNumber(child, key) : fallback;
  }
  double AsNumber(const YAML::Node& value, const std::string& key) const {
    if (value.IsScalar()) {
      try {
        return value.as<double>();
      } catch (const YAML::Exception&) {
      }
    }
    throw Error(value, "'" + key + "' must be a number, got '" + Dump(value) + "'.");
  }

  std::string String(const YAML::Node& node, const std::string& key, const std::string& where) const {
    return AsString(Require(node, key, where), key);
  }
  std::string String(const YAML::Node& node, const std::string& key, const std::string& /*where*/,
                     const std::string& fallback) const {
    const YAML::Node child = node[key];
    return child ? AsString(child, key) : fallback;
  }
  std::string AsString(const YAML::Node& value, const std::string& key) const {
    if (!value.IsScalar()) throw Error(value, "'" + key + "' must be a single value, got '" + Dump(value) + "'.");
    return value.as<std::string>();
  }

  /// A list of exactly `size` numbers.
  Eigen::VectorXd Numbers(const YAML::Node& value, const std::string& key, int size) const {
    if (!value.IsSequence() || static_cast<int>(value.size()) != size) {
      throw Error(value, "'" + key + "' must be a list of " + std::to_string(size) + " numbers, got '" + Dump(value) +
                             "'.");
    }
    Eigen::VectorXd out(size);
    for (int i = 0; i < size; ++i) out[i] = AsNumber(value[i], key);
    return out;
  }

  static std::string Dump(const YAML::Node& value) {
    YAML::Emitter out;
    out << YAML::Flow << value;
    return out.c_str();
  }

 private:
  std::string path_;
  YAML::Node root_;
};

}  // namespace cairn::planning::internal
