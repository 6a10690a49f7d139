// Between face-vertex arrays (libigl's V, F: what numpy, trimesh and PyTorch
// users hold) and the library, with no Python in sight, so that the module
// (module.cpp) and its overhead benchmark (bench/python_overhead.py) run the
// same code. A mesh given as arrays is cleaned as every command cleans a
// file (clean_mesh, largest component), and per-vertex results come back in
// the caller's numbering: the row of V.
#pragma once

#include "reebkit/attributes/graph_record.h"
#include "reebkit/core/mesh.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace reebkit::python {

/// A mesh made from arrays, and what cleaning it reported.
struct ArrayMesh {
  Mesh mesh;                          ///< the largest component; source_vertex = row of V
  Index input_vertices = 0;           ///< rows of V
  std::vector<std::string> warnings;  ///< CleanupReport::warnings
};

/// The mesh of V (#V x 3 doubles, row-major) and F (#F x 3 vertex ids,
/// row-major), cleaned by clean_mesh (largest component). Throws
/// InvalidMeshError naming "(V, F)" as the file when nothing usable is left
/// or an id is out of range.
ArrayMesh mesh_from_arrays(const double* V, Index vertices, const std::int32_t* F, Index faces);

/// Per-vertex `values` of `mesh` (made from `rows` rows of V, holes filled
/// or not) at the caller's rows: out[source_index(v)] = values[v], `missing`
/// for the rows the mesh left out.
template <typename T>
std::vector<T> to_input_numbering(const Mesh& mesh, Index rows, const std::vector<T>& values, T missing) {
  std::vector<T> out(static_cast<std::size_t>(rows), missing);
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Index row = mesh.source_index(v);
    if (row != kInvalidIndex) out[static_cast<std::size_t>(row)] = values[static_cast<std::size_t>(v)];
  }
  return out;
}

/// Rows of V -> vertices of the mesh. Throws InvalidArgument naming a row
/// out of range or left out by cleaning (not in the largest component, unused).
std::vector<Index> from_input_numbering(const ArrayMesh& m, const std::vector<Index>& rows);

/// The Reeb graph of an array mesh: what `reeb graph` computes, with the
/// per-vertex arrays in the caller's numbering.
struct ArrayGraph {
  GraphRecord record;  ///< vertex ids are rows of V (-1: a vertex added to close a hole)
  std::vector<Index>
      vertex_node;  ///< #V rows: node of each vertex, -1 where the mesh left it out; empty for a collection entry
  std::vector<double> fq;  ///< #V rows: f_q, NaN where left out; empty for a collection entry
  /// The options it was analysed with (a collection entry: the collection's);
  /// none for a graph of unknown origin.
  std::optional<AnalysisOptions> analysis;
};

/// analyze_mesh, compute_attributes and make_graph_record, as `reeb graph`
/// and `reeb index` run them on a mesh file.
ArrayGraph graph_of(ArrayMesh m, const AnalysisOptions& options);

}  // namespace reebkit::python
