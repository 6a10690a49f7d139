#include "reebkit/matching/graph_matching.h"

#include "reebkit/core/error.h"
#include "reebkit/matching/assignment.h"
#include "reebkit/matching/edge_consistency.h"
#include "reebkit/matching/matching_options.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace reebkit {

namespace {

using F = MatchableGraph::Feature;

void require_ok(const GraphRecord& entry) {
  if (!entry.ok) throw InvalidArgument("match_graphs: entry '" + entry.name + "' has no graph (" + entry.error + ")");
}

/// The weights of the node cost, per feature column (NodeCost::l1 for the
/// L1 block), from MatchingOptions once per match.
struct NodeCost {
  std::array<double, F::kL1Block> l1{};  // zero on the padding
  double structure = 0.0;                // weight of each of degree, start type, end type
  explicit NodeCost(const MatchingOptions& o) {
    for (const int k : {F::kSqrtArea, F::kFqMin, F::kFqMax, F::kExtent, F::kRadius})
      l1[at(k)] = o.attribute_weight / 5.0;
    l1[F::kSqrtNeighbourArea] = o.structure_weight / 4.0;
    for (int k = 0; k < kRadiusProfileLevels; ++k) l1[at(F::kProfile + k)] = o.profile_weight / kRadiusProfileLevels;
    for (int k = 0; k < kShapeBins; ++k) l1[at(F::kShape + k)] = o.shape_weight / 2.0;
    for (int k = 0; k < kShapeBins; ++k) l1[at(F::kGeodesicShape + k)] = o.geodesic_shape_weight / 2.0;
    for (int k = 0; k < kRegionSpectrumLength; ++k)
      l1[at(F::kSpectrum + k)] = o.spectrum_weight / kRegionSpectrumLength;
    structure = o.structure_weight / 4.0;
  }
  static std::size_t at(int k) { return static_cast<std::size_t>(k); }
};

/// a + s + p + h + h_g + r of the cost model at (i, j), weighted: the
/// L1 block in four independent sums (a fixed order; the compiler may run
/// them side by side), then the degree and type terms of s.
double node_dissimilarity(const double* x, const double* y, const NodeCost& c) {
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  for (int k = 0; k < F::kL1Block; k += 4)
    for (int l = 0; l < 4; ++l) sum[l] += c.l1[NodeCost::at(k + l)] * std::abs(x[k + l] - y[k + l]);
  const double max_degree = std::max({x[F::kDegree], y[F::kDegree], 1.0});
  const double structure = std::abs(x[F::kDegree] - y[F::kDegree]) / max_degree +
                           (x[F::kStartType] != y[F::kStartType] ? 1.0 : 0.0) +
                           (x[F::kEndType] != y[F::kEndType] ? 1.0 : 0.0);
  return ((sum[0] + sum[1]) + (sum[2] + sum[3])) + c.structure * structure;
}

/// w_i of the cost model.
double node_weight(const MatchableGraph& g, std::size_t i, const MatchingOptions& o) {
  return g.relative_area[i] + o.min_node_weight;
}

/// The cost of matching nodes of weights wi and wj at dissimilarity d
/// (a + s + e, weighted).
double pair_cost(double wi, double wj, double d) { return 0.5 * (wi + wj) * d; }

/// The cost of leaving a node of weight w unmatched.
double unmatched_node_cost(double w, const MatchingOptions& o) { return o.unmatched_cost * w; }

/// Buffers reused by every match on a thread.
struct Workspace {
  std::vector<double> dissimilarity;  // n x m
  std::vector<double> cost;           // n x m
  std::vector<std::int32_t> assignment, forward, backward, previous;
  AssignmentSolver solver;
  EdgeInconsistencyRows edges;
};

/// The calling thread's buffers (match_graphs and match_distance_up_to).
Workspace& thread_workspace() {
  thread_local Workspace workspace;
  return workspace;
}

/// Whether a should give the rows of the assignment: the graph with fewer
/// nodes, ties broken by the feature arrays and then the adjacency, so that
/// match(a, b) and match(b, a) solve the same problem (exact symmetry).
bool rows_first(const MatchableGraph& a, const MatchableGraph& b) {
  if (a.num_nodes != b.num_nodes) return a.num_nodes < b.num_nodes;
  if (a.features != b.features) return a.features < b.features;
  return a.adjacent <= b.adjacent;
}

/// The match with a's nodes as rows. \pre a.num_nodes <= b.num_nodes.
/// Padded problem reduced to rows: matching i to j costs
/// pair(i, j) - delete(i) - insert(j), and each row i has its own "delete"
/// column of cost 0 (AssignmentSolver::solve_or_leave); the optimum plus the
/// sum of all deletion and insertion costs is the optimum of the
/// (n + m) x (n + m) padded matrix. Returns the distance, or a lower bound
/// of it above `limit` as soon as the first solve gives one (w.forward is
/// then not final).
double match_rows(const MatchableGraph& a, const MatchableGraph& b, const MatchingOptions& o, Workspace& w,
                  double limit = std::numeric_limits<double>::infinity()) {
  const std::int32_t n = a.num_nodes, m = b.num_nodes;
  const auto un = static_cast<std::size_t>(n), um = static_cast<std::size_t>(m);
  const auto weight = [&](const MatchableGraph& g, std::size_t i) { return node_weight(g, i, o); };
  double total_weight = 0.0;
  for (std::size_t i = 0; i < un; ++i) total_weight += weight(a, i);
  for (std::size_t j = 0; j < um; ++j) total_weight += weight(b, j);

  w.dissimilarity.resize(un * um);
  const NodeCost node_cost(o);
  for (std::size_t i = 0; i < un; ++i) {
    const double* x = &a.features[i * MatchableGraph::kFeatureCount];
    for (std::size_t j = 0; j < um; ++j)
      w.dissimilarity[i * um + j] = node_dissimilarity(x, &b.features[j * MatchableGraph::kFeatureCount], node_cost);
  }
  w.cost.resize(un * um);
  w.forward.assign(un, -1);
  w.backward.assign(um, -1);
  const int rounds = std::max(0, o.refine_rounds);
  for (int round = 0; round <= rounds; ++round) {
    if (round > 0) w.edges.reset(a, b, w.forward, w.backward);
    for (std::size_t i = 0; i < un; ++i) {
      const double wi = weight(a, i);
      double* row = &w.cost[i * um];
      const double* e = round > 0 ? w.edges.row(static_cast<std::int32_t>(i)).data() : nullptr;
      for (std::size_t j = 0; j < um; ++j) {
        double d = w.dissimilarity[i * um + j];
        if (round > 0) d += o.edge_weight * e[j];
        const double wj = weight(b, j);
        row[j] = pair_cost(wi, wj, d) - o.unmatched_cost * (wi + wj);
      }
    }
    w.solver.solve_or_leave(w.cost.data(), n, m, w.assignment);
    w.previous.swap(w.forward);
    w.forward.assign(un, -1);
    w.backward.assign(um, -1);
    for (std::size_t i = 0; i < un; ++i) {
      const std::int32_t j = w.assignment[i];
      if (j >= 0) w.forward[i] = j, w.backward[static_cast<std::size_t>(j)] = static_cast<std::int32_t>(i);
    }
    if (round > 0 && w.forward == w.previous) break;
    if (round == 0 && round < rounds && limit < std::numeric_limits<double>::infinity() && total_weight > 0.0) {
      // The node-only cost of this correspondence, optimal for node costs,
      // is at most that of the final one, which is at most the final cost
      // (its edge terms are >= 0, node weights being >= 0): a lower bound,
      // lowered by 1e-9 of its terms for rounding as in match_lower_bound.
      double node_only = 0.0, magnitude = 0.0;
      const auto add = [&](double term) { node_only += term, magnitude += std::abs(term); };
      for (std::size_t i = 0; i < un; ++i) {
        const std::int32_t j = w.forward[i];
        add(j < 0 ? unmatched_node_cost(weight(a, i), o)
                  : pair_cost(weight(a, i), weight(b, static_cast<std::size_t>(j)),
                              w.dissimilarity[i * um + static_cast<std::size_t>(j)]));
      }
      for (std::size_t j = 0; j < um; ++j)
        if (w.backward[j] < 0) add(unmatched_node_cost(weight(b, j), o));
      const double bound = (node_only - 1e-9 * magnitude) / total_weight;
      if (bound > limit) return bound;
    }
  }
  // The cost of the final correspondence, its edge term included, summed
  // term by term (matched pairs, then unmatched nodes) so that identical
  // graphs come out at exactly 0.
  double total = 0.0;
  for (std::size_t i = 0; i < un; ++i) {
    const std::int32_t j = w.forward[i];
    if (j < 0) {
      total += unmatched_node_cost(weight(a, i), o);
      continue;
    }
    const auto uj = static_cast<std::size_t>(j);
    double d = w.dissimilarity[i * um + uj];
    if (o.edge_weight > 0.0)
      d += o.edge_weight * edge_inconsistency(a, b, static_cast<std::int32_t>(i), j, w.forward, w.backward);
    total += pair_cost(weight(a, i), weight(b, uj), d);
  }
  for (std::size_t j = 0; j < um; ++j)
    if (w.backward[j] < 0) total += unmatched_node_cost(weight(b, j), o);
  return total_weight > 0.0 ? total / total_weight : 0.0;
}

/// Half the L1 distance of two histograms times `weight` (0 without
/// reading them when the weight is 0; exactly symmetric: |x - y| = |y - x|).
double weighted_half_l1(const std::vector<double>& x, const std::vector<double>& y, double weight) {
  if (weight == 0.0) return 0.0;
  double l1 = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) l1 += std::abs(x[k] - y[k]);
  return weight * l1 / 2.0;
}

