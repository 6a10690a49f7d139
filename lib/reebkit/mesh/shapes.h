// Meshes generated in code: analytic test cases, benchmark inputs and the
// embedded demo collection. All are clean (see mesh_cleanup.h) and, except
// the grid, closed.
#pragma once

#include "reebkit/core/mesh.h"

#include <vector>

namespace reebkit {

/// Planar (nx+1) x (ny+1) vertex grid with spacing h in the z = 0 plane, each
/// square split along its (+1,+1) diagonal. Vertex (i, j) has index j*(nx+1)+i.
/// On this graph the Dijkstra distance from (0,0) to (i,j), i,j >= 0, is
/// h * (min(i,j) * sqrt(2) + |i - j|).
Mesh make_grid(int nx, int ny, double h = 1.0);

/// Unit-edge cube [0,1]^3, 8 vertices and 12 triangles.
Mesh make_cube();

/// Icosahedron subdivided `levels` times, projected to the sphere of `radius`
/// (10 * 4^levels + 2 vertices).
Mesh make_icosphere(int levels, double radius = 1.0);

/// Torus with `major` x `minor` vertices, radii R (tube centre) and r (tube).
/// Genus 1.
Mesh make_torus(int major, int minor, double R = 1.0, double r = 0.35);

/// A closed surface of any genus: the boundary of a plate of (2 genus + 1) x
/// 3 x 1 unit cubes with `genus` square holes through it (the cubes at
/// (2i + 1, 1) left out), each cube face split into `resolution` x
/// `resolution` squares. Manifold, consistently oriented; genus >= 0,
/// resolution >= 1.
Mesh make_holed_plate(int genus, int resolution = 4);

/// Options of make_star.
struct StarOptions {
  int arms = 5;             ///< number of protrusions (>= 1)
  int levels = 5;           ///< icosphere subdivision levels of the base sphere
  double arm_length = 2.0;  ///< how far a tip stands out, in base-sphere radii
  double arm_width = 0.20;  ///< angular half-width of an arm at its base, radians
  /// Rotates the arm directions (a Fibonacci spiral) so that shapes with the
  /// same arm count can differ in layout; 0 keeps the default layout.
  double twist = 0.0;
};

/// A closed genus-0 "urchin": a sphere with `arms` prominent protrusions whose
/// tips are the natural feature points. Arm directions come from a Fibonacci
/// spiral, so arms are well separated for every count.
Mesh make_star(const StarOptions& options = {});

/// The unit direction of each arm of make_star(options), in arm order.
std::vector<Vec3> star_arm_directions(const StarOptions& options);

}  // namespace reebkit
