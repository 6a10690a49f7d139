#include "reebkit/features/feature_points.h"

#include "reebkit/core/error.h"
#include "reebkit/core/named_values.h"
#include "reebkit/features/critical_points.h"
#include "reebkit/features/persistence.h"
#include "reebkit/geodesic/dijkstra.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <utility>

namespace reebkit {

namespace {

constexpr Index kCanonicalSeed = 0;

constexpr NamedValues<DiameterStart, 2> kDiameterStartNames{"diameter start",
                                                            {{{DiameterStart::Vertex, "vertex"},
                                                              {DiameterStart::Centroid, "centroid"}}}};

constexpr NamedValues<FeatureRule, 4> kFeatureRuleNames{"feature rule",
                                                        {{{FeatureRule::Intersection, "intersection"},
                                                          {FeatureRule::Center, "center"},
                                                          {FeatureRule::Confirmed, "confirmed"},
                                                          {FeatureRule::Average, "average"}}}};

constexpr NamedValues<FeatureSite, 3> kFeatureSiteNames{"feature site",
                                                        {{{FeatureSite::Extremum, "extremum"},
                                                          {FeatureSite::Midpoint, "midpoint"},
                                                          {FeatureSite::Tips, "tips"}}}};

// A mutually farthest (or best found) pair and the distance fields from it.
struct DiameterEnds {
  Index s1 = kInvalidIndex, s2 = kInvalidIndex;
  std::vector<double> f1, f2;  // distances from s1 and from s2
  int passes = 0;              // full geodesic passes spent

