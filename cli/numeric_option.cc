#include "numeric_option.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "cairn/common/number_text.h"
#include "usage_error.h"

namespace cairn::cli {
namespace {

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

// Decimal syntax only: [+-] digits [. digits] [e [+-] digits], with at least one digit before the exponent.
// (std::strtod would also take hexadecimal, "nan" and "inf", and leading blanks.)
bool IsDecimal(const std::string& text) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  std::size_t digits = 0;
  while (i < text.size() && IsDigit(text[i])) ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && IsDigit(text[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t exponent_digits = 0;
    while (i < text.size() && IsDigit(text[i])) ++i, ++exponent_digits;
    if (exponent_digits == 0) return false;
  }
  return i == text.size();
}

bool IsInteger(const std::string& text) {
  std::size_t i = (!text.empty() && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  if (i == text.size()) return false;
  for (; i < text.size(); ++i) {
    if (!IsDigit(text[i])) return false;
  }
  return true;
}

bool IsNonFiniteWord(std::string text) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.erase(0, 1);
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text == "nan" || text == "inf" || text == "infinity";
}

[[noreturn]] void Refuse(const std::string& option, const std::string& text, const std::string& problem,
                         const NumberRange& range, bool integer) {
  throw UsageError(option + " '" + text + "' " + problem + "; give " + range.Describe(integer));
}

}  // namespace

template <typename T>
T ParseNumber(const std::string& option, const std::string& text, const NumberRange& range) {
  constexpr bool kInteger = std::is_integral_v<T>;
  if (IsNonFiniteWord(text)) Refuse(option, text, "is not a finite number", range, kInteger);
  if (!IsDecimal(text)) Refuse(option, text, "is not a number", range, kInteger);
  errno = 0;
  const double number = std::strtod(text.c_str(), nullptr);
  const bool overflow = errno == ERANGE && std::fabs(number) > 1.0;  // ERANGE also flags harmless underflow
  if constexpr (kInteger) {
    long long parsed = 0;
    if (IsInteger(text)) {
      // Digits are converted exactly: a double would round 2^53 + 1.
      errno = 0;
      parsed = std::strtoll(text.c_str(), nullptr, 10);
      if (errno == ERANGE) Refuse(option, text, "is out of range", range, true);
    } else {
      // "1e3" or "20.0" name integers too.
      if (overflow || std::fabs(number) > 9007199254740992.0) Refuse(option, text, "is out of range", range, true);
      if (number != std::floor(number)) Refuse(option, text, "is not an integer", range, true);
      parsed = static_cast<long long>(number);
    }
    if (!range.Contains(static_cast<double>(parsed)) || parsed < static_cast<long long>(range.lower()) ||
        parsed > static_cast<long long>(range.upper())) {
      const bool even = range.odd_only() && parsed % 2 == 0 && NumberRange::Closed(range.lower(), range.upper())
                                                                   .Contains(static_cast<double>(parsed));
      Refuse(option, text, even ? "is even" : "is out of range", range, true);
    }
    return static_cast<T>(parsed);
  } else {
    if (overflow || !range.Contains(number)) Refuse(option, text, "is out of range", range, false);
    return static_cast<T>(number);
  }
}

template <typename T>
CLI::Option* AddNumberOption(CLI::App& app, const std::string& name, T* value, const std::string& description,
                             const NumberRange& range) {
  constexpr bool kInteger = std::is_integral_v<T>;
  if constexpr (kInteger) {
    if (range.lower() < static_cast<double>(std::numeric_limits<T>::lowest()) ||
        range.upper() > static_cast<double>(std::numeric_limits<T>::max())) {
      throw std::logic_error("AddNumberOption " + name + ": the range does not fit the option's integer type");
    }
  }
  CLI::Option* option = app.add_option_function<std::string>(
      name, [value, name, range](const std::string& text) { *value = ParseNumber<T>(name, text, range); },
      description + "; " + range.Describe(kInteger));
  option->type_name(kInteger ? "INT" : "NUMBER");
  if constexpr (kInteger) {
    option->default_str(std::to_string(*value));
  } else {
    option->default_str(FormatShort(static_cast<double>(*value)));
  }
  return option;
}

template double ParseNumber<double>(const std::string&, const std::string&, const NumberRange&);
template int ParseNumber<int>(const std::string&, const std::string&, const NumberRange&);
template unsigned ParseNumber<unsigned>(const std::string&, const std::string&, const NumberRange&);
template long long ParseNumber<long long>(const std::string&, const std::string&, const NumberRange&);
template CLI::Option* AddNumberOption<double>(CLI::App&, const std::string&, double*, const std::string&,
                                              const NumberRange&);
template CLI::Option* AddNumberOption<int>(CLI::App&, const std::string&, int*, const std::string&, const NumberRange&);
template CLI::Option* AddNumberOption<unsigned>(CLI::App&, const std::string&, unsigned*, const std::string&,
                                                const NumberRange&);
template CLI::Option* AddNumberOption<long long>(CLI::App&, const std::string&, long long*, const std::string&,
                                                 const NumberRange&);

}  // namespace cairn::cli
