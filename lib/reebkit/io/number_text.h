// Appending numbers to a text buffer for the ASCII writers: std::to_chars,
// shortest form, so that every double reads back to the same bits.
#pragma once

#include <charconv>
#include <string>

namespace reebkit {

/// Appends `value` (an integer or a floating-point number) in its shortest exact form.
template <typename T>
void append_number(std::string& out, T value) {
  char digits[32];
  const auto result = std::to_chars(digits, digits + sizeof digits, value);
  out.append(digits, result.ptr);
}

}  // namespace reebkit
