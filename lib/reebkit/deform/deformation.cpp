#include "reebkit/deform/deformation.h"

#include "reebkit/core/error.h"
#include "reebkit/geodesic/dijkstra.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace reebkit {

namespace {

// |a x b| / (|a| |b|) below this (about 6 degrees) counts as parallel.
constexpr double kMinAxisSine = 0.1;

std::string node_name(Index node) { return "deform_component: node " + std::to_string(node); }

// parents[n]: the nodes whose regions hand over to n.
std::vector<std::vector<Index>> parent_lists(const ReebGraph& g) {
  std::vector<std::vector<Index>> parents(g.nodes.size());
  for (const auto& [a, b] : g.edges) parents[static_cast<std::size_t>(b)].push_back(a);
  return parents;
}

// node and every later node all of whose parents are in the component; edges
// go from earlier to later nodes, so one ascending pass settles them all.
std::vector<char> component_of(Index node, const std::vector<std::vector<Index>>& parents) {
  std::vector<char> in(parents.size(), 0);
  in[static_cast<std::size_t>(node)] = 1;
  for (std::size_t n = static_cast<std::size_t>(node) + 1; n < parents.size(); ++n)
    in[n] = !parents[n].empty() && std::all_of(parents[n].begin(), parents[n].end(),
                                               [&](Index p) { return in[static_cast<std::size_t>(p)] != 0; });
  return in;
}

// The default axis of Deformation::axis, or zero when there is none.
Vec3 default_axis(const MeshAnalysis& a, const Deformation& plan, Index root) {
  double area = 0.0;
  Vec3 barycenter = Vec3::Zero();
  for (const Index n : plan.nodes) {
    const ReebNode& node = a.reeb.nodes[static_cast<std::size_t>(n)];
    area += node.area;
    barycenter += node.area * node.barycenter;
  }
  if (!(area > 0.0)) return Vec3::Zero();
  const Vec3 d = (barycenter / area - plan.pivot).normalized();
  std::vector<Vec3> towards{a.reeb.nodes[static_cast<std::size_t>(root)].barycenter};
  if (!plan.attach_loop.empty()) towards.push_back(a.mesh.vertices.row(plan.attach_loop.front()).transpose());
  for (const Vec3& target : towards) {
    const Vec3 axis = d.cross((target - plan.pivot).normalized());
    if (axis.norm() >= kMinAxisSine) return axis.normalized();
  }
  return Vec3::Zero();
}

double smoothstep(double t) { return t * t * (3.0 - 2.0 * t); }

}  // namespace

void check_graph_node(const MeshAnalysis& analysis, Index node, const std::string& who) {
  const ReebGraph& g = analysis.reeb;
  if (g.nodes.empty() || g.vertex_node.size() != static_cast<std::size_t>(analysis.mesh.num_vertices()))
    throw InvalidArgument(who + ": the analysis of " + analysis.mesh.source +
                          " has no Reeb graph (AnalysisOptions::reeb_graph is false)");
  if (node < 0 || node >= g.num_nodes())
    throw InvalidArgument(who + ": node " + std::to_string(node) + " does not exist (the Reeb graph has " +
                          std::to_string(g.num_nodes()) + " nodes)");
}

