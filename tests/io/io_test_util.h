// Helpers shared by the io tests: a scratch folder, error capture, soups as
// plain lists, a mesh with awkward coordinates for round trips.
#pragma once

#include "reebkit/core/error.h"
#include "reebkit/core/mesh.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace reebkit::test {

/// A fresh folder under the system temp folder, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("reebkit_io_" + std::to_string(::getpid()) + "_" + (info ? info->name() : "test"));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

using Polygons = std::vector<std::vector<Index>>;

/// The MeshFileError `action` throws; fails the test when it throws none.
template <typename Action>
MeshFileError error_of(Action&& action) {
  try {
    action();
  } catch (const MeshFileError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a MeshFileError";
  return MeshFileError("", "no error");
}

/// what() of the MeshFileError that `parse` (parse_off, parse_ply, ...) throws on `text`.
inline std::string parse_error(PolygonSoup (*parse)(std::string_view, std::string), std::string_view text,
                               const std::string& source) {
  return error_of([&] { parse(text, source); }).what();
}

/// Passes when `text` contains every one of `parts`.
inline ::testing::AssertionResult contains(std::string_view text, std::initializer_list<std::string_view> parts) {
  for (const std::string_view part : parts) {
    if (text.find(part) == std::string_view::npos) {
      return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
    }
  }
  return ::testing::AssertionSuccess();
}

/// The polygons of a soup as lists of vertex indices.
inline Polygons polygons(const PolygonSoup& soup) {
  Polygons out;
  for (Index p = 0; p < soup.num_polygons(); ++p) {
    out.emplace_back(soup.face_vertex.begin() + soup.face_offset[static_cast<std::size_t>(p)],
                     soup.face_vertex.begin() + soup.face_offset[static_cast<std::size_t>(p) + 1]);
  }
  return out;
}

/// The triangles of a mesh as lists of vertex indices, to compare with polygons().
inline Polygons polygons(const Mesh& mesh) {
  Polygons out;
  for (Index f = 0; f < mesh.num_triangles(); ++f) {
    out.push_back({mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)});
  }
  return out;
}

/// A tetrahedron whose coordinates have no short decimal form (0.1, 1/3,
/// 1e-300, pi * 1e12, -0.0), so that a round trip must keep every bit.
inline Mesh awkward_tetrahedron() {
  Mesh mesh;
  mesh.vertices.resize(4, 3);
  mesh.vertices << 0.1, 1.0 / 3.0, 1e-300,    //
      3.141592653589793e12, -0.0, 2.0 / 3.0,  //
      -7.0, 5e-324, 0.30000000000000004,      //
      1.7976931348623157e308, -1.0 / 7.0, 42.0;
  mesh.triangles.resize(4, 3);
  mesh.triangles << 0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0;
  return mesh;
}

/// Bitwise equality of two coordinate arrays (also tells -0.0 from 0.0).
inline ::testing::AssertionResult same_bits(const Points& a, const Points& b) {
  if (a.rows() != b.rows()) return ::testing::AssertionFailure() << a.rows() << " rows vs " << b.rows();
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    for (Eigen::Index k = 0; k < 3; ++k) {
      if (std::memcmp(&a(i, k), &b(i, k), sizeof(double)) != 0) {
        return ::testing::AssertionFailure() << "row " << i << " col " << k << ": " << a(i, k) << " vs " << b(i, k);
      }
    }
  }
  return ::testing::AssertionSuccess();
}

/// Passes when `soup` holds the vertices of `mesh` bit for bit and its triangles in order.
inline ::testing::AssertionResult same_mesh(const PolygonSoup& soup, const Mesh& mesh) {
  if (polygons(soup) != polygons(mesh)) return ::testing::AssertionFailure() << "the polygons differ";
  return same_bits(soup.vertices, mesh.vertices);
}

}  // namespace reebkit::test
