// A small streaming JSON writer: objects, arrays, strings (escaped), numbers
// (shortest form that reads back exactly; NaN/inf as null), booleans.
// Output is indented for people and parsed by any JSON reader (json.load).
#pragma once

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace reebkit {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  /// The key of the next value inside an object.
  JsonWriter& key(std::string_view name);

  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(double number);
  JsonWriter& value(long long number);
  JsonWriter& value(int number) { return value(static_cast<long long>(number)); }
  JsonWriter& value(bool flag);
  JsonWriter& null();

  /// A one-line array of numbers, e.g. a position or an id list.
  template <typename Range>
  JsonWriter& numbers(const Range& range) {
    begin_inline_array();
    for (const auto& x : range) value(x);
    return end_array();
  }

  /// key(name).value(v) in one call.
  template <typename T>
  JsonWriter& field(std::string_view name, const T& v) {
    key(name);
    return value(v);
  }

 private:
  struct Level {
    bool is_object;
    bool inline_items;
    int count;
  };
  void before_value();
  void newline();
  void begin_inline_array();

  std::ostream& out_;
  std::vector<Level> stack_;
  bool after_key_ = false;
};

}  // namespace reebkit
