// Bad meshes in bulk: the extractor over every CGAL mesh (the awkward and
// broken ones included) and over malformed copies of a real mesh made here.
// Each mesh is indexed or becomes a failed entry whose reason names its file
// and the problem; nothing crashes and the batch goes on to the end.
#include "reebkit/collection/extract_collection.h"

#include "io/io_test_util.h"
#include "reebkit/io/off.h"
#include "reebkit/store/collection_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

namespace reebkit::test {
namespace {

/// The mesh the malformed copies are made from: SHREC07's first mesh when
/// ../shared/datasets is there, the embedded cactus otherwise.
std::filesystem::path source_mesh() {
  if (const auto shrec = shared_dataset("shrec07_watertight")) return *shrec / "1.off";
  return embedded_dataset_dir() / "cactus.off";
}

struct OffText {
  std::vector<std::string> vertices;  // "x y z"
  std::vector<std::string> faces;     // "3 a b c"
  std::string text() const {
    std::ostringstream out;
    out << "OFF\n" << vertices.size() << " " << faces.size() << " 0\n";
    for (const auto& v : vertices) out << v << "\n";
    for (const auto& f : faces) out << f << "\n";
    return out.str();
  }
};

OffText read_off_text(const std::filesystem::path& path) {
  const PolygonSoup soup = read_off(path);
  OffText out;
  for (Index v = 0; v < soup.num_vertices(); ++v) {
    std::ostringstream line;
    line.precision(17);
    line << soup.vertices(v, 0) << " " << soup.vertices(v, 1) << " " << soup.vertices(v, 2);
    out.vertices.push_back(line.str());
  }
  for (Index f = 0; f < soup.num_polygons(); ++f) {
    std::ostringstream line;
    line << soup.face_offset[f + 1] - soup.face_offset[f];
    for (Index k = soup.face_offset[f]; k < soup.face_offset[f + 1]; ++k) line << " " << soup.face_vertex[k];
    out.faces.push_back(line.str());
  }
  return out;
}

/// What a malformed copy must give: an entry, or a failure whose reason holds `reason`.
struct Expected {
  bool ok = false;
  std::string reason;
};

/// Writes the malformed copies of `source` into `dir`; returns what each must give.
std::map<std::string, Expected> write_malformed(const std::filesystem::path& source, const std::filesystem::path& dir) {
  const OffText good = read_off_text(source);
  const std::string text = good.text();
  std::map<std::string, Expected> out;
  const auto write = [&](const std::string& name, const std::string& content, Expected expected) {
    std::ofstream(dir / name, std::ios::binary) << content;
    out[name] = std::move(expected);
  };
  write("good.off", text, {true, ""});
  write("truncated.off", text.substr(0, text.size() / 2), {false, "truncated"});
  write("empty.off", "", {false, "empty"});
  OffText nan = good;
  nan.vertices[3] = "nan 0 0";
  write("nan.off", nan.text(), {false, "non-finite"});
  OffText inf = good;
  inf.vertices[5] = "0 inf 0";
  write("inf.off", inf.text(), {false, "non-finite"});
  OffText out_of_range = good;
  out_of_range.faces[2] = "3 0 1 " + std::to_string(good.vertices.size() + 7);
  write("out_of_range.off", out_of_range.text(), {false, "refers to vertex"});
  OffText negative = good;
  negative.faces[4] = "3 0 -2 1";
  write("negative.off", negative.text(), {false, "refers to vertex"});
  OffText collapsed = good;  // every vertex on one line: every face has zero area
  for (std::size_t v = 0; v < collapsed.vertices.size(); ++v) collapsed.vertices[v] = std::to_string(v) + " 0 0";
  write("zero_area.off", collapsed.text(), {false, "degenerate"});
  // Every vertex twice, the first half of the faces on the second copies: a
  // crack (two boundaries) across the surface, as texture seams leave.
  OffText doubled = good;
  for (const auto& v : good.vertices) doubled.vertices.push_back(v);
  for (std::size_t f = 0; f < doubled.faces.size() / 2; ++f) {
    std::istringstream in(doubled.faces[f]);
    Index n, a, b, c;
    in >> n >> a >> b >> c;
    const Index shift = static_cast<Index>(good.vertices.size());
    doubled.faces[f] =
        "3 " + std::to_string(a + shift) + " " + std::to_string(b + shift) + " " + std::to_string(c + shift);
  }
  write("duplicated_vertices.off", doubled.text(), {true, ""});
  OffText cloud = good;
  cloud.faces.clear();
  write("point_cloud.off", cloud.text(), {false, "no faces"});
  // Two triangles sharing one vertex only (a non-manifold "bowtie").
  write("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n", {true, ""});
  return out;
}

TEST(BadMeshes, MalformedCopiesAreIndexedOrReportedAndTheBatchGoesOn) {
  const TempDir dir;
  std::filesystem::create_directories(dir / "meshes");
  const std::map<std::string, Expected> expected = write_malformed(source_mesh(), dir / "meshes");
  const std::vector<MeshInput> inputs = list_mesh_inputs({(dir / "meshes").string()});
  ASSERT_EQ(inputs.size(), expected.size());

  ExtractionOptions options;
  options.threads = 2;
  const ExtractionSummary summary = extract_collection(inputs, {}, dir / "c.h5", options);
  EXPECT_EQ(summary.computed(), static_cast<std::int64_t>(expected.size()));

  const CollectionReader reader(dir / "c.h5");
  ASSERT_EQ(reader.size(), static_cast<std::int64_t>(expected.size()));
  for (std::int64_t i = 0; i < reader.size(); ++i) {
    const GraphRecord record = reader.entry(i);
    const Expected& want = expected.at(record.name);
    if (want.ok) {
      EXPECT_TRUE(record.ok) << record.name << ": " << record.error;
      EXPECT_GT(record.num_nodes(), 0) << record.name;
      continue;
    }
    EXPECT_FALSE(record.ok) << record.name << " was indexed";
    EXPECT_NE(record.error.find(record.name), std::string::npos) << record.name << ": " << record.error;
    EXPECT_NE(record.error.find(want.reason), std::string::npos) << record.name << ": " << record.error;
  }
}

TEST(BadMeshes, EveryCgalMeshIsIndexedOrReportedByName) {
  const auto cgal = shared_dataset("cgal_meshes");
  if (!cgal) GTEST_SKIP() << "../shared/datasets/cgal_meshes.tar.xz is not unpacked (ctest -R unpack_datasets)";
  const TempDir dir;
  const std::vector<MeshInput> inputs = list_mesh_inputs({cgal->string()});
  ASSERT_GE(inputs.size(), 140u);

  ExtractionOptions options;
  options.threads = 2;
  const ExtractionSummary summary = extract_collection(inputs, {}, dir / "c.h5", options);
  EXPECT_EQ(summary.computed(), static_cast<std::int64_t>(inputs.size()));
  for (const FailedMesh& failed : summary.failed) {
    // The reason names the file and says what is wrong with it.
    EXPECT_NE(failed.reason.find(failed.name), std::string::npos) << failed.reason;
    EXPECT_GT(failed.reason.size(), failed.name.size() + 10) << failed.reason;
  }
  const CollectionReader reader(dir / "c.h5");
  EXPECT_EQ(reader.size(), static_cast<std::int64_t>(inputs.size()));
  std::cout << inputs.size() << " CGAL meshes: " << summary.ok << " indexed, " << summary.failed.size()
            << " reported\n";
  for (const FailedMesh& failed : summary.failed) std::cout << "  " << failed.reason << "\n";
}

}  // namespace
}  // namespace reebkit::test
