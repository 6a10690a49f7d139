#include "reebkit/mesh/shapes.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace reebkit {

namespace {

constexpr double kPi = 3.14159265358979323846;

Mesh from_lists(const std::vector<Vec3>& points, const std::vector<std::array<Index, 3>>& tris) {
  Mesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) mesh.vertices.row(static_cast<Eigen::Index>(i)) = points[i];
  mesh.triangles.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) mesh.triangles(static_cast<Eigen::Index>(i), k) = tris[i][static_cast<std::size_t>(k)];
  return mesh;
}

// Quad (a, b, c, d) in counter-clockwise order, split along a-c.
void add_quad(std::vector<std::array<Index, 3>>& tris, Index a, Index b, Index c, Index d) {
  tris.push_back({a, b, c});
  tris.push_back({a, c, d});
}

}  // namespace

Mesh make_grid(int nx, int ny, double h) {
  if (nx < 1 || ny < 1) throw InvalidArgument("make_grid: nx and ny must be >= 1");
  std::vector<Vec3> points;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) points.emplace_back(h * i, h * j, 0.0);
  std::vector<std::array<Index, 3>> tris;
  const auto id = [nx](int i, int j) { return static_cast<Index>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) add_quad(tris, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return from_lists(points, tris);
}

Mesh make_cube() {
  std::vector<Vec3> points;
  for (int k = 0; k < 8; ++k) points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  std::vector<std::array<Index, 3>> tris;
  add_quad(tris, 0, 2, 3, 1);  // z = 0
  add_quad(tris, 4, 5, 7, 6);  // z = 1
  add_quad(tris, 0, 1, 5, 4);  // y = 0
  add_quad(tris, 2, 6, 7, 3);  // y = 1
  add_quad(tris, 0, 4, 6, 2);  // x = 0
  add_quad(tris, 1, 3, 7, 5);  // x = 1
  return from_lists(points, tris);
}

Mesh make_holed_plate(int genus, int resolution) {
  if (genus < 0 || resolution < 1) throw InvalidArgument("make_holed_plate: genus must be >= 0, resolution >= 1");
  const int nx = 2 * genus + 1, ny = 3;
  const auto full = [&](int x, int y, int z) {
    return x >= 0 && x < nx && y >= 0 && y < ny && z == 0 && !(y == 1 && x % 2 == 1);
  };
  // Lattice points at 1/resolution, welded by their integer coordinates.
  std::vector<Vec3> points;
  std::unordered_map<std::uint64_t, Index> index;
  const auto point = [&](const std::array<int, 3>& p) {
    const std::uint64_t key = (static_cast<std::uint64_t>(p[0]) << 42) | (static_cast<std::uint64_t>(p[1]) << 21) |
                              static_cast<std::uint64_t>(p[2]);
    const auto [it, inserted] = index.try_emplace(key, static_cast<Index>(points.size()));
    if (inserted) points.emplace_back(p[0], p[1], p[2]);
    return it->second;
  };
  std::vector<std::array<Index, 3>> tris;
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y) {
      if (!full(x, y, 0)) continue;
      const std::array<int, 3> cell = {x, y, 0};
      for (int a = 0; a < 3; ++a)
        for (const int side : {0, 1}) {
          std::array<int, 3> next = cell;
          next[static_cast<std::size_t>(a)] += side == 0 ? -1 : 1;
          if (full(next[0], next[1], next[2])) continue;
          // The face normal to axis a, spanned by the axes b, c that follow
          // it; corners counter-clockwise seen from outside.
          const auto b = static_cast<std::size_t>((a + 1) % 3), c = static_cast<std::size_t>((a + 2) % 3);
          for (int i = 0; i < resolution; ++i)
            for (int j = 0; j < resolution; ++j) {
              std::array<Index, 4> q;
              const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
              for (int k = 0; k < 4; ++k) {
                std::array<int, 3> p = {cell[0] * resolution, cell[1] * resolution, cell[2] * resolution};
                p[static_cast<std::size_t>(a)] += side * resolution;
                p[b] += i + du[k];
                p[c] += j + dv[k];
                q[static_cast<std::size_t>(k)] = point(p);
              }
              if (side == 1)
                add_quad(tris, q[0], q[1], q[2], q[3]);
              else
                add_quad(tris, q[0], q[3], q[2], q[1]);
            }
        }
    }
  Mesh mesh = from_lists(points, tris);
  mesh.vertices /= resolution;
  return mesh;
}

Mesh make_icosphere(int levels, double radius) {
  if (levels < 0) throw InvalidArgument("make_icosphere: levels must be >= 0");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> points = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : points) p.normalize();
  std::vector<std::array<Index, 3>> tris = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::unordered_map<std::uint64_t, Index> midpoint;
    const auto mid = [&](Index a, Index b) {
      const std::uint64_t key =
          (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
      const auto [it, inserted] = midpoint.try_emplace(key, static_cast<Index>(points.size()));
      if (inserted)
        points.push_back((points[static_cast<std::size_t>(a)] + points[static_cast<std::size_t>(b)]).normalized());
      return it->second;
    };
    std::vector<std::array<Index, 3>> finer;
    finer.reserve(tris.size() * 4);
    for (const auto& [a, b, c] : tris) {
      const Index ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    tris.swap(finer);
  }
  for (auto& p : points) p *= radius;
  return from_lists(points, tris);
}

Mesh make_torus(int major, int minor, double R, double r) {
  if (major < 3 || minor < 3) throw InvalidArgument("make_torus: major and minor must be >= 3");
  std::vector<Vec3> points;
  for (int i = 0; i < major; ++i) {
    const double u = 2 * kPi * i / major;
    for (int j = 0; j < minor; ++j) {
      const double w = 2 * kPi * j / minor;
      points.emplace_back((R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w));
    }
  }
  std::vector<std::array<Index, 3>> tris;
  const auto id = [major, minor](int i, int j) { return static_cast<Index>((i % major) * minor + (j % minor)); };
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) add_quad(tris, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return from_lists(points, tris);
}

std::vector<Vec3> star_arm_directions(const StarOptions& options) {
  if (options.arms < 1) throw InvalidArgument("make_star: arms must be >= 1");
  std::vector<Vec3> dirs;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  const int n = options.arms;
  for (int i = 0; i < n; ++i) {
    // Fibonacci spiral; a single arm points up.
    const double z = n == 1 ? 1.0 : 1.0 - 2.0 * (i + 0.5) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden * i + options.twist;
    dirs.emplace_back(rho * std::cos(phi), rho * std::sin(phi), z);
  }
  return dirs;
}

Mesh make_star(const StarOptions& options) {
  const std::vector<Vec3> dirs = star_arm_directions(options);
  Mesh mesh = make_icosphere(options.levels);
  const double cos_width = std::cos(options.arm_width);
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    const Vec3 u = mesh.vertices.row(v).transpose();
    double radius = 1.0;
    for (const Vec3& d : dirs) {
      // 0 outside the arm's cone, arm_length on its axis. Linear in cos(angle),
      // so the tip is a small rounded cap (a flat-topped profile would put the
      // extrema of different distance functions on opposite rims of the cap).
      radius += options.arm_length * std::max(0.0, (u.dot(d) - cos_width) / (1.0 - cos_width));
    }
    mesh.vertices.row(v) = (radius * u).transpose();
  }
  return mesh;
}

}  // namespace reebkit
