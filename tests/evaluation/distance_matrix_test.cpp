// PSB binary and SHREC ASCII distance matrices: the byte layout, exact round
// trips, and errors that name the file and the problem.
#include "reebkit/evaluation/distance_matrix.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "reebkit/io/file_bytes.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

namespace reebkit::test {
namespace {

DistanceMatrix awkward_matrix() {
  DistanceMatrix m(3, 3);
  m << 0.0f, 0.1f, 1e-30f,   //
      3.4e38f, 0.0f, -2.5f,  //
      std::numeric_limits<float>::infinity(), 1.0f / 3.0f, 0.0f;
  return m;
}

TEST(DistanceMatrix, PsbLayoutIsRowMajorFloat32WithoutHeader) {
  const TempDir dir;
  const DistanceMatrix m = awkward_matrix();
  write_psb_matrix(dir / "d.matrix", m);
  const std::string bytes = read_file_bytes(dir / "d.matrix");
  ASSERT_EQ(bytes.size(), 9 * sizeof(float));
  float second = 0, fourth = 0;  // (0, 1) and (1, 0)
  std::memcpy(&second, bytes.data() + 4, 4);
  std::memcpy(&fourth, bytes.data() + 12, 4);
  EXPECT_EQ(second, 0.1f);
  EXPECT_EQ(fourth, 3.4e38f);
}

TEST(DistanceMatrix, BothFormatsRoundTripEveryBit) {
  const TempDir dir;
  const DistanceMatrix m = awkward_matrix();
  write_psb_matrix(dir / "d.matrix", m);
  write_shrec_matrix(dir / "d.txt", m);
  for (const DistanceMatrix& back : {read_psb_matrix(dir / "d.matrix"), read_shrec_matrix(dir / "d.txt"),
                                     read_distance_matrix(dir / "d.matrix"), read_distance_matrix(dir / "d.txt")}) {
    ASSERT_EQ(back.rows(), 3);
    ASSERT_EQ(back.cols(), 3);
    EXPECT_EQ(std::memcmp(back.data(), m.data(), 9 * sizeof(float)), 0);
  }
}

// Before: `reeb distances -o x.m` wrote the binary format and `reeb eval x.m`
// read it as ASCII, failing: the format is told by the contents.
TEST(DistanceMatrix, EitherFormatIsReadWhateverTheExtension) {
  const TempDir dir;
  const DistanceMatrix m = awkward_matrix();
  write_psb_matrix(dir / "binary.m", m);
  write_shrec_matrix(dir / "ascii.matrix", m);
  write_psb_matrix(dir / "binary", m);
  for (const char* name : {"binary.m", "ascii.matrix", "binary"}) {
    const DistanceMatrix back = read_distance_matrix(dir / name);
    ASSERT_EQ(back.rows(), 3) << name;
    EXPECT_EQ(std::memcmp(back.data(), m.data(), 9 * sizeof(float)), 0) << name;
  }
  // A 1 x 1 binary matrix is 4 bytes, as is the text "0 0\n": the text is read as text (and refused: 2 numbers).
  write_bytes(dir / "short.matrix", "0 0\n");
  const std::string text = thrown_message<Error>([&] { read_distance_matrix(dir / "short.matrix"); });
  EXPECT_NE(text.find("short.matrix"), std::string::npos) << text;
  EXPECT_EQ(text.find("float32"), std::string::npos) << text;
}

TEST(DistanceMatrix, ShrecTextIsNLinesOfNNumbers) {
  const TempDir dir;
  write_bytes(dir / "d.txt", "0 1.5 2\n\n1.5 0 +3\r\n  2e0\t3 0   \n");
  const DistanceMatrix m = read_shrec_matrix(dir / "d.txt");
  ASSERT_EQ(m.rows(), 3);
  EXPECT_EQ(m(0, 1), 1.5f);
  EXPECT_EQ(m(1, 2), 3.0f);
  EXPECT_EQ(m(2, 0), 2.0f);
  EXPECT_EQ(m(2, 2), 0.0f);
}

TEST(DistanceMatrix, PsbErrorsNameTheFileAndTheProblem) {
  const TempDir dir;
  write_bytes(dir / "seven.matrix", std::string(7, '\0'));
  write_bytes(dir / "three.matrix", std::string(12, '\0'));
  write_bytes(dir / "empty.matrix", "");
  const std::string seven = thrown_message<Error>([&] { read_psb_matrix(dir / "seven.matrix"); });
  EXPECT_NE(seven.find("seven.matrix: 7 bytes is not a whole number of float32"), std::string::npos) << seven;
  const std::string three = thrown_message<Error>([&] { read_psb_matrix(dir / "three.matrix"); });
  EXPECT_NE(three.find("three.matrix: 3 float32 values do not make a square"), std::string::npos) << three;
  const std::string empty = thrown_message<Error>([&] { read_psb_matrix(dir / "empty.matrix"); });
  EXPECT_NE(empty.find("empty.matrix: empty distance matrix"), std::string::npos) << empty;
  const std::string missing = thrown_message<Error>([&] { read_psb_matrix(dir / "none.matrix"); });
  EXPECT_NE(missing.find("none.matrix"), std::string::npos) << missing;
  EXPECT_THROW(write_psb_matrix(dir / "x.matrix", DistanceMatrix(2, 3)), InvalidArgument);
}

TEST(DistanceMatrix, ShrecErrorsNameTheFileLineAndProblem) {
  const TempDir dir;
  write_bytes(dir / "ragged.txt", "0 1 2\n1 0\n2 1 0\n");
  write_bytes(dir / "word.txt", "0 1\nx 0\n");
  write_bytes(dir / "wide.txt", "0 1 2\n1 0 2\n");
  write_bytes(dir / "blank.txt", " \n\n");
  const std::string ragged = thrown_message<Error>([&] { read_shrec_matrix(dir / "ragged.txt"); });
  EXPECT_NE(ragged.find("ragged.txt:2: row 2 has 2 distances, the first row 3"), std::string::npos) << ragged;
  const std::string word = thrown_message<Error>([&] { read_shrec_matrix(dir / "word.txt"); });
  EXPECT_NE(word.find("word.txt:2:"), std::string::npos) << word;
  EXPECT_NE(word.find("'x'"), std::string::npos) << word;
  const std::string wide = thrown_message<Error>([&] { read_shrec_matrix(dir / "wide.txt"); });
  EXPECT_NE(wide.find("wide.txt: 2 rows of 3 distances, not a square matrix"), std::string::npos) << wide;
  const std::string blank = thrown_message<Error>([&] { read_shrec_matrix(dir / "blank.txt"); });
  EXPECT_NE(blank.find("blank.txt: empty distance matrix"), std::string::npos) << blank;
}

}  // namespace
}  // namespace reebkit::test
