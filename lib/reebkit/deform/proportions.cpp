#include "reebkit/deform/proportions.h"

#include "reebkit/core/error.h"
#include "reebkit/deform/deformation.h"
#include "reebkit/geodesic/dijkstra.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace reebkit {

namespace {

double smoothstep(double t) { return t * t * (3.0 - 2.0 * t); }

// A region: pivoting on all of it, ramped from its vertices next to another
// region, cut along f_q.
void plan_region(const MeshAnalysis& a, Index node, double falloff, ProportionPlan& plan) {
  const ReebGraph& g = a.reeb;
  const MeshGraph& mg = a.graph;
  const auto inside = [&](Index v) { return g.vertex_node[static_cast<std::size_t>(v)] == node; };
  plan.nodes = {node};
  std::vector<Index> border;
  for (Index v = 0; v < a.mesh.num_vertices(); ++v) {
    if (!inside(v)) continue;
    plan.anchor.push_back(v);
    const auto first = mg.neighbor.begin() + mg.offset[v], last = mg.neighbor.begin() + mg.offset[v + 1];
    if (!std::all_of(first, last, inside)) border.push_back(v);
  }
  const DistanceField from_border = border.empty() ? DistanceField{} : dijkstra(mg, border);
  double extent = 0.0;
  if (!border.empty())
    for (const Index v : plan.anchor) extent = std::max(extent, from_border.distance[static_cast<std::size_t>(v)]);
  const double ramp = falloff * extent;
  for (const Index v : plan.anchor) {
    const auto i = static_cast<std::size_t>(v);
    const double d = border.empty() ? ramp : from_border.distance[i];
    if (border.empty() || d > 0.0) plan.weight[i] = d >= ramp ? 1.0 : smoothstep(d / ramp);
    plan.position[i] = a.fq.value[i];
  }
}

// A component: the component, attach loop and ramp of
// plan_deformation, cut along the geodesic distance from the attach loop.
void plan_component(const MeshAnalysis& a, Index node, double falloff, ProportionPlan& plan) {
  DeformOptions component;
  component.node = node;
  component.falloff = falloff;
  component.axis = Vec3::UnitZ();  // the rotation is not used: no default axis needed
  Deformation deformation = plan_deformation(a, component);
  plan.nodes = std::move(deformation.nodes);
  plan.anchor = deformation.attach_loop.empty()
                    ? std::vector<Index>{a.reeb.nodes[static_cast<std::size_t>(node)].birth_vertex}
                    : std::move(deformation.attach_loop);
  plan.weight = std::move(deformation.weight);
  const DistanceField from_loop = dijkstra(a.graph, plan.anchor);
  for (Index v = 0; v < a.mesh.num_vertices(); ++v) {
    const auto i = static_cast<std::size_t>(v);
    if (std::binary_search(plan.nodes.begin(), plan.nodes.end(), a.reeb.vertex_node[i]))
      plan.position[i] = from_loop.distance[i];
  }
}

}  // namespace

