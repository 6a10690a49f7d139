// Fixed-size numbers in binary mesh files (PLY, STL), in either byte order,
// independent of the byte order of the machine.
#pragma once

#include <algorithm>
#include <cassert>
#include <cstring>
#include <string>
#include <string_view>

namespace reebkit {

inline constexpr bool kHostBigEndian = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;

/// A cursor over a byte buffer that reads numbers stored in a given byte order.
class ByteReader {
 public:
  ByteReader(std::string_view bytes, bool big_endian) : bytes_(bytes), big_endian_(big_endian) {}

  std::size_t remaining() const { return bytes_.size() - pos_; }

  /// The next sizeof(T) bytes as a T. Precondition: remaining() >= sizeof(T).
  template <typename T>
  T read() {
    assert(remaining() >= sizeof(T));
    char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if (big_endian_ != kHostBigEndian) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  /// Precondition: remaining() >= n.
  void skip(std::size_t n) {
    assert(remaining() >= n);
    pos_ += n;
  }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  bool big_endian_;
};

/// Appends the bytes of `value` in the given byte order.
template <typename T>
void append_bytes(std::string& out, T value, bool big_endian) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian != kHostBigEndian) std::reverse(raw, raw + sizeof(T));
  out.append(raw, sizeof(T));
}

}  // namespace reebkit