/// g_s(A, B) of MatchingOptions: the root mean square log ratio d of the
/// first global_spectrum_eigenvalues eigenvalues, saturated as d / (d +
/// global_spectrum_scale).
double global_spectrum_term(const MatchableGraph& a, const MatchableGraph& b, const MatchingOptions& o) {
  if (o.global_spectrum_weight == 0.0) return 0.0;
  const auto n = static_cast<std::size_t>(o.global_spectrum_eigenvalues);
  double sum = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    sum += (a.global_spectrum[k] - b.global_spectrum[k]) * (a.global_spectrum[k] - b.global_spectrum[k]);
  const double d = std::sqrt(sum / static_cast<double>(n));
  return o.global_spectrum_weight * d / (d + o.global_spectrum_scale);
}

/// g_h(A, B) of MatchingOptions: the mean absolute difference d of the heat
/// kernel quantiles, saturated as d / (d + global_heat_scale).
double global_heat_term(const MatchableGraph& a, const MatchableGraph& b, const MatchingOptions& o) {
  if (o.global_heat_weight == 0.0) return 0.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < a.global_heat.size(); ++k) sum += std::abs(a.global_heat[k] - b.global_heat[k]);
  const double d = sum / static_cast<double>(a.global_heat.size());
  return o.global_heat_weight * d / (d + o.global_heat_scale);
}

