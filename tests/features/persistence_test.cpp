#include "reebkit/features/persistence.h"

#include "reebkit/core/error.h"
#include "reebkit/features/critical_points.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/geodesic/fast_marching.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/mesh/resampling.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/mesh/transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace reebkit {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<Index> extrema_ids(const std::vector<PersistencePair>& pairs) {
  std::vector<Index> ids;
  for (const PersistencePair& p : pairs) ids.push_back(p.extremum);
  return ids;
}

// ---------------------------------------------------------------------------
// A strip of 2 x 9 vertices (make_grid(8, 1)) with f(i, j) = g[i]: a 1D
// profile whose maxima and minima, and the levels where they merge, are read
// off g. Both rows tie, so sos_less puts row 1 (ids 9..17) above row 0 (ids
// 0..8): maxima sit on row 1, minima on row 0, and so do their saddles.

TEST(Persistence, StripWithKnownProfile) {
  //                       col: 0  1  2  3  4  5  6    7    8
  const std::vector<double> g = {0, 4, 2, 3, 1, 5, 0.5, 2.5, 1.2};
  const MeshGraph graph = build_mesh_graph(make_grid(8, 1));
  std::vector<double> f(18);
  for (Index v = 0; v < 18; ++v) f[static_cast<std::size_t>(v)] = g[static_cast<std::size_t>(v % 9)];
  const ExtremaPersistence p = extrema_persistence(graph, f);
  const auto top = [](int col) { return static_cast<Index>(9 + col); };
  const auto bottom = [](int col) { return static_cast<Index>(col); };

  // Superlevel sets: the peak at column 3 (3) meets the one at column 1 (4)
  // at column 2 (2): persistence 1. Column 1 then meets the global maximum
  // (column 5) only at column 4 (1): persistence 3, not 2 (elder rule: its
  // component is older than column 3's). Column 7 meets at column 6 (0.5).
  ASSERT_EQ(p.maxima.size(), 4u);
  const std::vector<std::tuple<Index, Index, double>> maxima = {{top(1), top(4), 3.0},
                                                                {top(3), top(2), 1.0},
                                                                {top(5), kInvalidIndex, kInf},
                                                                {top(7), top(6), 2.0}};
  for (std::size_t k = 0; k < maxima.size(); ++k) {
    EXPECT_EQ(p.maxima[k].extremum, std::get<0>(maxima[k])) << k;
    EXPECT_EQ(p.maxima[k].saddle, std::get<1>(maxima[k])) << k;
    EXPECT_DOUBLE_EQ(p.maxima[k].persistence, std::get<2>(maxima[k])) << k;
  }
  // Sublevel sets: minima at columns 0 (global), 2, 4, 6, 8. Column 8 (1.2)
  // meets column 6 (0.5) at column 7 (2.5); column 2 meets column 4 at
  // column 3; column 4 meets column 0 at column 1; column 6 meets column 0's
  // component at column 5 (5), the highest saddle.
  ASSERT_EQ(p.minima.size(), 5u);
  const std::vector<std::tuple<Index, Index, double>> minima = {{bottom(0), kInvalidIndex, kInf},
                                                                {bottom(2), bottom(3), 1.0},
                                                                {bottom(4), bottom(1), 3.0},
                                                                {bottom(6), bottom(5), 4.5},
                                                                {bottom(8), bottom(7), 2.5 - 1.2}};
  for (std::size_t k = 0; k < minima.size(); ++k) {
    EXPECT_EQ(p.minima[k].extremum, std::get<0>(minima[k])) << k;
    EXPECT_EQ(p.minima[k].saddle, std::get<1>(minima[k])) << k;
    EXPECT_DOUBLE_EQ(p.minima[k].persistence, std::get<2>(minima[k])) << k;
  }
  // Thresholds: >= 2 keeps the global ones, column 1's and 7's maxima and
  // column 4's and 6's minima.
  EXPECT_EQ(persistent_extrema(graph, f, 2.0),
            (std::vector<Index>{bottom(0), bottom(4), bottom(6), top(1), top(5), top(7)}));
  EXPECT_EQ(persistent_extrema(graph, f, kInf), (std::vector<Index>{bottom(0), top(5)}));
}

