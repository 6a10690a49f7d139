// End to end: `reeb eval` on toy matrices whose measures follow by hand from
// the PSB definitions (retrieval_metrics.h), with a second method compared.
#include "io/io_test_util.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/io/file_bytes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace reebkit::test {
namespace {

/// Exit status of `command` and what it printed (stdout and stderr).
std::pair<int, std::string> run_captured(const std::string& command, const std::filesystem::path& log) {
  const int status = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file_bytes(log)};
}

std::string fixed3(double v) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << v;
  return out.str();
}

std::string row(const std::string& method, const std::string& average, double nn, double ft, double st, double e,
                double dcg) {
  return "| " + method + " | " + average + " | " + fixed3(nn) + " | " + fixed3(ft) + " | " + fixed3(st) + " | " +
         fixed3(e) + " | " + fixed3(dcg) + " |";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

class ReebEvalCli : public ::testing::Test {
 protected:
  void SetUp() override {
    // ant = models 0-2, bird = 3-6, cod = 7-8 (too small to be a query, but ranked).
    write_bytes(dir_ / "toy.cla", "PSB 1\n3 9\n\nant 0 3\nm0\nm1\nm2\n\nbird 0 4\nm3\nm4\nm5\nm6\n\ncod 0 2\nm7\nm8\n");
    // Every distance equal: rankings by index. ant queries see 2 ants first; bird
    // queries see the 3 ants, then the 3 other birds, then cod.
    write_psb_matrix(dir_ / "const.matrix", DistanceMatrix::Constant(9, 9, 1.0f));
    // Perfect: 0 inside a class, 1 across (SHREC ASCII, named on the command line).
    DistanceMatrix perfect(9, 9);
    const int cls[9] = {0, 0, 0, 1, 1, 1, 1, 2, 2};
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) perfect(i, j) = cls[i] == cls[j] ? 0.0f : 1.0f;
    write_shrec_matrix(dir_ / "perfect.txt", perfect);
  }

  std::string reeb(const std::string& args) { return std::string(REEB_BINARY) + " eval " + args; }

  TempDir dir_;
};

