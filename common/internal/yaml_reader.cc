#include "cairn/common/internal/yaml_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include <yaml-cpp/eventhandler.h>

#include "cairn/common/number_text.h"
#include "cairn/common/text_suggestions.h"

namespace cairn::internal {
namespace {

// Walks the parser's events (not the node tree, so an alias is one event however large its anchor) and reports
// the first key that appears twice in one mapping. yaml-cpp's node tree keeps both entries but every lookup
// finds only the first, so a repeated key would silently not take effect.
class DuplicateKeyFinder : public YAML::EventHandler {
 public:
  struct Duplicate {
    bool found{false};
    std::string key;
    int line{0};        // 1-based, of the second occurrence
    int first_line{0};  // 1-based, of the first
  };

  const Duplicate& duplicate() const { return duplicate_; }

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { Value(mark, "~", true); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { Value(mark, std::string(), false); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string& value) override {
    Value(mark, value, true);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    Value(mark, std::string(), false);
    open_.push_back(Collection{false, true, {}});
  }
  void OnSequenceEnd() override { open_.pop_back(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    Value(mark, std::string(), false);
    open_.push_back(Collection{true, true, {}});
  }
  void OnMapEnd() override { open_.pop_back(); }

 private:
  struct Collection {
    bool is_map;
    bool expecting_key;                // in a map: the next node is a key
    std::map<std::string, int> keys;  // scalar keys seen so far, with their lines
  };

  // A node starts (a scalar, or the start of a collection) in the innermost open collection.
  void Value(const YAML::Mark& mark, const std::string& text, bool scalar) {
    if (open_.empty() || !open_.back().is_map) return;
    Collection& map = open_.back();
    const bool is_key = map.expecting_key;
    map.expecting_key = !map.expecting_key;
    // Only scalar keys are compared; a list or mapping as a key (YAML's "? ") is rare and has no text to compare.
    if (!is_key || !scalar || duplicate_.found) return;
    const auto [where, inserted] = map.keys.emplace(text, mark.line + 1);
    if (!inserted) duplicate_ = Duplicate{true, text, mark.line + 1, where->second};
  }

  std::vector<Collection> open_;
  Duplicate duplicate_;
};

std::string ReadWholeFile(const std::string& path, std::size_t max_bytes) {
  if (max_bytes < 1 || max_bytes > YamlReader::kMaxFileBytes) {
    throw std::invalid_argument("YamlReader: the size limit " + FormatShort(max_bytes) + " for '" + path +
                                "' must be in [1, " + FormatShort(YamlReader::kMaxFileBytes) + "] bytes.");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("Cannot read '" + path + "'; check that the file exists and is readable.");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw std::invalid_argument("Cannot read '" + path + "'; check that it is a regular file.");
  if (static_cast<std::size_t>(size) > max_bytes) {
    throw std::invalid_argument("Cannot read '" + path + "': it has " + FormatShort(static_cast<long long>(size)) +
                                " bytes, more than the " + FormatShort(max_bytes) + " a file of its kind may have.");
  }
  in.seekg(0, std::ios::beg);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw std::invalid_argument("Cannot read '" + path + "'; check that the file exists and is readable.");
  return text.str();
}

// A node's 1-based line, or 0 when it has none (a key that is not there).
int LineOf(const YAML::Node& node) {
  try {
    return node.IsDefined() ? node.Mark().line + 1 : 0;
  } catch (const YAML::Exception&) {
    return 0;
  }
}

}  // namespace

YamlReader::YamlReader(std::string path, std::size_t max_bytes) : YamlReader(path, ReadWholeFile(path, max_bytes)) {}

YamlReader YamlReader::FromText(std::string path, std::string text) {
  return YamlReader(std::move(path), std::move(text));
}

YamlReader::YamlReader(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
  try {
    root_ = YAML::Load(text_);
    std::istringstream stream(text_);
    YAML::Parser parser(stream);
    DuplicateKeyFinder finder;
    parser.HandleNextDocument(finder);
    if (finder.duplicate().found) {
      const auto& d = finder.duplicate();
      throw std::invalid_argument("In '" + path_ + "' line " + FormatShort(d.line) + ": the key '" + d.key +
                                  "' appears twice in one mapping (first at line " + FormatShort(d.first_line) +
                                  "); keep one of them.");
    }
  } catch (const YAML::Exception& error) {
    throw std::invalid_argument("Malformed YAML in '" + path_ + "' at line " + FormatShort(error.mark.line + 1) +
                                ": " + error.msg);
  }
  if (!root_.IsMap()) {
    throw std::invalid_argument("'" + path_ + "' must hold a YAML mapping (lines of 'key: value') at the top level.");
  }
}

std::string YamlReader::folder() const {
  const auto slash = path_.find_last_of('/');
  return slash == std::string::npos ? std::string() : path_.substr(0, slash + 1);
}

std::string YamlReader::Resolve(const std::string& relative) const {
  return !relative.empty() && relative[0] == '/' ? relative : folder() + relative;
}

std::invalid_argument YamlReader::Error(const YAML::Node& node, const std::string& message) const {
  const int line = LineOf(node);
  return std::invalid_argument("In '" + path_ + "'" + (line > 0 ? " line " + FormatShort(line) : std::string()) +
                               ": " + message);
}

void YamlReader::Fail(const YAML::Node& node, const std::string& message) const { throw Error(node, message); }

void YamlReader::CheckKeys(const YAML::Node& node, const std::vector<std::string>& allowed,
                           const std::string& where) const {
  if (!node.IsMap()) Fail(node, where + " must be a mapping of keys to values, got '" + Dump(node) + "'.");
  for (const auto& entry : node) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : Dump(entry.first);
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string message = "unknown key '" + key + "' in " + where + ".";
    const std::vector<std::string> close = ClosestNames(key, allowed, 1);
    if (!close.empty() && EditDistance(key, close.front()) <= 3) message += " Did you mean '" + close.front() + "'?";
    message += " Allowed keys: " + QuotedList(allowed) + ".";
    Fail(entry.first, message);
  }
}

bool YamlReader::Has(const YAML::Node& node, const std::string& key) {
  if (!node.IsMap()) return false;
  const YAML::Node child = node[key];
  return child.IsDefined() && !child.IsNull();
}

YAML::Node YamlReader::Require(const YAML::Node& node, const std::string& key, const std::string& where) const {
  if (!node.IsMap()) Fail(node, where + " must be a mapping of keys to values, got '" + Dump(node) + "'.");
  const YAML::Node child = node[key];
  if (!child.IsDefined()) Fail(node, "missing key '" + key + "' in " + where + ".");
  if (child.IsNull()) Fail(child, "key '" + key + "' in " + where + " has no value.");
  return child;
}

double YamlReader::AsNumber(const YAML::Node& value, const std::string& key) const {
  double number = 0.0;
  if (!value.IsScalar() || !YAML::convert<double>::decode(value, number)) {
    Fail(value, "'" + key + "' must be a number, got '" + Dump(value) + "'.");
  }
  if (!std::isfinite(number)) Fail(value, "'" + key + "' must be a finite number, got '" + Dump(value) + "'.");
  return number;
}

double YamlReader::Number(const YAML::Node& node, const std::string& key, const std::string& where) const {
  return AsNumber(Require(node, key, where), key);
}

double YamlReader::Number(const YAML::Node& node, const std::string& key, const std::string& where,
                          double fallback) const {
  return Has(node, key) ? Number(node, key, where) : fallback;
}

long long YamlReader::AsInteger(const YAML::Node& value, const std::string& key, long long lo, long long hi) const {
  double number = 0.0;
  const bool numeric = value.IsScalar() && YAML::convert<double>::decode(value, number);
  if (!numeric || !(number >= static_cast<double>(lo) && number <= static_cast<double>(hi)) ||
      number != std::floor(number)) {
    Fail(value, "'" + key + "' must be an integer in [" + FormatShort(lo) + ", " + FormatShort(hi) + "], got '" +
                    Dump(value) + "'.");
  }
  return static_cast<long long>(number);
}

long long YamlReader::Integer(const YAML::Node& node, const std::string& key, const std::string& where, long long lo,
                              long long hi) const {
  return AsInteger(Require(node, key, where), key, lo, hi);
}

long long YamlReader::Integer(const YAML::Node& node, const std::string& key, const std::string& where, long long lo,
                              long long hi, long long fallback) const {
  return Has(node, key) ? Integer(node, key, where, lo, hi) : fallback;
}

bool YamlReader::AsBool(const YAML::Node& value, const std::string& key) const {
  bool flag = false;
  if (!value.IsScalar() || !YAML::convert<bool>::decode(value, flag)) {
    Fail(value, "'" + key + "' must be true or false, got '" + Dump(value) + "'.");
  }
  return flag;
}

std::string YamlReader::AsString(const YAML::Node& value, const std::string& key) const {
  if (!value.IsScalar()) Fail(value, "'" + key + "' must be a single value, got '" + Dump(value) + "'.");
  return value.Scalar();
}

std::string YamlReader::String(const YAML::Node& node, const std::string& key, const std::string& where) const {
  return AsString(Require(node, key, where), key);
}

std::string YamlReader::String(const YAML::Node& node, const std::string& key, const std::string& where,
                               const std::string& fallback) const {
  return Has(node, key) ? String(node, key, where) : fallback;
}

Eigen::VectorXd YamlReader::Numbers(const YAML::Node& value, const std::string& key, int size) const {
  if (!value.IsSequence() || static_cast<int>(value.size()) != size) {
    Fail(value, "'" + key + "' must be a list of " + FormatShort(size) + " numbers, got '" + Dump(value) + "'.");
  }
  Eigen::VectorXd out(size);
  for (int i = 0; i < size; ++i) out[i] = AsNumber(value[static_cast<std::size_t>(i)], key);
  return out;
}

std::vector<double> YamlReader::NumberList(const YAML::Node& value, const std::string& key,
                                           std::size_t max_size) const {
  if (!value.IsSequence()) Fail(value, "'" + key + "' must be a list of numbers, got '" + Dump(value) + "'.");
  if (value.size() > max_size) {
    Fail(value, "'" + key + "' has " + FormatShort(value.size()) + " numbers, more than the " +
                    FormatShort(max_size) + " allowed.");
  }
  std::vector<double> out;
  out.reserve(value.size());
  for (const YAML::Node& item : value) out.push_back(AsNumber(item, key));
  return out;
}

std::vector<std::string> YamlReader::Strings(const YAML::Node& value, const std::string& key, int size) const {
  if (!value.IsSequence() || (size >= 0 && static_cast<int>(value.size()) != size)) {
    Fail(value, "'" + key + "' must be a list of " + (size >= 0 ? FormatShort(size) + " " : std::string()) +
                    "names, got '" + Dump(value) + "'.");
  }
  std::vector<std::string> out;
  out.reserve(value.size());
  for (const YAML::Node& item : value) out.push_back(AsString(item, key));
  return out;
}

std::string YamlReader::Dump(const YAML::Node& value) {
  if (!value.IsDefined()) return "";
  YAML::Emitter out;
  out << YAML::Flow << value;
  std::string text = out.c_str();
  // One line, and short: a message quotes what the file says, not a whole matrix of weights.
  std::replace(text.begin(), text.end(), '\n', ' ');
  constexpr std::size_t kMaxChars = 80;
  if (text.size() > kMaxChars) text = text.substr(0, kMaxChars - 3) + "...";
  return text;
}

}  // namespace cairn::internal
