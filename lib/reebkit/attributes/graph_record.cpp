#include "reebkit/attributes/graph_record.h"

#include "reebkit/reeb/reeb_graph.h"

#include <numeric>

namespace reebkit {

// One row per group of columns.
// clang-format off
const std::array<const char*, kNodeAttributeCount> kNodeAttributeNames = {
    "relative_area", "fq_min", "fq_max", "fq_span", "geodesic_extent", "mean_radius", "vertex_share",
    "degree", "start_type", "end_type",
    "radius_0", "radius_1", "radius_2", "radius_3", "radius_4", "radius_5", "radius_6", "radius_7",
    "shape_0", "shape_1", "shape_2", "shape_3", "shape_4", "shape_5", "shape_6", "shape_7",
    "geodesic_0", "geodesic_1", "geodesic_2", "geodesic_3", "geodesic_4", "geodesic_5", "geodesic_6", "geodesic_7",
    "spectrum_1", "spectrum_2", "spectrum_3", "spectrum_4", "spectrum_5", "spectrum_6"};

const std::array<const char*, kEdgeAttributeCount> kEdgeAttributeNames = {"boundary_length", "event_fq"};

const std::array<const char*, kSignatureLength> kSignatureNames = {
    "nodes", "leaves", "bifurcations", "junctions", "cycles", "root_area",
    "leaf_area_0", "leaf_area_1", "leaf_area_2", "leaf_area_3", "leaf_area_4", "leaf_area_5",
    "leaf_extent_0", "leaf_extent_1", "leaf_extent_2", "leaf_extent_3", "leaf_extent_4", "leaf_extent_5",
    "area_hist_0", "area_hist_1", "area_hist_2", "area_hist_3", "area_hist_4", "area_hist_5",
    "laplacian_2", "laplacian_3", "laplacian_4", "laplacian_5",
    "laplacian_6", "laplacian_7", "laplacian_8", "laplacian_9",
    "d2_0", "d2_1", "d2_2", "d2_3", "d2_4", "d2_5", "d2_6", "d2_7",
    "d2_8", "d2_9", "d2_10", "d2_11", "d2_12", "d2_13", "d2_14", "d2_15",
    "axis_position_0", "axis_position_1", "axis_position_2", "axis_position_3",
    "axis_position_4", "axis_position_5", "axis_position_6", "axis_position_7",
    "axis_offset_0", "axis_offset_1", "axis_offset_2", "axis_offset_3",
    "axis_offset_4", "axis_offset_5", "axis_offset_6", "axis_offset_7",
    "dna_1", "dna_2", "dna_3", "dna_4", "dna_5", "dna_6", "dna_7", "dna_8",
    "dna_9", "dna_10", "dna_11", "dna_12", "dna_13", "dna_14", "dna_15", "dna_16",
    "heat_t1_1", "heat_t1_2", "heat_t1_3", "heat_t1_4", "heat_t1_5", "heat_t1_6", "heat_t1_7", "heat_t1_8",
    "heat_t2_1", "heat_t2_2", "heat_t2_3", "heat_t2_4", "heat_t2_5", "heat_t2_6", "heat_t2_7", "heat_t2_8",
    "heat_t3_1", "heat_t3_2", "heat_t3_3", "heat_t3_4", "heat_t3_5", "heat_t3_6", "heat_t3_7", "heat_t3_8",
    "heat_t4_1", "heat_t4_2", "heat_t4_3", "heat_t4_4", "heat_t4_5", "heat_t4_6", "heat_t4_7", "heat_t4_8"};
// clang-format on

std::int64_t independent_cycles(const GraphRecord& record) {
  // Union-find over the nodes counts the connected components.
  std::vector<std::size_t> parent(static_cast<std::size_t>(record.num_nodes()));
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto root = [&parent](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::int64_t components = record.num_nodes();
  for (std::size_t k = 0; k + 1 < record.edges.size(); k += 2) {
    const std::size_t a = root(static_cast<std::size_t>(record.edges[k]));
    const std::size_t b = root(static_cast<std::size_t>(record.edges[k + 1]));
    if (a != b) {
      parent[a] = b;
      --components;
    }
  }
  return record.num_edges() - record.num_nodes() + components;
}

std::int64_t leaf_count(const GraphRecord& record) {
  std::int64_t leaves = 0;
  for (std::int32_t k = 0; k < record.num_nodes(); ++k)
    leaves += record.nodes[static_cast<std::size_t>(k) * kNodeColumnCount + kNodeEnd] ==
              static_cast<std::int32_t>(NodeType::Termination);
  return leaves;
}

}  // namespace reebkit