/// global_shape_weight * g(A, B) + global_geodesic_weight * g_g(A, B) +
/// global_spectrum_weight * g_s(A, B) + global_heat_weight * g_h(A, B).
double global_shape_term(const MatchableGraph& a, const MatchableGraph& b, const MatchingOptions& o) {
  return weighted_half_l1(a.global_shape, b.global_shape, o.global_shape_weight) +
         weighted_half_l1(a.global_geodesic, b.global_geodesic, o.global_geodesic_weight) +
         global_spectrum_term(a, b, o) + global_heat_term(a, b, o);
}

}  // namespace

MatchableGraph make_matchable_graph(const GraphRecord& entry) {
  require_ok(entry);
  MatchableGraph g;
  g.num_nodes = entry.num_nodes();
  const auto n = static_cast<std::size_t>(g.num_nodes);
  g.relative_area.resize(n);
  g.neighbour_offset.assign(n + 1, 0);
  g.adjacent.assign(n * n, 0);
  for (std::int32_t e = 0; e < entry.num_edges(); ++e) {
    const auto u = static_cast<std::size_t>(entry.edges[2 * static_cast<std::size_t>(e)]);
    const auto v = static_cast<std::size_t>(entry.edges[2 * static_cast<std::size_t>(e) + 1]);
    ++g.neighbour_offset[u + 1];
    ++g.neighbour_offset[v + 1];
    g.adjacent[u * n + v] = g.adjacent[v * n + u] = 1;
  }
  for (std::size_t i = 0; i < n; ++i) g.neighbour_offset[i + 1] += g.neighbour_offset[i];
  g.neighbours.resize(static_cast<std::size_t>(g.neighbour_offset[n]));
  std::vector<std::int32_t> fill(g.neighbour_offset.begin(), g.neighbour_offset.end() - 1);
  for (std::int32_t e = 0; e < entry.num_edges(); ++e) {
    const std::int32_t u = entry.edges[2 * static_cast<std::size_t>(e)],
                       v = entry.edges[2 * static_cast<std::size_t>(e) + 1];
    g.neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(u)]++)] = v;
    g.neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = u;
  }
  if (entry.signature.size() != static_cast<std::size_t>(kSignatureLength))
    throw InvalidArgument("make_matchable_graph: entry '" + entry.name + "' has a signature of " +
                          std::to_string(entry.signature.size()) + " entries, not " + std::to_string(kSignatureLength));
  g.global_shape.assign(entry.signature.begin() + kSigGlobalShape, entry.signature.begin() + kSigGlobalGeodesic);
  g.global_geodesic.assign(entry.signature.begin() + kSigGlobalGeodesic, entry.signature.begin() + kSigGlobalSpectrum);
  // The signature's y = s / (1 + s) back to ln s = ln(y / (1 - y)).
  const auto unsquashed = [&](int from, int count) {
    std::vector<double> out(static_cast<std::size_t>(count));
    for (std::size_t k = 0; k < out.size(); ++k) {
      const double y = std::clamp(entry.signature[static_cast<std::size_t>(from) + k], 1e-12, 1.0 - 1e-12);
      out[k] = std::log(y / (1.0 - y));
    }
    return out;
  };
  g.global_spectrum = unsquashed(kSigGlobalSpectrum, kGlobalSpectrumLength);
  g.global_heat = unsquashed(kSigGlobalHeat, kGlobalHeatLength);
  const auto attribute = [&](std::size_t i, NodeAttribute c) {
    return entry.node_attributes[i * kNodeAttributeCount + c];
  };
  for (std::size_t i = 0; i < n; ++i) g.relative_area[i] = attribute(i, kNodeRelativeArea);
  g.features.resize(n * MatchableGraph::kFeatureCount);
  for (std::size_t i = 0; i < n; ++i) {
    double neighbour_area = 0.0;
    for (std::int32_t k = g.neighbour_offset[i]; k < g.neighbour_offset[i + 1]; ++k)
      neighbour_area += g.relative_area[static_cast<std::size_t>(g.neighbours[static_cast<std::size_t>(k)])];
    double* x = &g.features[i * MatchableGraph::kFeatureCount];
    x[F::kSqrtArea] = std::sqrt(std::max(0.0, g.relative_area[i]));
    x[F::kFqMin] = attribute(i, kNodeFqMin);
    x[F::kFqMax] = attribute(i, kNodeFqMax);
    x[F::kExtent] = attribute(i, kNodeGeodesicExtent);
    x[F::kRadius] = attribute(i, kNodeMeanRadius);
    x[F::kSqrtNeighbourArea] = std::sqrt(neighbour_area);
    x[F::kDegree] = static_cast<double>(g.neighbour_offset[i + 1] - g.neighbour_offset[i]);
    x[F::kStartType] = attribute(i, kNodeStartType);
    x[F::kEndType] = attribute(i, kNodeEndType);
    for (int k = 0; k < kRadiusProfileLevels; ++k)
      x[F::kProfile + k] = attribute(i, NodeAttribute(kNodeRadiusProfile + k));
    for (int k = 0; k < kShapeBins; ++k) {
      x[F::kShape + k] = attribute(i, NodeAttribute(kNodeShapeHistogram + k));
      x[F::kGeodesicShape + k] = attribute(i, NodeAttribute(kNodeGeodesicHistogram + k));
    }
    for (int k = 0; k < kRegionSpectrumLength; ++k)
      x[F::kSpectrum + k] = attribute(i, NodeAttribute(kNodeSpectrum + k));
  }
  return g;
}

