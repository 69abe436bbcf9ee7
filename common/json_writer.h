#pragma once

/// @file
/// The one way Cairn writes JSON (the commands' --json output, plan.json, friction.json, ...).

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace cairn {

/// Writes one JSON document front to back: objects, arrays, keys and values in order, laid out the way Cairn's
/// files and commands print JSON (`{"key": value, "list": [1, 2]}` on one line unless BreakLine asks for more).
/// Strings are escaped by nlohmann-json (quotes, backslashes, control characters; invalid UTF-8 becomes U+FFFD),
/// so any text, a path or a label, gives valid JSON. Numbers are written with the format each value asks for;
/// JSON has no NaN or infinity, so a non-finite number is written as null.
///
///     JsonWriter json;
///     json.BeginObject().Key("scenario").String(name).Key("precision").Number(p, JsonWriter::Fixed(4));
///     json.Key("frames").BeginArray().Integer(1).Integer(2).EndArray().EndObject();
///     json.WriteFile(path);  // or print json.text()
///
/// Calls out of order (a value where a key is due, EndArray closing an object, a second top-level value, text()
/// of an unfinished document) are bugs in the caller: they throw std::logic_error saying what was expected.
class JsonWriter {
 public:
  /// How a number is written: "%.*g" with `digits` significant digits, or "%.*f" with `digits` decimals.
  struct NumberFormat {
    enum class Style { kSignificant, kFixed };
    Style style{Style::kSignificant};
    int digits{6};
  };

  /// `digits` significant digits, as printf's "%.*g" (the default, with 6 digits, is FormatShort's). Throws
  /// std::invalid_argument unless 1 <= digits <= 17.
  static NumberFormat Significant(int digits);
  /// `decimals` digits after the point, as printf's "%.*f". Throws std::invalid_argument unless
  /// 0 <= decimals <= 17.
  static NumberFormat Fixed(int decimals);

  /// Starts an object (as a value: at the top, in an array, or after Key).
  JsonWriter& BeginObject();
  /// Ends the innermost object.
  JsonWriter& EndObject();
  /// Starts an array (as a value).
  JsonWriter& BeginArray();
  /// Ends the innermost array.
  JsonWriter& EndArray();
  /// The key of the next member of the innermost object.
  JsonWriter& Key(std::string_view key);

  /// A string value.
  JsonWriter& String(std::string_view value);
  /// A number; null when it is NaN or infinite.
  JsonWriter& Number(double value, NumberFormat format = Significant(6));
  /// An integer, every digit. (Integers of any type; bool is Bool's.)
  template <typename T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>, int> = 0>
  JsonWriter& Integer(T value) {
    if constexpr (std::is_signed_v<T>) {
      return WriteInteger(static_cast<long long>(value));
    } else {
      return WriteUnsigned(static_cast<unsigned long long>(value));
    }
  }
  /// true or false.
  JsonWriter& Bool(bool value);
  /// null.
  JsonWriter& Null();

  /// Puts the next member or element on a new line indented by `indent` spaces, for documents that people read
  /// (one line per body of a robot, say). Throws std::invalid_argument unless 0 <= indent <= 64.
  JsonWriter& BreakLine(int indent);

  /// True once the top-level value is complete.
  bool complete() const;
  /// The document. Throws std::logic_error while it is incomplete (an object or array still open, or nothing
  /// written yet).
  const std::string& text() const;
  /// Writes text() and a final newline to `path` atomically (see WriteFileAtomically); throws as text() does, or
  /// std::runtime_error naming the path when it cannot be written.
  void WriteFile(const std::string& path) const;

 private:
  enum class Container { kObject, kArray };
  struct Open {
    Container container;
    int items;
  };

  JsonWriter& WriteInteger(long long value);
  JsonWriter& WriteUnsigned(unsigned long long value);
  // Writes the separator (and BreakLine's line break) before the next item of `open`.
  void Separate(Open* open);
  // Writes what goes before a value (separator, line break) and checks that a value may come here.
  void BeforeValue(const char* what);
  void AfterValue();
  [[noreturn]] void Misuse(const std::string& what) const;

  std::string text_;
  std::vector<Open> open_;
  bool key_pending_{false};  // Key written, its value not yet
  bool done_{false};         // the top-level value is complete
  int break_indent_{-1};     // BreakLine's indent for the next item, -1 for none
};

}  // namespace cairn
