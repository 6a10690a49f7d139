// The Reeb graph of a mesh in files for people and other tools: a JSON
// document of the graph (schema in docs/formats.md), the
// segmentation as a colored PLY, and the graph and its topological skeleton
// (Tierny et al. 2006, section 5.2, figures 9 and 10a) as OBJ lines.
//
// Each function takes the analyses of a mesh's connected components (one
// MeshAnalysis each, as `reeb graph --all-components` makes them; usually
// just one) and writes them as one graph: node ids run on across components
// in their order, vertices are counted across them, and mesh vertices are
// named by their index in the file (Mesh::source_index).
#pragma once

#include "reebkit/attributes/graph_record.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace reebkit {

/// The graph as JSON: mesh, counts, feature points, nodes with their
/// attributes, edges with theirs, cycles, leaves, skeleton, signature and
/// step timings. Written from collection entries (one per component,
/// make_graph_record), so that `reeb graph` and `reeb export` (an entry
/// read back from a collection file) print the same document; `mesh` is the
/// `mesh` field. Throws InvalidArgument when `components` is empty or a
/// component is a failed entry.
void write_reeb_graph_json(std::ostream& out, const std::string& mesh, const std::vector<GraphRecord>& components);
/// The same from the analyses (with compute_attributes), into the file `path`
/// (write_file_bytes: atomically). Throws as above, and MeshFileError naming
/// the file when it cannot be written.
void write_reeb_graph_json(const std::filesystem::path& path, const std::vector<MeshAnalysis>& components);

/// The mesh colored by segment (category_color of the node id), with the
/// per-vertex properties `node` (node id) and `fq` (f_q); binary PLY.
/// Throws as write_reeb_graph_json, and MeshFileError from write_ply.
void write_segmentation_ply(const std::filesystem::path& path, const std::vector<MeshAnalysis>& components);

/// Lines for MeshLab or Blender. Object `reeb_graph`: a vertex per node at its
/// barycenter (vertex k + 1 is node k) and an `l` line per edge. Object
/// `skeleton`: each node's skeleton points as one polyline, and a segment
/// from the last point of every edge's earlier node to the first point of its
/// later node, so the skeleton is drawn connected where the graph is.
/// Throws as write_reeb_graph_json.
void write_skeleton_obj(const std::filesystem::path& path, const std::vector<MeshAnalysis>& components);

}  // namespace reebkit
