// The Python module `reebkit` (docs/python.md): numpy arrays in and out,
// each function a thin call into the library.
#include "bindings.h"

#include "reebkit/core/error.h"
#include "reebkit/core/option_value.h"
#include "reebkit/core/version.h"
#include "reebkit/pipeline/analysis_options.h"

namespace reebkit::python {

ArrayMesh mesh_argument(const PointsArray& V, const IndexArray& F) {
  if (V.ndim() != 2 || V.shape(1) != 3) throw py::value_error("V must be an (n, 3) array of vertex positions");
  if (F.ndim() != 2 || F.shape(1) != 3) throw py::value_error("F must be an (m, 3) array of triangle vertex ids");
  const double* vertices = V.data();
  const std::int32_t* faces = F.data();
  const auto n = static_cast<Index>(V.shape(0)), m = static_cast<Index>(F.shape(0));
  ArrayMesh out;
  {
    const py::gil_scoped_release release;
    out = mesh_from_arrays(vertices, n, faces, m);
  }
  warn(out.warnings);
  return out;
}

void warn(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (PyErr_WarnEx(PyExc_RuntimeWarning, w.c_str(), 2) != 0) throw py::error_already_set();
}

AnalysisOptions analysis_options(const py::kwargs& kwargs) {
  return options_from_keywords(analysis_option_fields(), "analysis option", kwargs);
}

py::dict options_dict(const AnalysisOptions& options) {
  py::dict out;
  for (const NamedOption& option : named_analysis_options(options))
    out[option.name.c_str()] = std::visit([](const auto& v) -> py::object { return py::cast(v); }, option.value);
  return out;
}

std::string analysis_options_doc() {
  std::string doc;
  const AnalysisOptions defaults;
  for (const AnalysisOptionField& field : analysis_option_fields()) {
    // As Python writes the value (0.0, 0.05, 'fmm'), the keyword argument's literal.
    const std::string literal =
        py::repr(std::visit([](const auto& v) -> py::object { return py::cast(v); }, field.get(defaults)));
    doc += "    " + field.name + "=" + literal + ": " + field.help + "\n";
  }
  return doc;
}

void bind_errors(py::module_& m) {
  // Derived classes registered last: pybind11 tries the latest translator first.
  auto& error = py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  error.doc() = "Base class of every error reebkit raises; the message names the file and the problem.";
  py::register_exception<MeshFileError>(m, "MeshFileError", error).doc() =
      "A mesh file that cannot be opened or parsed: '<file>:<line>: <problem>'.";
  py::register_exception<InvalidMeshError>(m, "InvalidMeshError", error).doc() =
      "A mesh that cannot be used (no faces, non-finite coordinates, ...): '<source>: <problem>'.";
  py::register_exception<InvalidArgument>(m, "InvalidArgument", py::make_tuple(error, py::handle(PyExc_ValueError)))
      .doc() = "A broken precondition (bad option value, vertex id out of range, ...); also a ValueError.";
}

}  // namespace reebkit::python

PYBIND11_MODULE(reebkit, m) {
  namespace rp = reebkit::python;
  m.doc() =
      "reebkit: invariant high-level Reeb graphs of triangle meshes (Tierny et al. 2006), numpy arrays in and "
      "out. Meshes are V: (n, 3) float64 vertex positions and F: (m, 3) int32 triangles; per-vertex results "
      "are numbered as the rows of V. Documentation: docs/python.md.";
  m.attr("__version__") = REEBKIT_VERSION;
  rp::bind_errors(m);
  rp::bind_graph(m);
  rp::bind_mesh(m);
  rp::bind_collection(m);
  rp::bind_index(m);
}
