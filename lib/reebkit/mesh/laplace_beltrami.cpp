#include "reebkit/mesh/laplace_beltrami.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/intrinsic_delaunay.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <string>
#include <vector>

namespace reebkit {

namespace {

/// A triangle of nonzero area: its corners and what each corner adds.
struct Element {
  std::array<Index, 3> v;
  /// Half the cotangent of the angle at corner k, which weighs the edge
  /// opposite it (corners k + 1 and k + 2).
  std::array<double, 3> half_cot;
  double area;
};

/// The columns of a symmetric matrix with the pattern of the mesh's edges
/// (and the diagonal), in compressed column storage: each column's rows
/// increasing. Built straight from the elements: a triplet list would hold
/// 21 entries per triangle, allocated and sorted for each operator.
struct Pattern {
  std::vector<int> outer, inner;
  /// at[9 e + 3 r + c]: the position in `inner` of element e's entry (row
  /// e.v[r], column e.v[c]), where its terms are summed.
  std::vector<int> at;
};

Pattern edge_pattern(const std::vector<Element>& elements, Index n) {
  Pattern p;
  // Each corner lists itself and the triangle's two other corners, with the
  // element entry each stands for; the duplicates are merged per column below.
  struct Candidate {
    int row, entry;
  };
  std::vector<int> count(static_cast<std::size_t>(n) + 1, 0);
  for (const Element& e : elements)
    for (const Index v : e.v) count[static_cast<std::size_t>(v) + 1] += 3;
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  std::vector<Candidate> candidates(static_cast<std::size_t>(count.back()));
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (int c = 0; c < 3; ++c) {
      const auto col = static_cast<std::size_t>(elements[e].v[static_cast<std::size_t>(c)]);
      for (int r = 0; r < 3; ++r) {
        const auto row = static_cast<int>(elements[e].v[static_cast<std::size_t>(r)]);
        candidates[static_cast<std::size_t>(fill[col]++)] = {row, static_cast<int>(9 * e) + 3 * r + c};
      }
    }
  p.outer.assign(static_cast<std::size_t>(n) + 1, 0);
  p.inner.reserve(candidates.size() / 2 + static_cast<std::size_t>(n));
  p.at.resize(9 * elements.size());
  // Per column: its distinct rows (a vertex and its neighbours, a handful),
  // sorted; then each candidate's entry gets the position of its row.
  std::vector<int> seen_in(static_cast<std::size_t>(n), -1), position(static_cast<std::size_t>(n));
  for (std::size_t col = 0; col < static_cast<std::size_t>(n); ++col) {
    const auto first = candidates.begin() + count[col], last = candidates.begin() + count[col + 1];
    const std::size_t begin = p.inner.size();
    for (auto it = first; it != last; ++it)
      if (seen_in[static_cast<std::size_t>(it->row)] != static_cast<int>(col)) {
        seen_in[static_cast<std::size_t>(it->row)] = static_cast<int>(col);
        p.inner.push_back(it->row);
      }
    std::sort(p.inner.begin() + static_cast<std::ptrdiff_t>(begin), p.inner.end());
    for (std::size_t k = begin; k < p.inner.size(); ++k)
      position[static_cast<std::size_t>(p.inner[k])] = static_cast<int>(k);
    for (auto it = first; it != last; ++it)
      p.at[static_cast<std::size_t>(it->entry)] = position[static_cast<std::size_t>(it->row)];
    p.outer[col + 1] = static_cast<int>(p.inner.size());
  }
  return p;
}

Eigen::SparseMatrix<double> matrix(const Pattern& p, const std::vector<double>& values) {
  const auto n = static_cast<Eigen::Index>(p.outer.size() - 1);
  return Eigen::Map<const Eigen::SparseMatrix<double>>(n, n, static_cast<Eigen::Index>(p.inner.size()), p.outer.data(),
                                                       p.inner.data(), values.data());
}

/// Whether a triangle spans surface, to rounding: twice its area above 1e-12
/// of its longest side squared. Otherwise its cotangents are undefined.
bool has_area(double twice_area, double longest_squared) { return twice_area > 1e-12 * longest_squared; }

/// The elements of the mesh's own triangles, or of its intrinsic Delaunay
/// triangulation, that have area.
std::vector<Element> elements_of(const Mesh& mesh, bool intrinsic) {
  std::vector<Element> elements;
  elements.reserve(static_cast<std::size_t>(mesh.num_triangles()));
  Element e;
  if (intrinsic) {
    const IntrinsicTriangulation t = intrinsic_delaunay(mesh);
    for (Index f = 0; f < t.triangles.rows(); ++f) {
      std::array<double, 3> l2;  // squared side lengths, l2[k] opposite corner k
      for (int k = 0; k < 3; ++k) l2[static_cast<std::size_t>(k)] = t.lengths(f, k) * t.lengths(f, k);
      const double twice_area = intrinsic_twice_area(t.lengths(f, 0), t.lengths(f, 1), t.lengths(f, 2));
      if (!has_area(twice_area, std::max({l2[0], l2[1], l2[2]}))) continue;
      e.v = {t.triangles(f, 0), t.triangles(f, 1), t.triangles(f, 2)};
      for (std::size_t k = 0; k < 3; ++k)  // the law of cosines: cot = (b^2 + c^2 - a^2) / (4 area)
        e.half_cot[k] = (l2[(k + 1) % 3] + l2[(k + 2) % 3] - l2[k]) / (4 * twice_area);
      e.area = 0.5 * twice_area;
      elements.push_back(e);
    }
    return elements;
  }
  for (Index f = 0; f < mesh.num_triangles(); ++f) {
    e.v = {mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)};
    const Vec3 p[3] = {mesh.vertices.row(e.v[0]), mesh.vertices.row(e.v[1]), mesh.vertices.row(e.v[2])};
    const double twice_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    if (!has_area(twice_area,
                  std::max({(p[1] - p[0]).squaredNorm(), (p[2] - p[1]).squaredNorm(), (p[0] - p[2]).squaredNorm()})))
      continue;
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k is opposite the edge (i, j); its cotangent is
      // dot / |cross| of the two edge vectors leaving the corner, and
      // |cross| = twice the area for every corner.
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      e.half_cot[static_cast<std::size_t>(k)] = 0.5 * (p[i] - p[k]).dot(p[j] - p[k]) / twice_area;
    }
    e.area = 0.5 * twice_area;
    elements.push_back(e);
  }
  return elements;
}

}  // namespace

