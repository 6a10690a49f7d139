// A 64-bit hash of a file's bytes: how the collection extractor recognizes a
// mesh it has already indexed (--resume) and one that changed since.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>

namespace reebkit {

/// FNV-1a (64 bit) of `bytes`, read 8 bytes at a time. Not cryptographic:
/// it tells files apart, it does not authenticate them.
std::uint64_t hash_bytes(std::string_view bytes);

/// hash_bytes of the whole file. Throws MeshFileError naming the file when it
/// cannot be read.
std::uint64_t content_hash(const std::filesystem::path& path);

}  // namespace reebkit