// ---------------------------------------------------------------------------
// Brute-force oracle: a maximum m dies at the highest vertex t (sos order)
// such that the vertices at or above t reachable from m include one above m;
// that is, max over paths from m to a higher vertex of the lowest vertex on
// the path. One breadth-first search per candidate t: O(n^2) per extremum.
// sign = -1 gives the minima (the order reversed).

std::vector<PersistencePair> oracle(const MeshGraph& graph, const std::vector<double>& f, int sign) {
  const Index n = graph.num_vertices();
  const auto above = [&](Index a, Index b) { return sign > 0 ? sos_less(f, b, a) : sos_less(f, a, b); };
  std::vector<Index> order(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v) order[static_cast<std::size_t>(v)] = v;
  std::sort(order.begin(), order.end(), above);  // most extreme first
  const auto neighbours = [&](Index v) {
    return std::vector<Index>(graph.neighbor.begin() + graph.offset[static_cast<std::size_t>(v)],
                              graph.neighbor.begin() + graph.offset[static_cast<std::size_t>(v) + 1]);
  };
  std::vector<PersistencePair> out;
  for (Index m = 0; m < n; ++m) {
    const auto nb = neighbours(m);
    if (std::any_of(nb.begin(), nb.end(), [&](Index u) { return above(u, m); })) continue;  // not an extremum
    PersistencePair pair{m, kInvalidIndex, kInf};
    for (const Index t : order) {
      if (!above(m, t)) continue;
      std::vector<char> seen(static_cast<std::size_t>(n), 0);
      std::vector<Index> stack = {m};
      seen[static_cast<std::size_t>(m)] = 1;
      bool higher = false;
      while (!stack.empty() && !higher) {
        const Index v = stack.back();
        stack.pop_back();
        for (const Index u : neighbours(v)) {
          if (seen[static_cast<std::size_t>(u)] || above(t, u)) continue;  // below t: outside the set
          seen[static_cast<std::size_t>(u)] = 1;
          higher = higher || above(u, m);
          stack.push_back(u);
        }
      }
      if (higher) {
        pair = {m, t, sign * (f[static_cast<std::size_t>(m)] - f[static_cast<std::size_t>(t)])};
        break;
      }
    }
    out.push_back(pair);
  }
  return out;
}

// Small meshes with different connectivity: closed of genus 0 and 1, with a
// boundary, and irregular (resampled) copies.
std::vector<std::pair<std::string, Mesh>> small_meshes() {
  std::vector<std::pair<std::string, Mesh>> out;
  out.emplace_back("icosphere", make_icosphere(2));
  out.emplace_back("torus", make_torus(14, 8));
  out.emplace_back("grid", make_grid(11, 8));
  out.emplace_back("resampled icosphere", resample_mesh(make_icosphere(1), ResamplingOptions{0.3, 5}));
  out.emplace_back("resampled torus", resample_mesh(make_torus(9, 5), ResamplingOptions{0.3, 7}));
  return out;
}

// Random values; with `levels` > 0 rounded to that many distinct values, so
// that ties (broken by vertex id) are everywhere.
std::vector<double> random_function(Index n, unsigned seed, int levels = 0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> f(static_cast<std::size_t>(n));
  for (double& x : f) x = levels > 0 ? std::floor(u(rng) * levels) : u(rng);
  return f;
}

// Random functions (continuous and heavily tied) and geodesic distances from
// a vertex, on every small mesh.
template <typename Check>
void for_each_case(const Check& check) {
  for (const auto& [name, mesh] : small_meshes()) {
    const MeshGraph graph = build_mesh_graph(mesh);
    const Index n = graph.num_vertices();
    for (unsigned seed = 1; seed <= 4; ++seed) {
      check(name + ", random seed " + std::to_string(seed), mesh, graph, random_function(n, seed));
      check(name + ", 4-level random seed " + std::to_string(seed), mesh, graph, random_function(n, seed, 4));
    }
    check(name + ", dijkstra", mesh, graph, dijkstra(graph, n / 3).distance);
    check(name + ", fast marching", mesh, graph, fast_marching(graph, n / 3).distance);
  }
}

