// A generated collection for the memory experiment of index_bench.sh:
// N small meshes as OFF files (stars with 1-6 arms and tori of several sizes,
// about 150-400 vertices each), named 00000.off, 00001.off, ...
//
//   build/bench/make_collection DIR N
#include "reebkit/io/off.h"
#include "reebkit/mesh/shapes.h"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: make_collection DIR N\n";
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    const int n = std::stoi(argv[2]);
    std::filesystem::create_directories(dir);
    for (int i = 0; i < n; ++i) {
      char name[32];
      std::snprintf(name, sizeof name, "%05d.off", i);
      reebkit::StarOptions star;
      star.arms = 1 + i % 6;
      star.levels = 2;
      star.twist = 0.37 * i;
      const reebkit::Mesh mesh = i % 4 == 3 ? reebkit::make_torus(16 + i % 9, 8 + i % 5) : reebkit::make_star(star);
      reebkit::write_off(dir / name, mesh);
    }
  } catch (const std::exception& e) {
    std::cerr << "make_collection: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
