#include "reebkit/output/obj_lines.h"

#include "reebkit/core/error.h"

#include <gtest/gtest.h>

#include <sstream>

namespace reebkit {
namespace {

TEST(ObjLines, PointsAreNumberedFromOneAndReadBackExactly) {
  std::ostringstream text;
  ObjLinesWriter obj(text);
  const Vec3 p(0.1, -1.0 / 3.0, 1e-300), q(12345.678901234567, 2.0, -0.0);
  obj.comment("two points").object("segment");
  EXPECT_EQ(obj.point(p), 1);
  EXPECT_EQ(obj.point(q), 2);
  EXPECT_EQ(obj.points(), 2);
  obj.line({1, 2}).line({2, 1, 2});

  std::istringstream in(text.str());
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "# two points");
  std::getline(in, line);
  EXPECT_EQ(line, "o segment");
  for (const Vec3& want : {p, q}) {
    std::string tag;
    Vec3 got;
    in >> tag >> got.x() >> got.y() >> got.z();
    EXPECT_EQ(tag, "v");
    EXPECT_EQ(got, want);
  }
  std::getline(in, line);  // the rest of the last `v` line
  std::getline(in, line);
  EXPECT_EQ(line, "l 1 2");
  std::getline(in, line);
  EXPECT_EQ(line, "l 2 1 2");
  EXPECT_FALSE(std::getline(in, line));
}

TEST(ObjLines, RejectsShortLinesUnwrittenPointsAndBrokenComments) {
  std::ostringstream text;
  ObjLinesWriter obj(text);
  obj.point(Vec3::Zero());
  obj.point(Vec3::Ones());
  EXPECT_THROW(obj.line({1}), InvalidArgument);
  EXPECT_THROW(obj.line({1, 3}), InvalidArgument);
  EXPECT_THROW(obj.line({0, 1}), InvalidArgument);
  EXPECT_THROW(obj.comment("two\nlines"), InvalidArgument);
  EXPECT_NO_THROW(obj.line({2, 1}));
}

}  // namespace
}  // namespace reebkit
