// A small generated collection for the retrieval tests: urchins with 2 to 6
// arms in two layouts each, and tori, analysed into collection entries
// (classes "arms<k>" and "torus") plus one failed entry; written to a
// collection file on request.
#pragma once

#include "reebkit/attributes/graph_attributes.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/pipeline/analyze_mesh.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/store/collection_file.h"

#include <filesystem>
#include <string>
#include <vector>

namespace reebkit::test {

inline GraphRecord entry_of(const Mesh& mesh, const std::string& name, const std::string& class_label) {
  const MeshAnalysis analysis = analyze_mesh(mesh);
  GraphRecord entry = make_graph_record(analysis, compute_attributes(analysis));
  entry.name = name;
  entry.class_label = class_label;
  return entry;
}

/// 13 entries: arms2-a, arms2-b, ..., arms6-b, torus-a, torus-b, and
/// "broken" (failed) in the middle, at index 6.
inline const std::vector<GraphRecord>& generated_entries() {
  static const std::vector<GraphRecord> entries = [] {
    std::vector<GraphRecord> out;
    for (int arms = 2; arms <= 6; ++arms)
      for (const double twist : {0.0, 0.7}) {
        StarOptions star;
        star.arms = arms;
        star.levels = 3;
        star.twist = twist;
        const std::string label = "arms" + std::to_string(arms);
        out.push_back(entry_of(make_star(star), label + (twist == 0.0 ? "-a" : "-b"), label));
        if (out.size() == 6) out.push_back(failed_graph_record("broken", "", 0, "broken: no faces"));
      }
    out.push_back(entry_of(make_torus(40, 16), "torus-a", "torus"));
    out.push_back(entry_of(make_torus(48, 12, 1.0, 0.3), "torus-b", "torus"));
    return out;
  }();
  return entries;
}

/// generated_entries() written to `path`.
inline void write_generated_collection(const std::filesystem::path& path) {
  CollectionWriter writer(path, Provenance{}, false);
  for (const GraphRecord& e : generated_entries()) writer.append(e);
  writer.close();
}

}  // namespace reebkit::test
