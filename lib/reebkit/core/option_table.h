// A table of the options of an Options struct by name: one row per option
// (its name, its help line, the values it may take, how to read, set and
// check it), from which the command line (one flag per row), the Python
// keywords, the range checks, the collection file and the docs' lists of
// options follow. Adding an option is one row (option_field). The tables:
// analysis_option_fields (pipeline/analysis_options.h) and
// matching_option_fields (matching/matching_options.h).
#pragma once

#include "reebkit/core/error.h"
#include "reebkit/core/option_value.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace reebkit {

/// The values a numeric option may take: finite and in [lowest, highest],
/// or (lowest, highest] when `above_lowest` (NaN and infinities never).
struct OptionRange {
  double lowest = -std::numeric_limits<double>::infinity();
  double highest = std::numeric_limits<double>::infinity();
  bool above_lowest = false;

  bool holds(double x) const { return std::isfinite(x) && (above_lowest ? x > lowest : x >= lowest) && x <= highest; }
  /// "[0, inf)", "(0, 1]".
  std::string text() const {
    const auto bound = [](double x) { return std::isinf(x) ? std::string("inf") : option_text(x); };
    return (above_lowest ? "(" : "[") + bound(lowest) + ", " + bound(highest) + (std::isinf(highest) ? ")" : "]");
  }
};

/// One option of `Options`.
template <typename Options>
struct OptionField {
  std::string name;   ///< snake_case, as stored and as a Python keyword; the flag is --name with '-' for '_'
  std::string help;   ///< one line for --help and the docs
  OptionRange range;  ///< a number's values (a text option: those its parser accepts)
  /// The option's value in `options`: its kind (integer, number, text) is
  /// the option's for every Options.
  std::function<OptionValue(const Options& options)> get;
  /// Sets the option. Throws InvalidArgument naming the option when `value`
  /// is of another kind or out of the option's type's range, and the
  /// option's own error for a text it does not know.
  std::function<void(Options& options, const OptionValue& value)> set;
  /// Throws InvalidArgument naming the option, its value and its range when
  /// its value in `options` is out of that range.
  std::function<void(const Options& options)> check;

  /// set, then check: `options` is left as it was when either throws.
  void set_checked(Options& options, const OptionValue& value) const {
    Options changed = options;
    set(changed, value);
    check(changed);
    options = changed;
  }
  /// The values a number may take as text ("[0, inf)"); "" for a text
  /// option (its help names them).
  std::string values() const {
    return std::holds_alternative<std::string>(get(Options{})) ? std::string() : range.text();
  }
  /// The help line with the values: what --help and the docs show.
  std::string described() const { return values().empty() ? help : help + "; values in " + values(); }
};

namespace option_table_detail {

/// A number as an OptionValue; a text option's type T supplies
/// `OptionValue option_value_of(T)` (found by argument-dependent lookup).
template <typename T>
OptionValue to_value(const T& x) {
  if constexpr (std::is_floating_point_v<T>)
    return static_cast<double>(x);
  else if constexpr (std::is_integral_v<T>)
    return static_cast<std::int64_t>(x);
  else
    return option_value_of(x);
}

/// The inverse; a text option's type supplies `void set_from_option(const
/// OptionValue&, T&)`.
template <typename T>
void from_value(const OptionValue& value, T& x, const std::string& label) {
  if constexpr (std::is_floating_point_v<T>) {
    x = static_cast<T>(std::get<double>(value));
  } else if constexpr (std::is_integral_v<T>) {
    const std::int64_t v = std::get<std::int64_t>(value);
    if (v < std::numeric_limits<T>::min() || v > std::numeric_limits<T>::max())
      throw InvalidArgument(label + ": " + std::to_string(v) + " is out of range");
    x = static_cast<T>(v);
  } else {
    set_from_option(value, x);
  }
}

}  // namespace option_table_detail

/// The row of the option that `access` selects (a generic lambda `[](auto&
/// o) -> auto& { return o.part.member; }`), whose values lie in `range`.
/// `what` names the table in messages ("analysis option").
template <typename Options, typename Access>
OptionField<Options> option_field(const std::string& what, const std::string& name, const std::string& help,
                                  Access access, OptionRange range = {}) {
  using T = std::decay_t<decltype(access(std::declval<Options&>()))>;
  const std::string label = what + " " + name;
  OptionField<Options> field;
  field.name = name;
  field.help = help;
  field.range = range;
  field.get = [access](const Options& o) { return option_table_detail::to_value(access(o)); };
  field.set = [access, label](Options& o, const OptionValue& value) {
    const OptionValue kind = option_table_detail::to_value(T{});
    if (value.index() != kind.index())
      throw InvalidArgument(label + ": expected " + option_kind(kind) + ", got " + option_kind(value) + " '" +
                            option_text(value) + "'");
    option_table_detail::from_value(value, access(o), label);
  };
  if constexpr (std::is_arithmetic_v<T>)
    field.check = [access, label, range](const Options& o) {
      const T value = access(o);
      if (!range.holds(static_cast<double>(value)))
        throw InvalidArgument(label + ": " + option_text(option_table_detail::to_value(value)) +
                              " is out of its range " + range.text());
    };
  else
    field.check = [](const Options&) {};  // a text option has no range
  return field;
}

/// Checks every option's range (OptionField::check).
template <typename Options>
void check_options(const std::vector<OptionField<Options>>& fields, const Options& options) {
  for (const OptionField<Options>& f : fields) f.check(options);
}

/// `options` by name, in table order.
template <typename Options>
std::vector<NamedOption> named_options(const std::vector<OptionField<Options>>& fields, const Options& options) {
  std::vector<NamedOption> out;
  for (const OptionField<Options>& f : fields) out.push_back({f.name, f.get(options)});
  return out;
}

/// Sets the option of `assignment` "NAME=VALUE", VALUE read as the option's
/// kind (option_value_from_text), and checks its range. Throws
/// InvalidArgument naming `assignment` for no '=', an unknown NAME, a VALUE
/// of another kind or out of the option's range (`options` unchanged then).
template <typename Options>
void set_option_text(const std::vector<OptionField<Options>>& fields, Options& options, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  const std::string name = assignment.substr(0, eq);
  const OptionField<Options>* field = nullptr;
  for (const OptionField<Options>& f : fields)
    if (f.name == name) field = &f;
  if (eq == std::string::npos || !field)
    throw InvalidArgument(assignment + ": expected NAME=VALUE, NAME one of the options");
  try {
    field->set_checked(options, option_value_from_text(field->get(options), assignment.substr(eq + 1)));
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(assignment + ": " + e.what());
  }
}

/// The row named `name`, or nullptr.
template <typename Options>
const OptionField<Options>* find_option(const std::vector<OptionField<Options>>& fields, const std::string& name) {
  for (const OptionField<Options>& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace reebkit
