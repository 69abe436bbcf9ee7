#include "cairn/perception/haptics/traversability_memory.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <sys/stat.h>

#include "cairn/common/atomic_file.h"
#include "cairn/common/number_text.h"

namespace cairn::perception {
namespace {

constexpr const char* kMagic = "cairn_traversability_memory";
constexpr int kFormatVersion = 1;

void CheckScale(double value, const char* name, const char* paper) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(std::string(name) + " is " + FormatShort(value) +
                                "; it must be a positive, finite scale factor (the paper uses " + paper + ")");
  }
}

void CheckK(int k) {
  if (k < 1 || k > TraversabilityMemory::kMaxNeighbours) {
    throw std::invalid_argument("k is " + FormatShort(k) + "; it must be between 1 and " +
                                FormatShort(TraversabilityMemory::kMaxNeighbours) + " (the paper uses 5)");
  }
}

// Splits one line of the memory file into whitespace-separated tokens.
std::vector<std::string> Tokens(const std::string& line) {
  std::vector<std::string> result;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
    if (j > i) result.push_back(line.substr(i, j - i));
    i = j;
  }
  return result;
}

class Parser {
 public:
  Parser(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  [[noreturn]] void Fail(const std::string& what) const {
    throw std::runtime_error(source_ + ":" + FormatShort(line_number_) + ": " + what);
  }

  // The tokens of the next non-empty line; fails at the end of the text with `expected`.
  std::vector<std::string> Next(const std::string& expected) {
    while (position_ < text_.size()) {
      std::size_t end = text_.find('\n', position_);
      if (end == std::string::npos) end = text_.size();
      ++line_number_;
      std::vector<std::string> tokens = Tokens(text_.substr(position_, end - position_));
      position_ = end + 1;
      if (!tokens.empty()) return tokens;
    }
    ++line_number_;
    Fail("the file ends where " + expected + " was expected");
  }

  bool AtEnd() {
    while (position_ < text_.size()) {
      std::size_t end = text_.find('\n', position_);
      if (end == std::string::npos) end = text_.size();
      ++line_number_;
      if (!Tokens(text_.substr(position_, end - position_)).empty()) return false;
      position_ = end + 1;
    }
    return true;
  }

  double Number(const std::string& token, const std::string& what) const {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
      Fail(what + " '" + token + "' is not a finite number");
    }
    return value;
  }

  long long Integer(const std::string& token, const std::string& what, long long lo, long long hi) const {
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(token.c_str(), &end, 10);
    if (end == token.c_str() || *end != '\0' || errno == ERANGE || value < lo || value > hi) {
      Fail(what + " '" + token + "' is not an integer between " + FormatShort(lo) + " and " + FormatShort(hi));
    }
    return value;
  }

  double KeyNumber(const std::string& key) {
    const std::vector<std::string> tokens = Next("'" + key + " <value>'");
    if (tokens.size() != 2 || tokens[0] != key) Fail("expected '" + key + " <value>'");
    return Number(tokens[1], key);
  }

  long long KeyInteger(const std::string& key, long long lo, long long hi) {
    const std::vector<std::string> tokens = Next("'" + key + " <value>'");
    if (tokens.size() != 2 || tokens[0] != key) Fail("expected '" + key + " <value>'");
    return Integer(tokens[1], key, lo, hi);
  }

 private:
  const std::string& text_;
  const std::string& source_;
  std::size_t position_{0};
  long long line_number_{0};
};

}  // namespace

TraversabilityMemory::TraversabilityMemory() : TraversabilityMemory(Options{}, 14) {}

TraversabilityMemory::TraversabilityMemory(const Options& options, int lines) : options_(options), lines_(lines) {
  Validate(options);
  AffordanceDescriptor check(lines);  // validates the line count with the descriptor's message
  (void)check;
}

void TraversabilityMemory::Validate(const Options& options) {
  CheckScale(options.zeta, "zeta", "0.5");
  CheckScale(options.beta, "beta", "0.2");
  CheckScale(options.gamma, "gamma", "2");
  CheckScale(options.delta, "delta", "2");
  CheckK(options.k);
}

double TraversabilityMemory::DissimilarityTo(const double* o, const double* p) const {
  double sum = 0.0;
  const auto relative = [](double observed, double stored, double scale) {
    if (observed > 0.0) return std::min(1.0, scale * std::abs(observed - stored) / observed);
    return stored == observed ? 0.0 : 1.0;
  };
  for (int l = 0; l < lines_; ++l) {
    const double* a = o + 4 * l;
    const double* b = p + 4 * l;
    sum += std::min(1.0, options_.zeta * std::abs(a[0] - b[0]));
    sum += std::min(1.0, options_.beta * std::abs(a[1] - b[1]));
    sum += relative(a[2], b[2], options_.gamma);
    sum += relative(a[3], b[3], options_.delta);
  }
  return sum / (4.0 * lines_);
}

