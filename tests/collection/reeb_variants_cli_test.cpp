// `reeb variants` on two embedded meshes: the files and the .cla agree, every
// variant loads with the genus of its source, the rotated copy has the same
// Reeb graph, and the same seed writes the same bytes.
#include "io/io_test_util.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/pipeline/analyze_mesh.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <set>

namespace reebkit::test {
namespace {

const char* const kSuffixes[] = {"", "_rotated", "_resampled", "_posed1", "_posed2", "_noisy"};

int run_variants(const std::filesystem::path& in, const std::filesystem::path& out) {
  const std::string command =
      std::string(REEB_BINARY) + " variants '" + in.string() + "' -o '" + out.string() + "' > /dev/null 2>&1";
  return std::system(command.c_str());
}

Mesh load(const std::filesystem::path& path) { return std::move(load_mesh(path).components.front()); }

class ReebVariantsCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directories(dir_ / "in");
    for (const char* name : {"cactus.off", "eight.off"})  // genus 0 and 2
      std::filesystem::copy_file(embedded_dataset_dir() / name, dir_ / "in" / name);
    ASSERT_EQ(run_variants(dir_ / "in", dir_ / "out"), 0);
  }
  TempDir dir_;
};

TEST_F(ReebVariantsCli, FilesAndClassFileAgree) {
  const std::vector<PsbClass> classes = read_psb_classes(dir_ / "out" / "variants.cla");
  ASSERT_EQ(classes.size(), 2u);
  EXPECT_EQ(classes[0].name, "cactus");
  EXPECT_EQ(classes[1].name, "eight");
  std::set<std::string> listed;
  for (const PsbClass& c : classes) {
    ASSERT_EQ(c.models.size(), std::size(kSuffixes)) << c.name;
    for (std::size_t k = 0; k < c.models.size(); ++k) EXPECT_EQ(c.models[k], c.name + kSuffixes[k]);
    listed.insert(c.models.begin(), c.models.end());
  }
  // What reeb index would read from the folder is exactly what the .cla lists, in the right class.
  const ClassMap map = class_map(classes);
  std::set<std::string> files;
  for (const MeshInput& input : list_mesh_inputs({(dir_ / "out").string()})) {
    files.insert(std::filesystem::path(input.name).stem().string());
    const std::string source = class_of(map, input.name);
    EXPECT_EQ(input.name.rfind(source, 0), 0u) << input.name << " in class " << source;
  }
  EXPECT_EQ(files, listed);
}

TEST_F(ReebVariantsCli, MeshFilesGivenByAbsolutePathWriteIntoTheOutputFolderOnly) {
  // Named as given, an absolute path must not turn `dir / name` into the
  // input's own folder (which overwrote the inputs once).
  const std::filesystem::path input = std::filesystem::absolute(dir_ / "in" / "cactus.off");
  const std::string before = read_file_bytes(input);
  ASSERT_EQ(run_variants(input, dir_ / "abs"), 0);
  EXPECT_EQ(read_file_bytes(input), before);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "in" / "cactus_rotated.off"));
  for (const char* suffix : kSuffixes)
    EXPECT_TRUE(std::filesystem::exists(dir_ / "abs" / (std::string("cactus") + suffix + ".off"))) << suffix;
  EXPECT_EQ(read_psb_classes(dir_ / "abs" / "variants.cla").front().name, "cactus");
  // An output folder that is the input's own folder is refused, not overwritten.
  EXPECT_NE(run_variants(input, dir_ / "in"), 0);
  EXPECT_EQ(read_file_bytes(input), before);
}

TEST_F(ReebVariantsCli, EveryVariantLoadsWithTheGenusOfItsSource) {
  for (const auto& [name, genus] : {std::pair<std::string, int>{"cactus", 0}, {"eight", 2}}) {
    const Mesh original = load(dir_ / "in" / (name + ".off"));
    for (const char* suffix : kSuffixes) {
      const Mesh variant = load(dir_ / "out" / (name + suffix + ".off"));
      const MeshTopology topology = analyze_topology(variant);
      EXPECT_EQ(topology.genus, genus) << name << suffix;
      EXPECT_TRUE(topology.closed) << name << suffix;
      if (std::string(suffix) == "_resampled") {
        EXPECT_EQ(variant.num_triangles(), 4 * original.num_triangles());
        // The source's vertices stay (the new ones slide along its edges: resampling_test.cpp).
        EXPECT_TRUE(variant.vertices.topRows(original.num_vertices()).isApprox(original.vertices, 1e-12));
      } else if (std::string(suffix) != "_rotated") {
        EXPECT_TRUE(variant.triangles == original.triangles) << name << suffix;
        const double diagonal =
            (original.vertices.colwise().maxCoeff() - original.vertices.colwise().minCoeff()).norm();
        const double moved = (variant.vertices - original.vertices).rowwise().norm().maxCoeff();
        if (std::string(suffix).empty()) {
          EXPECT_EQ(moved, 0.0);
        } else if (std::string(suffix) == "_noisy") {
          EXPECT_LE(moved, 0.002 * diagonal * (1 + 1e-9));
        } else {  // posed
          EXPECT_GT(moved, 0.01 * diagonal) << name << suffix;
        }
      }
    }
  }
}