void expect_same_pairs(const std::vector<PersistencePair>& got, const std::vector<PersistencePair>& want,
                       const std::string& what) {
  ASSERT_EQ(extrema_ids(got), extrema_ids(want)) << what;
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(got[k].saddle, want[k].saddle) << what << ", extremum " << got[k].extremum;
    EXPECT_EQ(got[k].persistence, want[k].persistence) << what << ", extremum " << got[k].extremum;
  }
}

TEST(Persistence, MatchesTheBruteForceOracle) {
  for_each_case([](const std::string& what, const Mesh&, const MeshGraph& graph, const std::vector<double>& f) {
    const ExtremaPersistence p = extrema_persistence(graph, f);
    expect_same_pairs(p.maxima, oracle(graph, f, +1), what + ", maxima");
    expect_same_pairs(p.minima, oracle(graph, f, -1), what + ", minima");
  });
}

TEST(Persistence, PersistentExtremaAreThoseThatPassTheThreshold) {
  // persistent_extrema searches from each extremum instead of pairing them
  // all: the same set as filtering extrema_persistence, at every threshold,
  // including the persistence values themselves (>= is inclusive).
  for_each_case([](const std::string& what, const Mesh&, const MeshGraph& graph, const std::vector<double>& f) {
    const ExtremaPersistence p = extrema_persistence(graph, f);
    std::vector<double> thresholds = {0.0, 1e-9, 0.01, 0.05, 0.2, 1.0, kInf};
    for (const auto* pairs : {&p.maxima, &p.minima})
      for (const PersistencePair& e : *pairs) thresholds.push_back(e.persistence);
    for (const double t : thresholds) {
      std::vector<Index> want;
      for (const auto* pairs : {&p.maxima, &p.minima})
        for (const PersistencePair& e : *pairs)
          if (e.persistence >= t) want.push_back(e.extremum);
      std::sort(want.begin(), want.end());
      want.erase(std::unique(want.begin(), want.end()), want.end());
      ASSERT_EQ(persistent_extrema(graph, f, t), want) << what << ", threshold " << t;
    }
  });
}

TEST(Persistence, ExtremaAreThoseOfTheLinkClassification) {
  for_each_case([](const std::string& what, const Mesh&, const MeshGraph& graph, const std::vector<double>& f) {
    const ExtremaPersistence p = extrema_persistence(graph, f);
    std::vector<Index> maxima, minima;
    for (Index v = 0; v < graph.num_vertices(); ++v) {
      const CriticalType type = classify_vertex(graph, f, v);
      if (type == CriticalType::Maximum) maxima.push_back(v);
      if (type == CriticalType::Minimum) minima.push_back(v);
    }
    EXPECT_EQ(extrema_ids(p.maxima), maxima) << what;
    EXPECT_EQ(extrema_ids(p.minima), minima) << what;
    EXPECT_EQ(persistent_extrema(graph, f, 0.0), local_extrema(graph, f)) << what;
    // Every local extremum has persistence >= 0; one of each kind never dies.
    for (const auto* pairs : {&p.maxima, &p.minima}) {
      EXPECT_EQ(std::count_if(pairs->begin(), pairs->end(),
                              [](const PersistencePair& e) { return e.persistence == kInf; }),
                1)
          << what;
      for (const PersistencePair& e : *pairs) EXPECT_GE(e.persistence, 0.0) << what;
    }
  });
}

TEST(Persistence, DistinctValuesGivePositivePersistence) {
  // Without ties every extremum lies strictly above (below) its saddle.
  for (const auto& [name, mesh] : small_meshes()) {
    const MeshGraph graph = build_mesh_graph(mesh);
    const std::vector<double> f = random_function(graph.num_vertices(), 11);
    const ExtremaPersistence p = extrema_persistence(graph, f);
    std::size_t local_maxima = 0;
    for (Index v = 0; v < graph.num_vertices(); ++v)
      local_maxima += classify_vertex(graph, f, v) == CriticalType::Maximum;
    EXPECT_EQ(std::count_if(p.maxima.begin(), p.maxima.end(),
                            [](const PersistencePair& e) { return e.persistence > 0; }),
              static_cast<std::ptrdiff_t>(local_maxima))
        << name;
  }
}

