#include "reebkit/core/error.h"

#include <gtest/gtest.h>

namespace reebkit {
namespace {

TEST(MeshFileError, MessageNamesFileLineAndProblem) {
  const MeshFileError e("shapes/cat.off", 12, "expected 3 coordinates, found 2");
  EXPECT_STREQ(e.what(), "shapes/cat.off:12: expected 3 coordinates, found 2");
  EXPECT_EQ(e.file(), "shapes/cat.off");
  EXPECT_EQ(e.line(), 12u);
  EXPECT_EQ(e.problem(), "expected 3 coordinates, found 2");
}

TEST(MeshFileError, BinaryFilesHaveNoLineNumber) {
  const MeshFileError e("a.stl", "truncated: 3 of 10 triangles");
  EXPECT_STREQ(e.what(), "a.stl: truncated: 3 of 10 triangles");
}

TEST(InvalidMeshError, MessageNamesSourceAndProblem) {
  const InvalidMeshError e("b.ply", "no faces");
  EXPECT_STREQ(e.what(), "b.ply: no faces");
  const Error& base = e;  // caught as the common base
  EXPECT_STREQ(base.what(), "b.ply: no faces");
}

}  // namespace
}  // namespace reebkit