TEST_F(ReebVariantsCli, TheRotatedCopyHasTheSameReebGraph) {
  for (const std::string name : {"cactus", "eight"}) {
    const MeshAnalysis a = analyze_mesh(load(dir_ / "out" / (name + ".off")));
    const MeshAnalysis b = analyze_mesh(load(dir_ / "out" / (name + "_rotated.off")));
    const double scale = (b.mesh.vertices.row(1) - b.mesh.vertices.row(0)).norm() /
                         (a.mesh.vertices.row(1) - a.mesh.vertices.row(0)).norm();
    EXPECT_TRUE(scale < 0.999 || scale > 1.001) << "not rescaled";
    std::vector<Index> fa = a.features.vertices, fb = b.features.vertices;
    std::sort(fa.begin(), fa.end());
    std::sort(fb.begin(), fb.end());
    EXPECT_EQ(fa, fb) << name;
    ASSERT_EQ(a.reeb.num_nodes(), b.reeb.num_nodes()) << name;
    EXPECT_EQ(a.reeb.edges, b.reeb.edges) << name;
    EXPECT_EQ(a.reeb.vertex_node, b.reeb.vertex_node) << name;
    for (Index n = 0; n < a.reeb.num_nodes(); ++n) {
      EXPECT_EQ(a.reeb.nodes[static_cast<std::size_t>(n)].type, b.reeb.nodes[static_cast<std::size_t>(n)].type);
      EXPECT_EQ(a.reeb.nodes[static_cast<std::size_t>(n)].end, b.reeb.nodes[static_cast<std::size_t>(n)].end);
    }
  }
}

// Before: `reeb variants datasets/*.off -o coll/` wrote into coll/datasets/
// and named the classes datasets/elk.
TEST_F(ReebVariantsCli, MeshFilesGivenByRelativePathAreNamedByTheirStem) {
  const auto [status, out] =
      run_command("cd " + shell_quoted(dir_ / "") + " && " + REEB_BINARY + " variants in/cactus.off -o rel 2>&1");
  ASSERT_EQ(status, 0) << out;
  EXPECT_EQ(read_psb_classes(dir_ / "rel" / "variants.cla").front().name, "cactus");
  std::vector<std::string> expected = {"variants.cla"};
  for (const char* suffix : kSuffixes) expected.push_back(std::string("cactus") + suffix + ".off");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(files_in(dir_ / "rel"), expected);
  // Two meshes of one stem would be one class: refused, naming both.
  std::filesystem::create_directories(dir_ / "in2");
  std::filesystem::copy_file(dir_ / "in" / "cactus.off", dir_ / "in2" / "cactus.off");
  const auto [twice, twice_out] = run_command("cd " + shell_quoted(dir_ / "") + " && " + REEB_BINARY +
                                              " variants in/cactus.off in2/cactus.off -o twice 2>&1");
  EXPECT_EQ(twice, 1) << twice_out;
  EXPECT_NE(twice_out.find("would both be named 'cactus'"), std::string::npos) << twice_out;
}

TEST_F(ReebVariantsCli, TheSameSeedWritesTheSameFiles) {
  ASSERT_EQ(run_variants(dir_ / "in", dir_ / "again"), 0);
  for (const MeshInput& input : list_mesh_inputs({(dir_ / "out").string()}))
    EXPECT_EQ(read_file_bytes(input.path), read_file_bytes(dir_ / "again" / input.name)) << input.name;
  EXPECT_EQ(read_file_bytes(dir_ / "out" / "variants.cla"), read_file_bytes(dir_ / "again" / "variants.cla"));
}

}  // namespace
}  // namespace reebkit::test