TEST(Persistence, PairsUseDistinctSaddles) {
  // Each extremum but the global one dies at a saddle vertex, which kills at
  // most L+ - 1 maxima and L- - 1 minima (components met around its link).
  // On a closed surface of genus g a saddle has L+ = L- = m + 1, its
  // multiplicity m; the saddle units not used by a pair are exactly the 2g
  // cycles (Euler: #max + #min - sum m = 2 - 2g), and no unit serves both a
  // maximum and a minimum.
  for_each_case([](const std::string& what, const Mesh& mesh, const MeshGraph& graph, const std::vector<double>& f) {
    const ExtremaPersistence p = extrema_persistence(graph, f);
    std::map<Index, int> killed_maxima, killed_minima;
    for (const PersistencePair& e : p.maxima)
      if (e.saddle != kInvalidIndex) ++killed_maxima[e.saddle];
    for (const PersistencePair& e : p.minima)
      if (e.saddle != kInvalidIndex) ++killed_minima[e.saddle];
    for (const auto& [s, k] : killed_maxima) {
      EXPECT_EQ(classify_vertex(graph, f, s), CriticalType::Saddle) << what << ", vertex " << s;
      EXPECT_LE(k, count_link_components(graph, f, s).upper - 1) << what << ", vertex " << s;
    }
    for (const auto& [s, k] : killed_minima) {
      EXPECT_EQ(classify_vertex(graph, f, s), CriticalType::Saddle) << what << ", vertex " << s;
      EXPECT_LE(k, count_link_components(graph, f, s).lower - 1) << what << ", vertex " << s;
    }
    const MeshTopology topology = analyze_topology(mesh);
    if (!topology.closed) return;
    int unused = 0;
    for (Index s = 0; s < graph.num_vertices(); ++s) {
      const LinkCount link = count_link_components(graph, f, s);
      if (link.upper == 0 || link.lower == 0) continue;
      const int free_units = (link.upper - 1) - killed_maxima[s] - killed_minima[s];
      EXPECT_GE(free_units, 0) << what << ", vertex " << s;
      unused += free_units;
    }
    EXPECT_EQ(unused, 2 * topology.genus) << what;
  });
}

// ---------------------------------------------------------------------------
// Geodesic distances on shapes.

StarOptions star(int arms, int levels) {
  StarOptions o;
  o.arms = arms;
  o.levels = levels;
  return o;
}

TEST(Persistence, StarTipsAreThePersistentMaxima) {
  // d(tip of one arm, .) on a star: the other tips are maxima that persist
  // about an arm's length; the rest (more on resampled copies, and with
  // Dijkstra) are ripples that merge within a small fraction of it. (With 3
  // arms the far side of the ball is a real maximum too.)
  for (const int arms : {5, 6, 10})
    for (std::uint64_t seed = 0; seed <= 2; ++seed) {
      const Mesh base = make_star(star(arms, 3));
      const Mesh mesh = seed == 0 ? base : resample_mesh(base, ResamplingOptions{0.2, seed});
      const MeshGraph graph = build_mesh_graph(mesh);
      Index tip = 0;
      const Vec3 d0 = star_arm_directions(star(arms, 3)).front();
      for (Index v = 1; v < mesh.num_vertices(); ++v)
        if (mesh.vertices.row(v).dot(d0) > mesh.vertices.row(tip).dot(d0)) tip = v;
      for (const Geodesic method : {Geodesic::Dijkstra, Geodesic::FastMarching}) {
        const DistanceField field = geodesic_distances(graph, {tip}, method);
        const ExtremaPersistence p = extrema_persistence(graph, field.distance);
        const double threshold = 0.1 * field.max_distance;
        EXPECT_EQ(std::count_if(p.maxima.begin(), p.maxima.end(),
                                [&](const PersistencePair& e) { return e.persistence >= threshold; }),
                  arms - 1)
            << arms << " arms, seed " << seed << ", " << geodesic_name(method) << ", " << p.maxima.size()
            << " local maxima";
        EXPECT_EQ(p.minima.front().extremum, tip);  // a distance has one persistent minimum, its source
      }
    }
}