  double length() const { return f1[static_cast<std::size_t>(s2)]; }
  bool longer_than(const DiameterEnds& o) const {
    if (length() != o.length()) return length() > o.length();
    return std::minmax(s1, s2) < std::minmax(o.s1, o.s2);
  }
};

// A full pass's distances from one source, kept for a later step.
struct SourceField {
  Index source = kInvalidIndex;
  std::vector<double> distance;
};

// to_ends[v] <- the distance from v to the nearest end found so far, with
// the ends of `e` (f2 absent when only its length was kept): the field whose
// maximum is the next farthest-point seed.
void add_ends(std::vector<double>& to_ends, const DiameterEnds& e) {
  if (to_ends.empty()) to_ends.assign(e.f1.size(), std::numeric_limits<double>::infinity());
  for (std::size_t v = 0; v < to_ends.size(); ++v) {
    to_ends[v] = std::min(to_ends[v], e.f1[v]);
    if (!e.f2.empty()) to_ends[v] = std::min(to_ends[v], e.f2[v]);
  }
}

// The vertex of largest f counted in units of kTieGrid x max f, ties to the
// larger id: the maximum of f as the extrema are classified below (sos_less
// on the snapped field), whatever the rounding of a moved or scaled copy.
Index grid_farthest(const std::vector<double>& f) {
  const double far = *std::max_element(f.begin(), f.end());
  const double unit = kTieGrid * far, top = std::round(far / unit);
  Index v = static_cast<Index>(f.size()) - 1;
  while (std::round(f[static_cast<std::size_t>(v)] / unit) != top) --v;
  return v;
}

// What a call of find_diameter_ends must leave behind: each level is one
// pass more (the pass from s1, then the pass from s2 and the extra sweeps).
enum class Keep {
  Start,   ///< s1 only
  Length,  ///< s1, s2 and f1 (so length())
  Fields,  ///< s1, s2, f1 and f2, the pair mutually farthest where the sweeps allow
};

// How find_diameter_ends starts and compares.
struct Sweep {
  /// The seed is already an end (far from every end found so far): it is
  /// v_s1 itself, one pass less.
  bool seed_is_end = false;
  /// The farthest vertex of a pass is grid_farthest's, not the field's own
  /// (largest distance, then id).
  bool grid_ties = false;
  Keep keep = Keep::Fields;
};

// The second half of a double sweep whose first pass `e` holds (s1, s2 and
// f1): the pass from s2, then more (v_s1 <- v_s2, v_s2 <- farthest) until the
// pair is mutually farthest or `max_extra_sweeps` more passes were spent.
// Returns the passes it ran.
int complete_sweep(GeodesicSolver& solver, DiameterEnds& e, int max_extra_sweeps, bool grid_ties) {
  const DistanceField& field = solver.run({e.s2});
  const auto farthest = [&] { return grid_ties ? grid_farthest(field.distance) : field.farthest; };
  Index back = farthest();  // farthest from s2
  e.f2 = field.distance;
  int passes = 1;
  for (int extra = 0; extra < max_extra_sweeps && back != e.s1; ++extra) {
    // d(s2, back) > d(s1, s2): the pair moves outward along the diameter.
    e.s1 = e.s2;
    e.s2 = back;
    e.f1.swap(e.f2);
    solver.run({e.s2});
    back = farthest();
    e.f2 = field.distance;
    ++passes;
  }
  return passes;
}

// Double sweep from `seed` (complete_sweep); passes that `how.keep` does
// not need are not run.
DiameterEnds find_diameter_ends(GeodesicSolver& solver, Index seed, int max_extra_sweeps, Sweep how = {}) {
  DiameterEnds e;
  const DistanceField& field = solver.run({seed});
  const auto farthest = [&] { return how.grid_ties ? grid_farthest(field.distance) : field.farthest; };
  if (field.reached != static_cast<Index>(field.distance.size()))
    throw InvalidArgument("extract_feature_points: the mesh graph is not connected (" + std::to_string(field.reached) +
                          " of " + std::to_string(field.distance.size()) +
                          " vertices reachable); extract each component on its own");
  e.passes = 1;
  e.s1 = seed;
  if (!how.seed_is_end) {
    e.s1 = farthest();
    if (how.keep == Keep::Start) return e;
    solver.run({e.s1});
    ++e.passes;
  }
  e.s2 = farthest();
  e.f1 = field.distance;
  if (how.keep == Keep::Fields) e.passes += complete_sweep(solver, e, max_extra_sweeps, how.grid_ties);
  return e;
}

// Eqs. (2) and (4): v_s1 farthest from v_r, v_s2 farthest from v_s1, then
// up to `extra_sweeps` further sweeps until the two are mutually farthest.
// The search runs from v_r and from vertex 0 and from options.extra_seeds
// farthest-point seeds (the vertex farthest from every diameter end found so
// far, from the distance fields the sweeps already computed) and keeps the
// longest pair (ties: smaller ids), so a start vertex changes the result only
// where it finds a longer diameter. `passes` of the result counts them all.
// `fields`: the winner's f1 and f2 are wanted (else only its s1, and no
// pass is run that neither the comparison nor the next seed reads).
DiameterEnds search_diameter_ends(GeodesicSolver& search, const FeatureOptions& options, int extra_sweeps,
                                  bool fields) {
  const bool from_start = options.start_vertex != kCanonicalSeed;
  const bool compared = options.extra_seeds > 0 || from_start;
  // A sweep's f2 is read by the result (fields) and by the choice of the
  // next farthest-point seed; its length by the comparison.
  const auto keep = [&](bool seed_follows) {
    return fields || seed_follows ? Keep::Fields : compared ? Keep::Length : Keep::Start;
  };
  DiameterEnds ends =
      find_diameter_ends(search, kCanonicalSeed, extra_sweeps, {false, false, keep(options.extra_seeds > 0)});
  int passes = ends.passes;
  std::vector<double> to_ends;
  const auto consider = [&](Index seed, Sweep how) {
    DiameterEnds other = find_diameter_ends(search, seed, extra_sweeps, how);
    passes += other.passes;
    if (how.keep == Keep::Fields) add_ends(to_ends, other);
    if (other.longer_than(ends)) ends = std::move(other);
  };
  if (options.extra_seeds > 0) add_ends(to_ends, ends);
  for (int k = 0; k < options.extra_seeds; ++k)  // max_element: ties go to the smallest id
    consider(static_cast<Index>(std::max_element(to_ends.begin(), to_ends.end()) - to_ends.begin()),
             {false, false, keep(k + 1 < options.extra_seeds)});
  if (from_start) consider(options.start_vertex, {false, false, keep(false)});
  ends.passes = passes;
  return ends;
}

// FeatureOptions::protrusion_persistence: the extrema of f1 and f2 (snapped
// to the tie grid) persisting at least that share of the diameter, the most
// extreme (largest f1 + f2, then the id) first, each made a feature point
// where none lies within 2 epsilon.
void add_protrusion_tips(const MeshGraph& graph, const FeatureOptions& options, const std::vector<double>& f1,
                         const std::vector<double>& f2, GeodesicSolver& solver, FeaturePoints& out) {
  const double threshold = std::round(options.protrusion_persistence / kTieGrid);
  std::vector<Index> tips = persistent_extrema(graph, f1, threshold);
  const std::vector<Index> tips2 = persistent_extrema(graph, f2, threshold);
  tips.insert(tips.end(), tips2.begin(), tips2.end());
  const auto extremeness = [&](Index v) { return f1[static_cast<std::size_t>(v)] + f2[static_cast<std::size_t>(v)]; };
  std::sort(tips.begin(), tips.end(),
            [&](Index a, Index b) { return std::make_pair(-extremeness(a), a) < std::make_pair(-extremeness(b), b); });
  tips.erase(std::unique(tips.begin(), tips.end()), tips.end());
  GeodesicOptions reach{2.0 * options.epsilon * out.diameter};
  reach.separate_sources = true;
  // The field changes only when a tip is added: one pass, then one per tip added.
  const DistanceField* near_features = &solver.run(out.vertices, reach);
  for (const Index v : tips) {
    if (near_features->distance[static_cast<std::size_t>(v)] <= reach.radius) continue;
    out.vertices.push_back(v);
    near_features = &solver.run(out.vertices, reach);
  }
}

// FeatureSite::Midpoint: the vertex halfway between a and b, within `reach`
// of both (about d(a, b)): the smallest max(d(a, w), d(b, w)), then the
// smallest |d(a, w) - d(b, w)|, both counted on the tie grid `unit` (so that
// a similar copy makes the same choice), then, as eq. (6)'s greedy order,
// the more extreme vertex (larger f1 + f2, on the grid), then the id: a and
// b a single edge apart, with no vertex between, keep the more extreme.
// `fallback` where no vertex is within reach of both (fast marching is not
// symmetric: d(a, b) from a may exceed it from b).
Index geodesic_midpoint(GeodesicSolver& solver, Index a, Index b, double reach, double unit,
                        const std::vector<double>& f1, const std::vector<double>& f2, Index fallback) {
  const GeodesicOptions ball{reach};
  // The ball around a, kept as (vertex, distance) pairs: a few vertices, not
  // a copy of the whole field.
  std::vector<std::pair<Index, double>> from_a;
  const DistanceField& field = solver.run({a}, ball);
  for (const Index w : solver.settled()) from_a.emplace_back(w, field.distance[static_cast<std::size_t>(w)]);
  const DistanceField& from_b = solver.run({b}, ball);
  Index best = kInvalidIndex;
  std::tuple<double, double, double, Index> best_key;
  for (const auto& [w, x] : from_a) {
    const auto k = static_cast<std::size_t>(w);
    const double y = from_b.distance[k];
    if (!(y <= reach)) continue;  // outside the ball around b
    const auto key =
        std::make_tuple(std::round(std::max(x, y) / unit), std::round(std::abs(x - y) / unit), -(f1[k] + f2[k]), w);
    if (best == kInvalidIndex || key < best_key) {
      best_key = key;
      best = w;
    }
  }
  return best == kInvalidIndex ? fallback : best;
}

// FeatureSite::Tips: the tips around a pair are the extrema of f1 and f2
// persisting at least this share of the diameter (a fingertip, a toe: below
// eq. (6)'s min_persistence, above the ripples of a sampling) within this
// share of epsilon x the diameter of the pair's midpoint.
constexpr double kSiteTipPersistence = 0.01;
constexpr double kSiteTipRadius = 0.5;

// FeatureSite::Tips: the vertex within `radius` of `site` (a pair's
// midpoint) with the least sum of squared distances to the tips (`tips`,
// sorted) within `radius` of site, their geodesic centre; distances counted
// in whole units of `coarse`, so that the sums are exact and a similar copy
// makes the same choice; ties as the midpoint's (the larger f1 + f2 on the
// grid, then the id). `site` itself where fewer than two tips lie around it.
Index tips_centre(GeodesicSolver& solver, Index site, const std::vector<Index>& tips, double radius, double coarse,
                  const std::vector<double>& f1, const std::vector<double>& f2) {
  std::vector<std::pair<Index, double>> ball;  // (vertex, sum of squared distances)
  std::vector<Index> around;
  solver.run({site}, GeodesicOptions{radius});
  for (const Index w : solver.settled()) {
    ball.emplace_back(w, 0.0);
    if (std::binary_search(tips.begin(), tips.end(), w)) around.push_back(w);
  }
  if (around.size() < 2) return site;
  const GeodesicOptions reach{2.0 * radius};
  for (const Index t : around) {
    const DistanceField& from_t = solver.run({t}, reach);
    for (auto& [w, sum] : ball) {
      const double d = std::round(from_t.distance[static_cast<std::size_t>(w)] / coarse);  // inf beyond reach
      sum += d * d;
    }
  }
  Index best = site;
  std::tuple<double, double, Index> best_key{std::numeric_limits<double>::infinity(), 0.0, site};
  for (const auto& [w, sum] : ball) {
    const auto key = std::make_tuple(sum, -(f1[static_cast<std::size_t>(w)] + f2[static_cast<std::size_t>(w)]), w);
    if (key < best_key) {
      best_key = key;
      best = w;
    }
  }
  return best;
}

// a[v], for the per-vertex fields below.
double at(const std::vector<double>& a, Index v) { return a[static_cast<std::size_t>(v)]; }

// `f` counted in whole units of `unit` (kTieGrid x the diameter; f as it
// is where the unit is 0): see extract_feature_points.
std::vector<double> snapped(std::vector<double> f, double unit) {
  if (unit > 0.0)
    for (double& x : f) x = std::round(x / unit);
  return f;
}

// Takes `v` as a feature point: appends it to out.vertices and lowers
// to_features to the distances from it within `near`'s radius.
void take_feature_point(Index v, const GeodesicOptions& near, GeodesicSolver& solver, FeaturePoints& out,
                        std::vector<double>& to_features) {
  out.vertices.push_back(v);
  const DistanceField& ball = solver.run({v}, near);
  for (const Index w : solver.settled()) {
    const auto k = static_cast<std::size_t>(w);
    to_features[k] = std::min(to_features[k], ball.distance[k]);
  }
}

// The local maxima of `f` (on the tie grid) persisting at least
// `persistence` x the diameter, other than the ends out.source1 and
// out.source2, by increasing id.
std::vector<Index> persistent_maxima(const MeshGraph& graph, const std::vector<double>& f, double persistence,
                                     const FeaturePoints& out) {
  std::vector<Index> maxima = persistent_extrema(graph, f, std::round(persistence / kTieGrid));
  maxima.erase(std::remove_if(maxima.begin(), maxima.end(),
                              [&](Index v) {
                                return v == out.source1 || v == out.source2 || !is_local_maximum(graph, f, v);
                              }),
               maxima.end());
  return maxima;
}

// `tips` by decreasing f, ties to the smaller id.
void sort_largest_first(std::vector<Index>& tips, const std::vector<double>& f) {
  std::sort(tips.begin(), tips.end(),
            [&](Index a, Index b) { return std::make_pair(-at(f, a), a) < std::make_pair(-at(f, b), b); });
}

// The tips seen from the centre of the diameter (the vertex of smallest
// max(f1, f2) on the snapped f1 and f2, ties to the smaller id, stored in
// out.center): the local maxima of f_c, the distance from it, persisting at
// least options.tip_persistence x the diameter, other than the ends s1 and
// s2, the farthest from the centre first (ties: the smaller id). The centre
// lies on the bulk of the shape whichever pair of ends is the diameter, and
// from there the tip of every protrusion longer than the threshold is a
// maximum.
std::vector<Index> tips_from_center(const MeshGraph& graph, const FeatureOptions& options,
                                    const std::vector<double>& f1, const std::vector<double>& f2,
                                    GeodesicSolver& solver, FeaturePoints& out) {
  Index center = 0;
  for (Index v = 1; v < graph.num_vertices(); ++v)
    if (std::max(at(f1, v), at(f2, v)) < std::max(at(f1, center), at(f2, center))) center = v;
  out.center = center;
  const std::vector<double> fc = snapped(solver.run({center}).distance, kTieGrid * out.diameter);
  std::vector<Index> tips = persistent_maxima(graph, fc, options.tip_persistence, out);
  sort_largest_first(tips, fc);
  return tips;
}

// FeatureRule::Center: the ends s1 and s2, then the centre's tips that lie
// within `near`'s radius of an extremum of f1 or f2 (out.extrema1,
// out.extrema2), in tips_from_center's order, each where no feature point
// lies within that radius.
void center_feature_points(const MeshGraph& graph, const FeatureOptions& options, const std::vector<double>& f1,
                           const std::vector<double>& f2, const GeodesicOptions& near, GeodesicSolver& solver,
                           FeaturePoints& out) {
  std::vector<Index> tips = tips_from_center(graph, options, f1, f2, solver, out);
  tips.insert(tips.begin(), {out.source1, out.source2});
  std::vector<double> to_features(f1.size(), std::numeric_limits<double>::infinity());
  // A maximum of f_c far from every extremum of f1 and f2 is where the
  // fronts from the centre meet around the bulk (its antipode), not a tip.
  std::vector<Index> extrema = out.extrema1;
  extrema.insert(extrema.end(), out.extrema2.begin(), out.extrema2.end());
  const std::vector<double> to_extrema = solver.run(extrema, near).distance;
  for (const Index v : tips) {
    const bool end = v == out.source1 || v == out.source2;
    if (at(to_features, v) <= near.radius || (!end && !(at(to_extrema, v) <= near.radius))) continue;
    take_feature_point(v, near, solver, out, to_features);
  }
}

// FeatureRule::Average: the ends, then the maxima of the mean of
// options.average_sources geodesic functions (f1, f2 and those from the
// farthest-point samples after the ends, each the vertex farthest from the
// sources so far), the nearest source left out, persisting at least
// tip_persistence x the diameter, the largest mean first (ties: the smaller
// id), each at the centre of the tips of the mean around it (as
// FeatureSite::Tips) where no feature point lies within `near`'s radius.
// `searched`: the full passes the diameter search ran and did not keep (its
// farthest-point seeds), by source: the first sample after the ends is the
// search's first seed wherever that seed found no longer diameter, and its
// field is taken from there instead of run again.
void average_feature_points(const MeshGraph& graph, const FeatureOptions& options, const std::vector<double>& f1,
                            const std::vector<double>& f2, const GeodesicOptions& near, GeodesicSolver& solver,
                            const std::vector<SourceField>& searched, FeaturePoints& out) {
  std::vector<double> sum(out.f1.size()), to_sources(out.f1.size());
  for (std::size_t v = 0; v < sum.size(); ++v) {
    sum[v] = out.f1[v] + out.f2[v];
    to_sources[v] = std::min(out.f1[v], out.f2[v]);
  }
  for (int k = 2; k < options.average_sources; ++k) {
    const Index sample = grid_farthest(to_sources);
    const auto found =
        std::find_if(searched.begin(), searched.end(), [&](const SourceField& f) { return f.source == sample; });
    if (found == searched.end()) ++out.sample_passes;
    const std::vector<double>& distance = found != searched.end() ? found->distance : solver.run({sample}).distance;
    for (std::size_t v = 0; v < sum.size(); ++v) {
      sum[v] += distance[v];
      to_sources[v] = std::min(to_sources[v], distance[v]);
    }
  }
  // The nearest source left out: a tip that holds a source persists as
  // much as one that does not.
  for (std::size_t v = 0; v < sum.size(); ++v) sum[v] = (sum[v] - to_sources[v]) / (options.average_sources - 1);
  std::vector<double> mean = snapped(std::move(sum), kTieGrid * out.diameter);
  // The ends above every other vertex: a maximum persists until the mean
  // reaches a higher one or an end, so that the global maximum of a round
  // shape, where no protrusion stands out, is not a tip.
  const double top = *std::max_element(mean.begin(), mean.end()) + 1.0;
  mean[static_cast<std::size_t>(out.source1)] = mean[static_cast<std::size_t>(out.source2)] = top;
  std::vector<Index> tips = persistent_maxima(graph, mean, options.tip_persistence, out);
  sort_largest_first(tips, mean);
  const std::vector<Index> site_tips = persistent_maxima(graph, mean, kSiteTipPersistence, out);  // by id
  std::vector<double> to_features(out.f1.size(), std::numeric_limits<double>::infinity());
  take_feature_point(out.source1, near, solver, out, to_features);
  take_feature_point(out.source2, near, solver, out, to_features);
  const double unit = kTieGrid * out.diameter;
  for (const Index v : tips) {
    if (at(to_features, v) <= near.radius) continue;
    const Index site = tips_centre(solver, v, site_tips, kSiteTipRadius * near.radius, 1000.0 * unit, f1, f2);
    if (!(at(to_features, site) <= near.radius)) take_feature_point(site, near, solver, out, to_features);
  }
}

}  // namespace

const char* feature_rule_name(FeatureRule rule) { return kFeatureRuleNames.name(rule); }

FeatureRule parse_feature_rule(const std::string& name) { return kFeatureRuleNames.parse(name); }

const char* diameter_start_name(DiameterStart start) { return kDiameterStartNames.name(start); }

DiameterStart parse_diameter_start(const std::string& name) { return kDiameterStartNames.parse(name); }

const char* feature_site_name(FeatureSite site) { return kFeatureSiteNames.name(site); }

FeatureSite parse_feature_site(const std::string& name) { return kFeatureSiteNames.parse(name); }

Index farthest_from_centroid(const Mesh& mesh) {
  const Index n = mesh.num_vertices();
  if (n == 0) throw InvalidArgument("farthest_from_centroid: empty mesh");
  Vec3 centroid = Vec3::Zero();
  double area = 0.0;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const double a = triangle_area(mesh, t);
    for (int k = 0; k < 3; ++k) centroid += (a / 3.0) * mesh.vertices.row(mesh.triangles(t, k)).transpose();
    area += a;
  }
  centroid = area > 0.0 ? Vec3(centroid / area) : Vec3(mesh.vertices.colwise().mean().transpose());
  std::vector<double> distance(static_cast<std::size_t>(n));
  for (Index v = 0; v < n; ++v)
    distance[static_cast<std::size_t>(v)] = (mesh.vertices.row(v).transpose() - centroid).norm();
  return grid_farthest(distance);
}

