#include "mesh_arrays.h"

#include "reebkit/core/error.h"
#include "reebkit/mesh/mesh_cleanup.h"
#include "reebkit/pipeline/mesh_record.h"

#include <limits>

namespace reebkit::python {

ArrayMesh mesh_from_arrays(const double* V, Index vertices, const std::int32_t* F, Index faces) {
  PolygonSoup soup;
  soup.source = "(V, F)";
  soup.vertices = Eigen::Map<const Points>(V, vertices, 3);
  soup.face_vertex.assign(F, F + 3 * static_cast<std::size_t>(faces));
  soup.face_offset.resize(static_cast<std::size_t>(faces) + 1);
  for (Index f = 0; f <= faces; ++f) soup.face_offset[static_cast<std::size_t>(f)] = 3 * f;
  CleanedMesh cleaned = clean_mesh(soup);
  return {std::move(cleaned.components.front()), vertices, std::move(cleaned.report.warnings)};
}

std::vector<Index> from_input_numbering(const ArrayMesh& m, const std::vector<Index>& rows) {
  std::vector<Index> vertex_of_row(static_cast<std::size_t>(m.input_vertices), kInvalidIndex);
  for (Index v = 0; v < m.mesh.num_vertices(); ++v) vertex_of_row[static_cast<std::size_t>(m.mesh.source_index(v))] = v;
  std::vector<Index> out;
  out.reserve(rows.size());
  for (const Index row : rows) {
    if (row < 0 || row >= m.input_vertices)
      throw InvalidArgument("vertex " + std::to_string(row) + " is out of range (V has " +
                            std::to_string(m.input_vertices) + " rows)");
    const Index v = vertex_of_row[static_cast<std::size_t>(row)];
    if (v == kInvalidIndex)
      throw InvalidArgument("vertex " + std::to_string(row) +
                            " is not on the analysed surface (the largest connected component, used vertices)");
    out.push_back(v);
  }
  return out;
}

ArrayGraph graph_of(ArrayMesh m, const AnalysisOptions& options) {
  const MeshAnalysis analysis = analyze_mesh(std::move(m.mesh), options);
  ArrayGraph out{make_graph_record(analysis, compute_attributes(analysis)), {}, {}, options};
  const Index rows = m.input_vertices;
  out.vertex_node = to_input_numbering(analysis.mesh, rows, analysis.reeb.vertex_node, kInvalidIndex);
  out.fq = to_input_numbering(analysis.mesh, rows, analysis.fq.value, std::numeric_limits<double>::quiet_NaN());
  return out;
}

}  // namespace reebkit::python
