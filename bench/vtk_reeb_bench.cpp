// reebkit's Reeb graph against VTK's vtkPolyDataToReebGraphFilter on the same
// meshes and the same scalar field f_q (built only when VTK is found:
// Debian's libvtk9-dev, not installed by tools/run).
//
//   build/bench/vtk_reeb_bench
//
// For each mesh: the time of build_reeb_graph and of the VTK filter's
// Update() (median of 3, VTK once above 60 s), their ratio, and both graphs'
// node and independent-cycle counts (and how many meshes agree on the cycles): VTK builds the full Reeb graph of the
// piecewise-linear f_q (a node per critical point), reebkit the high-level
// graph of the paper. VTK is skipped on larger meshes once a run took > 60 s.
#include "reebkit/core/timer.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkEdgeListIterator.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataToReebGraphFilter.h>
#include <vtkReebGraph.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

namespace {

using namespace reebkit;

vtkNew<vtkPolyData> to_vtk(const Mesh& mesh, const std::vector<double>& f) {
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(mesh.num_vertices());
  for (Index v = 0; v < mesh.num_vertices(); ++v)
    points->SetPoint(v, mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  vtkNew<vtkCellArray> triangles;
  for (Index t = 0; t < mesh.num_triangles(); ++t) {
    const vtkIdType ids[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    triangles->InsertNextCell(3, ids);
  }
  vtkNew<vtkDoubleArray> field;
  field->SetName("fq");
  field->SetNumberOfTuples(mesh.num_vertices());
  for (Index v = 0; v < mesh.num_vertices(); ++v) field->SetValue(v, f[static_cast<std::size_t>(v)]);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  poly->GetPointData()->AddArray(field);
  return poly;
}

// Independent cycles of a graph: #edges - #vertices + #components.
long long cycles(vtkReebGraph* graph) {
  std::vector<vtkIdType> parent(static_cast<std::size_t>(graph->GetNumberOfVertices()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](vtkIdType x) {
    while (parent[static_cast<std::size_t>(x)] != x)
      x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
  };
  long long components = graph->GetNumberOfVertices();
  vtkNew<vtkEdgeListIterator> it;
  graph->GetEdges(it);
  while (it->HasNext()) {
    const vtkEdgeType e = it->Next();
    const vtkIdType a = find(e.Source), b = find(e.Target);
    if (a != b) {
      parent[static_cast<std::size_t>(a)] = b;
      --components;
    }
  }
  return graph->GetNumberOfEdges() - graph->GetNumberOfVertices() + components;
}

double median3(std::vector<double> t) {
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

bool vtk_enabled = true;
int compared = 0, agreeing = 0;  // meshes VTK ran on, and those where both graphs have as many cycles

void compare(const std::string& name, const Mesh& input) {
  const MeshAnalysis a = analyze_mesh(input);
  std::vector<double> ours;
  for (int run = 0; run < 3; ++run) {
    Timer t;
    const ReebGraph g = build_reeb_graph(a.mesh, a.graph, a.fq.value);
    ours.push_back(t.lap());
  }
  std::printf("%-24s %9d %9.2f %6d %6d", name.c_str(), a.mesh.num_vertices(), median3(ours), a.reeb.num_nodes(),
              a.reeb.independent_cycles());
  if (!vtk_enabled) {
    std::printf("   (VTK skipped: a smaller mesh took > 60 s)\n");
    return;
  }
  const auto poly = to_vtk(a.mesh, a.fq.value);
  std::vector<double> theirs;
  long long nodes = 0, loops = 0;
  for (int run = 0; run < 3; ++run) {
    vtkNew<vtkPolyDataToReebGraphFilter> filter;
    filter->SetInputData(poly);
    filter->SetFieldId(0);
    Timer t;
    filter->Update();
    theirs.push_back(t.lap());
    nodes = filter->GetOutput()->GetNumberOfVertices();
    loops = cycles(filter->GetOutput());
    if (theirs.back() > 60e3) break;
  }
  const double vtk_ms = theirs.size() == 3 ? median3(theirs) : theirs.back();
  if (vtk_ms > 60e3) vtk_enabled = false;
  ++compared;
  agreeing += loops == a.reeb.independent_cycles();
  std::printf(" %11.1f %8.0fx %6lld %6lld%s\n", vtk_ms, vtk_ms / median3(ours), nodes, loops,
              loops == a.reeb.independent_cycles() ? "" : "  cycles differ");
}

}  // namespace

int main() {
  std::printf("%-24s %9s %9s %6s %6s %11s %9s %6s %6s\n", "mesh", "vertices", "reebkit_ms", "nodes", "cycles", "vtk_ms",
              "ratio", "nodes", "cycles");
  const std::filesystem::path data = REEBKIT_UNPACKED_DATASETS;
  // Closed meshes with handles first (those Definition 6 loses cycles on
  // among them), then larger genus-0 ones.
  for (const char* file :
       {"cgal_meshes/elk.off", "cgal_meshes/eight.off", "cgal_meshes/pipe.off", "cgal_meshes/joint.off",
        "cgal_meshes/femur.off", "cgal_meshes/pinion.off", "cgal_meshes/couplingdown.off", "cgal_meshes/turbine.off",
        "cgal_meshes/cheese.off", "shrec07_watertight/5.off", "shrec07_watertight/163.off",
        "shrec07_watertight/305.off", "cgal_meshes/bunny00.off"})
    if (std::filesystem::exists(data / file)) compare(file, load_mesh(data / file).components.front());
  for (const int genus : {1, 2, 4, 8})
    compare("holed plate genus " + std::to_string(genus), make_holed_plate(genus, 4));
  for (const int levels : {4, 5, 6, 7}) {
    StarOptions star;
    star.arms = 6;
    star.levels = levels;
    compare("star level " + std::to_string(levels), make_star(star));
  }
  std::printf("cycles agree with VTK on %d of the %d meshes VTK ran on\n", agreeing, compared);
  return 0;
}
