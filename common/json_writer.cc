#include "cairn/common/json_writer.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cairn/common/atomic_file.h"
#include "cairn/common/number_text.h"

namespace cairn {
namespace {

// "%.*g" and "%.*f" of a finite double; "%.17f" of 1e308 needs 327 characters, so the buffer is sized per call.
std::string FormatNumber(double value, const JsonWriter::NumberFormat& format) {
  const char* pattern = format.style == JsonWriter::NumberFormat::Style::kFixed ? "%.*f" : "%.*g";
  const int size = std::snprintf(nullptr, 0, pattern, format.digits, value);
  std::string text(static_cast<std::size_t>(size) + 1, '\0');
  std::snprintf(text.data(), text.size(), pattern, format.digits, value);
  text.resize(static_cast<std::size_t>(size));
  return text;
}

// nlohmann-json's serializer escapes the string; invalid UTF-8 is replaced (U+FFFD) rather than thrown on, so a
// path with a stray Latin-1 byte still gives a valid document.
std::string QuotedJsonString(std::string_view value) {
  return nlohmann::json(std::string(value)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

JsonWriter::NumberFormat JsonWriter::Significant(int digits) {
  if (digits < 1 || digits > 17) {
    throw std::invalid_argument("JsonWriter::Significant: " + FormatShort(digits) +
                                " significant digits; use 1 to 17 (17 round-trips every double)");
  }
  return NumberFormat{NumberFormat::Style::kSignificant, digits};
}

JsonWriter::NumberFormat JsonWriter::Fixed(int decimals) {
  if (decimals < 0 || decimals > 17) {
    throw std::invalid_argument("JsonWriter::Fixed: " + FormatShort(decimals) + " decimals; use 0 to 17");
  }
  return NumberFormat{NumberFormat::Style::kFixed, decimals};
}

void JsonWriter::Misuse(const std::string& what) const {
  throw std::logic_error("JsonWriter: " + what + " (document so far: " +
                         (text_.size() > 80 ? "..." + text_.substr(text_.size() - 80) : text_) + ")");
}

void JsonWriter::Separate(Open* open) {
  if (open->items > 0) text_ += ',';
  if (break_indent_ >= 0) {
    text_ += '\n';
    text_.append(static_cast<std::size_t>(break_indent_), ' ');
    break_indent_ = -1;
  } else if (open->items > 0) {
    text_ += ' ';
  }
  ++open->items;
}

void JsonWriter::BeforeValue(const char* what) {
  if (done_) Misuse(std::string(what) + " after the top-level value is complete");
  if (open_.empty()) return;
  Open& open = open_.back();
  if (open.container == Container::kObject) {
    if (!key_pending_) Misuse(std::string(what) + " in an object where a Key is due");
    key_pending_ = false;
    return;  // Key wrote the separator
  }
  Separate(&open);
}

void JsonWriter::AfterValue() {
  if (open_.empty()) done_ = true;
}

JsonWriter& JsonWriter::BeginObject() {
  BeforeValue("BeginObject");
  text_ += '{';
  open_.push_back(Open{Container::kObject, 0});
  return *this;
}

JsonWriter& JsonWriter::EndObject() {
  if (open_.empty() || open_.back().container != Container::kObject) Misuse("EndObject without an open object");
  if (key_pending_) Misuse("EndObject after a Key without its value");
  open_.pop_back();
  text_ += '}';
  break_indent_ = -1;
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::BeginArray() {
  BeforeValue("BeginArray");
  text_ += '[';
  open_.push_back(Open{Container::kArray, 0});
  return *this;
}

JsonWriter& JsonWriter::EndArray() {
  if (open_.empty() || open_.back().container != Container::kArray) Misuse("EndArray without an open array");
  open_.pop_back();
  text_ += ']';
  break_indent_ = -1;
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::Key(std::string_view key) {
  if (open_.empty() || open_.back().container != Container::kObject) Misuse("Key outside an object");
  if (key_pending_) Misuse("Key '" + std::string(key) + "' after a Key without its value");
  Open& open = open_.back();
  Separate(&open);
  text_ += QuotedJsonString(key);
  text_ += ": ";
  key_pending_ = true;
  return *this;
}

JsonWriter& JsonWriter::String(std::string_view value) {
  BeforeValue("String");
  text_ += QuotedJsonString(value);
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::Number(double value, NumberFormat format) {
  BeforeValue("Number");
  text_ += std::isfinite(value) ? FormatNumber(value, format) : std::string("null");
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::WriteInteger(long long value) {
  BeforeValue("Integer");
  text_ += FormatShort(value);
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::WriteUnsigned(unsigned long long value) {
  BeforeValue("Integer");
  text_ += FormatShort(value);
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::Bool(bool value) {
  BeforeValue("Bool");
  text_ += value ? "true" : "false";
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::Null() {
  BeforeValue("Null");
  text_ += "null";
  AfterValue();
  return *this;
}

JsonWriter& JsonWriter::BreakLine(int indent) {
  if (indent < 0 || indent > 64) {
    throw std::invalid_argument("JsonWriter::BreakLine: indent " + FormatShort(indent) + "; use 0 to 64 spaces");
  }
  break_indent_ = indent;
  return *this;
}

bool JsonWriter::complete() const { return done_; }

const std::string& JsonWriter::text() const {
  if (!done_) {
    Misuse(text_.empty() ? std::string("text() of an empty document")
                         : "text() with " + FormatShort(open_.size()) + " object(s)/array(s) still open");
  }
  return text_;
}

void JsonWriter::WriteFile(const std::string& path) const { WriteFileAtomically(path, text() + "\n"); }

}  // namespace cairn
