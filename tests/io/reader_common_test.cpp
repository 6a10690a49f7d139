// Limits every mesh reader shares (reader_common.h): a header claiming an
// absurd size gives a clear error naming the file, and no reader reserves
// memory for what it was told rather than for what the file can hold.
#include "reebkit/io/reader_common.h"

#include "io/io_test_util.h"
#include "reebkit/io/off.h"
#include "reebkit/io/ply.h"
#include "reebkit/io/stl.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <new>
#include <string>
#include <utility>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define REEBKIT_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define REEBKIT_TEST_ASAN 1
#endif
#endif

namespace reebkit::test {
namespace {

/// A binary little-endian PLY whose one face claims `corners` corners.
std::string ply_face_claiming(std::uint32_t corners) {
  std::string out =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  out.append(36, '\0');  // three vertices at the origin
  out.append(reinterpret_cast<const char*>(&corners), sizeof corners);
  const std::int32_t first[3] = {0, 1, 2};
  out.append(reinterpret_cast<const char*>(first), sizeof first);
  return out;
}

/// A binary STL of one triangle whose header claims `count` triangles.
std::string stl_claiming(std::uint32_t count) {
  std::string out(80, ' ');
  out.append(reinterpret_cast<const char*>(&count), sizeof count);
  out.append(50, '\0');
  return out;
}

struct Case {
  const char* what;
  std::function<void()> parse;
  std::vector<std::string> message;  // what the error must say
};

std::vector<Case> absurd_headers() {
  return {
      {"OFF claiming 10^12 vertices",
       [] { parse_off("OFF\n1000000000000 1 0\n0 0 0\n", "a.off"); },
       {"a.off:2:", "bad vertex count 1000000000000"}},
      {"OFF claiming 2^31 - 1 vertices and faces",
       [] { parse_off("OFF\n2147483647 2147483647 0\n0 0 0\n", "a.off"); },
       {"a.off", "truncated: file ends after 1 of 2147483647 vertices"}},
      {"OFF face claiming 10^9 corners",
       [] { parse_off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000 0 1 2\n", "a.off"); },
       {"a.off:6:", "expected a vertex index"}},
      {"ASCII PLY claiming 10^12 vertices",
       [] { parse_ply("ply\nformat ascii 1.0\nelement vertex 1000000000000\nend_header\n", "a.ply"); },
       {"a.ply:3:", "bad 'vertex' element count 1000000000000"}},
      {"binary PLY claiming 2^31 - 1 vertices",
       [] {
         parse_ply(
             "ply\nformat binary_little_endian 1.0\nelement vertex 2147483647\nproperty float x\n"
             "property float y\nproperty float z\nend_header\n" +
                 std::string(12, '\0'),
             "a.ply");
       },
       {"a.ply", "truncated", "of 2147483647 vertices"}},
      {"binary PLY face claiming 10^9 corners",
       [] { parse_ply(ply_face_claiming(1000000000u), "a.ply"); },
       {"a.ply", "truncated"}},
      {"binary STL claiming 2^32 - 1 triangles",
       [] { parse_stl(stl_claiming(4294967295u), "a.stl"); },
       {"a.stl", "truncated: the binary header declares 4294967295 triangles"}},
  };
}

/// The message of the error `parse` throws; "bad_alloc" when it ran out of
/// memory instead; "" when it threw nothing.
std::string message_of(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const Error& e) {
    return e.what();
  } catch (const std::bad_alloc&) {
    return "bad_alloc";
  }
  return "";
}

TEST(ReaderLimits, AbsurdSizesInHeadersAreClearErrors) {
  for (const Case& c : absurd_headers()) {
    SCOPED_TRACE(c.what);
    const std::string message = message_of(c.parse);
    for (const std::string& part : c.message) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

#ifndef REEBKIT_TEST_ASAN
/// The program's address space now, in bytes (/proc/self/statm).
std::uint64_t address_space_bytes() {
  std::uint64_t pages = 0;
  std::ifstream("/proc/self/statm") >> pages;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

TEST(ReaderLimits, AbsurdSizesInHeadersFailWithinA256MiBAddressSpaceLimit) {
  // In a child whose address space may grow by 256 MiB only: a reader that
  // reserved room for a claimed 2^31 vertices (48 GiB of coordinates) would
  // get bad_alloc instead of its error. (Not under AddressSanitizer, which
  // maps terabytes of shadow memory up front.)
  for (const Case& c : absurd_headers()) {
    SCOPED_TRACE(c.what);
    // (a child with no file size limit to speak of: RLIMIT_AS is set inside)
    const auto [status, message] = run_with_file_size_limit(std::uint64_t{1} << 40, [&](int fd) {
      const rlim_t bytes = address_space_bytes() + (256u << 20);
      const rlimit limit = {bytes, bytes};
      ::setrlimit(RLIMIT_AS, &limit);
      const std::string text = message_of(c.parse);
      (void)!::write(fd, text.data(), text.size());
    });
    EXPECT_EQ(status, 0) << message;
    for (const std::string& part : c.message) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}
#endif

}  // namespace
}  // namespace reebkit::test
