// Random points on a surface, uniform with respect to area: a triangle drawn
// with probability proportional to its weight, then a point uniform on it
// (Osada, Funkhouser, Chazelle and Dobkin, "Shape distributions", ACM TOG
// 2002, section 4, eq. 1). The D2 shape distributions of the graph
// attributes (attributes/graph_attributes.h) and of the D2 retrieval
// baseline (experiments/baselines.cpp) draw their points here.
#pragma once

#include "reebkit/core/mesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace reebkit {

/// Triangles to draw from and their cumulative weights: triangle[k] weighs
/// cumulative[k] - cumulative[k - 1] (its area, or its area times a share of
/// it). A view of arrays the caller keeps.
struct WeightedTriangles {
  const Index* triangle = nullptr;
  const double* cumulative = nullptr;
  std::size_t size = 0;
  double total() const { return size ? cumulative[size - 1] : 0.0; }
};

/// Triangles with their cumulative areas, summed in the order given.
struct TriangleAreas {
  std::vector<Index> triangle;
  std::vector<double> cumulative;
  WeightedTriangles view() const { return {triangle.data(), cumulative.data(), triangle.size()}; }
};

/// The triangles `triangles` of `mesh`, weighted by area.
TriangleAreas triangle_areas(const Mesh& mesh, std::vector<Index> triangles);
/// Every triangle of `mesh`, weighted by area.
TriangleAreas triangle_areas(const Mesh& mesh);

/// `count` random points of the triangles of `from`, uniform with respect to
/// their weights: per point, a triangle k with probability proportional to
/// its weight, then (1 - sqrt(r1)) a + sqrt(r1) (1 - r2) b + sqrt(r1) r2 c
/// for its corners a, b, c (Osada et al., eq. 1). The uniform numbers r are
/// the top 53 bits of a std::mt19937_64 seeded with `seed`, so that the
/// same seed gives the same points on every platform (unlike
/// std::uniform_real_distribution). Throws InvalidArgument when count < 0
/// or the total weight is not positive.
std::vector<Vec3> sample_surface(const Mesh& mesh, const WeightedTriangles& from, int count, std::uint64_t seed);

}  // namespace reebkit
