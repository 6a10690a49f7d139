// reebkit.load_mesh, features, quotient_function, geodesic_distance,
// reeb_graph and analysis_options: one mesh, as `reeb features` and `reeb
// graph` analyse it.
#include "bindings.h"

#include "reebkit/geodesic/geodesic_solver.h"
#include "reebkit/mesh/load_mesh.h"

#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <limits>

namespace reebkit::python {

namespace {

/// The mesh V, F and its analysis up to f_q (AnalysisOptions::reeb_graph =
/// false) with the options given as keyword arguments, as `reeb features` runs it.
std::pair<ArrayMesh, MeshAnalysis> features_and_fq(const PointsArray& V, const IndexArray& F,
                                                   const py::kwargs& kwargs) {
  AnalysisOptions options = analysis_options(kwargs);
  options.reeb_graph = false;
  ArrayMesh mesh = mesh_argument(V, F);
  const py::gil_scoped_release release;
  MeshAnalysis analysis = analyze_mesh(mesh.mesh, options);
  return {std::move(mesh), std::move(analysis)};
}

}  // namespace

void bind_mesh(py::module_& m) {
  const std::string options_doc =
      "\n\nAnalysis options (keyword arguments; defaults as the command line's):\n" + analysis_options_doc();

  m.def(
      "load_mesh",
      [](const std::filesystem::path& path) {
        CleanedMesh cleaned;
        {
          const py::gil_scoped_release release;
          cleaned = load_mesh(path);
        }
        warn(cleaned.report.warnings);
        Mesh& mesh = cleaned.components.front();
        const auto n = static_cast<py::ssize_t>(mesh.num_vertices()),
                   f = static_cast<py::ssize_t>(mesh.num_triangles());
        return py::make_tuple(owning_array(std::move(mesh.vertices), {n, 3}),
                              owning_array(std::move(mesh.triangles), {f, 3}));
      },
      py::arg("path"),
      "load_mesh(path) -> (V, F)\n\n"
      "Reads an OFF, OBJ, PLY or STL file and cleans it as every `reeb` command does (triangulated, degenerate "
      "and duplicate faces and unused vertices dropped, largest connected component): V: (n, 3) float64, F: "
      "(m, 3) int32. Cleaning warnings become RuntimeWarnings; an unreadable file raises MeshFileError, a "
      "file without a usable mesh InvalidMeshError, both naming the file.");

  m.def(
      "features",
      [](const PointsArray& V, const IndexArray& F, const py::kwargs& kwargs) {
        const auto [mesh, analysis] = features_and_fq(V, F, kwargs);
        std::vector<Index> rows;
        for (const Index v : analysis.features.vertices) rows.push_back(analysis.mesh.source_index(v));
        const auto k = static_cast<py::ssize_t>(rows.size());
        return owning_array(std::move(rows), {k});
      },
      py::arg("V"), py::arg("F"),
      ("features(V, F, **options) -> (p,) int32\n\n"
       "The feature points of the mesh (section 4.1.2, eqs. 1-6; `reeb features`), as rows of V in selection "
       "order; -1 for a vertex added to close a hole. V: (n, 3) float64, F: (m, 3) int32." +
       options_doc)
          .c_str());

  m.def(
      "quotient_function",
      [](const PointsArray& V, const IndexArray& F, const py::kwargs& kwargs) {
        const auto [mesh, analysis] = features_and_fq(V, F, kwargs);
        return owning_array(to_input_numbering(analysis.mesh, mesh.input_vertices, analysis.fq.value,
                                               std::numeric_limits<double>::quiet_NaN()),
                            {static_cast<py::ssize_t>(mesh.input_vertices)});
      },
      py::arg("V"), py::arg("F"),
      ("quotient_function(V, F, **options) -> (n,) float64\n\n"
       "f_q = 1 - normalized geodesic distance to the nearest feature point (eqs. 7-8), in [0, 1]; NaN for a "
       "vertex left out by cleaning. V: (n, 3) float64, F: (m, 3) int32." +
       options_doc)
          .c_str());

  m.def(
      "geodesic_distance",
      [](const PointsArray& V, const IndexArray& F, const IndexArray& sources, const std::string& method) {
        if (sources.ndim() > 1) throw py::value_error("sources must be a vertex id or a 1-D array of them");
        const Geodesic geodesic = parse_geodesic(method);
        const ArrayMesh mesh = mesh_argument(V, F);
        const std::vector<Index> from =
            from_input_numbering(mesh, std::vector<Index>(sources.data(), sources.data() + sources.size()));
        DistanceField field;
        {
          const py::gil_scoped_release release;
          field = geodesic_distances(build_mesh_graph(mesh.mesh), from, geodesic);
        }
        return owning_array(to_input_numbering(mesh.mesh, mesh.input_vertices, field.distance,
                                               std::numeric_limits<double>::infinity()),
                            {static_cast<py::ssize_t>(mesh.input_vertices)});
      },
      py::arg("V"), py::arg("F"), py::arg("sources"),
      py::arg("method") = std::string(geodesic_name(FeatureOptions{}.geodesic)),
      "Returns an (n,) float64 array (default method: FeatureOptions::geodesic, as `--geodesic`).\n\n"
      "Geodesic distance of every vertex to the nearest of `sources` (a row of V or a 1-D array of them): "
      "'dijkstra' (shortest edge paths) or 'fmm' (fast marching across the triangles); inf for a vertex "
      "left out by cleaning. V: (n, 3) float64, F: (m, 3) int32.");

  m.def(
      "reeb_graph",
      [](const PointsArray& V, const IndexArray& F, const py::kwargs& kwargs) {
        const AnalysisOptions options = analysis_options(kwargs);
        ArrayMesh mesh = mesh_argument(V, F);
        const py::gil_scoped_release release;
        return graph_of(std::move(mesh), options);
      },
      py::arg("V"), py::arg("F"),
      ("reeb_graph(V, F, **options) -> ReebGraph\n\n"
       "The attributed high-level Reeb graph of the mesh (section 4.2; what `reeb graph` writes): nodes, "
       "edges, segmentation (vertex_node), f_q, skeleton, feature points, attributes. V: (n, 3) float64, F: "
       "(m, 3) int32." +
       options_doc)
          .c_str());

  m.def(
      "analysis_options", [] { return options_dict(AnalysisOptions{}); },
      "analysis_options() -> dict: every analysis option with its default (pipeline/analysis_options.h).");
}

}  // namespace reebkit::python
