#include "reebkit/collection/mesh_inputs.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"

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

/// The message of the InvalidArgument `f` throws ("" when none).
template <typename F>
std::string argument_error(F&& f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
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
  const std::string message =
      argument_error([&] { list_mesh_inputs({(dir / "list.lst").string(), (dir / "nowhere").string()}); });
  EXPECT_NE(message.find("missing inputs"), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "list.lst").string() + ":3: "), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "nowhere").string()), std::string::npos) << message;
}

TEST(MeshInputs, DuplicateNamesAndUnknownKindsAreErrors) {
  const TempDir dir;
  touch(dir / "one/x.off");
  touch(dir / "two/x.off");
  touch(dir / "data.csv");
  const std::string twice = argument_error([&] { list_mesh_inputs({(dir / "one").string(), (dir / "two").string()}); });
  EXPECT_NE(twice.find("two meshes named 'x.off'"), std::string::npos) << twice;
  EXPECT_NE(twice.find((dir / "two" / "x.off").string()), std::string::npos) << twice;
  const std::string kind = argument_error([&] { list_mesh_inputs({(dir / "data.csv").string()}); });
  EXPECT_NE(kind.find("data.csv: not a folder"), std::string::npos) << kind;
}

}  // namespace
}  // namespace reebkit::test
