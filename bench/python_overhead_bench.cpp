// The C++ side of bench/python_overhead.py: the call that reebkit.reeb_graph(V, F)
// makes (mesh_from_arrays + graph_of, python/mesh_arrays.h), timed without Python.
//
//   build/bench/python_overhead_bench MESH.off RUNS
//
// Writes a torus of 100,000 faces to MESH.off (what the Python side loads),
// reads it back and prints the milliseconds of each of RUNS calls on its
// arrays, one per line.
#include "mesh_arrays.h"

#include "reebkit/core/timer.h"
#include "reebkit/io/off.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/mesh/shapes.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: python_overhead_bench MESH.off RUNS\n");
    return 2;
  }
  reebkit::write_off(argv[1], reebkit::make_torus(250, 200));  // 50,000 vertices, 100,000 faces
  const reebkit::Mesh mesh = reebkit::load_mesh(argv[1]).components.front();
  const int runs = std::stoi(argv[2]);
  for (int run = 0; run < runs; ++run) {
    reebkit::Timer timer;
    const auto graph =
        reebkit::python::graph_of(reebkit::python::mesh_from_arrays(mesh.vertices.data(), mesh.num_vertices(),
                                                                    mesh.triangles.data(), mesh.num_triangles()),
                                  reebkit::AnalysisOptions{});
    std::printf("%.3f\n", timer.lap());
    if (graph.record.nodes.empty()) return 1;
  }
  return 0;
}
