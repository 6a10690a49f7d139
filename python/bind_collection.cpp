// reebkit.Collection (a collection file of `reeb index`: entries, query,
// all-pairs distances) and reebkit.evaluate (`reeb eval`'s measures).
#include "bindings.h"

#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/evaluation/graph_stability.h"
#include "reebkit/evaluation/retrieval_metrics.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/retrieval/all_pairs.h"
#include "reebkit/retrieval/query.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

namespace reebkit::python {

namespace {

struct Collection {
  std::string path;
  CollectionReader reader;
  AnalysisOptions analysis;  ///< those the collection was indexed with
  /// Read on the first query: the query file's signature index when there is
  /// one for the collection as it is, otherwise the whole collection.
  std::optional<QueryableFile> file;
  std::unique_ptr<const SearchableCollection> searchable;

  std::vector<QueryResult> query(const GraphRecord& record, const QueryOptions& options) {
    if (!file && !searchable) {
      file = open_query_file(reader);
      if (!file) searchable = std::make_unique<const SearchableCollection>(load_searchable(reader));
    }
    return file ? query_collection(reader, *file, record, options) : query_collection(*searchable, record, options);
  }
};

std::int64_t entry_index(const Collection& c, std::int64_t i) {
  const std::int64_t n = c.reader.size();
  if (i < -n || i >= n) throw py::index_error("collection index " + std::to_string(i) + " out of range");
  return i < 0 ? i + n : i;
}

std::int64_t entry_index(const Collection& c, const std::string& name) {
  if (const auto i = c.reader.find(name)) return *i;
  throw py::key_error(c.path + ": no mesh named '" + name + "'");
}

/// The graph of a query that is not a ReebGraph: a mesh (V, F) or a mesh
/// file analysed with the collection's options, as `reeb query` analyses a
/// file, or an entry's name.
GraphRecord query_record(const Collection& c, const py::object& query) {
  if (py::isinstance<py::tuple>(query)) {
    const auto vf = query.cast<py::tuple>();
    if (vf.size() != 2) throw py::value_error("a query mesh is a tuple (V, F)");
    ArrayMesh mesh = mesh_argument(vf[0].cast<PointsArray>(), vf[1].cast<IndexArray>());
    const py::gil_scoped_release release;
    return graph_of(std::move(mesh), c.analysis).record;
  }
  const std::string spec = query.cast<std::filesystem::path>().string();
  if (const auto i = c.reader.find(spec)) return c.reader.entry(*i);
  const py::gil_scoped_release release;
  return analyze_mesh_file(spec, spec, c.analysis);
}

/// Throws ValueError when `graph` was analysed with other options than the
/// collection's entries: its distances to them would mean nothing.
void refuse_other_analysis(const Collection& c, const ArrayGraph& graph) {
  if (!graph.analysis) return;
  const std::vector<OptionDifference> differences = analysis_option_differences(*graph.analysis, c.analysis);
  if (differences.empty()) return;
  std::string list;
  for (const OptionDifference& d : differences)
    list += (list.empty() ? "" : ", ") + d.name + " " + d.first + " (the collection: " + d.second + ")";
  throw py::value_error("the query graph was analysed with other options than the entries of " + c.path + ": " + list +
                        "; analyse it with **collection.analysis_options, or query the mesh itself");
}

py::dict scores(const RetrievalScores& s) {
  py::dict out;
  out["NN"] = s.nearest_neighbor;
  out["FT"] = s.first_tier;
  out["ST"] = s.second_tier;
  out["E"] = s.e_measure;
  out["DCG"] = s.dcg;
  out["precision"] = s.precision;
  return out;
}

/// The class of each row: a .cla file (rows in its order) or a label per row.
ModelClasses classes_of(const py::object& classes) {
  if (py::isinstance<py::str>(classes) || py::hasattr(classes, "__fspath__"))
    return model_classes(read_psb_classes(classes.cast<std::filesystem::path>()));
  ModelClasses out;
  for (const py::handle label : classes) {
    const auto name = label.cast<std::string>();
    const auto known = std::find(out.names.begin(), out.names.end(), name);
    out.of_model.push_back(static_cast<Index>(known - out.names.begin()));
    if (known == out.names.end()) out.names.push_back(name);
  }
  return out;
}

}  // namespace

void bind_collection(py::module_& m) {
  const QueryOptions query_defaults;
  py::class_<Collection>(m, "Collection",
                         "Collection(path): a collection file written by `reeb index` (docs/collection-file.md). "
                         "len(c); c[i] or c['name'] -> ReebGraph; names, classes, signatures; query; distances.")
      .def(py::init([](const std::filesystem::path& path) {
             const py::gil_scoped_release release;
             CollectionReader reader(path);
             const AnalysisOptions analysis = analysis_options_from(reader.provenance().analysis_options);
             return std::make_unique<Collection>(
                 Collection{path.string(), std::move(reader), analysis, std::nullopt, nullptr});
           }),
           py::arg("path"))
      .def("__len__", [](const Collection& c) { return c.reader.size(); })
      .def("__getitem__",
           [](const Collection& c, std::int64_t i) {
             return ArrayGraph{c.reader.entry(entry_index(c, i)), {}, {}, c.analysis};
           })
      .def("__getitem__",
           [](const Collection& c, const std::string& name) {
             return ArrayGraph{c.reader.entry(entry_index(c, name)), {}, {}, c.analysis};
           })
      .def("__contains__", [](const Collection& c, const std::string& name) { return c.reader.find(name).has_value(); })
      .def(
          "graphs",
          [](const Collection& c) {
            std::vector<GraphRecord> records;
            {
              const py::gil_scoped_release release;
              records = c.reader.entries(0, c.reader.size());
            }
            py::list out;
            for (GraphRecord& r : records) out.append(ArrayGraph{std::move(r), {}, {}, c.analysis});
            return out;
          },
          "every entry as a ReebGraph, in collection order (one read per dataset)")
      .def_property_readonly("path", [](const Collection& c) { return c.path; })
      .def_property_readonly(
          "names", [](const Collection& c) { return c.reader.names(); }, "the meshes' names, in collection order")
      .def_property_readonly(
          "classes", [](const Collection& c) { return c.reader.class_labels(); },
          "the meshes' class labels ('' when none), in collection order")
      .def_property_readonly(
          "signatures",
          [](py::object self) {
            const auto& s = self.cast<const Collection&>().reader.signatures();
            return view_array(s.data(), {static_cast<py::ssize_t>(s.size() / kSignatureLength), kSignatureLength},
                              {kSignatureLength * sizeof(double), sizeof(double)}, self);
          },
          ("(N, " + std::to_string(kSignatureLength) +
           ") float64: every entry's signature (NaN rows for failed entries)")
              .c_str())
      .def_property_readonly(
          "analysis_options", [](const Collection& c) { return options_dict(c.analysis); },
          "the analysis options the collection was indexed with (query analyses meshes with them)")
      .def(
          "query",
          [](Collection& c, const py::object& query, int k, int candidates, int threads,
             const MatchingOptions& matching) {
            const bool graph = py::isinstance<ArrayGraph>(query);
            if (graph) refuse_other_analysis(c, query.cast<const ArrayGraph&>());
            const GraphRecord computed = graph ? GraphRecord() : query_record(c, query);
            const GraphRecord& record = graph ? query.cast<const ArrayGraph&>().record : computed;
            QueryOptions options;
            options.k = k;
            options.candidates = candidates;
            options.threads = threads;
            options.matching = matching;
            std::vector<QueryResult> results;
            {
              const py::gil_scoped_release release;
              results = c.query(record, options);
            }
            py::list out;
            for (std::size_t r = 0; r < results.size(); ++r) {
              py::dict row;
              row["rank"] = r + 1;
              row["name"] = results[r].name;
              row["class"] = results[r].class_label;
              row["distance"] = results[r].distance;
              row["signature_distance"] = results[r].signature_distance;
              row["index"] = results[r].index;
              out.append(row);
            }
            return out;
          },
          py::arg("query"), py::arg("k") = query_defaults.k, py::arg("candidates") = query_defaults.candidates,
          py::arg("threads") = query_defaults.threads, py::arg("matching") = MatchingOptions(),
          "Returns a list of dict (defaults: QueryOptions, as `reeb query --help`).\n\n"
          "The k entries nearest to `query` (`reeb query`): a ReebGraph, a mesh (V, F), an entry's name or a "
          "mesh file (both analysed with the collection's analysis options). Each result: rank, name, class, "
          "distance, signature_distance, index. The first query reads the collection's query file (its signature "
          "index; the candidates' graphs are read per query), or without one the whole collection.")
      .def(
          "distances",
          [](const Collection& c, int threads, const MatchingOptions& matching) {
            const std::vector<std::int64_t> rows = matrix_rows(c.reader);
            const std::string failed = failed_rows_warning(c.reader, rows);
            if (!failed.empty()) warn({failed});
            PairwiseDistances d;
            {
              const py::gil_scoped_release release;
              AllPairsOptions options;
              options.threads = threads;
              options.matching = matching;
              d = all_pairs_distances(c.reader, rows, options);
            }
            const py::ssize_t n = d.size();
            return owning_array(std::move(d.values), {n, n});
          },
          py::arg("threads") = AllPairsOptions{}.threads, py::arg("matching") = MatchingOptions(),
          "Returns an (N, N) float64 array (defaults: AllPairsOptions, as `reeb distances --help`).\n\n"
          "Graph-matching distances of every pair of entries (`reeb distances`), rows and columns in collection "
          "order (names, classes); threads=0: as many as OpenMP offers.")
      .def(
          "graph_stability",
          [](const Collection& c) {
            GraphStability s;
            {
              const py::gil_scoped_release release;
              s = graph_stability(c.reader);
            }
            py::list classes;
            for (const ClassStability& k : s.classes) {
              py::dict row;
              row["class"] = k.label;
              row["members"] = k.members;
              row["most_common"] = py::make_tuple(k.most_common.features, k.most_common.nodes, k.most_common.cycles);
              row["agreeing"] = k.agreeing;
              classes.append(row);
            }
            py::dict out;
            out["classes"] = classes;
            out["members"] = s.members;
            out["agreeing"] = s.agreeing;
            out["share"] = s.share();
            return out;
          },
          "Returns a dict: how stable the graphs of each class are (`reeb info`).\n\n"
          "Per class (in label order), its graphs built ('members'), the (feature points, nodes, cycles) most of "
          "them have ('most_common', ties to the smallest) and how many have it ('agreeing'); then the totals "
          "over every class and 'share' = agreeing / members. Entries without a class or that failed count "
          "nowhere.")
      .def("__repr__", [](const Collection& c) {
        return "<reebkit.Collection '" + c.path + "': " + std::to_string(c.reader.size()) + " meshes>";
      });

  m.def(
      "evaluate",
      [](const py::array_t<float, py::array::c_style | py::array::forcecast>& matrix, const py::object& classes) {
        if (matrix.ndim() != 2) throw py::value_error("matrix must be an (N, N) array");
        const ModelClasses model = classes_of(classes);
        const DistanceMatrix distances =
            Eigen::Map<const DistanceMatrix>(matrix.data(), matrix.shape(0), matrix.shape(1));
        RetrievalEvaluation e;
        {
          const py::gil_scoped_release release;
          e = evaluate_retrieval(distances, model);
        }
        py::dict out = scores(e.micro);
        out["macro"] = scores(e.macro);
        out["recall"] = e.recall;
        out["queries"] = e.queries.size();
        py::dict per_class;
        for (const ClassScores& c : e.classes) {
          py::dict row = scores(c.mean);
          row["size"] = c.size;
          row["queries"] = c.queries;
          per_class[c.name.c_str()] = row;
        }
        out["classes"] = per_class;
        return out;
      },
      py::arg("matrix"), py::arg("classes"),
      "evaluate(matrix, classes) -> dict\n\n"
      "The Princeton Shape Benchmark measures of a distance matrix (`reeb eval`; definitions in "
      "evaluation/retrieval_metrics.h): matrix (N, N), row i = distances from model i (converted to float32, "
      "as the PSB .matrix holds them); classes: a label per row, or a .cla file whose models are the rows in "
      "its order. Returns NN, FT, ST, E, DCG and precision (at each recall level) averaged over the queries; "
      "macro (the same averaged over the classes); recall; queries; classes (per class, with size and queries).");
}

}  // namespace reebkit::python
