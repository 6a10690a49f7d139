// reeb query collection.h5 MESH_OR_NAME: the meshes of a collection nearest
// to a query, pre-filtered by graph signature (FLANN, exact) and reranked by
// graph matching (docs/command-line.md, "Query and distances"); with the
// collection's query file, reading only the candidates' graphs.
#include "reeb/cli.h"
#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/json_writer.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/retrieval/query.h"

#include <iomanip>
#include <iostream>
#include <optional>

namespace reebkit::cli {

namespace {

/// The query's entry: the collection's own entry `index` when `query` names
/// one of its meshes, otherwise the mesh file analysed as reeb index analysed
/// the collection (largest component, the collection's analysis options).
GraphRecord query_entry(const CollectionReader& collection, const std::string& query,
                        const std::optional<std::int64_t>& index) {
  if (index) return collection.entry(*index);
  return analyze_mesh_file(query, query, analysis_options_from(collection.provenance().analysis_options));
}

void write_json(std::ostream& out, const std::string& collection, const std::string& query, bool in_collection,
                const QueryOptions& options, const std::vector<QueryResult>& results) {
  JsonWriter json(out);
  json.begin_object()
      .field("collection", collection)
      .field("query", query)
      .field("query_in_collection", in_collection)
      .field("k", options.k)
      .field("candidates", options.candidates);
  json.key("results").begin_array();
  for (std::size_t r = 0; r < results.size(); ++r)
    json.begin_object()
        .field("rank", static_cast<long long>(r + 1))
        .field("name", results[r].name)
        .field("class", results[r].class_label)
        .field("distance", results[r].distance)
        .field("signature_distance", results[r].signature_distance)
        .field("index", static_cast<long long>(results[r].index))
        .end_object();
  json.end_array().end_object();
  out << "\n";
}

}  // namespace

int run_query(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string path, query;
  QueryOptions query_options;
  bool json = false;
  options.add_options()("collection", po::value(&path)->required(), "collection file written by reeb index")(
      "query", po::value(&query)->required(),
      "a mesh of the collection (its name, as reeb info --list lists them) or a mesh file (analysed first)")(
      "k,k", po::value(&query_options.k)->default_value(query_options.k),
      "results to list")("candidates", po::value(&query_options.candidates)->default_value(query_options.candidates),
                         "nearest graph signatures reranked by graph matching (>= the collection size: every mesh)")(
      "threads", po::value(&query_options.threads)->default_value(query_options.threads),
      "threads matching the candidates (0: as many as OpenMP offers)")("json", po::bool_switch(&json),
                                                                       "print the ranked list as JSON");
  options.add(matching_options(query_options.matching));
  po::positional_options_description positional;
  positional.add("collection", 1).add("query", 1);
  po::variables_map vm;
  if (!parse(args,
             "reeb query collection.h5 MESH_OR_NAME [-k 10] [--candidates 100] [--threads N] [--json] "
             "[matching options]\n(a mesh file is analysed with the collection's analysis options)",
             options, positional, vm))
    return 0;

  const CollectionReader collection(path);
  Timer timer;
  const std::optional<std::int64_t> index = collection.find(query);
  const bool in_collection = index.has_value();
  const GraphRecord entry = query_entry(collection, query, index);
  if (!entry.ok) throw Error(path + ": mesh '" + query + "' failed when indexed: " + entry.error);
  const double extract_ms = timer.lap();
  // With a current query file only the signature index and the candidates'
  // graphs are read; otherwise the whole collection.
  const std::optional<QueryableFile> file = open_query_file(collection);
  const std::optional<SearchableCollection> searchable =
      file ? std::nullopt : std::optional<SearchableCollection>(load_searchable(collection));
  const double load_ms = timer.lap();
  const std::vector<QueryResult> results = file ? query_collection(collection, *file, entry, query_options)
                                                : query_collection(*searchable, entry, query_options);
  const double query_ms = timer.lap();
  std::cerr << std::fixed << std::setprecision(2) << (in_collection ? "graph read: " : "graph extracted: ")
            << extract_ms << " ms, "
            << (file ? "signature index read from " + QueryFile::path_of(path).string()
                     : std::string("collection read and signature index"))
            << " (" << (file ? file->index : searchable->index).size() << " graphs): " << load_ms
            << " ms, query: " << query_ms << " ms\n"
            << std::defaultfloat;

  if (json) {
    write_json(std::cout, path, query, in_collection, query_options, results);
    return 0;
  }
  std::cout << "rank\tdistance\tclass\tname\n";
  for (std::size_t r = 0; r < results.size(); ++r)
    std::cout << r + 1 << "\t" << std::setprecision(6) << results[r].distance << "\t"
              << (results[r].class_label.empty() ? "-" : results[r].class_label) << "\t" << results[r].name << "\n";
  return 0;
}

}  // namespace reebkit::cli
