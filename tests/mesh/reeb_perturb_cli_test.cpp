// `reeb perturb` on an embedded mesh: the variant has the vertex count asked
// for, and its correspondence file (one original vertex id per line after
// '#' comments, docs/formats.md) maps each vertex near its original.
#include "io/io_test_util.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/mesh_io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace reebkit::test {
namespace {

std::vector<Index> read_correspondence(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<Index> ids;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') ids.push_back(static_cast<Index>(std::stol(line)));
  return ids;
}

/// The vertices as numbered in the file.
Points read_vertices(const std::filesystem::path& path) { return read_polygon_soup(path).vertices; }

/// The longest edge of the polygons of the file.
double longest_edge(const std::filesystem::path& path) {
  const PolygonSoup soup = read_polygon_soup(path);
  double longest = 0.0;
  for (Index p = 0; p < soup.num_polygons(); ++p)
    for (Index i = soup.face_offset[p]; i < soup.face_offset[p + 1]; ++i) {
      const Index next = i + 1 < soup.face_offset[p + 1] ? i + 1 : soup.face_offset[p];
      longest = std::max(longest,
                         (soup.vertices.row(soup.face_vertex[i]) - soup.vertices.row(soup.face_vertex[next])).norm());
    }
  return longest;
}

TEST(ReebPerturbCli, VariantAndCorrespondence) {
  TempDir dir;
  const std::filesystem::path input = embedded_dataset_dir() / "elk.off";
  const Points original = read_vertices(input);
  const auto n = static_cast<double>(original.rows());
  const double diagonal = (original.colwise().maxCoeff() - original.colwise().minCoeff()).norm();
  struct Case {
    std::string options;
    double vertices;   // expected count, 0 = any
    double tolerance;  // how far a vertex may be from its original vertex
  };
  const double edge = longest_edge(input);
  const Case cases[] = {
      {"--decimate 0.5", 0.5 * n, 1e-6 * diagonal},              // kept vertices stay
      {"--remesh " + std::to_string(original.rows()), n, edge},  // inside an original triangle
      {"--subdivide 1", 0, 0.5 * edge},                          // a midpoint, half an edge from either end
      {"--noise 0.001", n, 0.01 * diagonal},                     // 10 sigma
      {"--pose 3", n, diagonal},                                 // a turned limb moves far; the ids stay
  };
  for (const Case& c : cases) {
    const std::filesystem::path out = dir / "variant.off";
    const auto [status, output] = run_command(std::string(REEB_BINARY) + " perturb " + shell_quoted(input) + " -o " +
                                              shell_quoted(out) + " " + c.options);
    ASSERT_EQ(status, 0) << c.options << "\n" << output;
    const Points variant = read_vertices(out);
    const std::vector<Index> ids = read_correspondence(dir / "variant.corr");
    ASSERT_EQ(ids.size(), static_cast<std::size_t>(variant.rows())) << c.options;
    if (c.vertices > 0) {
      EXPECT_NEAR(static_cast<double>(variant.rows()), c.vertices, 0.02 * c.vertices + 1) << c.options;
    }
    for (Eigen::Index v = 0; v < variant.rows(); ++v) {
      const Index o = ids[static_cast<std::size_t>(v)];
      ASSERT_GE(o, 0);
      ASSERT_LT(o, original.rows());
      EXPECT_LE((variant.row(v) - original.row(o)).norm(), c.tolerance) << c.options << ", vertex " << v;
    }
  }
}

// --pose turns leaves of the graph that the analysis options give (the
// defaults unless given), so that a benchmark can pin the graph it is made
// on: the defaults spelled out give the same variant, the toe scale of
// layout 8 (other leaves on the elk) another.
TEST(ReebPerturbCli, ThePoseIsPlannedOnTheGraphOfTheAnalysisOptions) {
  TempDir dir;
  const std::filesystem::path input = embedded_dataset_dir() / "elk.off";
  const auto posed = [&](const std::string& name, const std::string& options) {
    const std::filesystem::path out = dir / (name + ".off");
    const auto [status, output] = run_command(std::string(REEB_BINARY) + " perturb " + shell_quoted(input) + " -o " +
                                              shell_quoted(out) + " --pose 3 " + options);
    EXPECT_EQ(status, 0) << options << "\n" << output;
    return read_vertices(out);
  };
  const Points defaults = posed("defaults", "");
  EXPECT_EQ(posed("spelled_out", "--epsilon 0.15 --min-persistence 0.03 --feature-site tips"), defaults);
  const Points toe_scale = posed("toe_scale", "--epsilon 0.05 --min-persistence 0.01");
  ASSERT_EQ(toe_scale.rows(), defaults.rows());
  EXPECT_GT((toe_scale - defaults).rowwise().norm().maxCoeff(), 0.01);
}

// --pose-leaves and --pose-degrees: no turn or a zero angle leaves every
// vertex where it was; four leaves move more vertices than two, larger
// angles move them farther.
TEST(ReebPerturbCli, ThePoseTurnsAsManyLeavesAsAskedByTheAnglesAsked) {
  TempDir dir;
  const std::filesystem::path input = embedded_dataset_dir() / "elk.off";
  const Points original = read_vertices(input);
  const auto moved = [&](const std::string& options) {  // how far each vertex moved
    const std::filesystem::path out = dir / "posed.off";
    const auto [status, output] = run_command(std::string(REEB_BINARY) + " perturb " + shell_quoted(input) + " -o " +
                                              shell_quoted(out) + " --pose 3 " + options);
    EXPECT_EQ(status, 0) << options << "\n" << output;
    const Points posed = read_vertices(out);
    EXPECT_EQ(posed.rows(), original.rows()) << options;
    return Eigen::VectorXd((posed - original).rowwise().norm());
  };
  const double diagonal = (original.colwise().maxCoeff() - original.colwise().minCoeff()).norm();
  const auto count_moved = [&](const Eigen::VectorXd& d) { return (d.array() > 1e-9 * diagonal).count(); };
  EXPECT_EQ(count_moved(moved("--pose-leaves 0")), 0);
  EXPECT_EQ(count_moved(moved("--pose-degrees 0:0")), 0);
  const Eigen::VectorXd two = moved(""), four = moved("--pose-leaves 4");
  EXPECT_GT(count_moved(two), 0);
  EXPECT_GT(count_moved(four), count_moved(two));
  EXPECT_GT(moved("--pose-leaves 4 --pose-degrees 60:60").maxCoeff(),
            moved("--pose-leaves 4 --pose-degrees 10:10").maxCoeff());
  for (const std::string bad :
       {"--pose-degrees 30", "--pose-degrees 40:30", "--pose-degrees 0:200", "--pose-leaves -1"})
    EXPECT_NE(run_command(std::string(REEB_BINARY) + " perturb " + shell_quoted(input) + " -o " +
                          shell_quoted(dir / "bad.off") + " --pose 3 " + bad)
                  .first,
              0)
        << bad;
}

TEST(ReebPerturbCli, RotationScaleTranslationAreExact) {
  TempDir dir;
  const std::filesystem::path input = embedded_dataset_dir() / "cactus.off";
  const std::filesystem::path out = dir / "moved.off";
  const auto [status, output] = run_command(std::string(REEB_BINARY) + " perturb " + shell_quoted(input) + " -o " +
                                            shell_quoted(out) + " --rotate z:90 --scale 2 --translate 1,2,3");
  ASSERT_EQ(status, 0) << output;
  const Points original = read_vertices(input), moved = read_vertices(out);
  ASSERT_EQ(moved.rows(), original.rows());
  for (Eigen::Index v = 0; v < original.rows(); ++v) {
    const Vec3 p = original.row(v);
    EXPECT_TRUE(moved.row(v).transpose().isApprox(Vec3(-2 * p.y() + 1, 2 * p.x() + 2, 2 * p.z() + 3), 1e-6));
  }
  EXPECT_NE(run_command(std::string(REEB_BINARY) + " perturb " + shell_quoted(input) + " -o " + shell_quoted(out) +
                        " --rotate q:90")
                .first,
            0);
}

// Before: -o on the input overwrote it (exit 0).
TEST(ReebPerturbCli, OutputsAreCheckedBeforeAnyWork) {
  TempDir dir;
  std::filesystem::copy_file(embedded_dataset_dir() / "cactus.off", dir / "m.off");
  const std::string mesh = read_file_bytes(dir / "m.off");
  const std::string perturb = std::string(REEB_BINARY) + " perturb " + shell_quoted(dir / "m.off") + " --scale 2 ";
  for (const std::string& outputs :
       {"-o " + shell_quoted(dir / "m.off"),
        "-o " + shell_quoted(dir / "v.off") + " --correspondence " + shell_quoted(dir / "m.off"),
        "-o " + shell_quoted(dir / "v.off") + " --correspondence " + shell_quoted(dir / "v.off")}) {
    const auto [status, out] = run_command(perturb + outputs + " 2>&1");
    EXPECT_EQ(status, 1) << outputs << "\n" << out;
    EXPECT_EQ(out.find("read and cleaned"), std::string::npos) << out;
    EXPECT_EQ(read_file_bytes(dir / "m.off"), mesh);
  }
  EXPECT_EQ(files_in(dir / ""), std::vector<std::string>{"m.off"});
}

}  // namespace
}  // namespace reebkit::test
