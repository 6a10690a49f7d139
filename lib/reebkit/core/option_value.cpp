#include "reebkit/core/option_value.h"

#include <charconv>

namespace reebkit {

std::string option_text(const OptionValue& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return *text;
  char digits[32];
  const auto* integer = std::get_if<std::int64_t>(&value);
  const auto end = integer ? std::to_chars(digits, digits + sizeof digits, *integer).ptr
                           : std::to_chars(digits, digits + sizeof digits, std::get<double>(value)).ptr;
  return std::string(digits, end);
}

const char* option_kind(const OptionValue& value) {
  static const char* const kinds[] = {"integer", "number", "text"};
  return kinds[value.index()];
}

}  // namespace reebkit