Deformation plan_deformation(const MeshAnalysis& analysis, const DeformOptions& options) {
  const ReebGraph& g = analysis.reeb;
  const Index nv = analysis.mesh.num_vertices();
  check_graph_node(analysis, options.node, "deform_component");
  if (!(options.falloff >= 0.0 && options.falloff <= 1.0))
    throw InvalidArgument("deform_component: falloff " + std::to_string(options.falloff) + " is outside [0, 1]");
  if (!std::isfinite(options.angle_degrees) || !options.axis.allFinite())
    throw InvalidArgument("deform_component: the angle and the axis must be finite");

  const std::vector<std::vector<Index>> parents = parent_lists(g);
  const auto& node_parents = parents[static_cast<std::size_t>(options.node)];
  if (node_parents.empty())
    throw InvalidArgument(node_name(options.node) +
                          " is a root (the region around the minimum of f_q): it has no parent to pivot on");
  const std::vector<char> in = component_of(options.node, parents);

  Deformation plan;
  plan.angle_degrees = options.angle_degrees;
  for (Index n = 0; n < g.num_nodes(); ++n)
    if (in[static_cast<std::size_t>(n)]) plan.nodes.push_back(n);

  // The component's border: its vertices next to a vertex outside it; those
  // next to a parent region form the attach loop, the others are held.
  const auto inside = [&](Index v) {
    return in[static_cast<std::size_t>(g.vertex_node[static_cast<std::size_t>(v)])] != 0;
  };
  const auto in_parent = [&](Index v) {
    const Index n = g.vertex_node[static_cast<std::size_t>(v)];
    return std::find(node_parents.begin(), node_parents.end(), n) != node_parents.end();
  };
  const MeshGraph& mg = analysis.graph;
  std::vector<Index> held;
  for (Index v = 0; v < nv; ++v) {
    if (!inside(v)) continue;
    const auto first = mg.neighbor.begin() + mg.offset[v], last = mg.neighbor.begin() + mg.offset[v + 1];
    if (std::any_of(first, last, in_parent))
      plan.attach_loop.push_back(v);
    else if (!std::all_of(first, last, inside))
      held.push_back(v);
  }
  const ReebNode& node = g.nodes[static_cast<std::size_t>(options.node)];
  plan.pivot =
      node.skeleton.empty() ? Vec3(analysis.mesh.vertices.row(node.birth_vertex).transpose()) : node.skeleton.front();

  if (options.axis != Vec3::Zero()) {
    plan.axis = options.axis.normalized();
  } else {
    Index root = options.node;
    while (!parents[static_cast<std::size_t>(root)].empty()) root = parents[static_cast<std::size_t>(root)].front();
    plan.axis = default_axis(analysis, plan, root);
    if (plan.axis == Vec3::Zero())
      throw InvalidArgument(node_name(options.node) +
                            ": no default axis (the component has no area or lies in line with the pivot); "
                            "give an axis");
  }

  // The ramp: geodesic distance from the attach loop (from the birth vertex,
  // in the parent region, when the component has no vertex next to it),
  // times the same ramp from the held vertices.
  const DistanceField from_loop =
      dijkstra(mg, plan.attach_loop.empty() ? std::vector<Index>{node.birth_vertex} : plan.attach_loop);
  for (Index v = 0; v < nv; ++v)
    if (inside(v)) plan.extent = std::max(plan.extent, from_loop.distance[static_cast<std::size_t>(v)]);
  const double ramp = options.falloff * plan.extent;
  const auto ramp_weight = [ramp](double d) { return d >= ramp ? 1.0 : smoothstep(d / ramp); };
  const DistanceField from_held = held.empty() ? DistanceField{} : dijkstra(mg, held);
  plan.weight.assign(static_cast<std::size_t>(nv), 0.0);
  for (Index v = 0; v < nv; ++v) {
    const auto i = static_cast<std::size_t>(v);
    if (!inside(v) || !(from_loop.distance[i] > 0.0)) continue;
    plan.weight[i] = ramp_weight(from_loop.distance[i]) * (held.empty() ? 1.0 : ramp_weight(from_held.distance[i]));
  }
  return plan;
}

Mesh apply_deformation(const Mesh& mesh, const Deformation& deformation) {
  if (deformation.weight.size() != static_cast<std::size_t>(mesh.num_vertices()))
    throw InvalidArgument("apply_deformation: " + mesh.source + " has " + std::to_string(mesh.num_vertices()) +
                          " vertices, the deformation " + std::to_string(deformation.weight.size()));
  Mesh out = mesh;
  const double angle = deformation.angle_degrees * (static_cast<double>(EIGEN_PI) / 180.0);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const double turn = deformation.weight[static_cast<std::size_t>(v)] * angle;
    if (turn == 0.0) continue;
    const Eigen::AngleAxisd rotation(turn, deformation.axis);
    out.vertices.row(v) =
        (deformation.pivot + rotation * (mesh.vertices.row(v).transpose() - deformation.pivot)).transpose();
  }
  return out;
}

Mesh deform_component(const MeshAnalysis& analysis, const DeformOptions& options) {
  return apply_deformation(analysis.mesh, plan_deformation(analysis, options));
}

}  // namespace reebkit
