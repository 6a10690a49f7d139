#include "reebkit/evaluation/distance_matrix.h"

#include "reebkit/core/error.h"
#include "reebkit/io/binary_bytes.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/number_text.h"
#include "reebkit/io/text_scanner.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace reebkit {
namespace {

void require_square(const std::filesystem::path& path, const DistanceMatrix& distances) {
  if (distances.rows() != distances.cols())
    throw InvalidArgument(path.string() + ": a distance matrix must be square, this one is " +
                          std::to_string(distances.rows()) + " x " + std::to_string(distances.cols()));
}

}  // namespace

DistanceMatrix read_psb_matrix(const std::filesystem::path& path) {
  const std::string bytes = read_file_bytes(path);
  if (bytes.empty()) throw Error(path.string() + ": empty distance matrix");
  if (bytes.size() % sizeof(float) != 0)
    throw Error(path.string() + ": " + std::to_string(bytes.size()) + " bytes is not a whole number of float32 values");
  const std::size_t values = bytes.size() / sizeof(float);
  const auto n = static_cast<std::size_t>(std::llround(std::sqrt(static_cast<double>(values))));
  if (n * n != values)
    throw Error(path.string() + ": " + std::to_string(values) + " float32 values do not make a square N x N matrix");
  DistanceMatrix out(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  ByteReader reader(bytes, /*big_endian=*/false);
  for (std::size_t i = 0; i < values; ++i) out.data()[i] = reader.read<float>();
  return out;
}

void write_psb_matrix(const std::filesystem::path& path, const DistanceMatrix& distances) {
  require_square(path, distances);
  std::string bytes;
  bytes.reserve(static_cast<std::size_t>(distances.size()) * sizeof(float));
  for (Eigen::Index i = 0; i < distances.size(); ++i) append_bytes(bytes, distances.data()[i], /*big_endian=*/false);
  write_file_bytes(path, bytes);
}

DistanceMatrix read_shrec_matrix(const std::filesystem::path& path) {
  const std::string text = read_file_bytes(path);
  TextScanner scanner(text, path.string(), TextScanner::Options{});
  std::vector<float> values;
  std::size_t columns = 0, rows = 0;
  while (scanner.skip_to_token()) {
    std::size_t count = 0;
    for (std::string_view token = scanner.token_on_line(); !token.empty(); token = scanner.token_on_line()) {
      values.push_back(static_cast<float>(scanner.to_number(token, "a distance")));
      ++count;
    }
    if (rows == 0) columns = count;
    if (count != columns)
      scanner.fail("row " + std::to_string(rows + 1) + " has " + std::to_string(count) + " distances, the first row " +
                   std::to_string(columns));
    ++rows;
    scanner.next_line();
  }
  if (rows == 0) throw Error(path.string() + ": empty distance matrix");
  if (rows != columns)
    throw Error(path.string() + ": " + std::to_string(rows) + " rows of " + std::to_string(columns) +
                " distances, not a square matrix");
  DistanceMatrix out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(columns));
  std::copy(values.begin(), values.end(), out.data());
  return out;
}

void write_shrec_matrix(const std::filesystem::path& path, const DistanceMatrix& distances) {
  require_square(path, distances);
  std::string text;
  for (Eigen::Index i = 0; i < distances.rows(); ++i) {
    for (Eigen::Index j = 0; j < distances.cols(); ++j) {
      if (j > 0) text += ' ';
      append_number(text, distances(i, j));
    }
    text += '\n';
  }
  write_file_bytes(path, text);
}

DistanceMatrix read_distance_matrix(const std::filesystem::path& path) {
  // The ASCII format is numbers and blanks only; a binary matrix has other
  // bytes (the zeros of its diagonal at least), whatever the file's name.
  const std::string bytes = read_file_bytes(path);
  const bool text = !bytes.empty() && std::all_of(bytes.begin(), bytes.end(), [](unsigned char c) {
    return c != 0 && (std::isdigit(c) || std::isspace(c) || std::strchr("+-.eEinfaINFA", c) != nullptr);
  });
  return text ? read_shrec_matrix(path) : read_psb_matrix(path);
}

}  // namespace reebkit
