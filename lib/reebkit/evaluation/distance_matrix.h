// Distance matrices of shape retrieval methods, in the two formats benchmarks
// exchange them in:
//  - the Princeton Shape Benchmark binary `.matrix` (Shilane et al. 2004):
//    N x N float32, row-major, native (little-endian) byte order, no header;
//    N follows from the size, which must be 4 N^2 bytes;
//  - the SHREC ASCII matrix: N lines of N numbers separated by blanks.
// Row i holds the distances from model i (the query) to every model, rows in
// the order the models are listed in the collection's .cla file.
#pragma once

#include <Eigen/Core>

#include <filesystem>

namespace reebkit {

/// N x N distances, row i = distances from query i.
using DistanceMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Reads a PSB binary `.matrix`. Throws Error "<file>: <problem>" when the file
/// is missing, empty, or its size is not 4 N^2 bytes.
DistanceMatrix read_psb_matrix(const std::filesystem::path& path);

/// Writes `distances` (square) as a PSB binary `.matrix`.
/// Throws InvalidArgument for a non-square matrix, Error when writing fails.
void write_psb_matrix(const std::filesystem::path& path, const DistanceMatrix& distances);

/// Reads a SHREC ASCII matrix. Throws Error "<file>:<line>: <problem>" on a
/// token that is not a number, a line whose count differs from the first
/// line's, or a line count that differs from that count.
DistanceMatrix read_shrec_matrix(const std::filesystem::path& path);

/// Writes `distances` (square) as a SHREC ASCII matrix, every float in its
/// shortest form that reads back to the same bits.
void write_shrec_matrix(const std::filesystem::path& path, const DistanceMatrix& distances);

/// A matrix in either format, told apart by the contents (whatever the
/// file's extension): a file of numbers and blanks only is SHREC ASCII,
/// any other PSB binary.
DistanceMatrix read_distance_matrix(const std::filesystem::path& path);

}  // namespace reebkit
