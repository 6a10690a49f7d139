// A setting as a name and a typed value: how the command line offers the
// analysis options and how the collection file stores them (one typed HDF5
// attribute each), without either knowing the option structs.
#pragma once

#include <cstdint>
#include <string>
#include <variant>

namespace reebkit {

/// An integer, a real number or a text.
using OptionValue = std::variant<std::int64_t, double, std::string>;

struct NamedOption {
  std::string name;  ///< snake_case, e.g. "min_persistence"
  OptionValue value;
};

/// `value` as text: integers in decimal, real numbers in the shortest form
/// that reads back to the same bits ("0.05", "1e-300"), text as it is.
std::string option_text(const OptionValue& value);

/// "integer", "number" or "text": the kind of a value, for messages.
const char* option_kind(const OptionValue& value);

/// `text` read as a value of the kind of `kind` (the whole text: "12",
/// "0.05", "1e-3", any text for a text). Throws InvalidArgument naming the
/// text and the kind when it does not read as one.
OptionValue option_value_from_text(const OptionValue& kind, const std::string& text);

}  // namespace reebkit