LaplaceBeltrami laplace_beltrami(const Mesh& mesh, const LaplaceBeltramiOptions& options) {
  const std::string source = mesh.source.empty() ? "mesh" : mesh.source;
  if (mesh.num_triangles() == 0) throw InvalidMeshError(source, "no triangle: no Laplace-Beltrami operator");
  // The triangles with area, their vertices renumbered to the rows.
  std::vector<Element> elements = elements_of(mesh, options.intrinsic_delaunay);
  std::vector<Index> row(static_cast<std::size_t>(mesh.num_vertices()), kInvalidIndex);
  for (const Element& e : elements)
    for (const Index v : e.v) row[static_cast<std::size_t>(v)] = 0;
  // Rows and columns for the vertices with area only.
  LaplaceBeltrami result;
  for (std::size_t v = 0; v < row.size(); ++v)
    if (row[v] != kInvalidIndex) {
      row[v] = static_cast<Index>(result.vertex.size());
      result.vertex.push_back(static_cast<Index>(v));
    }
  if (result.vertex.empty())
    throw InvalidMeshError(source, "no triangle of nonzero area: no Laplace-Beltrami operator");
  for (Element& e : elements)
    for (Index& v : e.v) v = row[static_cast<std::size_t>(v)];
  const auto n = static_cast<Index>(result.vertex.size());

  // Each sum in the order of the elements, as a triplet list would add up its
  // duplicates.
  const Pattern pattern = edge_pattern(elements, n);
  std::vector<double> stiffness(pattern.inner.size(), 0.0), mass;
  if (options.mass == MassMatrix::Consistent) mass.assign(pattern.inner.size(), 0.0);
  std::vector<double> lumped(options.mass == MassMatrix::Lumped ? static_cast<std::size_t>(n) : 0, 0.0);
  for (std::size_t element = 0; element < elements.size(); ++element) {
    const Element& e = elements[element];
    const int* position = pattern.at.data() + 9 * element;
    // The position of entry (row e.v[r], column e.v[c]).
    const auto at = [position](int r, int c) { return static_cast<std::size_t>(position[3 * r + c]); };
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double half_cot = e.half_cot[static_cast<std::size_t>(k)];
      stiffness[at(i, j)] -= half_cot;
      stiffness[at(j, i)] -= half_cot;
      stiffness[at(i, i)] += half_cot;
      stiffness[at(j, j)] += half_cot;
    }
    for (int a = 0; a < 3; ++a) {
      if (options.mass == MassMatrix::Lumped) {
        lumped[static_cast<std::size_t>(e.v[static_cast<std::size_t>(a)])] += e.area / 3;
        continue;
      }
      for (int b = 0; b < 3; ++b) mass[at(b, a)] += e.area / (a == b ? 6 : 12);
    }
  }
  result.stiffness = matrix(pattern, stiffness);
  if (options.mass == MassMatrix::Consistent) {
    result.mass = matrix(pattern, mass);
  } else {
    Pattern diagonal;
    diagonal.outer.resize(static_cast<std::size_t>(n) + 1);
    std::iota(diagonal.outer.begin(), diagonal.outer.end(), 0);
    diagonal.inner.assign(diagonal.outer.begin(), diagonal.outer.end() - 1);
    result.mass = matrix(diagonal, lumped);
  }
  return result;
}

}  // namespace reebkit
