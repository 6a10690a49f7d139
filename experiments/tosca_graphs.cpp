// Reeb graphs of the TOSCA poses with and without hole filling, as Markdown:
// one row per mesh (boundary loops, then feature points, nodes, leaves and
// cycles of the graph as loaded and after fill_holes), then per class how
// the (leaves, cycles) pairs of its holed and closed poses compare.
//
//   build/experiments/tosca_graphs /tmp/data/tosca_dev > results/tosca_graphs.md
#include "batch_failures.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/core/timer.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/mesh_topology.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

using reebkit::Index;

struct GraphCounts {
  std::size_t features = 0;
  std::size_t features_on_new_vertices = 0;  ///< feature points at a vertex fill_holes added
  Index nodes = 0;
  Index leaves = 0;
  Index cycles = 0;
};

GraphCounts count(const reebkit::MeshAnalysis& a) {
  GraphCounts c;
  c.features = a.features.vertices.size();
  c.features_on_new_vertices =
      static_cast<std::size_t>(std::count_if(a.features.vertices.begin(), a.features.vertices.end(), [&](Index v) {
        return a.mesh.source_index(v) == reebkit::kInvalidIndex;
      }));
  c.nodes = a.reeb.num_nodes();
  c.leaves = a.reeb.leaf_count();
  c.cycles = a.reeb.independent_cycles();
  return c;
}

std::string leaves_cycles(const GraphCounts& c) { return std::to_string(c.leaves) + "/" + std::to_string(c.cycles); }

/// `closed` without its triangles whose three vertices lie on the boundary
/// of `holed` (same vertex numbering, as within a TOSCA class): the holes of
/// one pose punched into another, so that holes and pose can be told apart.
/// The TOSCA holes have no inner vertices, but the triangulations of two
/// poses differ by edge flips, so the punched hole can be smaller than the
/// holed pose's.
reebkit::Mesh punched(const reebkit::Mesh& closed, const reebkit::Mesh& holed) {
  const reebkit::MeshGraph graph = reebkit::build_mesh_graph(holed);
  const auto on_boundary = [&](Index v) {
    return graph.ring[static_cast<std::size_t>(v)] != reebkit::RingKind::Closed;
  };
  reebkit::Mesh out = closed;
  Index n = 0;
  for (Index t = 0; t < closed.num_triangles(); ++t)
    if (!(on_boundary(closed.triangles(t, 0)) && on_boundary(closed.triangles(t, 1)) &&
          on_boundary(closed.triangles(t, 2))))
      out.triangles.row(n++) = closed.triangles.row(t);
  out.triangles.conservativeResize(n, 3);
  return out;
}

struct Row {
  std::string name;
  reebkit::Mesh mesh;
  Index loops = 0;
  GraphCounts open;    ///< holes kept
  GraphCounts filled;  ///< default options (small holes filled)
};

/// "michael12" -> ("michael", 12); "dog" -> ("dog", -1).
std::pair<std::string, int> class_and_pose(const std::string& stem) {
  std::size_t i = stem.size();
  while (i > 0 && std::isdigit(static_cast<unsigned char>(stem[i - 1]))) --i;
  return {stem.substr(0, i), i == stem.size() ? -1 : std::stoi(stem.substr(i))};
}

