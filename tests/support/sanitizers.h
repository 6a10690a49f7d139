// Whether the tests run under AddressSanitizer (`bash tools/run check`),
// where the analysis of a mesh runs several times slower: the tests that
// analyse a whole real collection then take a sparser sample of it, and say so.
#pragma once

#include <iostream>

#if defined(__SANITIZE_ADDRESS__)
#define REEBKIT_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define REEBKIT_TEST_ASAN 1
#endif
#endif

namespace reebkit::test {

#ifdef REEBKIT_TEST_ASAN
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif

/// Every how many meshes of a collection a test analyses: `stride`, or
/// `sanitized_stride` under AddressSanitizer (printed).
inline int mesh_stride(int stride, int sanitized_stride) {
  if (!kAddressSanitizer) return stride;
  std::cout << "[ sample ] AddressSanitizer build: every " << sanitized_stride << "th mesh instead of every "
            << stride << "\n";
  return sanitized_stride;
}

}  // namespace reebkit::test
