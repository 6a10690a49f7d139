#include "reebkit/io/content_hash.h"

#include "reebkit/core/error.h"
#include "support/test_support.h"

#include <fstream>

namespace reebkit {
namespace {

TEST(ContentHash, EmptyInputIsTheFnvOffsetBasis) { EXPECT_EQ(hash_bytes(""), 0xcbf29ce484222325ULL); }

TEST(ContentHash, OneByteIsOneFnv1aStep) {
  // FNV-1a of "a": (offset ^ 0x61) * prime, mod 2^64.
  EXPECT_EQ(hash_bytes("a"), (0xcbf29ce484222325ULL ^ 0x61ULL) * 0x100000001b3ULL);
}

TEST(ContentHash, EveryByteMatters) {
  std::string text = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const std::uint64_t h = hash_bytes(text);
  for (std::size_t i = 0; i < text.size(); ++i) {
    std::string changed = text;
    changed[i] = static_cast<char>(changed[i] ^ 1);
    EXPECT_NE(hash_bytes(changed), h) << "byte " << i;
  }
  EXPECT_NE(hash_bytes(text + " "), h);
  EXPECT_EQ(hash_bytes(text), h);
}

TEST(ContentHash, FileHashIsTheHashOfItsBytes) {
  const auto path = std::filesystem::temp_directory_path() / "reebkit_content_hash_test.off";
  const std::string text = "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  std::ofstream(path, std::ios::binary) << text;
  EXPECT_EQ(content_hash(path), hash_bytes(text));
  std::filesystem::remove(path);
  EXPECT_THROW(content_hash(path), MeshFileError);
}

}  // namespace
}  // namespace reebkit
