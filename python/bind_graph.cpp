// reebkit.ReebGraph (an attributed Reeb graph: arrays viewing the library's
// GraphRecord), reebkit.MatchingOptions and reebkit.match.
#include "bindings.h"

#include "reebkit/matching/graph_matching.h"
#include "reebkit/matching/matching_options.h"
#include "reebkit/reeb/reeb_graph.h"

#include <pybind11/stl.h>

namespace reebkit::python {

namespace {

/// Rows of a row-major table of `columns` values of type T.
template <typename T>
std::vector<py::ssize_t> row_strides(int columns) {
  return {static_cast<py::ssize_t>(columns * sizeof(T)), static_cast<py::ssize_t>(sizeof(T))};
}

/// Column `column` of a row-major table (rows x columns), viewed.
template <typename T>
py::array_t<T> column(const std::vector<T>& table, int columns, int column, py::handle owner) {
  const auto rows = static_cast<py::ssize_t>(table.size() / static_cast<std::size_t>(columns));
  return view_array(table.data() + column, {rows}, {static_cast<py::ssize_t>(columns * sizeof(T))}, owner);
}

/// Columns [first, first + count) of a row-major table, viewed.
template <typename T>
py::array_t<T> columns(const std::vector<T>& table, int width, int first, int count, py::handle owner) {
  const auto rows = static_cast<py::ssize_t>(table.size() / static_cast<std::size_t>(width));
  return view_array(table.data() + first, {rows, static_cast<py::ssize_t>(count)}, row_strides<T>(width), owner);
}

/// A vector, viewed as a 1-D array.
template <typename T>
py::array_t<T> vector_view(const std::vector<T>& values, py::handle owner) {
  return view_array(values.data(), {static_cast<py::ssize_t>(values.size())}, {sizeof(T)}, owner);
}

/// A per-vertex array of an ArrayGraph, viewed; None for a collection entry (empty).
template <typename T>
py::object per_vertex(std::vector<T> ArrayGraph::*member, py::handle self) {
  const std::vector<T>& values = self.cast<const ArrayGraph&>().*member;
  if (values.empty()) return py::none();
  return vector_view(values, self);
}

template <std::size_t N>
py::list names(const std::array<const char*, N>& names) {
  py::list out;
  for (const char* n : names) out.append(n);
  return out;
}

const GraphRecord& record_of(py::handle self) { return self.cast<const ArrayGraph&>().record; }

}  // namespace

void bind_graph(py::module_& m) {
  py::list types;
  for (const NodeType t : {NodeType::Root, NodeType::Bifurcation, NodeType::Junction, NodeType::Termination})
    types.append(node_type_name(t));
  m.attr("NODE_TYPES") = py::tuple(types);

  py::class_<ArrayGraph>(m, "ReebGraph",
                         "An attributed high-level Reeb graph (attributes/graph_record.h): from reeb_graph(V, F) "
                         "or an entry of a Collection. Arrays are read-only views of the graph (no copy). Vertex "
                         "ids are rows of V (-1: a vertex added to close a hole).")
      .def_property_readonly(
          "name", [](const ArrayGraph& g) { return g.record.name; },
          "the mesh's name in its collection ('' for reeb_graph)")
      .def_property_readonly(
          "class_label", [](const ArrayGraph& g) { return g.record.class_label; },
          "its class in the collection ('' when none)")
      .def_property_readonly(
          "ok", [](const ArrayGraph& g) { return g.record.ok; },
          "False for a collection entry that failed (see error): no graph")
      .def_property_readonly("error", [](const ArrayGraph& g) { return g.record.error; })
      .def_property_readonly("num_nodes", [](const ArrayGraph& g) { return g.record.num_nodes(); })
      .def_property_readonly(
          "nodes",
          [](py::object self) {
            const GraphRecord& r = record_of(self);
            py::dict out;
            out["type"] = column(r.nodes, kNodeColumnCount, kNodeType, self);
            out["end"] = column(r.nodes, kNodeColumnCount, kNodeEnd, self);
            out["birth_vertex"] = column(r.nodes, kNodeColumnCount, kNodeBirthVertex, self);
            out["vertex_count"] = column(r.nodes, kNodeColumnCount, kNodeVertexCount, self);
            out["area"] = column(r.node_geometry, kGeomColumnCount, kGeomArea, self);
            out["fq_min"] = column(r.node_geometry, kGeomColumnCount, kGeomFqMin, self);
            out["fq_max"] = column(r.node_geometry, kGeomColumnCount, kGeomFqMax, self);
            out["barycenter"] = columns(r.node_geometry, kGeomColumnCount, kGeomBarycenterX, 3, self);
            return out;
          },
          "dict of (k,) arrays: type and end (int32 indices into NODE_TYPES: how the node's region starts "
          "and ends), birth_vertex, vertex_count (int32), area, fq_min, fq_max (float64); barycenter (k, 3)")
      .def_property_readonly(
          "edges", [](py::object self) { return columns(record_of(self).edges, 2, 0, 2, self); },
          "(e, 2) int32: (earlier node, later node), sorted")
      .def_property_readonly(
          "node_attributes",
          [](py::object self) {
            return columns(record_of(self).node_attributes, kNodeAttributeCount, 0, kNodeAttributeCount, self);
          },
          "(k, 26) float64: the invariant node attributes, columns NODE_ATTRIBUTES")
      .def_property_readonly(
          "edge_attributes",
          [](py::object self) {
            return columns(record_of(self).edge_attributes, kEdgeAttributeCount, 0, kEdgeAttributeCount, self);
          },
          "(e, 2) float64: the edge attributes, columns EDGE_ATTRIBUTES")
      .def_property_readonly(
          "signature", [](py::object self) { return vector_view(record_of(self).signature, self); },
          "(48,) float64: the fixed-length signature of the query pre-filter, entries SIGNATURE")
      .def_property_readonly(
          "feature_points", [](py::object self) { return vector_view(record_of(self).feature_points, self); },
          "(p,) int32: the feature points (vertex ids), in selection order")
      .def_property_readonly(
          "skeleton",
          [](py::object self) {
            const GraphRecord& r = record_of(self);
            py::list out;
            for (std::size_t n = 0; n + 1 < r.skeleton_offset.size(); ++n) {
              const auto first = r.skeleton_offset[n], count = r.skeleton_offset[n + 1] - first;
              out.append(view_array(r.skeleton_points.data() + 3 * first, {static_cast<py::ssize_t>(count), 3},
                                    row_strides<double>(3), self));
            }
            return out;
          },
          "list of (s_i, 3) float64 arrays: each node's part of the topological skeleton")
      .def_property_readonly(
          "vertex_node", [](py::object self) { return per_vertex(&ArrayGraph::vertex_node, self); },
          "(n,) int32: the node of each vertex (the segmentation), -1 for a vertex left out by cleaning; "
          "None for a collection entry")
      .def_property_readonly(
          "fq", [](py::object self) { return per_vertex(&ArrayGraph::fq, self); },
          "(n,) float64: the quotient function f_q the graph was built from, NaN for a vertex left out; None for "
          "a collection entry")
      .def_property_readonly(
          "cycles", [](const ArrayGraph& g) { return independent_cycles(g.record); },
          "independent cycles (first Betti number) of the graph")
      .def_property_readonly("leaves", [](const ArrayGraph& g) { return leaf_count(g.record); })
      .def(
          "to_networkx",
          [](py::object self) {
            const GraphRecord& r = record_of(self);
            const py::object graph = py::module_::import("networkx").attr("Graph")();
            const py::dict nodes = self.attr("nodes");
            for (std::int32_t n = 0; n < r.num_nodes(); ++n) {
              py::dict data;
              for (const auto& [key, values] : nodes) data[key] = values[py::int_(n)];
              data["type"] = node_type_name(static_cast<NodeType>(r.nodes[n * kNodeColumnCount + kNodeType]));
              data["end"] = node_type_name(static_cast<NodeType>(r.nodes[n * kNodeColumnCount + kNodeEnd]));
              graph.attr("add_node")(n, **data);
            }
            for (std::int32_t e = 0; e < r.num_edges(); ++e) graph.attr("add_edge")(r.edges[2 * e], r.edges[2 * e + 1]);
            return graph;
          },
          "The graph as a networkx.Graph (needs networkx): nodes 0..k-1 with the entries of `nodes` as "
          "attributes (type and end by name).")
      .def("__repr__", [](const ArrayGraph& g) {
        return "<reebkit.ReebGraph " + (g.record.name.empty() ? std::string() : "'" + g.record.name + "' ") +
               std::to_string(g.record.num_nodes()) + " nodes, " + std::to_string(g.record.num_edges()) + " edges, " +
               std::to_string(independent_cycles(g.record)) + " cycles>";
      });
  m.attr("NODE_ATTRIBUTES") = names(kNodeAttributeNames);
  m.attr("EDGE_ATTRIBUTES") = names(kEdgeAttributeNames);
  m.attr("SIGNATURE") = names(kSignatureNames);

  py::class_<MatchingOptions> matching_options(
      m, "MatchingOptions",
      "The cost model of graph matching (matching/graph_matching.h, docs/method.md); the defaults are the "
      "library's, as `reeb match --help` shows them; each option is checked against its range when set.");
  matching_options
      .def(py::init([](const py::kwargs& kwargs) {
             return options_from_keywords(matching_option_fields(), "matching option", kwargs);
           }),
           "The library's defaults, or those given as keywords (MatchingOptions(unmatched_cost=2.0)).")
      .def("__repr__", [](const MatchingOptions& options) {
        std::string fields;
        for (const NamedOption& option : named_options(matching_option_fields(), options))
          fields += (fields.empty() ? "" : ", ") + option.name + "=" + option_text(option.value);
        return "MatchingOptions(" + fields + ")";
      });
  // One property per row of the table (matching/matching_options.h), each
  // value checked against its range when set.
  for (const MatchingOptionField& field : matching_option_fields())
    matching_options.def_property(
        field.name.c_str(),
        [&field](const MatchingOptions& options) {
          return std::visit([](const auto& v) -> py::object { return py::cast(v); }, field.get(options));
        },
        [&field](MatchingOptions& options, const py::object& value) {
          field.set_checked(options, option_value(field, value));
        },
        field.help.c_str());

  m.def(
      "match",
      [](const ArrayGraph& a, const ArrayGraph& b, const MatchingOptions& options) {
        GraphMatch match;
        {
          const py::gil_scoped_release release;
          match = match_graphs(a.record, b.record, options);
        }
        const auto k = static_cast<py::ssize_t>(match.correspondence.size());
        return py::make_tuple(match.distance, owning_array(std::move(match.correspondence), {k}));
      },
      py::arg("g1"), py::arg("g2"), py::arg("matching") = MatchingOptions(),
      "Returns (distance, correspondence).\n\n"
      "The graph-matching distance of two ReebGraphs (as `reeb match`) and, for each node of g1, the node of g2 "
      "it is matched to: (k1,) int32, -1 for a deleted node.");
}

}  // namespace reebkit::python
