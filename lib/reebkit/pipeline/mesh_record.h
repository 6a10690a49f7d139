// The per-mesh chain load -> analyse -> attributes -> record: the attributed
// graph record (attributes/graph_record.h) of one mesh, as the collection
// file stores it. The graph JSON (output/reeb_graph_export.h) is written
// from these records, so `reeb graph` and `reeb export` print the same
// document.
#pragma once

#include "reebkit/attributes/graph_record.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace reebkit {

/// The graph part of an entry: nodes (type, end, birth vertex, vertex
/// count), their geometry, node and edge attributes, edges, feature points,
/// skeleton and signature; the vertex and face counts of the surface as read
/// (hole filling excluded); timings graph, features, quotient and Reeb graph
/// from the analysis. Vertex ids are those of the file (Mesh::source_index;
/// -1 for a vertex added to close a hole). ok = true; the caller fills name,
/// class label, content hash and the load and attribute times.
/// \pre analysis.reeb has been built; `attributes` are compute_attributes(analysis).
///      Throws InvalidArgument otherwise.
GraphRecord make_graph_record(const MeshAnalysis& analysis, const GraphAttributes& attributes);

/// Reads the mesh file at `path` (its largest component), analyses it,
/// computes its attributes and returns its entry, named `name`, with the
/// load and attribute times and the content hash (io/content_hash.h) of the
/// bytes it read filled in: the file is read once. Errors propagate (they
/// name the file); `content_hash`, when given, holds the hash as soon as the
/// file is read, for the failed entry of a file that cannot be analysed.
GraphRecord analyze_mesh_file(const std::filesystem::path& path, std::string name, const AnalysisOptions& options = {},
                              std::uint64_t* content_hash = nullptr);

/// A failed entry: ok = false, `error`, NaN signature, no graph.
GraphRecord failed_graph_record(std::string name, std::string class_label, std::uint64_t content_hash,
                                std::string error);

}  // namespace reebkit
