// A program built on an installed reebkit (docs/install.md): the attributed
// Reeb graph of one mesh, analysed as the collection was, then the k entries
// of the collection nearest to it by graph matching.
//   query_collection MESH COLLECTION.h5 [K]
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/retrieval/query.h"

#include <exception>
#include <iomanip>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: query_collection MESH COLLECTION.h5 [K]\n";
    return 2;
  }
  try {
    const reebkit::CollectionReader collection(argv[2]);
    const reebkit::GraphRecord graph =
        reebkit::analyze_mesh_file(argv[1], argv[1],
                                   reebkit::analysis_options_from(collection.provenance().analysis_options));
    std::cout << "nodes " << graph.num_nodes() << " edges " << graph.num_edges() << " cycles "
              << reebkit::independent_cycles(graph) << " leaves " << reebkit::leaf_count(graph) << "\n";
    reebkit::QueryOptions options;
    if (argc == 4) options.k = std::stoi(argv[3]);
    for (const reebkit::QueryResult& result : reebkit::query_collection(collection, graph, options))
      std::cout << std::setprecision(17) << result.distance << " " << result.name << "\n";
  } catch (const std::exception& error) {
    std::cerr << error.what() << "\n";
    return 1;
  }
  return 0;
}