/// "a x3, b" for the values of `items` in first-seen order.
std::string tally(const std::vector<std::string>& items) {
  std::vector<std::pair<std::string, int>> counts;
  for (const auto& s : items) {
    auto it = std::find_if(counts.begin(), counts.end(), [&](const auto& c) { return c.first == s; });
    if (it == counts.end())
      counts.emplace_back(s, 1);
    else
      ++it->second;
  }
  std::string out;
  for (const auto& [s, n] : counts) out += (out.empty() ? "" : ", ") + s + (n > 1 ? " x" + std::to_string(n) : "");
  return out.empty() ? "-" : out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: tosca_graphs TOSCA_DIR\n";
    return 2;
  }
  try {
    const std::vector<reebkit::MeshInput> files = reebkit::list_mesh_inputs({argv[1]});

    reebkit::Timer timer;
    reebkit::AnalysisOptions keep_holes;
    keep_holes.holes.max_loop_length = 0;
    std::map<std::string, std::vector<Row>> classes;
    std::size_t new_vertex_features = 0;
    std::cout << "# TOSCA Reeb graphs, holes kept and filled\n\n"
              << "`build/experiments/tosca_graphs TOSCA_DIR` (experiments/tosca_graphs.cpp). "
              << "Default options except where marked: as loaded = `holes.max_loop_length = 0`; filled = default "
                 "(max_loop_length = "
              << reebkit::HoleFillingOptions{}.max_loop_length << " sqrt(area)). L/C = leaves/cycles.\n\n"
              << "| mesh | boundary loops | features | nodes | L/C | features filled | nodes filled | L/C filled |\n"
              << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    BatchFailures failures("tosca_graphs");
    for (const reebkit::MeshInput& file : files) {
      Row row;
      try {
        const reebkit::Mesh mesh = reebkit::load_mesh(file.path).components.front();
        row.name = file.path.stem().string();
        row.mesh = mesh;
        row.loops = reebkit::analyze_topology(mesh).boundary_loops;
        row.open = count(reebkit::analyze_mesh(mesh, keep_holes));
        row.filled = count(reebkit::analyze_mesh(mesh));
      } catch (const std::exception& e) {
        failures.add(e.what(), file.path.string());
        continue;
      }
      std::cout << "| " << row.name << " | " << row.loops << " | " << row.open.features << " | " << row.open.nodes
                << " | " << leaves_cycles(row.open) << " | " << row.filled.features << " | " << row.filled.nodes
                << " | " << leaves_cycles(row.filled) << " |\n";
      new_vertex_features += row.filled.features_on_new_vertices;
      classes[class_and_pose(row.name).first].push_back(row);
    }

    std::cout << "\nPer class, the L/C pairs (leaves/cycles) of the closed poses and of the holed poses, as loaded "
                 "and filled (xN: N poses).\n\n"
              << "| class | closed poses | holed poses as loaded | holed poses filled |\n|---|---|---|---|\n";
    for (const auto& [name, rows] : classes) {
      std::vector<std::string> closed, holed_open, holed_filled;
      for (const Row& r : rows) {
        if (r.loops == 0) {
          closed.push_back(leaves_cycles(r.open));
        } else {
          holed_open.push_back(leaves_cycles(r.open));
          holed_filled.push_back(leaves_cycles(r.filled));
        }
      }
      std::cout << "| " << name << " | " << tally(closed) << " | " << tally(holed_open) << " | " << tally(holed_filled)
                << " |\n";
    }
    std::cout << "\nFeature points at a vertex added by fill_holes, over all meshes: " << new_vertex_features << "\n";

    std::cout << "\nThe same pose with and without holes: each closed pose with the holes of the first holed pose "
                 "of its class punched in (its missing triangles removed), as loaded and filled.\n\n"
              << "| closed pose | holes of | boundary edges / loops punched | features | L/C | features punched | L/C "
                 "punched | features filled | "
                 "L/C filled |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& [name, rows] : classes) {
      const auto holed = std::find_if(rows.begin(), rows.end(), [](const Row& r) { return r.loops > 0; });
      if (holed == rows.end()) continue;
      for (const Row& r : rows) {
        if (r.loops > 0) continue;
        reebkit::MeshTopology topology;
        GraphCounts open, filled;
        try {
          const reebkit::Mesh mesh = punched(r.mesh, holed->mesh);
          topology = reebkit::analyze_topology(mesh);
          open = count(reebkit::analyze_mesh(mesh, keep_holes));
          filled = count(reebkit::analyze_mesh(mesh));
        } catch (const std::exception& e) {
          failures.add(r.name + " with the holes of " + holed->name + ": " + e.what());
          continue;
        }
        std::cout << "| " << r.name << " | " << holed->name << " | " << topology.boundary_edges << " / "
                  << topology.boundary_loops << " | " << r.open.features << " | " << leaves_cycles(r.open) << " | "
                  << open.features << " | " << leaves_cycles(open) << " | " << filled.features << " | "
                  << leaves_cycles(filled) << " |\n";
      }
    }
    std::cerr << "tosca_graphs: " << timer.lap() / 1000.0 << " s\n";
    return failures.finish(files.size());
  } catch (const std::exception& e) {
    std::cerr << "tosca_graphs: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