TEST(Persistence, InvariantToSimilarityTransforms) {
  // Distances scale with the mesh and change only in their last bits, so the
  // pairs of every extremum that is not a rounding-level ripple are the same
  // and their persistence relative to the diameter agrees to 1e-9.
  const Mesh mesh = resample_mesh(make_star(star(6, 3)), ResamplingOptions{0.2, 3});
  const Index source = 17;
  for (const Geodesic method : {Geodesic::Dijkstra, Geodesic::FastMarching}) {
    const DistanceField reference_field = geodesic_distances(build_mesh_graph(mesh), {source}, method);
    const ExtremaPersistence reference = extrema_persistence(build_mesh_graph(mesh), reference_field.distance);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Similarity t;
      t.rotation = random_rotation(seed);
      t.scale = 0.3 * static_cast<double>(seed * seed);
      t.translation = Vec3(3.0, -7.0, 1e2) * static_cast<double>(seed);
      const MeshGraph graph = build_mesh_graph(transformed(mesh, t));
      const DistanceField field = geodesic_distances(graph, {source}, method);
      const ExtremaPersistence moved = extrema_persistence(graph, field.distance);
      for (const auto& [got, want] :
           {std::pair{&moved.maxima, &reference.maxima}, std::pair{&moved.minima, &reference.minima}}) {
        const auto significant = [](const std::vector<PersistencePair>& pairs, double diameter) {
          std::vector<std::tuple<Index, Index, double>> out;
          for (const PersistencePair& e : pairs)
            if (e.persistence > 1e-6 * diameter) out.emplace_back(e.extremum, e.saddle, e.persistence / diameter);
          return out;
        };
        const auto a = significant(*got, field.max_distance);
        const auto b = significant(*want, reference_field.max_distance);
        ASSERT_EQ(a.size(), b.size()) << geodesic_name(method) << ", seed " << seed;
        ASSERT_GE(a.size(), got == &moved.maxima ? 5u : 1u);  // the tips; the source
        for (std::size_t k = 0; k < a.size(); ++k) {
          EXPECT_EQ(std::get<0>(a[k]), std::get<0>(b[k])) << k;
          EXPECT_EQ(std::get<1>(a[k]), std::get<1>(b[k])) << k;
          if (std::isinf(std::get<2>(b[k])))
            EXPECT_TRUE(std::isinf(std::get<2>(a[k])));
          else
            EXPECT_NEAR(std::get<2>(a[k]), std::get<2>(b[k]), 1e-9) << k;
        }
      }
      EXPECT_EQ(persistent_extrema(graph, field.distance, 0.02 * field.max_distance),
                persistent_extrema(build_mesh_graph(mesh), reference_field.distance,
                                   0.02 * reference_field.max_distance));
    }
  }
}

TEST(Persistence, RejectsBadInput) {
  const MeshGraph graph = build_mesh_graph(make_cube());
  EXPECT_THROW(extrema_persistence(graph, std::vector<double>(7, 0.0)), InvalidArgument);
  EXPECT_THROW(persistent_extrema(graph, std::vector<double>(7, 0.0), 0.1), InvalidArgument);
  EXPECT_THROW(persistent_extrema(graph, std::vector<double>(8, 0.0), -0.1), InvalidArgument);
  EXPECT_THROW(persistent_extrema(graph, std::vector<double>(8, 0.0), std::nan("")), InvalidArgument);
  // Constant f: ties broken by id, so vertex 7 is the one maximum, 0 the one minimum.
  const ExtremaPersistence p = extrema_persistence(graph, std::vector<double>(8, 1.0));
  ASSERT_EQ(p.maxima.size(), 1u);
  ASSERT_EQ(p.minima.size(), 1u);
  EXPECT_EQ(p.maxima.front().extremum, 7);
  EXPECT_EQ(p.minima.front().extremum, 0);
}

}  // namespace
}  // namespace reebkit