std::vector<MatchableGraph> make_matchable_graphs(const std::vector<GraphRecord>& entries) {
  std::vector<MatchableGraph> graphs;
  graphs.reserve(entries.size());
  for (const GraphRecord& e : entries) graphs.push_back(e.ok ? make_matchable_graph(e) : MatchableGraph{});
  return graphs;
}

GraphMatch match_graphs(const MatchableGraph& a, const MatchableGraph& b, const MatchingOptions& options) {
  Workspace& workspace = thread_workspace();
  GraphMatch match;
  match.correspondence.assign(static_cast<std::size_t>(a.num_nodes), -1);
  if (rows_first(a, b)) {
    match.distance = match_rows(a, b, options, workspace);
    std::copy(workspace.forward.begin(), workspace.forward.end(), match.correspondence.begin());
  } else {
    match.distance = match_rows(b, a, options, workspace);
    for (std::size_t j = 0; j < workspace.forward.size(); ++j)
      if (workspace.forward[j] >= 0)
        match.correspondence[static_cast<std::size_t>(workspace.forward[j])] = static_cast<std::int32_t>(j);
  }
  match.distance += global_shape_term(a, b, options);
  return match;
}

// Proof sketch. A correspondence C (a partial injection of A's nodes into
// B's) costs T(C) = sum over matched (i, j) of pair(i, j) + sum over the
// unmatched i of del(i) + sum over the unmatched j of ins(j), and the
// distance is T of the final correspondence over W = W_A + W_B. Lower the
// edge term of every pair to its least value (e in [0, 1], so edge_weight *
// e >= min(0, edge_weight)): pair(i, j) >= p(i, j) as node weights are >= 0
// (min_node_weight >= 0). Then, charging each node of B its insertion and
// refunding it to the row that matches it,
//   T(C) >= sum_j ins(j) + sum_i [i matched to j ? p(i, j) - ins(j) : del(i)]
//        >= sum_j ins(j) + sum_i min(del(i), min_j p(i, j) - ins(j)),
// each row taking its cheapest option, distinct columns no longer required;
// the same by columns with the roles of A and B exchanged. The larger of the
// two holds for every C, hence for the final one. It is the row-minima bound
// of the reduced assignment problem (dual potentials u = row minima, v = 0),
// so never above the first, node-only, solve either. Floating point: the
// bound is lowered by 1e-9 of the magnitude of the terms it sums, far more
// than the rounding of either sum ((n + m) x 2^-53 relative), and divided by
// W summed as match_graphs sums it, so it stays below the computed distance
// even when the inequalities are equalities (identical graphs: bound < 0).
double match_lower_bound(const MatchableGraph& a, const MatchableGraph& b, const MatchingOptions& options) {
  if (!rows_first(a, b)) return match_lower_bound(b, a, options);  // the orientation of match_graphs
  const MatchingOptions& o = options;
  const auto un = static_cast<std::size_t>(a.num_nodes), um = static_cast<std::size_t>(b.num_nodes);
  double total_weight = 0.0;
  for (std::size_t i = 0; i < un; ++i) total_weight += node_weight(a, i, o);
  for (std::size_t j = 0; j < um; ++j) total_weight += node_weight(b, j, o);
  if (!(total_weight > 0.0)) return global_shape_term(a, b, options);  // the graphs' part is then 0
  thread_local std::vector<double> column_best, insert;
  column_best.resize(um);
  insert.resize(um);
  double inserts = 0.0, deletes = 0.0, magnitude = 0.0, by_rows = 0.0, by_columns = 0.0;
  for (std::size_t j = 0; j < um; ++j) {
    insert[j] = column_best[j] = unmatched_node_cost(node_weight(b, j, o), o);
    inserts += insert[j];
    magnitude += std::abs(insert[j]);
  }
  const double least_edge_term = std::min(0.0, o.edge_weight);
  const NodeCost node_cost(o);
  for (std::size_t i = 0; i < un; ++i) {
    const double wi = node_weight(a, i, o), del = unmatched_node_cost(wi, o);
    const double* x = &a.features[i * MatchableGraph::kFeatureCount];
    double row_best = del;
    for (std::size_t j = 0; j < um; ++j) {
      const double p =
          pair_cost(wi, node_weight(b, j, o),
                    node_dissimilarity(x, &b.features[j * MatchableGraph::kFeatureCount], node_cost) + least_edge_term);
      row_best = std::min(row_best, p - insert[j]);
      column_best[j] = std::min(column_best[j], p - del);
    }
    deletes += del;
    by_rows += row_best;
    magnitude += std::abs(del) + std::abs(row_best);
  }
  for (std::size_t j = 0; j < um; ++j) {
    by_columns += column_best[j];
    magnitude += std::abs(column_best[j]);
  }
  return (std::max(inserts + by_rows, deletes + by_columns) - 1e-9 * magnitude) / total_weight +
         global_shape_term(a, b, options);
}

double match_distance_up_to(const MatchableGraph& a, const MatchableGraph& b, double limit,
                            const MatchingOptions& options) {
  Workspace& workspace = thread_workspace();
  // The graphs' part may stop once above limit - g; the slack keeps rounding
  // from stopping it when the sum is exactly at the limit.
  const double global = global_shape_term(a, b, options);
  const double part_limit = limit - global + 1e-12 * (1.0 + std::abs(limit));
  return (rows_first(a, b) ? match_rows(a, b, options, workspace, part_limit)
                           : match_rows(b, a, options, workspace, part_limit)) +
         global;
}

GraphMatch match_graphs(const GraphRecord& a, const GraphRecord& b, const MatchingOptions& options) {
  check_matching_options(options);
  return match_graphs(make_matchable_graph(a), make_matchable_graph(b), options);
}

}  // namespace reebkit
