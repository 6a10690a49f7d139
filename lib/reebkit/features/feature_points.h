// Feature points: vertices at the extremities of prominent components,
// found as the relaxed intersection of the local extrema of two geodesic
// functions (Tierny et al. 2006, section 4.1.2, Definition 5, eqs. 1-6).
#pragma once

#include "reebkit/core/mesh.h"
#include "reebkit/geodesic/geodesic_solver.h"
#include "reebkit/mesh/mesh_graph.h"

#include <string>
#include <vector>

namespace reebkit {

/// Where the feature point of a pair of extrema that eq. (6) joins lies.
enum class FeatureSite {
  /// On the candidate extremum itself (of f1 or of f2, the one the greedy
  /// order of eq. (6) takes): reebkit's rule before layout 10.
  Extremum,
  /// Halfway between the pair: the extremum of f1 and the extremum of f2
  /// nearest the candidate. On a round tip (a stubby arm, an ear) the two
  /// fall apart and the greedy order takes one or the other as the sampling
  /// decides; their midpoint moves only as much as each of them does.
  Midpoint,
  /// At the centre of the tips around the pair (the default since layout
  /// 15): the vertex within epsilon / 2 of the midpoint nearest, by the sum
  /// of squared geodesic distances, to the extrema of f1 and f2 there that
  /// persist at least 0.01 x the diameter (the fingertips of a hand, the
  /// toes of a paw). Which of several nearly tied tips is the farthest from
  /// the ends changes with the pose and the sampling, and the extrema and
  /// their midpoint jump with it from finger to finger; the set of tips,
  /// and its centre, stay. The midpoint where fewer than two tips lie
  /// around it; the diameter ends stay on themselves.
  Tips,
};

/// How the feature points are chosen from the geodesic functions.
enum class FeatureRule {
  /// Eq. (6): the relaxed intersection of the extrema of f1 and f2, the
  /// functions from the diameter ends. Which small protrusions (an ear, a
  /// jaw) are extrema of both depends on where the two ends lie, and on an
  /// articulated shape with several nearly tied pairs of ends the pose
  /// decides which pair is the diameter.
  Intersection,
  /// The tips seen from the centre: the diameter ends, then the local maxima
  /// of f_c, the distance from the centre of the diameter (the vertex of
  /// smallest max(f1, f2)), whose persistence is at least
  /// FeatureOptions::tip_persistence x diameter and which lie within epsilon
  /// of an extremum of f1 or of f2 (not necessarily both, as eq. 6 asks),
  /// farthest first, epsilon apart. The centre lies on the bulk of the shape
  /// whichever pair is the diameter, and from there the tip of every
  /// protrusion longer than the threshold is a maximum; the extrema of f1 or
  /// f2 rule out the maxima where the fronts from the centre meet around the
  /// bulk. One full pass more than eq. (6) (f_c). Not the default: it holds
  /// the graphs of more poses of articulated animals, and fewer feature
  /// points under resampling (docs/results.md, "The tips seen from the
  /// centre").
  Center,
  /// Eq. (6) confirmed by the centre: the points of eq. (6), each kept only
  /// where one of the tips seen from the centre (as under Center, without
  /// the test against f1 and f2) lies within epsilon; the diameter ends are
  /// always kept. A protrusion that one pair of ends makes an extremum of
  /// both functions, and another pair of the same articulated shape would
  /// not, is dropped unless the centre sees its tip. One full pass more than
  /// eq. (6) (f_c) and one ball from the tips.
  Confirmed,
  /// The tips of the mean geodesic distance: the diameter ends, then the
  /// local maxima of the mean of FeatureOptions::average_sources geodesic
  /// functions (f1, f2 and those from farthest-point samples after the ends),
  /// the nearest source left out at each vertex, that persist at least
  /// tip_persistence x diameter before the mean reaches a higher maximum or
  /// a diameter end, the largest mean first, epsilon apart, each at the
  /// centre of the mean's tips around it (as FeatureSite::Tips). Going out
  /// along a protrusion of length L raises the distance from every source
  /// outside it, so its tip persists about L in the mean whichever way it
  /// points, where eq. (6) sees it only when it points away from both ends.
  /// The mean geodesic distance as a pose-invariant function with its maxima
  /// at the tips of protrusions: M. Hilaga et al., SIGGRAPH 2001; E. Zhang
  /// et al., ACM TOG 2005. average_sources - 2 full passes more than eq. (6).
  /// FeatureOptions::site and protrusion_persistence do not apply.
  /// Not the default: the held-out animals keep their graphs under pose, and
  /// the points move a little more under resampling (docs/results.md, "The
  /// tips of the mean geodesic distance").
  Average,
};

/// "intersection", "center", "confirmed" or "average": the names of the option --feature-rule.
const char* feature_rule_name(FeatureRule rule);
/// Inverse of feature_rule_name; throws InvalidArgument naming the accepted values.
FeatureRule parse_feature_rule(const std::string& name);

/// Where the search for the diameter ends starts.
enum class DiameterStart {
  /// Eq. (2) from v_r = FeatureOptions::start_vertex (vertex 0 by default):
  /// a pass from it takes v_s1 farthest from it (reebkit's rule before
  /// layout 11). Vertex 0 lies wherever the file put it: the same surface
  /// numbered otherwise can end on another pair of nearly tied ends.
  Vertex,
  /// v_s1 = the vertex farthest from the area centroid of the surface
  /// (farthest_from_centroid): the same vertex however the mesh is numbered,
  /// moved or scaled, and no pass to find it.
  Centroid,
};

/// "vertex" or "centroid": the names of the option --diameter-start.
const char* diameter_start_name(DiameterStart start);
/// Inverse of diameter_start_name; throws InvalidArgument naming the accepted values.
DiameterStart parse_diameter_start(const std::string& name);

/// "extremum", "midpoint" or "tips": the names of the option --feature-site.
const char* feature_site_name(FeatureSite site);
/// Inverse of feature_site_name; throws InvalidArgument naming the accepted values.
FeatureSite parse_feature_site(const std::string& name);

struct FeatureOptions {
  /// epsilon of eq. (6): two extrema closer than epsilon (normalized geodesic
  /// distance, i.e. a fraction of `diameter`) are "the same place", and no
  /// two feature points lie closer. The paper's 0.05 is the scale of a toe:
  /// on a paw, a hand or a head the largest extrema of f1 and f2 fall on
  /// different toes, fingers, ears or lips, which the pose decides, so that
  /// a limb gets no point, one or several. 0.15 is the scale of a limb: one
  /// point per prominent component, the same count across poses far more
  /// often (docs/results.md, "Feature points at the scale of a limb").
  double epsilon = 0.15;
  /// Where the search for the diameter ends starts. Eqs. (2)-(4) take v_s1
  /// farthest from v_r and v_s2 farthest from v_s1; reebkit repeats that
  /// double sweep until the pair is mutually farthest, then tries
  /// `extra_seeds` more seeds, keeping the longest pair. Centroid (the
  /// default since layout 11) starts at the vertex farthest from the area
  /// centroid as v_s1, so that the graph does not depend on the numbering
  /// (docs/results.md, "A diameter search that does not depend on the
  /// numbering").
  DiameterStart start = DiameterStart::Centroid;
  /// v_r of eq. (2) under DiameterStart::Vertex: the search runs from vertex
  /// 0 and from v_r, keeping the longest pair (ties: smaller vertex ids), so
  /// v_r changes the result only where it leads to a longer diameter.
  Index start_vertex = 0;
  /// At most this many extra passes per sweep (v_s1 <- v_s2, v_s2 <- the
  /// vertex farthest from it). 0 = the paper's single double sweep. Only a
  /// mutually farthest pair is sure to be a pair of feature points (v_s1 an
  /// extremum of f2, v_s2 of f1); on a round rim (SHREC07 cups) one extra
  /// pass is not always enough, so the default allows three.
  int max_extra_sweeps = 3;
  /// Further sweeps from farthest-point seeds (the vertex farthest from the
  /// ends found so far), to find the true diameter more often. Under
  /// FastMarching a seed is tried in that metric after the first sweep: one
  /// pass from it, and the sweep from it only where that pass finds a longer
  /// diameter (docs/results.md, "Farthest-point seeds in the chosen metric").
  int extra_seeds = 1;
  /// At most this many full passes for v_s1, v_s2, f1 and f2 together (0: no
  /// limit): the extra sweeps of the first sweep stop two passes short of it,
  /// and a farthest-point seed is tried only while two passes remain (its own
  /// and the pass from its far end), its extra sweeps within what is left;
  /// the first double sweep always runs. Not applied under Dijkstra with
  /// DiameterStart::Vertex (layout 10's search). A bound on the time of a
  /// large mesh; a cut sweep can leave ends that are not mutually farthest.
  /// 4 since layout 16 (no limit before): the robustness suite and the pose
  /// benchmark measure no difference that a redraw of the meshes could not
  /// undo, and the pass count, hence the time, is bounded (docs/results.md,
  /// "A budget of search passes").
  int max_search_passes = 4;
  /// How the geodesic distances of the step are computed: f1, f2 and the
  /// epsilon balls (analyze_mesh uses the same method for f_q and the
  /// attributes). Dijkstra follows mesh edges, whose zig-zag error
  /// oscillates at the scale of the sampling and moves and adds extrema on a
  /// resampled or re-posed mesh; FastMarching (the default) crosses
  /// triangles and converges to the surface's distance (results/robustness/
  /// report.md). Under FastMarching v_s1 comes from one Dijkstra pass from
  /// v_r (eq. 2) and starts a sweep in the chosen metric: f1 from v_s1, v_s2
  /// farthest from v_s1 in it (eq. 4), f2 from v_s2, and up to
  /// max_extra_sweeps more until the two are mutually farthest; then the
  /// extra_seeds, in the same metric.
  Geodesic geodesic = Geodesic::FastMarching;
  /// Extrema of f1 and f2 whose topological persistence (features/
  /// persistence.h: how far f must change around one before it merges into a
  /// more extreme one) is below min_persistence x diameter are dropped from
  /// E1 and E2 before the relaxed intersection; 0 = the paper's rule, every
  /// local extremum. Against the shallow extrema that a resampling adds
  /// along the ridges where two geodesic fronts meet; a protrusion shorter
  /// than the threshold (fingers, claws) is dropped with them. The default
  /// 0.03 goes with epsilon (docs/results.md, "Feature points at the scale
  /// of a limb"; 0.01 at the paper's epsilon: "Sampling stability"). In [0, 1].
  double min_persistence = 0.03;
  /// An extension of eq. (6), off at 0: an extremum of f1 or f2 persisting
  /// at least protrusion_persistence x diameter (a limb, not a toe) that
  /// lies more than 2 epsilon from every feature point is made one too. On
  /// a paw or a hand the largest maxima of f1 and f2 can fall on different
  /// toes, more than epsilon apart, and the relaxed intersection then keeps
  /// no point for the whole limb. In [0, 1].
  double protrusion_persistence = 0.0;
  /// Where a feature point of eq. (6) lies: eq. (6) asks only that an
  /// extremum of f1 and one of f2 lie within epsilon of it. Midpoint
  /// (layouts 10-14) keeps the points of round tips in place under
  /// resampling (docs/results.md, "Feature points halfway between their two
  /// extrema"); Tips (the default since layout 15) also those of tips that
  /// split into nearly tied fingers or toes under pose (docs/results.md,
  /// "Feature points at the centre of their tips").
  FeatureSite site = FeatureSite::Tips;
  /// Which rule chooses the feature points: eq. (6) (Intersection, the
  /// paper's), the tips seen from the centre (Center), eq. (6) confirmed
  /// by them (Confirmed) or the tips of the mean geodesic distance (Average).
  FeatureRule rule = FeatureRule::Intersection;
  /// FeatureRule::Center and Confirmed: the persistence of a maximum of f_c,
  /// as a share of the diameter, that makes it a tip (a protrusion at least
  /// that long beyond where it joins the rest); FeatureRule::Average: of a
  /// maximum of the mean. Unused by eq. (6). In [0, 1].
  double tip_persistence = 0.08;
  /// FeatureRule::Average: the geodesic functions averaged, the two ends'
  /// included (at least 3). A sample that falls on a round bulk opposite an
  /// earlier one makes the earlier one's place a maximum of the mean: with
  /// 4 the capsule of a two-armed star gets a third point (with 3 and 8 it
  /// does not).
  int average_sources = 3;
};

/// Geodesic distances closer than this fraction of the diameter count as
/// equal in extract_feature_points (ties, broken by vertex id).
inline constexpr double kTieGrid = 1e-9;

struct FeaturePoints {
  /// F in selection order. Eq. (6): pairs of coinciding extrema first, then
  /// by how far apart the E1 and E2 extrema of a candidate lie; each at its
  /// FeatureOptions::site. FeatureRule::Center: source1, source2, then the
  /// tips farthest from the centre first; FeatureRule::Average: source1,
  /// source2, then the largest mean first.
  std::vector<Index> vertices;
  Index source1 = kInvalidIndex;  ///< v_s1, origin of f1 (eq. 2)
  Index source2 = kInvalidIndex;  ///< v_s2, origin of f2 (eq. 4)
  /// Geodesic distance d(v_s1, v_s2) = max f1, the approximate geodesic
  /// diameter: every normalized distance delta of the paper is d / diameter.
  double diameter = 0.0;
  /// E1: local minima and maxima of f1 (with persistence >= min_persistence x diameter)
  std::vector<Index> extrema1;
  /// E2: local minima and maxima of f2 (with persistence >= min_persistence x diameter)
  std::vector<Index> extrema2;
  /// FeatureRule::Center and Confirmed: the centre of the diameter, source
  /// of f_c; kInvalidIndex under eq. (6).
  Index center = kInvalidIndex;
  int sweeps = 0;  ///< full geodesic passes spent finding v_s1, v_s2, f1 and f2
  /// FeatureRule::Average: full passes from the farthest-point samples (a
  /// sample where the search already ran a pass, its seed, costs none).
  int sample_passes = 0;
  /// The method of f1, f2 and the epsilon balls (FeatureOptions::geodesic).
  Geodesic geodesic = Geodesic::FastMarching;
  /// f1 and f2 themselves (#V each, distances from source1 and from
  /// source2), handed on so that later steps need not compute them again.
  std::vector<double> f1, f2;
};

/// The vertex of `mesh` farthest from its area centroid (the mean of the
/// triangle centroids weighted by area; of the vertices, for a mesh without
/// area), Euclidean distances compared on the grid kTieGrid x the largest,
/// ties to the larger id: the start of DiameterStart::Centroid.
Index farthest_from_centroid(const Mesh& mesh);

/// Extracts the feature points of a connected mesh, whose graph is `graph`
/// (build_mesh_graph(mesh)).
/// \pre the graph is connected (one component) and non-empty; throws
///      InvalidArgument otherwise.
FeaturePoints extract_feature_points(const Mesh& mesh, const MeshGraph& graph, const FeatureOptions& options = {});

/// The same with a solver of method options.geodesic on `graph`, which the
/// caller reuses for the steps that follow (f_q). Throws InvalidArgument for
/// a solver of another method or graph.
FeaturePoints extract_feature_points(const Mesh& mesh, const MeshGraph& graph, const FeatureOptions& options,
                                     GeodesicSolver& solver);

}  // namespace reebkit
