// reeb deform MESH --node N --angle DEG -o posed.off: turns the component of
// a Reeb graph node about the loop where it attaches to the rest of the shape
// (Tierny et al. 2006, section 5.2, figure 10b). Without --node, lists the
// nodes to choose from.
#include "reeb/cli.h"
#include "reebkit/core/error.h"
#include "reebkit/deform/deformation.h"
#include "reebkit/io/mesh_io.h"

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace reebkit::cli {

namespace {

std::ostream& operator<<(std::ostream& out, const Vec3& p) {
  return out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
}

void list_nodes(const ReebGraph& g) {
  std::cout << g.num_nodes() << " Reeb graph nodes (pick one with --node; edges go from parent to child):\n"
            << "  node  starts at    ends at      vertices  f_q range      barycenter\n";
  for (Index n = 0; n < g.num_nodes(); ++n) {
    const ReebNode& node = g.nodes[static_cast<std::size_t>(n)];
    std::cout << "  " << std::setw(4) << n << "  " << std::left << std::setw(12) << node_type_name(node.type) << " "
              << std::setw(12) << node_type_name(node.end) << std::right << " " << std::setw(8) << node.vertex_count
              << "  " << std::fixed << std::setprecision(3) << node.fq_min << "-" << node.fq_max << std::defaultfloat
              << std::setprecision(6) << "    " << node.barycenter << "\n";
  }
  std::cout << "edges:";
  for (const auto& [a, b] : g.edges) std::cout << " " << a << "->" << b;
  std::cout << "\n";
}

void print(const MeshAnalysis& a, const Deformation& plan) {
  const auto moved = std::count_if(plan.weight.begin(), plan.weight.end(), [](double w) { return w > 0.0; });
  const auto full = std::count(plan.weight.begin(), plan.weight.end(), 1.0);
  std::cout << "component: node" << (plan.nodes.size() > 1 ? "s" : "");
  for (const Index n : plan.nodes) std::cout << " " << n;
  std::cout << "\npivot " << plan.pivot << " (the node's first skeleton point; " << plan.attach_loop.size()
            << " attach-loop vertices), axis " << plan.axis << ", angle " << plan.angle_degrees << " degrees\n"
            << "moved " << moved << " of " << a.mesh.num_vertices() << " vertices (" << full
            << " by the full angle); vertex ids as in the file:";
  Index shown = 0;
  for (Index v = 0; v < a.mesh.num_vertices() && shown < 20; ++v)
    if (plan.weight[static_cast<std::size_t>(v)] > 0.0 && a.mesh.source_index(v) != kInvalidIndex) {
      std::cout << " " << a.mesh.source_index(v);
      ++shown;
    }
  std::cout << (moved > shown ? " ..." : "") << "\n";
}

}  // namespace

int run_deform(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string mesh_path, out_path;
  DeformOptions deform;
  std::vector<double> axis;
  options.add_options()("mesh", po::value(&mesh_path)->required(), "mesh file (.off .obj .ply .stl)")(
      "node", po::value(&deform.node),
      "Reeb graph node whose component turns (omit to list the nodes)")("angle",
                                                                        po::value(&deform.angle_degrees)
                                                                            ->default_value(deform.angle_degrees),
                                                                        "rotation angle, degrees")(
      "axis", po::value(&axis)->multitoken(),
      "rotation axis x y z (default: from the geometry, positive angles fold the component towards the root)")(
      "falloff", po::value(&deform.falloff)->default_value(deform.falloff),
      "fraction of the component's extent over which the rotation ramps up from 0, in [0, 1]")(
      "output,o", po::value(&out_path),
      "write the posed mesh (.off or .ply): the analyzed mesh, i.e. cleaned, small holes filled (new vertices last)");
  po::positional_options_description positional;
  positional.add("mesh", 1);
  po::variables_map vm;
  if (!parse(args, "reeb deform MESH --node N --angle DEG [--axis X Y Z] [--falloff F] -o posed.off", options,
             positional, vm))
    return 0;
  if (!axis.empty() && axis.size() != 3) throw po::error("--axis takes three numbers");
  if (axis.size() == 3) deform.axis = Vec3(axis[0], axis[1], axis[2]);
  if (vm.count("node") && out_path.empty()) throw po::error("the option '--output' is required with --node");
  check_outputs({out_path}, {mesh_path});

  CleanedMesh cleaned = load_for_command(mesh_path, false).cleaned;
  AnalysisOptions graph_alone;  // no attributes: the graph and its regions are what a deformation needs
  graph_alone.prepare_attributes = false;
  const MeshAnalysis analysis = analyze_mesh(std::move(cleaned.components.front()), graph_alone);
  std::cout << mesh_path << ": " << analysis.mesh.num_vertices() << " vertices, " << analysis.reeb.num_nodes()
            << " Reeb graph nodes, " << analysis.features.vertices.size() << " feature points\n";
  if (!vm.count("node")) {
    list_nodes(analysis.reeb);
    return 0;
  }
  const Deformation plan = plan_deformation(analysis, deform);
  print(analysis, plan);
  write_mesh(out_path, apply_deformation(analysis.mesh, plan));
  std::cout << "wrote " << out_path << "\n";
  return 0;
}

}  // namespace reebkit::cli