FeaturePoints extract_feature_points(const Mesh& mesh, const MeshGraph& graph, const FeatureOptions& options) {
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(graph, options.geodesic);
  return extract_feature_points(mesh, graph, options, *solver);
}

FeaturePoints extract_feature_points(const Mesh& mesh, const MeshGraph& graph, const FeatureOptions& options,
                                     GeodesicSolver& solver) {
  const Index n = graph.num_vertices();
  if (n == 0) throw InvalidArgument("extract_feature_points: empty mesh");
  if (mesh.num_vertices() != n)
    throw InvalidArgument("extract_feature_points: the mesh has " + std::to_string(mesh.num_vertices()) +
                          " vertices and its graph " + std::to_string(n));
  if (options.start_vertex < 0 || options.start_vertex >= n)
    throw InvalidArgument("extract_feature_points: start vertex " + std::to_string(options.start_vertex) +
                          " out of range [0, " + std::to_string(n) + ")");
  if (!(options.epsilon > 0.0 && options.epsilon <= 1.0))
    throw InvalidArgument("extract_feature_points: epsilon must lie in (0, 1], got " + std::to_string(options.epsilon));
  if (!(options.min_persistence >= 0.0 && options.min_persistence <= 1.0))
    throw InvalidArgument("extract_feature_points: min_persistence must lie in [0, 1], got " +
                          std::to_string(options.min_persistence));
  if (!(options.tip_persistence >= 0.0 && options.tip_persistence <= 1.0))
    throw InvalidArgument("extract_feature_points: tip_persistence must lie in [0, 1], got " +
                          std::to_string(options.tip_persistence));
  if (options.average_sources < 3)
    throw InvalidArgument("extract_feature_points: average_sources must be at least 3, got " +
                          std::to_string(options.average_sources));
  if (!(options.protrusion_persistence >= 0.0 && options.protrusion_persistence <= 1.0))
    throw InvalidArgument("extract_feature_points: protrusion_persistence must lie in [0, 1], got " +
                          std::to_string(options.protrusion_persistence));
  if (&solver.graph() != &graph || solver.method() != options.geodesic)
    throw InvalidArgument(std::string("extract_feature_points: the solver must run ") +
                          geodesic_name(options.geodesic) + " on the mesh graph analysed");

  FeaturePoints out;
  out.geodesic = options.geodesic;
  DiameterEnds ends;
  std::vector<SourceField> searched;  // the seeds' passes, for FeatureRule::Average
  if (options.start == DiameterStart::Vertex && options.geodesic == Geodesic::Dijkstra) {
    ends = search_diameter_ends(solver, options, options.max_extra_sweeps, true);
  } else {
    // v_s1 is the vertex farthest from the centroid (DiameterStart::Centroid)
    // or the end of a Dijkstra search from vertex 0 and from
    // options.start_vertex, v_r (DiameterStart::Vertex); the sweep then runs
    // in the chosen metric, with ties on the grid of the extrema below, so
    // that the ends are extrema of f1 and f2 as they classify them. The farthest-point seeds are tried in
    // that metric too: a seed's own pass says whether it leads to a longer
    // diameter, and only then is the sweep run from it.
    Index start = kInvalidIndex;
    int passes = 0;
    if (options.start == DiameterStart::Centroid) {
      start = farthest_from_centroid(mesh);
    } else {  // the search's fields are freed before the sweep
      DijkstraSolver search(graph);
      FeatureOptions first = options;
      first.extra_seeds = 0;
      const DiameterEnds found = search_diameter_ends(search, first, 0, false);
      start = found.s1;
      passes = found.passes;
    }
    const int budget = options.max_search_passes > 0 ? options.max_search_passes : std::numeric_limits<int>::max();
    const auto extras_within = [&](int reserved) {  // extra sweeps that leave `reserved` passes of the budget
      return std::max(0, std::min(budget - passes - reserved, options.max_extra_sweeps));
    };
    ends = find_diameter_ends(solver, start, extras_within(2), {true, true});
    passes += ends.passes;
    std::vector<double> to_ends;
    add_ends(to_ends, ends);
    for (int k = 0; k < options.extra_seeds && passes + 2 <= budget; ++k) {
      const Index seed = grid_farthest(to_ends);
      DiameterEnds other = find_diameter_ends(solver, seed, 0, {true, true, Keep::Length});
      passes += other.passes;
      add_ends(to_ends, other);
      // Longer by more than the grid: a similar copy, whose lengths differ
      // by rounding only, makes the same choice.
      const double unit = kTieGrid * ends.length();
      if (!(std::round(other.length() / unit) > std::round(ends.length() / unit))) {
        if (options.rule == FeatureRule::Average) searched.push_back({seed, std::move(other.f1)});
        continue;
      }
      // The sweep from the seed goes on from its first pass, already run.
      passes += complete_sweep(solver, other, extras_within(1), true);
      ends = std::move(other);
      add_ends(to_ends, ends);
    }
    ends.passes = passes;
  }
  out.sweeps = ends.passes;
  const Index s1 = ends.s1, s2 = ends.s2;
  out.source1 = s1;
  out.source2 = s2;
  out.diameter = ends.f1[static_cast<std::size_t>(s2)];
  // From here on, distances are counted in units of kTieGrid x diameter and
  // rounded to whole units: distances that differ by less are ties, broken by
  // vertex id, so that a rotated, moved or scaled copy of the mesh, whose
  // distances differ from these by rounding only, breaks every tie the same
  // way and keeps its feature points (the invariance of sections 4.1.1 and 5.3; a
  // symmetric shape has many such ties). Sums of whole units are exact.
  const double unit = kTieGrid * out.diameter;
  const std::vector<double> f1 = snapped(ends.f1, unit), f2 = snapped(ends.f2, unit);
  out.f1 = std::move(ends.f1);
  out.f2 = std::move(ends.f2);

  // Eq. (5): E1, E2 are the local extrema (figure 3 classification), those
  // that persist at least min_persistence x diameter when it is set.
  const auto extrema = [&](const std::vector<double>& f) {
    return options.min_persistence > 0.0 ? persistent_extrema(graph, f, std::round(options.min_persistence / kTieGrid))
                                         : local_extrema(graph, f);
  };
  out.extrema1 = extrema(f1);
  out.extrema2 = extrema(f2);

  // Eq. (6): v belongs to F when an extremum of f1 and one of f2 lie within
  // epsilon of it, and no feature point already taken lies within epsilon.
  const double radius = options.epsilon * out.diameter, radius_units = std::round(options.epsilon / kTieGrid);
  GeodesicOptions near{radius};
  near.separate_sources = true;  // the extrema are points
  if (options.rule == FeatureRule::Average) {
    average_feature_points(graph, options, f1, f2, near, solver, searched, out);
    return out;
  }
  if (options.rule == FeatureRule::Center) {
    center_feature_points(graph, options, f1, f2, near, solver, out);
    if (options.protrusion_persistence > 0.0) add_protrusion_tips(graph, options, f1, f2, solver, out);
    return out;
  }
  // The distance to the nearest extremum of each function, and which it is.
  std::vector<double> to_e1, to_e2;
  std::vector<Index> nearest_e1, nearest_e2;
  const auto reach = [&](const std::vector<Index>& sources, std::vector<double>& to, std::vector<Index>& nearest) {
    const DistanceField& field = solver.run(sources, near);
    to = snapped(field.distance, unit);
    nearest = field.nearest_source;
  };
  reach(out.extrema1, to_e1, nearest_e1);
  reach(out.extrema2, to_e2, nearest_e2);
  std::vector<Index> candidates;
  std::set_union(out.extrema1.begin(), out.extrema1.end(), out.extrema2.begin(), out.extrema2.end(),
                 std::back_inserter(candidates));
  candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                  [&](Index v) {
                                    return !(at(to_e1, v) < radius_units && at(to_e2, v) < radius_units);
                                  }),
                   candidates.end());
  if (options.rule == FeatureRule::Confirmed) {
    // Only where one of the centre's tips lies within epsilon (the ends of
    // the diameter are kept): a small protrusion that this pair of ends
    // makes an extremum of both functions, and another pair would not, is
    // not a tip from the centre, which the pose does not move off the bulk.
    const std::vector<Index> tips = tips_from_center(graph, options, f1, f2, solver, out);
    std::vector<double> to_tips(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
    if (!tips.empty()) to_tips = snapped(solver.run(tips, near).distance, unit);
    candidates.erase(std::remove_if(candidates.begin(), candidates.end(),
                                    [&](Index v) { return v != s1 && v != s2 && !(at(to_tips, v) < radius_units); }),
                     candidates.end());
  }
  // Greedy order: extrema of both functions first (gap 0), then the closest
  // pairs; among equals the more extreme vertex (larger f1 + f2), then the id.
  std::sort(candidates.begin(), candidates.end(), [&](Index a, Index b) {
    return std::make_tuple(at(to_e1, a) + at(to_e2, a), -(at(f1, a) + at(f2, a)), a) <
           std::make_tuple(at(to_e1, b) + at(to_e2, b), -(at(f1, b) + at(f2, b)), b);
  });
  std::vector<double> to_features(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  const auto partner = [&](const std::vector<Index>& of, const std::vector<Index>& nearest, Index v) {
    return of[static_cast<std::size_t>(nearest[static_cast<std::size_t>(v)])];
  };
  std::vector<Index> site_tips;  // FeatureSite::Tips
  if (options.site == FeatureSite::Tips) {
    const double threshold = std::round(kSiteTipPersistence / kTieGrid);
    const std::vector<Index> tips1 = persistent_extrema(graph, f1, threshold),
                             tips2 = persistent_extrema(graph, f2, threshold);
    std::set_union(tips1.begin(), tips1.end(), tips2.begin(), tips2.end(), std::back_inserter(site_tips));
  }
  for (const Index v : candidates) {
    if (at(to_features, v) <= radius) continue;
    Index site = v;
    if (options.site != FeatureSite::Extremum) {
      // v is one of the pair (its own nearest extremum); d(a, b) is at most
      // d(a, v) + d(v, b), plus the grid's rounding.
      const Index a = partner(out.extrema1, nearest_e1, v), b = partner(out.extrema2, nearest_e2, v);
      if (a != b) site = geodesic_midpoint(solver, a, b, (at(to_e1, v) + at(to_e2, v) + 2) * unit, unit, f1, f2, v);
      if (options.site == FeatureSite::Tips && site != s1 && site != s2)
        site = tips_centre(solver, site, site_tips, kSiteTipRadius * radius, 1000.0 * unit, f1, f2);
      if (at(to_features, site) <= radius) continue;
    }
    take_feature_point(site, near, solver, out, to_features);
  }
  if (options.protrusion_persistence > 0.0) add_protrusion_tips(graph, options, f1, f2, solver, out);
  return out;
}

}  // namespace reebkit
