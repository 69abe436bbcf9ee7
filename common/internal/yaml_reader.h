#pragma once

/// @file
/// Internal, not installed: the one way Cairn reads YAML files, with errors that name the file, the line and the
/// key. Include it only from .cc files (and link yaml-cpp privately) so that yaml-cpp stays out of Cairn's
/// public headers.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

namespace cairn::internal {

/// A parsed YAML file and typed reads of its values. Every mistake in the file is reported as
/// std::invalid_argument("In 'FILE' line N: ...") naming the key and what was expected, so that a user can find
/// and fix it; the reader itself refuses files that cannot be read, malformed YAML, a top level that is not a
/// mapping, and a key that appears twice in one mapping (yaml-cpp would silently keep the first).
///
/// Keys and `where` arguments are the caller's words for the place in the file ("terrain", "region 2",
/// "reach.dx"); they appear in the messages as given.
class YamlReader {
 public:
  /// Files larger than this are refused before they are read: Cairn's YAML files are configuration and models of
  /// a few megabytes at most. Loaders of files that should be smaller pass their own limit to the constructor:
  /// yaml-cpp needs about 140 bytes of memory per byte of a file of short entries, and about a microsecond, long
  /// before the loader can count them (a 4 MB list took 3 s and 590 MB).
  static constexpr std::size_t kMaxFileBytes = 256u << 20;

  /// Reads and parses `path`. Throws std::invalid_argument when the file cannot be read or is larger than
  /// `max_bytes` ("Cannot read 'FILE' ..."; checked from its size before reading, the limit named), is not valid
  /// YAML ("Malformed YAML in 'FILE' at line N: ..."), holds a duplicate key ("In 'FILE' line N: the key 'k'
  /// appears twice ...") or is not a mapping at the top. `max_bytes` must be in [1, kMaxFileBytes]
  /// (std::invalid_argument otherwise).
  explicit YamlReader(std::string path, std::size_t max_bytes = kMaxFileBytes);

  /// Parses `text` as the contents of `path` (for text the caller has already read; `path` names it in
  /// messages and resolves relative paths). Throws as the constructor does.
  static YamlReader FromText(std::string path, std::string text);

  /// The top-level mapping.
  const YAML::Node& root() const { return root_; }
  /// The file's path, as given.
  const std::string& path() const { return path_; }
  /// The bytes that were parsed.
  const std::string& text() const { return text_; }
  /// The folder holding the file, with a trailing slash ("" for the current folder).
  std::string folder() const;
  /// `relative` resolved against the file's folder (absolute paths are kept).
  std::string Resolve(const std::string& relative) const;

  /// "In 'FILE' line N: message", with the line of `node` (just "In 'FILE': message" for a node without one).
  std::invalid_argument Error(const YAML::Node& node, const std::string& message) const;
  /// Throws Error(node, message).
  [[noreturn]] void Fail(const YAML::Node& node, const std::string& message) const;

  /// Throws unless `node` (called `where`) is a mapping whose keys are all in `allowed`; an unknown key is named
  /// with its line, the closest allowed key when it is a likely typo, and the allowed keys.
  void CheckKeys(const YAML::Node& node, const std::vector<std::string>& allowed, const std::string& where) const;

  /// True when the mapping `node` has `key` with a value (not null).
  static bool Has(const YAML::Node& node, const std::string& key);
  /// `node[key]`; throws when the key is missing or has no value.
  YAML::Node Require(const YAML::Node& node, const std::string& key, const std::string& where) const;

  /// `value` as a finite number; throws naming `key` otherwise (text, a list, .nan, .inf).
  double AsNumber(const YAML::Node& value, const std::string& key) const;
  /// The finite number at `key` of `node` (required).
  double Number(const YAML::Node& node, const std::string& key, const std::string& where) const;
  /// The finite number at `key` of `node`, or `fallback` when the key is absent or null.
  double Number(const YAML::Node& node, const std::string& key, const std::string& where, double fallback) const;

  /// `value` as an integer in [lo, hi] (written as an integer, or as a number with no fraction such as 1e3);
  /// throws naming `key` and the range otherwise. lo and hi must lie within +-2^53, where doubles are exact.
  long long AsInteger(const YAML::Node& value, const std::string& key, long long lo, long long hi) const;
  /// The integer in [lo, hi] at `key` of `node` (required).
  long long Integer(const YAML::Node& node, const std::string& key, const std::string& where, long long lo,
                    long long hi) const;
  /// The integer in [lo, hi] at `key` of `node`, or `fallback` when the key is absent or null.
  long long Integer(const YAML::Node& node, const std::string& key, const std::string& where, long long lo,
                    long long hi, long long fallback) const;

  /// `value` as true or false (YAML's true/false, yes/no, on/off); throws naming `key` otherwise.
  bool AsBool(const YAML::Node& value, const std::string& key) const;

  /// `value` as text (a single value, not a list or a mapping); throws naming `key` otherwise.
  std::string AsString(const YAML::Node& value, const std::string& key) const;
  /// The text at `key` of `node` (required).
  std::string String(const YAML::Node& node, const std::string& key, const std::string& where) const;
  /// The text at `key` of `node`, or `fallback` when the key is absent or null.
  std::string String(const YAML::Node& node, const std::string& key, const std::string& where,
                     const std::string& fallback) const;

  /// `value` as a list of exactly `size` finite numbers; throws naming `key` otherwise.
  Eigen::VectorXd Numbers(const YAML::Node& value, const std::string& key, int size) const;
  /// `value` as a list of finite numbers of any length up to `max_size`; throws naming `key` otherwise.
  std::vector<double> NumberList(const YAML::Node& value, const std::string& key, std::size_t max_size) const;
  /// `value` as a list of texts; of exactly `size` entries unless size is -1. Throws naming `key` otherwise.
  std::vector<std::string> Strings(const YAML::Node& value, const std::string& key, int size = -1) const;

  /// `value` as YAML on one line ("[0.2, 0.1]"), cut to 80 characters, to show what a file says.
  static std::string Dump(const YAML::Node& value);

 private:
  YamlReader(std::string path, std::string text);

  std::string path_;
  std::string text_;
  YAML::Node root_;
};

}  // namespace cairn::internal
