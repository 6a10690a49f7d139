// The intrinsic Delaunay triangulation of a triangle mesh: its edges flipped,
// as the surface's metric sees them (edge lengths, not positions), until every
// edge is locally Delaunay (the two angles opposite it sum to at most pi).
// The surface, its area and its vertices stay what they were; only the
// triangles that span them change, and with them the linear elements: the
// cotangent Laplacian of the intrinsic Delaunay triangulation (Bobenko and
// Springborn, "A discrete Laplace-Beltrami operator for simplicial surfaces",
// Discrete & Computational Geometry 38(4), 2007) has no negative edge weight,
// and its eigenvalues do not pay for the slivers and caps that an edge
// collapse leaves (Fisher, Springborn, Bobenko and Schroeder, "An algorithm
// for the construction of intrinsic Delaunay triangulations with applications
// to digital geometry processing", Computing 81(2-3), 2007: the flip
// algorithm used here; Sharp, Soliman and Crane, "Navigating intrinsic
// triangulations", ACM TOG 38(4), 2019).
#pragma once

#include "reebkit/core/mesh.h"

#include <Eigen/Core>

namespace reebkit {

/// A triangulation of a mesh's vertices given by edge lengths alone. Two
/// triangles may share two edges, or an edge may join a vertex to itself
/// after flips: such triangulations are valid intrinsically, and the
/// Laplacian (laplace_beltrami.h) sums over them.
struct IntrinsicTriangulation {
  Triangles triangles;  ///< #F x 3 corners, oriented as the mesh's
  /// lengths(t, k): the length of the edge of triangle t opposite its corner k.
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> lengths;
  Index num_vertices = 0;
  Index flips = 0;  ///< how many edge flips it took
};

/// The intrinsic Delaunay triangulation of `mesh`. Only an edge with exactly
/// two triangles on it, oriented against each other, is flipped: boundary and
/// non-manifold edges stay, as do the edges of a triangle of (nearly) zero
/// area, whose angles are undefined. The flips follow the triangles' order,
/// so the same mesh gives the same triangulation. The flip algorithm ends on
/// every surface (Bobenko and Springborn 2007).
IntrinsicTriangulation intrinsic_delaunay(const Mesh& mesh);

/// Twice the area of a triangle of side lengths a, b and c (Kahan's
/// rearrangement of Heron's formula, accurate for needles); 0 where they
/// violate the triangle inequality.
double intrinsic_twice_area(double a, double b, double c);

}  // namespace reebkit
