// SHREC07 .vts feature-point files: the vertex ids in file order, and an
// error naming the file and line for a line that is not "ID X Y Z".
#include "reebkit/io/vts.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

namespace reebkit::test {
namespace {

TEST(Vts, IdsInFileOrderAndErrorsNamingTheLine) {
  const TempDir dir;
  write_bytes(dir / "1.vts",
              "     4    -0.047776    -0.004247     0.416383\n   347 -0.01 -0.14 0.20\r\n\n1744 0 1e-3 5\n");
  EXPECT_EQ(read_vts(dir / "1.vts"), (std::vector<Index>{4, 347, 1744}));
  write_bytes(dir / "bad.vts", "4 0 0 0\n5 0 0\n");
  const MeshFileError e = error_of([&] { read_vts(dir / "bad.vts"); });
  EXPECT_EQ(e.line(), 2u);
  EXPECT_NE(e.problem().find("expected VERTEX_ID X Y Z"), std::string::npos) << e.what();
  write_bytes(dir / "negative.vts", "-1 0 0 0\n");
  EXPECT_THROW(read_vts(dir / "negative.vts"), MeshFileError);
  EXPECT_THROW(read_vts(dir / "missing.vts"), MeshFileError);
}

}  // namespace
}  // namespace reebkit::test
