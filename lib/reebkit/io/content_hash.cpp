#include "reebkit/io/content_hash.h"

#include "reebkit/io/file_bytes.h"

namespace reebkit {

std::uint64_t hash_bytes(std::string_view bytes) {
  constexpr std::uint64_t kOffset = 0xcbf29ce484222325ULL;
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  std::uint64_t h = kOffset;
  std::size_t i = 0;
  // Whole 8-byte words (assembled little-endian, so the value does not depend
  // on the machine), then the remaining bytes one by one.
  for (; i + 8 <= bytes.size(); i += 8) {
    std::uint64_t word = 0;
    for (int k = 7; k >= 0; --k)
      word = (word << 8) | static_cast<unsigned char>(bytes[i + static_cast<std::size_t>(k)]);
    h = (h ^ word) * kPrime;
  }
  for (; i < bytes.size(); ++i) h = (h ^ static_cast<unsigned char>(bytes[i])) * kPrime;
  return h;
}

std::uint64_t content_hash(const std::filesystem::path& path) { return hash_bytes(read_file_bytes(path)); }

}  // namespace reebkit