ProportionPlan plan_proportions(const MeshAnalysis& reference, const ProportionOptions& options) {
  const ReebGraph& g = reference.reeb;
  const Index nv = reference.mesh.num_vertices();
  check_graph_node(reference, options.node, "plan_proportions");
  if (!(std::isfinite(options.scale) && options.scale > 0.0) ||
      !(std::isfinite(options.thickness) && options.thickness > 0.0))
    throw InvalidArgument("plan_proportions: scale " + std::to_string(options.scale) + " and thickness " +
                          std::to_string(options.thickness) + " must be finite and > 0");
  if (!(options.falloff >= 0.0 && options.falloff <= 1.0))
    throw InvalidArgument("plan_proportions: falloff " + std::to_string(options.falloff) + " is outside [0, 1]");
  if (options.levels < 2)
    throw InvalidArgument("plan_proportions: " + std::to_string(options.levels) + " levels, at least 2 needed");

  ProportionPlan plan;
  plan.scale = options.scale;
  plan.thickness = options.thickness;
  plan.weight.assign(static_cast<std::size_t>(nv), 0.0);
  plan.position.assign(static_cast<std::size_t>(nv), 0.0);
  if (options.part == ProportionPart::Region)
    plan_region(reference, options.node, options.falloff, plan);
  else if (std::none_of(g.edges.begin(), g.edges.end(),
                        [&](const std::array<Index, 2>& e) { return e[1] == options.node; }))
    throw InvalidArgument("plan_proportions: node " + std::to_string(options.node) +
                          " is a root (the region around the minimum of f_q): it has no " +
                          "parent to attach a component to; its region (ProportionPart::Region) can change");
  else
    plan_component(reference, options.node, options.falloff, plan);

  // Levels: equal slices of the part's positions; empty ones dropped.
  const auto in_part = [&](Index v) {
    return std::binary_search(plan.nodes.begin(), plan.nodes.end(), g.vertex_node[static_cast<std::size_t>(v)]);
  };
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (Index v = 0; v < nv; ++v)
    if (in_part(v)) {
      low = std::min(low, plan.position[static_cast<std::size_t>(v)]);
      high = std::max(high, plan.position[static_cast<std::size_t>(v)]);
    }
  const double width = (high - low) / options.levels;
  std::vector<Index> slice(static_cast<std::size_t>(nv), -1);
  std::vector<double> sum(static_cast<std::size_t>(options.levels), 0.0);
  std::vector<Index> count(static_cast<std::size_t>(options.levels), 0);
  for (Index v = 0; v < nv; ++v) {
    if (!in_part(v)) continue;
    const auto i = static_cast<std::size_t>(v);
    const Index s =
        width > 0.0 ? std::min<Index>(options.levels - 1, static_cast<Index>((plan.position[i] - low) / width)) : 0;
    slice[i] = s;
    sum[static_cast<std::size_t>(s)] += plan.position[i];
    ++count[static_cast<std::size_t>(s)];
  }
  std::vector<Index> renumber(static_cast<std::size_t>(options.levels), -1);
  for (std::size_t s = 0; s < count.size(); ++s)
    if (count[s] > 0) {
      renumber[s] = static_cast<Index>(plan.level_position.size());
      plan.level_position.push_back(sum[s] / static_cast<double>(count[s]));
    }
  plan.level.assign(static_cast<std::size_t>(nv), -1);
  for (std::size_t i = 0; i < slice.size(); ++i)
    if (slice[i] >= 0) plan.level[i] = renumber[static_cast<std::size_t>(slice[i])];
  return plan;
}

Mesh apply_proportions(const Mesh& mesh, const ProportionPlan& plan) {
  const Index nv = mesh.num_vertices();
  if (plan.weight.size() != static_cast<std::size_t>(nv) || plan.level.size() != static_cast<std::size_t>(nv))
    throw InvalidArgument("apply_proportions: " + mesh.source + " has " + std::to_string(nv) + " vertices, the plan " +
                          std::to_string(plan.weight.size()));
  if (plan.anchor.empty()) throw InvalidArgument("apply_proportions: the plan has no anchor vertex (no pivot)");
  Mesh out = mesh;
  if (plan.scale == 1.0 && plan.thickness == 1.0) return out;
  const auto at = [&](Index v) -> Vec3 { return mesh.vertices.row(v).transpose(); };

  Vec3 pivot = Vec3::Zero();
  for (const Index v : plan.anchor) pivot += at(v);
  pivot /= static_cast<double>(plan.anchor.size());
  const std::size_t levels = plan.level_position.size();
  std::vector<Vec3> skeleton(levels, Vec3::Zero());
  std::vector<double> count(levels, 0.0);
  for (Index v = 0; v < nv; ++v) {
    const Index l = plan.level[static_cast<std::size_t>(v)];
    if (l < 0) continue;
    skeleton[static_cast<std::size_t>(l)] += at(v);
    count[static_cast<std::size_t>(l)] += 1.0;
  }
  for (std::size_t l = 0; l < levels; ++l) skeleton[l] /= count[l];

  for (Index v = 0; v < nv; ++v) {
    const auto i = static_cast<std::size_t>(v);
    const double w = plan.weight[i];
    if (w == 0.0) continue;
    Vec3 p = at(v);
    if (plan.thickness != 1.0) {
      // The skeleton point at the vertex's position along the part, and the
      // skeleton's direction there (none for a part of one level).
      Vec3 center = skeleton.front(), direction = Vec3::Zero();
      if (levels >= 2) {
        const auto upper = std::upper_bound(plan.level_position.begin(), plan.level_position.end(), plan.position[i]);
        const std::size_t j =
            std::clamp<std::size_t>(static_cast<std::size_t>(upper - plan.level_position.begin()), 1, levels - 1) - 1;
        const double t = std::clamp((plan.position[i] - plan.level_position[j]) /
                                        (plan.level_position[j + 1] - plan.level_position[j]),
                                    0.0, 1.0);
        center = (1.0 - t) * skeleton[j] + t * skeleton[j + 1];
        direction = (skeleton[j + 1] - skeleton[j]).normalized();
      }
      Vec3 across = p - center;
      across -= across.dot(direction) * direction;
      p += (plan.thickness - 1.0) * w * across;
    }
    if (plan.scale != 1.0) p = pivot + (1.0 + (plan.scale - 1.0) * w) * (p - pivot);
    out.vertices.row(v) = p.transpose();
  }
  return out;
}

}  // namespace reebkit
