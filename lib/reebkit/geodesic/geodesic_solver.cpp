#include "reebkit/geodesic/geodesic_solver.h"

#include "reebkit/core/error.h"
#include "reebkit/core/named_values.h"
#include "reebkit/geodesic/dijkstra.h"
#include "reebkit/geodesic/fast_marching.h"

namespace reebkit {

namespace {
constexpr NamedValues<Geodesic, 2> kGeodesicNames{"geodesic method",
                                                  {{{Geodesic::Dijkstra, "dijkstra"},
                                                    {Geodesic::FastMarching, "fmm"}}}};
}  // namespace

const char* geodesic_name(Geodesic method) { return kGeodesicNames.name(method); }

Geodesic parse_geodesic(const std::string& name) { return kGeodesicNames.parse(name); }

GeodesicSolver::GeodesicSolver(const MeshGraph& graph) : graph_(graph) {
  const auto n = static_cast<std::size_t>(graph.num_vertices());
  field_.distance.assign(n, std::numeric_limits<double>::infinity());
  field_.nearest_source.assign(n, kInvalidIndex);
}

GeodesicSolver::RunArrays GeodesicSolver::start(const std::vector<Index>& sources, const GeodesicOptions& options,
                                                const char* who) {
  const Index n = graph_.num_vertices();
  if (field_.distance.size() != static_cast<std::size_t>(n)) {  // released before
    field_.distance.assign(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
    field_.nearest_source.assign(static_cast<std::size_t>(n), kInvalidIndex);
  } else {
    for (const Index v : touched_) {
      field_.distance[static_cast<std::size_t>(v)] = std::numeric_limits<double>::infinity();
      field_.nearest_source[static_cast<std::size_t>(v)] = kInvalidIndex;
    }
  }
  touched_.clear();
  settled_.clear();
  heap_.clear();
  field_.farthest = kInvalidIndex;
  field_.max_distance = 0.0;
  field_.reached = 0;

  const Index* labels = options.labels ? options.labels->data() : nullptr;
  if (labels && options.labels->size() != static_cast<std::size_t>(n))
    throw InvalidArgument(std::string(who) + ": " + std::to_string(options.labels->size()) + " vertex labels for " +
                          std::to_string(n) + " vertices");
  const double* bound = options.bound ? options.bound->data() : nullptr;
  if (bound && options.bound->size() != static_cast<std::size_t>(n))
    throw InvalidArgument(std::string(who) + ": a bound of " + std::to_string(options.bound->size()) +
                          " distances for " + std::to_string(n) + " vertices");
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const Index v = sources[s];
    if (v < 0 || v >= n)
      throw InvalidArgument(std::string(who) + ": source vertex " + std::to_string(v) + " out of range [0, " +
                            std::to_string(n) + ")");
    if (labels && labels[v] != options.label)
      throw InvalidArgument(std::string(who) + ": source vertex " + std::to_string(v) + " has label " +
                            std::to_string(labels[v]) + ", the search is restricted to label " +
                            std::to_string(options.label));
    if (field_.nearest_source[static_cast<std::size_t>(v)] != kInvalidIndex) continue;  // listed twice
    if (bound && !(0.0 < bound[v])) continue;  // a source the bound measured already
    improve(v, 0.0, static_cast<Index>(s));
  }
  return {labels,
          field_.distance.data(),
          field_.nearest_source.data(),
          graph_.offset.data(),
          graph_.neighbor.data(),
          graph_.length.data(),
          bound};
}

DistanceField GeodesicSolver::release() {
  DistanceField out = std::move(field_);
  field_ = DistanceField{};
  touched_.clear();
  return out;
}

std::unique_ptr<GeodesicSolver> make_geodesic_solver(const MeshGraph& graph, Geodesic method) {
  if (method == Geodesic::FastMarching) return std::make_unique<FastMarchingSolver>(graph);
  return std::make_unique<DijkstraSolver>(graph);
}

DistanceField geodesic_distances(const MeshGraph& graph, const std::vector<Index>& sources, Geodesic method,
                                 const GeodesicOptions& options) {
  const std::unique_ptr<GeodesicSolver> solver = make_geodesic_solver(graph, method);
  solver->run(sources, options);
  return solver->release();
}

}  // namespace reebkit
