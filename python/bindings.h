// What the binding files of the module share: numpy arrays that own a moved
// C++ buffer or view one held by a Python object, the mesh arguments, the
// analysis options as keyword arguments, and one registration function per
// file (module.cpp calls them).
#pragma once

#include "mesh_arrays.h"

#include "reebkit/core/option_table.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <type_traits>
#include <vector>

namespace reebkit::python {

namespace py = pybind11;

/// A numpy array of `shape` that owns `values` (a std::vector or an Eigen
/// matrix, moved into a capsule: no copy).
template <typename Container>
auto owning_array(Container&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new Container(std::move(values));
  const py::capsule owner(owned, [](void* p) { delete static_cast<Container*>(p); });
  using T = std::remove_const_t<std::remove_pointer_t<decltype(owned->data())>>;
  return py::array_t<T>(std::move(shape), owned->data(), owner);
}

/// A read-only numpy view of `data` (no copy), which `owner` keeps alive.
template <typename T>
py::array_t<T> view_array(const T* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                          py::handle owner) {
  py::array_t<T> out(std::move(shape), std::move(strides), data, owner);
  out.attr("setflags")(py::arg("write") = false);
  return out;
}

/// C-contiguous arrays of the given type (numpy converts, copying, only an
/// array of another type or layout).
using PointsArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

/// mesh_from_arrays of V (n, 3) and F (m, 3), with the GIL released; throws
/// ValueError for other shapes.
ArrayMesh mesh_argument(const PointsArray& V, const IndexArray& F);

/// Emits each warning of cleaning as a Python RuntimeWarning.
void warn(const std::vector<std::string>& warnings);

/// A Python value (int, float or str) as the value of the option `field`:
/// an int where the option is a number is that number. Throws TypeError
/// for another type; the option's set then checks the kind.
template <typename Options>
OptionValue option_value(const OptionField<Options>& field, const py::handle& value) {
  const bool number = std::holds_alternative<double>(field.get(Options{}));
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  if (py::isinstance<py::int_>(value) && !number) return value.cast<std::int64_t>();
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) return value.cast<double>();
  throw py::type_error("option " + field.name + ": expected an int, a float or a str");
}

/// The options given as keyword arguments, by the names of the rows of
/// `fields` (the others keep the library's default), each in its range.
/// Throws TypeError naming an unknown option (`what`: "analysis option"),
/// InvalidArgument (a ValueError) for a value out of its range.
template <typename Options>
Options options_from_keywords(const std::vector<OptionField<Options>>& fields, const char* what,
                              const py::kwargs& kwargs) {
  Options options;
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    const OptionField<Options>* field = find_option(fields, name);
    if (!field) throw py::type_error(std::string("unknown ") + what + " '" + name + "'");
    field->set_checked(options, option_value(*field, value));
  }
  return options;
}

/// The analysis options given as keyword arguments (options_from_keywords).
AnalysisOptions analysis_options(const py::kwargs& kwargs);

/// `options` by name (the table of pipeline/analysis_options.h), as a dict.
py::dict options_dict(const AnalysisOptions& options);

/// "name=default: help" for each analysis option, one per line, for docstrings.
std::string analysis_options_doc();

void bind_errors(py::module_& m);
void bind_graph(py::module_& m);
void bind_mesh(py::module_& m);
void bind_collection(py::module_& m);
void bind_index(py::module_& m);

}  // namespace reebkit::python
