// reebkit.index: `reeb index` from Python (a collection of meshes into one
// collection file, resumable), with its progress handed to a callable and
// Ctrl-C (KeyboardInterrupt) handled as the command handles it.
#include "bindings.h"

#include "reebkit/collection/extract_collection.h"
#include "reebkit/collection/mesh_inputs.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/retrieval/query.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace reebkit::python {

namespace {

/// A path (str or os.PathLike) or a list of them, as strings.
std::vector<std::string> paths_argument(const py::object& inputs) {
  if (py::isinstance<py::str>(inputs) || py::hasattr(inputs, "__fspath__"))
    return {inputs.cast<std::filesystem::path>().string()};
  std::vector<std::string> out;
  for (const std::filesystem::path& path : inputs.cast<std::vector<std::filesystem::path>>())
    out.push_back(path.string());
  return out;
}

py::dict state_dict(const ProgressState& s) {
  py::dict out;
  out["total"] = s.total;
  out["ok"] = s.ok;
  out["failed"] = s.failed;
  out["skipped"] = s.skipped;
  out["seconds"] = s.seconds;
  return out;
}

}  // namespace

void bind_index(py::module_& m) {
  const std::string doc =
      "Indexes meshes into a collection file, as `reeb index INPUTS -o OUTPUT`: inputs is a folder (searched "
      "recursively for .off .obj .ply .stl), a list file (.txt .lst) or a mesh file, or a list of them; classes a "
      "PSB .cla file. threads=0 uses as many as OpenMP offers; resume=True keeps the entries already in the file "
      "and computes only new or changed meshes. progress, when given, is called after each mesh written with a "
      "dict (total, ok, failed, skipped, seconds). A mesh that fails is a failed entry of the file and the run "
      "goes on. Ctrl-C (KeyboardInterrupt), or an exception of progress, stops the run once the meshes in "
      "progress are written, then is raised; the file (OUTPUT.partial for a new collection) keeps every entry "
      "and resume=True completes it. Writes the query file beside the collection, as the command does. Returns "
      "{'file', 'ok', 'failed': [(name, reason)], 'skipped', 'kept', 'seconds'}.\n\nAnalysis options (keyword "
      "arguments; the collection keeps them; defaults as the command line's):\n" +
      analysis_options_doc();
  m.def(
      "index",
      [](const py::object& inputs, const std::filesystem::path& output,
         const std::optional<std::filesystem::path>& classes, int threads, bool resume, const py::object& progress,
         const py::kwargs& kwargs) {
        const std::string out_path = output.string();
        const std::vector<MeshInput> meshes = list_mesh_inputs(paths_argument(inputs));
        ExtractionOptions options;
        options.threads = threads;
        options.resume = resume;
        options.analysis = analysis_options(kwargs);
        options.command = "reebkit.index";
        std::vector<PsbClass> cla;
        if (classes) {
          options.classes_file = classes->string();
          cla = read_psb_classes(options.classes_file);
        }
        // The callable and Python's signal handlers run on the writer, which
        // is this thread: a KeyboardInterrupt (Ctrl-C) or an exception of the
        // callable stops the run as `reeb index`'s Ctrl-C does, and is raised
        // once the meshes in progress are written.
        std::atomic<bool> stop{false};
        std::optional<py::error_already_set> raised;
        options.stop = &stop;
        options.progress = [&](const ProgressState& state) {
          const py::gil_scoped_acquire gil;
          if (raised) return;
          try {
            if (!progress.is_none()) progress(state_dict(state));
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
          } catch (py::error_already_set& e) {
            raised.emplace(std::move(e));
            stop = true;
          }
        };
        ExtractionSummary summary;
        {
          const py::gil_scoped_release release;
          summary = extract_collection(meshes, cla, out_path, options);
          if (!summary.interrupted && !summary.all_failed) write_query_file(CollectionReader(out_path));
        }
        if (raised) {
          if (summary.interrupted && raised->matches(PyExc_KeyboardInterrupt)) {
            const std::string message = "reebkit.index interrupted: " + summary.file.string() + " holds " +
                                        std::to_string(summary.entries()) +
                                        " entries; index(..., resume=True) computes the others";
            PyErr_SetString(PyExc_KeyboardInterrupt, message.c_str());
            throw py::error_already_set();
          }
          throw std::move(*raised);
        }
        if (summary.all_failed)
          throw Error(out_path + ": every mesh failed (" + std::to_string(summary.failed.size()) +
                      "), the first: " + summary.failed.front().name + ": " + summary.failed.front().reason);
        py::dict out;
        out["file"] = summary.file.string();
        out["ok"] = summary.ok;
        py::list failed;
        for (const FailedMesh& f : summary.failed) failed.append(py::make_tuple(f.name, f.reason));
        out["failed"] = failed;
        out["skipped"] = summary.skipped;
        out["kept"] = summary.kept;
        out["seconds"] = summary.seconds;
        return out;
      },
      py::arg("inputs"), py::arg("output"), py::arg("classes") = py::none(), py::arg("threads") = 0,
      py::arg("resume") = false, py::arg("progress") = py::none(), doc.c_str());
}

}  // namespace reebkit::python