TEST_F(ReebEvalCli, ReportsTheHandComputedMeasuresOfTwoMethods) {
  const std::filesystem::path out = dir_ / "report";
  const auto [status, printed] =
      run_captured(reeb("'" + (dir_ / "const.matrix").string() + "' --cla '" + (dir_ / "toy.cla").string() + "' -o '" +
                        out.string() + "' --name ties --compare '" + (dir_ / "perfect.txt").string() + ":oracle'"),
                   dir_ / "log.txt");
  ASSERT_EQ(status, 0) << printed;

  // N - 1 = 8, E over m = 8. ant (K = 2): NN = FT = ST = DCG = 1, E = 2*2 / (8 + 2).
  // bird (K = 3): hits at 4, 5, 6: NN = FT = 0, ST = 1, E = 2*3 / (8 + 3),
  // DCG = (1/log2 4 + 1/log2 5 + 1/log2 6) / (1 + 1 + 1/log2 3).
  const double e_ant = 0.4, e_bird = 6.0 / 11.0;
  const double dcg_bird = (0.5 + 1 / std::log2(5.0) + 1 / std::log2(6.0)) / (2 + 1 / std::log2(3.0));
  const std::string micro =
      row("ties", "micro (7 queries)", 3 / 7.0, 3 / 7.0, 1, (3 * e_ant + 4 * e_bird) / 7, (3 + 4 * dcg_bird) / 7);
  const std::string macro = row("ties", "macro (2 classes)", 0.5, 0.5, 1, (e_ant + e_bird) / 2, (1 + dcg_bird) / 2);
  const std::string oracle = row("oracle", "micro (7 queries)", 1, 1, 1, (3 * e_ant + 4 * e_bird) / 7, 1);
  EXPECT_TRUE(contains(printed, micro)) << micro << "\n" << printed;
  EXPECT_TRUE(contains(printed, macro)) << macro << "\n" << printed;
  EXPECT_TRUE(contains(printed, oracle)) << oracle << "\n" << printed;

  const std::string report = read_file_bytes(out / "report.md");
  EXPECT_TRUE(contains(report, micro));
  EXPECT_TRUE(contains(report, oracle));
  EXPECT_TRUE(contains(report, "| bird | 4 | " + fixed3(0) + " | " + fixed3(0) + " | 1.000 | " + fixed3(e_bird)));
  EXPECT_TRUE(contains(report, "| cod | 2 | left out as queries"));
  EXPECT_TRUE(contains(report, "![precision-recall](pr.png)"));

  // pr.csv: header + 2 methods x (micro, macro, ant, bird) x 20 levels. Interpolated precision of
  // a bird query: hits (1/3, 1/4), (2/3, 2/5), (1, 1/2) -> 1/2 at every level; ants 1.
  const std::string csv = read_file_bytes(out / "pr.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 4 * 20);
  EXPECT_TRUE(contains(csv, "ties,bird,0.05,0.5\n"));
  EXPECT_TRUE(contains(csv, "ties,ant,1,1\n"));
  EXPECT_TRUE(contains(csv, "ties,macro,1,0.75\n"));
  EXPECT_TRUE(contains(csv, "oracle,micro,1,1\n"));
  EXPECT_FALSE(contains(csv, ",cod,"));

  EXPECT_EQ(read_file_bytes(out / "pr.png").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const std::string svg = read_file_bytes(out / "pr.svg");
  EXPECT_TRUE(contains(svg, "<svg"));

  // The same evaluation again writes the same figures, byte for byte: a
  // report re-run into results/ changes only where its figures do.
  const std::filesystem::path again = dir_ / "again";
  ASSERT_EQ(run_captured(reeb("'" + (dir_ / "const.matrix").string() + "' --cla '" + (dir_ / "toy.cla").string() +
                              "' -o '" + again.string() + "' --name ties --compare '" +
                              (dir_ / "perfect.txt").string() + ":oracle'"),
                         dir_ / "log2.txt")
                .first,
            0);
  EXPECT_EQ(read_file_bytes(again / "pr.svg"), svg);
  EXPECT_EQ(read_file_bytes(again / "pr.png"), read_file_bytes(out / "pr.png"));
}

// A tight class at 0, 0.1, 0.2 and a loose one at 1, 2, 3 on a line: as read,
// 1.0's nearest neighbour is 0.2 (NN 5/6); local scaling with k = 2 puts every
// nearest neighbour in its class (local_scaling_test.cpp has the radii).
TEST_F(ReebEvalCli, LocalScalingIsEvaluatedBesideTheMatrixAsRead) {
  write_bytes(dir_ / "line.cla", "PSB 1\n2 6\n\ntight 0 3\nm0\nm1\nm2\n\nloose 0 3\nm3\nm4\nm5\n");
  const double x[6] = {0.0, 0.1, 0.2, 1.0, 2.0, 3.0};
  DistanceMatrix d(6, 6);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) d(i, j) = static_cast<float>(std::abs(x[i] - x[j]));
  write_psb_matrix(dir_ / "line.matrix", d);
  const auto [status, printed] =
      run_captured(reeb("'" + (dir_ / "line.matrix").string() + "' --cla '" + (dir_ / "line.cla").string() + "' -o '" +
                        (dir_ / "r").string() + "' --no-plot --local-scaling 2"),
                   dir_ / "log.txt");
  ASSERT_EQ(status, 0) << printed;
  EXPECT_TRUE(contains(printed, "| line | micro (6 queries) | " + fixed3(5 / 6.0) + " |")) << printed;
  EXPECT_TRUE(contains(printed, "| line + local scaling (k = 2) | micro (6 queries) | 1.000 |")) << printed;
  const auto [bad, message] =
      run_captured(reeb("'" + (dir_ / "line.matrix").string() + "' --cla '" + (dir_ / "line.cla").string() + "' -o '" +
                        (dir_ / "r").string() + "' --no-plot --local-scaling 6"),
                   dir_ / "log.txt");
  EXPECT_EQ(bad, 1);
  EXPECT_TRUE(contains(message, "k = 6 is not in [1, 5]")) << message;
}

TEST_F(ReebEvalCli, AMatrixOfTheWrongSizeIsAnErrorNamingTheFile) {
  write_psb_matrix(dir_ / "small.matrix", DistanceMatrix::Zero(4, 4));
  const auto [status, printed] =
      run_captured(reeb("'" + (dir_ / "small.matrix").string() + "' --cla '" + (dir_ / "toy.cla").string() + "' -o '" +
                        (dir_ / "r").string() + "' --no-plot"),
                   dir_ / "log.txt");
  EXPECT_EQ(status, 1);
  EXPECT_TRUE(contains(printed, "small.matrix: 4 x 4 distances, but")) << printed;
  EXPECT_TRUE(contains(printed, "toy.cla lists 9 models")) << printed;
}

// Before: -o naming a file printed a raw "filesystem error".
TEST_F(ReebEvalCli, AnOutputFolderThatIsAFileIsAnErrorNamingIt) {
  write_psb_matrix(dir_ / "small.matrix", DistanceMatrix::Zero(9, 9));
  const auto [status, printed] =
      run_captured(reeb("'" + (dir_ / "small.matrix").string() + "' --cla '" + (dir_ / "toy.cla").string() + "' -o '" +
                        (dir_ / "small.matrix").string() + "' --no-plot"),
                   dir_ / "log.txt");
  EXPECT_EQ(status, 1);
  EXPECT_TRUE(contains(printed, "small.matrix: is a file, not a folder")) << printed;
  EXPECT_FALSE(contains(printed, "filesystem error")) << printed;
}

}  // namespace
}  // namespace reebkit::test
