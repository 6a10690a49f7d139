#include "reebkit/mesh/laplace_beltrami.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <string>
#include <vector>

namespace reebkit {

LaplaceBeltrami laplace_beltrami(const Mesh& mesh, const LaplaceBeltramiOptions& options) {
  const std::string source = mesh.source.empty() ? "mesh" : mesh.source;
  if (mesh.num_triangles() == 0) throw InvalidMeshError(source, "no triangle: no Laplace-Beltrami operator");
  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> stiffness, mass;
  stiffness.reserve(static_cast<std::size_t>(mesh.num_triangles()) * 9);
  mass.reserve(static_cast<std::size_t>(mesh.num_triangles()) * 9);
  std::vector<bool> covered(static_cast<std::size_t>(mesh.num_vertices()), false);  // on a triangle with area
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const Index v[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    const Vec3 p[3] = {mesh.vertices.row(v[0]), mesh.vertices.row(v[1]), mesh.vertices.row(v[2])};
    const double twice_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    const double longest =
        std::max({(p[1] - p[0]).squaredNorm(), (p[2] - p[1]).squaredNorm(), (p[0] - p[2]).squaredNorm()});
    if (!(twice_area > 1e-12 * longest)) continue;  // spans no surface; its cotangents are undefined
    for (const Index corner : v) covered[static_cast<std::size_t>(corner)] = true;
    for (int k = 0; k < 3; ++k) {
      // The angle at corner k is opposite the edge (i, j); its cotangent is
      // dot / |cross| of the two edge vectors leaving the corner, and
      // |cross| = twice the area for every corner.
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double half_cot = 0.5 * (p[i] - p[k]).dot(p[j] - p[k]) / twice_area;
      stiffness.emplace_back(v[i], v[j], -half_cot);
      stiffness.emplace_back(v[j], v[i], -half_cot);
      stiffness.emplace_back(v[i], v[i], half_cot);
      stiffness.emplace_back(v[j], v[j], half_cot);
    }
    const double area = 0.5 * twice_area;
    for (int a = 0; a < 3; ++a) {
      if (options.mass == MassMatrix::Lumped) {
        mass.emplace_back(v[a], v[a], area / 3);
        continue;
      }
      for (int b = 0; b < 3; ++b) mass.emplace_back(v[a], v[b], area / (a == b ? 6 : 12));
    }
  }
  // Rows and columns for the vertices with area only.
  LaplaceBeltrami result;
  std::vector<Index> row(covered.size(), kInvalidIndex);
  for (std::size_t v = 0; v < covered.size(); ++v)
    if (covered[v]) {
      row[v] = static_cast<Index>(result.vertex.size());
      result.vertex.push_back(static_cast<Index>(v));
    }
  if (result.vertex.empty())
    throw InvalidMeshError(source, "no triangle of nonzero area: no Laplace-Beltrami operator");
  for (std::vector<Triplet>* entries : {&stiffness, &mass})
    for (Triplet& e : *entries)
      e = Triplet(row[static_cast<std::size_t>(e.row())], row[static_cast<std::size_t>(e.col())], e.value());
  const auto n = static_cast<Eigen::Index>(result.vertex.size());
  result.stiffness.resize(n, n);
  result.stiffness.setFromTriplets(stiffness.begin(), stiffness.end());
  result.mass.resize(n, n);
  result.mass.setFromTriplets(mass.begin(), mass.end());
  return result;
}

}  // namespace reebkit
