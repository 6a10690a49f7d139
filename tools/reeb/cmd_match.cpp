// reeb match A B [--obj lines.obj]: the graph-matching distance of two
// meshes (matching/graph_matching.h) and the node correspondence. A and B
// are mesh files, analysed on the fly, or COLLECTION.h5:NAME entries.
#include "reeb/cli.h"
#include "reebkit/core/error.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/matching/graph_matching.h"
#include "reebkit/output/obj_lines.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/pipeline/mesh_record.h"
#include "reebkit/reeb/reeb_graph.h"
#include "reebkit/store/collection_file.h"

#include <algorithm>
#include <array>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>

namespace reebkit::cli {

namespace {

/// The collection file and entry name of a COLLECTION.h5:NAME spec; nothing for a mesh file.
std::optional<std::pair<std::string, std::string>> collection_entry(const std::string& spec) {
  const auto colon = spec.find(".h5:");
  if (colon == std::string::npos) return std::nullopt;
  return std::pair{spec.substr(0, colon + 3), spec.substr(colon + 4)};
}

/// The entry named by `spec`: COLLECTION.h5:NAME, or a mesh file whose
/// largest component is analysed with `analysis`.
GraphRecord entry_for(const std::string& spec, const AnalysisOptions& analysis) {
  const auto in_collection = collection_entry(spec);
  if (!in_collection) return analyze_mesh_file(spec, spec, analysis);
  const auto& [path, name] = *in_collection;
  const CollectionReader reader(path);
  const auto index = reader.find(name);
  if (!index) throw Error(path + ": no mesh named '" + name + "' (reeb info --list lists them)");
  GraphRecord entry = reader.entry(*index);
  if (!entry.ok) throw Error(path + ": mesh '" + name + "' failed when indexed: " + entry.error);
  return entry;
}

/// The analysis of the mesh files among the two specs: the command line's,
/// or the collection's when the other is a collection entry (then an
/// analysis option given on the command line is an error: the two graphs
/// would not be comparable).
AnalysisOptions analysis_of_files(const std::string& a, const std::string& b, const AnalysisOptions& command_line,
                                  const po::variables_map& vm) {
  const auto ca = collection_entry(a), cb = collection_entry(b);
  if (ca.has_value() == cb.has_value()) return command_line;
  const std::string& collection = ca ? ca->first : cb->first;
  const std::vector<std::string> given = given_analysis_options(vm);
  if (!given.empty())
    throw Error("the mesh file is analysed with the analysis options of " + collection +
                ", as its entries were: drop the analysis option " + given.front());
  return analysis_options_from(CollectionReader(collection).provenance().analysis_options);
}

std::string node_label(const GraphRecord& e, std::int32_t node) {
  const auto row = static_cast<std::size_t>(node) * kNodeColumnCount;
  return std::string(node_type_name(static_cast<NodeType>(e.nodes[row + kNodeType]))) + "->" +
         node_type_name(static_cast<NodeType>(e.nodes[row + kNodeEnd]));
}

double relative_area(const GraphRecord& e, std::int32_t node) {
  return e.node_attributes[static_cast<std::size_t>(node) * kNodeAttributeCount + kNodeRelativeArea];
}

void print_match(const GraphRecord& a, const GraphRecord& b, const GraphMatch& match) {
  std::cout << std::defaultfloat << std::setprecision(6) << "distance " << match.distance << "\n"
            << "A: " << a.name << " (" << a.num_nodes() << " nodes, " << a.num_edges() << " edges)\n"
            << "B: " << b.name << " (" << b.num_nodes() << " nodes, " << b.num_edges() << " edges)\n"
            << "correspondence (node, start->end type, relative area):\n";
  std::vector<char> matched(static_cast<std::size_t>(b.num_nodes()), 0);
  const auto side = [](const GraphRecord& e, std::int32_t node) {
    std::ostringstream s;
    s << std::setw(4) << node << "  " << std::left << std::setw(26) << node_label(e, node) << std::right << std::fixed
      << std::setprecision(4) << relative_area(e, node);
    return s.str();
  };
  for (std::int32_t i = 0; i < a.num_nodes(); ++i) {
    const std::int32_t j = match.correspondence[static_cast<std::size_t>(i)];
    std::cout << "  A " << side(a, i);
    if (j >= 0) {
      matched[static_cast<std::size_t>(j)] = 1;
      std::cout << "  <->  B " << side(b, j) << "\n";
    } else {
      std::cout << "  deleted\n";
    }
  }
  for (std::int32_t j = 0; j < b.num_nodes(); ++j)
    if (!matched[static_cast<std::size_t>(j)])
      std::cout << "  inserted" << std::string(37, ' ') << "B " << side(b, j) << "\n";
}

using Box = std::array<double, 2>;  // smallest and largest x

/// x range of a graph's node barycenters and skeleton points.
Box x_range(const GraphRecord& e) {
  Box box = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  const auto extend = [&](double x) { box = {std::min(box[0], x), std::max(box[1], x)}; };
  for (std::size_t i = 0; i < static_cast<std::size_t>(e.num_nodes()); ++i)
    extend(e.node_geometry[i * kGeomColumnCount + kGeomBarycenterX]);
  for (std::size_t p = 0; p < e.skeleton_points.size() / 3; ++p) extend(e.skeleton_points[3 * p]);
  return box;
}

/// Both graphs as OBJ lines between node barycenters (B shifted along x to
/// stand half A's width to the right of A), and a line per matched pair.
void write_obj(const std::string& path, const GraphRecord& a, const GraphRecord& b, const GraphMatch& match) {
  std::ostringstream out;
  const Box ba = x_range(a), bb = x_range(b);
  const double shift = ba[1] - bb[0] + 0.5 * (ba[1] - ba[0]);
  std::ostringstream title, vertices_note;
  title << "reeb match " << a.name << " " << b.name << ": distance " << match.distance;
  vertices_note << "vertices: node barycenters of A, then of B (shifted by " << shift << " along x)";
  ObjLinesWriter obj(out);
  obj.comment(title.str()).comment(vertices_note.str());
  const auto vertices = [&](const GraphRecord& e, double dx) {
    for (std::size_t i = 0; i < static_cast<std::size_t>(e.num_nodes()); ++i) {
      const double* g = &e.node_geometry[i * kGeomColumnCount];
      obj.point(Vec3(g[kGeomBarycenterX] + dx, g[kGeomBarycenterY], g[kGeomBarycenterZ]));
    }
  };
  vertices(a, 0.0);
  vertices(b, shift);
  const auto edges = [&](const char* name, const GraphRecord& e, Index first) {
    obj.object(name);
    for (std::size_t k = 0; k < static_cast<std::size_t>(e.num_edges()); ++k)
      obj.line({first + e.edges[2 * k], first + e.edges[2 * k + 1]});
  };
  edges("graph_a", a, 1);
  edges("graph_b", b, 1 + a.num_nodes());
  obj.object("correspondence");
  for (std::int32_t i = 0; i < a.num_nodes(); ++i) {
    const std::int32_t j = match.correspondence[static_cast<std::size_t>(i)];
    if (j >= 0) obj.line({1 + i, 1 + a.num_nodes() + j});
  }
  write_file_bytes(path, out.str());
}

}  // namespace

int run_match(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string spec_a, spec_b, obj_path;
  AnalysisOptions analysis;
  MatchingOptions matching;
  options
      .add_options()("a", po::value(&spec_a)->required(),
                     "first mesh: a mesh file or COLLECTION.h5:NAME")("b", po::value(&spec_b)->required(),
                                                                      "second mesh: a mesh file or COLLECTION.h5:NAME")(
          "obj", po::value(&obj_path), "write both graphs and lines between matched node barycenters as OBJ");
  options.add(analysis_options(analysis)).add(matching_options(matching));
  po::positional_options_description positional;
  positional.add("a", 1).add("b", 1);
  po::variables_map vm;
  if (!parse(args,
             "reeb match A B [--obj lines.obj] [analysis options] [matching options]\n"
             "(A, B: mesh files or collection.h5:NAME; a mesh file matched with a collection entry is analysed "
             "with the collection's analysis options)",
             options, positional, vm))
    return 0;
  const auto file_of = [](const std::string& spec) {
    const auto in_collection = collection_entry(spec);
    return in_collection ? in_collection->first : spec;
  };
  check_outputs({obj_path}, {file_of(spec_a), file_of(spec_b)});
  const AnalysisOptions files = analysis_of_files(spec_a, spec_b, analysis, vm);
  const GraphRecord a = entry_for(spec_a, files), b = entry_for(spec_b, files);
  const GraphMatch match = match_graphs(a, b, matching);
  print_match(a, b, match);
  if (!obj_path.empty()) {
    write_obj(obj_path, a, b, match);
    std::cout << "wrote " << obj_path << "\n";
  }
  return 0;
}

}  // namespace reebkit::cli
