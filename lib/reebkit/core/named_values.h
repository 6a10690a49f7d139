// The names of an enumeration's values, as the text options and the files
// spell them: one table per enumeration, read both ways.
#pragma once

#include "reebkit/core/error.h"

#include <array>
#include <cstddef>
#include <string>
#include <utility>

namespace reebkit {

template <typename Enum, std::size_t N>
struct NamedValues {
  const char* what;  ///< what a value is, for messages ("geodesic method")
  std::array<std::pair<Enum, const char*>, N> values;

  const char* name(Enum value) const {
    for (const auto& [v, n] : values)
      if (v == value) return n;
    throw InvalidArgument(std::string("unknown ") + what + " " + std::to_string(static_cast<int>(value)));
  }

  /// Throws InvalidArgument naming `text` and the accepted names.
  Enum parse(const std::string& text) const {
    std::string accepted;
    for (std::size_t k = 0; k < N; ++k) {
      if (text == values[k].second) return values[k].first;
      accepted += (k == 0 ? "" : k + 1 == N ? " or " : ", ") + std::string(values[k].second);
    }
    throw InvalidArgument("unknown " + std::string(what) + " '" + text + "' (expected " + accepted + ")");
  }
};

}  // namespace reebkit
