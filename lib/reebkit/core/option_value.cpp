#include "reebkit/core/option_value.h"

#include "reebkit/core/error.h"

#include <charconv>
#include <cstdlib>
#include <system_error>

namespace reebkit {

std::string option_text(const OptionValue& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return *text;
  char digits[32];
  const auto* integer = std::get_if<std::int64_t>(&value);
  const auto end = integer ? std::to_chars(digits, digits + sizeof digits, *integer).ptr
                           : std::to_chars(digits, digits + sizeof digits, std::get<double>(value)).ptr;
  return std::string(digits, end);
}

OptionValue option_value_from_text(const OptionValue& kind, const std::string& text) {
  if (std::holds_alternative<std::string>(kind)) return text;
  const char* const end = text.data() + text.size();
  if (std::holds_alternative<std::int64_t>(kind)) {
    std::int64_t integer = 0;
    const auto [at, error] = std::from_chars(text.data(), end, integer);
    if (error == std::errc() && at == end && !text.empty()) return integer;
  } else {
    char* at = nullptr;
    const double number = std::strtod(text.c_str(), &at);
    if (at == end && !text.empty()) return number;
  }
  throw InvalidArgument("'" + text + "' is not " +
                        (std::holds_alternative<std::int64_t>(kind) ? "an integer" : "a number"));
}

const char* option_kind(const OptionValue& value) {
  static const char* const kinds[] = {"integer", "number", "text"};
  return kinds[value.index()];
}

}  // namespace reebkit
