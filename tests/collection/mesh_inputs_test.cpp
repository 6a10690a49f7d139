#include "reebkit/collection/mesh_inputs.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace reebkit::test {
namespace {

void touch(const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << "x\n";
}

std::vector<std::string> names(const std::vector<MeshInput>& inputs) {
  std::vector<std::string> out;
  for (const MeshInput& m : inputs) out.push_back(m.name);
  return out;
}

TEST(NaturalOrder, DigitRunsCompareByValue) {
  EXPECT_TRUE(natural_less("2.off", "10.off"));
  EXPECT_FALSE(natural_less("10.off", "2.off"));
  EXPECT_TRUE(natural_less("a2", "a10"));
  EXPECT_TRUE(natural_less("x1y2", "x1y10"));
  EXPECT_TRUE(natural_less("pose9", "pose10b"));
  EXPECT_TRUE(natural_less("cat", "cat0"));          // a prefix first
  EXPECT_TRUE(natural_less("cat.off", "cat0.off"));  // '.' before a digit, as in plain order
  EXPECT_TRUE(natural_less("b1", "c0"));
  EXPECT_TRUE(natural_less("a/9.off", "a/10.off"));
  // Runs longer than any integer type compare by length, then digit by digit.
  EXPECT_TRUE(natural_less("m99999999999999999999999", "m100000000000000000000000"));
  EXPECT_TRUE(natural_less("m12345678901234567890123", "m12345678901234567890124"));
  EXPECT_FALSE(natural_less("a", "a"));
}

TEST(NaturalOrder, IsATotalOrderWithLeadingZerosTiedByPlainOrder) {
  EXPECT_TRUE(natural_less("a01", "a1"));
  EXPECT_FALSE(natural_less("a1", "a01"));
  EXPECT_TRUE(natural_less("a001", "a01"));
  EXPECT_TRUE(natural_less("a1", "a002"));
  const std::vector<std::string> words = {"",     "0",  "00",    "1",      "01",  "10",   "a",   "a0",
                                          "a00",  "a1", "a01",   "a10",    "a1b", "a01b", "a1c", "a2",
                                          "a10b", "b",  "a.off", "a1.off", "a-1", "A1",   "a/1", "~"};
  for (const std::string& x : words)
    for (const std::string& y : words) {
      EXPECT_NE(natural_less(x, y) || natural_less(y, x), x == y) << x << " " << y;  // total, irreflexive
      EXPECT_FALSE(natural_less(x, y) && natural_less(y, x)) << x << " " << y;       // asymmetric
      for (const std::string& z : words)
        EXPECT_FALSE(natural_less(x, y) && natural_less(y, z) && !natural_less(x, z)) << x << " " << y << " " << z;
    }
}

TEST(MeshInputs, FolderIsListedInNaturalOrder) {
  const TempDir dir;
  for (const char* f : {"10.off", "2.off", "1.off", "100.off", "20.off", "a/b10.off", "a/b9.off"}) touch(dir / f);
  EXPECT_EQ(names(list_mesh_inputs({(dir / "").string()})),
            (std::vector<std::string>{"1.off", "2.off", "10.off", "20.off", "100.off", "a/b9.off", "a/b10.off"}));
}

TEST(MeshInputs, FolderIsSearchedRecursivelySortedByRelativeName) {
  const TempDir dir;
  for (const char* f : {"b.off", "a/z.OBJ", "a/c.ply", "a/deep/x.Stl", "notes.txt", "a/readme.md", "c.off.bak"})
    touch(dir / f);
  const std::vector<MeshInput> found = list_mesh_inputs({(dir / "").string()});
  EXPECT_EQ(names(found), (std::vector<std::string>{"a/c.ply", "a/deep/x.Stl", "a/z.OBJ", "b.off"}));
  for (const MeshInput& m : found) {
    EXPECT_TRUE(std::filesystem::is_regular_file(m.path)) << m.path;
    EXPECT_TRUE(std::filesystem::equivalent(m.path, dir / m.name)) << m.name;
  }
}

TEST(MeshInputs, ListFileIsRelativeToItsFolderWithComments) {
  const TempDir dir;
  touch(dir / "meshes/one.off");
  touch(dir / "meshes/two.obj");
  touch(dir / "elsewhere.ply");
  std::ofstream(dir / "meshes/list.txt") << "# the collection\n\ntwo.obj   # second first\n  one.off\n"
                                         << (dir / "elsewhere.ply").string() << "\n";
  const std::vector<MeshInput> found = list_mesh_inputs({(dir / "meshes/list.txt").string()});
  ASSERT_EQ(names(found), (std::vector<std::string>{"two.obj", "one.off", (dir / "elsewhere.ply").generic_string()}));
  EXPECT_TRUE(std::filesystem::equivalent(found[0].path, dir / "meshes/two.obj"));
  EXPECT_TRUE(std::filesystem::equivalent(found[1].path, dir / "meshes/one.off"));
}

TEST(MeshInputs, MeshFilesKeepTheirOrderAndNameAsGiven) {
  const TempDir dir;
  touch(dir / "b.off");
  touch(dir / "a.off");
  const std::vector<MeshInput> found = list_mesh_inputs({(dir / "b.off").string(), (dir / "a.off").string()});
  EXPECT_EQ(names(found),
            (std::vector<std::string>{(dir / "b.off").generic_string(), (dir / "a.off").generic_string()}));
}

TEST(MeshInputs, MissingPathsAreAllNamedWithTheListLine) {
  const TempDir dir;
  touch(dir / "ok.off");
  std::ofstream(dir / "list.lst") << "ok.off\n# comment\ngone.off\n";
  const std::string message = thrown_message<InvalidArgument>([&] {
    list_mesh_inputs({(dir / "list.lst").string(), (dir / "nowhere").string()});
  });
  EXPECT_NE(message.find("missing inputs"), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "list.lst").string() + ":3: "), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "nowhere").string()), std::string::npos) << message;
}

TEST(MeshInputs, DuplicateNamesAndUnknownKindsAreErrors) {
  const TempDir dir;
  touch(dir / "one/x.off");
  touch(dir / "two/x.off");
  touch(dir / "data.csv");
  const std::string twice = thrown_message<InvalidArgument>([&] {
    list_mesh_inputs({(dir / "one").string(), (dir / "two").string()});
  });
  EXPECT_NE(twice.find("two meshes named 'x.off'"), std::string::npos) << twice;
  EXPECT_NE(twice.find((dir / "two" / "x.off").string()), std::string::npos) << twice;
  const std::string kind = thrown_message<InvalidArgument>([&] { list_mesh_inputs({(dir / "data.csv").string()}); });
  EXPECT_NE(kind.find("data.csv: not a folder"), std::string::npos) << kind;
}

}  // namespace
}  // namespace reebkit::test