double TraversabilityMemory::Dissimilarity(const AffordanceDescriptor& observed, const AffordanceDescriptor& stored,
                                           const Options& options) {
  if (observed.lines() != stored.lines()) {
    throw std::invalid_argument("the descriptors have " + FormatShort(observed.lines()) + " and " +
                                FormatShort(stored.lines()) + " lines; only descriptors of the same histogram compare");
  }
  TraversabilityMemory memory(options, observed.lines());
  return memory.DissimilarityTo(observed.values().data(), stored.values().data());
}

void TraversabilityMemory::Add(const AffordanceDescriptor& descriptor, bool traversable) {
  if (descriptor.lines() != lines_) {
    throw std::invalid_argument("the descriptor has " + FormatShort(descriptor.lines()) + " lines but the memory holds " +
                                FormatShort(lines_) + "-line descriptors; compute it with the memory's histogram");
  }
  if (size() >= kMaxEntries) {
    throw std::length_error("the memory already holds " + FormatShort(static_cast<long long>(kMaxEntries)) +
                            " entries, its limit");
  }
  values_.insert(values_.end(), descriptor.values().data(), descriptor.values().data() + 4 * lines_);
  labels_.push_back(traversable ? 1 : 0);
}

AffordanceRecall TraversabilityMemory::Recall(const AffordanceDescriptor& observed) const {
  return Recall(observed, options_.k);
}

AffordanceRecall TraversabilityMemory::Recall(const AffordanceDescriptor& observed, int k) const {
  CheckK(k);
  if (observed.lines() != lines_) {
    throw std::invalid_argument("the observed descriptor has " + FormatShort(observed.lines()) +
                                " lines but the memory holds " + FormatShort(lines_) + "-line descriptors");
  }
  // The k best so far, sorted by dissimilarity; a fixed array so that a recall allocates nothing.
  double best_phi[kMaxNeighbours] = {};
  int best_index[kMaxNeighbours] = {};
  int found = 0;
  const double* o = observed.values().data();
  const int stride = 4 * lines_;
  for (int i = 0; i < size(); ++i) {
    const double phi = DissimilarityTo(o, values_.data() + static_cast<std::size_t>(i) * stride);
    if (found == k && !(phi < best_phi[k - 1])) continue;
    int slot = found < k ? found++ : k - 1;
    while (slot > 0 && phi < best_phi[slot - 1]) {
      best_phi[slot] = best_phi[slot - 1];
      best_index[slot] = best_index[slot - 1];
      --slot;
    }
    best_phi[slot] = phi;
    best_index[slot] = i;
  }
  AffordanceRecall recall;
  recall.neighbours = found;
  if (found > 0) {
    recall.nearest = best_index[0];
    recall.nearest_dissimilarity = best_phi[0];
  }
  for (int j = 0; j < found; ++j) {
    (labels_[static_cast<std::size_t>(best_index[j])] != 0 ? recall.confidence_traversable
                                                           : recall.confidence_non_traversable) += 1.0 - best_phi[j];
  }
  recall.confidence_traversable /= k;
  recall.confidence_non_traversable /= k;
  recall.traversable = recall.confidence_traversable > recall.confidence_non_traversable;
  recall.confidence = std::max(recall.confidence_traversable, recall.confidence_non_traversable);
  return recall;
}

AffordanceDescriptor TraversabilityMemory::descriptor(int i) const {
  if (i < 0 || i >= size()) {
    throw std::out_of_range("memory entry " + FormatShort(i) + " does not exist; the memory holds " +
                            FormatShort(size()));
  }
  return AffordanceDescriptor::FromValues(Eigen::Map<const Eigen::VectorXd>(
      values_.data() + static_cast<std::size_t>(i) * 4 * lines_, 4 * lines_));
}

std::string TraversabilityMemory::ToText() const {
  std::string text = std::string(kMagic) + " " + FormatShort(kFormatVersion) + "\n";
  text += "zeta " + FormatExact(options_.zeta) + "\nbeta " + FormatExact(options_.beta) + "\ngamma " +
          FormatExact(options_.gamma) + "\ndelta " + FormatExact(options_.delta) + "\nk " + FormatShort(options_.k) +
          "\nlines " + FormatShort(lines_) + "\nentries " + FormatShort(size()) + "\n";
  for (int i = 0; i < size(); ++i) {
    text += labels_[static_cast<std::size_t>(i)] != 0 ? "1" : "0";
    for (int v = 0; v < 4 * lines_; ++v) {
      text += ' ';
      text += FormatExact(values_[static_cast<std::size_t>(i) * 4 * lines_ + v]);
    }
    text += '\n';
  }
  return text;
}

TraversabilityMemory TraversabilityMemory::FromText(const std::string& text, const std::string& source) {
  Parser parser(text, source);
  const std::vector<std::string> header = parser.Next("the header");
  if (header.size() != 2 || header[0] != kMagic) {
    parser.Fail("not a traversability memory (the first line must be '" + std::string(kMagic) + " " +
                FormatShort(kFormatVersion) + "')");
  }
  if (parser.Integer(header[1], "the format version", 1, 1000) != kFormatVersion) {
    parser.Fail("format version " + header[1] + " is not supported; this Cairn reads version " +
                FormatShort(kFormatVersion));
  }
  Options options;
  options.zeta = parser.KeyNumber("zeta");
  options.beta = parser.KeyNumber("beta");
  options.gamma = parser.KeyNumber("gamma");
  options.delta = parser.KeyNumber("delta");
  options.k = static_cast<int>(parser.KeyInteger("k", 1, kMaxNeighbours));
  const int lines = static_cast<int>(parser.KeyInteger("lines", 1, AffordanceDescriptor::kMaxBins));
  const long long entries = parser.KeyInteger("entries", 0, kMaxEntries);
  TraversabilityMemory memory = [&] {
    try {
      return TraversabilityMemory(options, lines);
    } catch (const std::invalid_argument& error) {
      parser.Fail(error.what());
    }
  }();
  // An entry is its label and 4 * lines numbers, each at least one character and a separator: a header that
  // declares more entries than the file could hold fails here, before anything is reserved for them.
  if (static_cast<double>(entries) * 2.0 * (1.0 + 4.0 * lines) > static_cast<double>(text.size())) {
    parser.Fail("the header declares " + FormatShort(entries) + " entries of " + FormatShort(1 + 4 * lines) +
                " fields, more than the file's " + FormatShort(static_cast<long long>(text.size())) +
                " bytes can hold; the file is truncated or its header is wrong");
  }
  memory.values_.reserve(static_cast<std::size_t>(entries) * 4 * lines);
  memory.labels_.reserve(static_cast<std::size_t>(entries));
  for (long long e = 0; e < entries; ++e) {
    const std::vector<std::string> tokens = parser.Next("entry " + FormatShort(e));
    if (tokens.size() != static_cast<std::size_t>(1 + 4 * lines)) {
      parser.Fail("entry " + FormatShort(e) + " has " + FormatShort(static_cast<long long>(tokens.size())) +
                  " fields; expected the label and " + FormatShort(4 * lines) + " values");
    }
    if (tokens[0] != "0" && tokens[0] != "1") {
      parser.Fail("entry " + FormatShort(e) + " has the label '" + tokens[0] +
                  "'; it must be 1 (traversable) or 0 (non-traversable)");
    }
    memory.labels_.push_back(tokens[0] == "1" ? 1 : 0);
    for (std::size_t v = 1; v < tokens.size(); ++v) {
      const double value = parser.Number(tokens[v], "value " + FormatShort(static_cast<long long>(v - 1)));
      if (value < 0.0) parser.Fail("value " + FormatShort(static_cast<long long>(v - 1)) + " is negative: " + tokens[v]);
      memory.values_.push_back(value);
    }
  }
  if (!parser.AtEnd()) parser.Fail("unexpected text after the " + FormatShort(entries) + " declared entries");
  return memory;
}

void TraversabilityMemory::Save(const std::string& path) const { WriteFileAtomically(path, ToText()); }

TraversabilityMemory TraversabilityMemory::Load(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw std::runtime_error("cannot read the memory file '" + path + "': " +
                             std::system_category().message(errno));
  }
  if (!S_ISREG(info.st_mode)) throw std::runtime_error("the memory file '" + path + "' is not a regular file");
  if (info.st_size > kMaxFileBytes) {
    throw std::runtime_error("the memory file '" + path + "' has " + FormatShort(static_cast<long long>(info.st_size)) +
                             " bytes; at most " + FormatShort(static_cast<long long>(kMaxFileBytes)) + " are read");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open the memory file '" + path + "'");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return FromText(buffer.str(), path);
}

}  // namespace cairn::perception
