#include "reeb/cli.h"

#include "reebkit/core/timer.h"

#include <iomanip>
#include <iostream>

namespace reebkit::cli {

bool parse(const std::vector<std::string>& args, const std::string& usage,
           const po::options_description& options, const po::positional_options_description& positional,
           po::variables_map& vm) {
  po::options_description all(options);
  all.add_options()("help,h", "show this help");
  po::store(po::command_line_parser(args).options(all).positional(positional).run(), vm);
  if (vm.count("help")) {
    std::cout << "usage: " << usage << "\n\n" << all << "\n";
    return false;
  }
  po::notify(vm);
  return true;
}

void add_geodesic_option(po::options_description& options, Geodesic& method) {
  options.add_options()("geodesic",
                        po::value<std::string>()
                            ->default_value(geodesic_name(method))
                            ->notifier([&method](const std::string& name) { method = parse_geodesic(name); }),
                        "geodesic distances: dijkstra (shortest edge paths) or fmm (fast marching across the "
                        "triangles, less sensitive to the sampling)");
}

void add_min_persistence_option(po::options_description& options, double& min_persistence) {
  options.add_options()("min-persistence", po::value(&min_persistence)->default_value(min_persistence),
                        "drop the extrema of f1 and f2 whose topological persistence is below this fraction of "
                        "the geodesic diameter before the relaxed intersection (0: every local extremum, as the "
                        "paper)");
}

LoadedMesh load_for_command(const std::string& path, bool all_components) {
  Timer timer;
  CleanupOptions cleanup;
  cleanup.keep_all_components = all_components;
  LoadedMesh out{load_mesh(path, cleanup), 0.0};
  out.milliseconds = timer.lap();
  for (const std::string& w : out.cleaned.report.warnings) std::cerr << "warning: " << w << "\n";
  std::cout << path << ": read and cleaned in " << std::fixed << std::setprecision(2) << out.milliseconds << " ms\n"
            << std::defaultfloat;
  return out;
}

}  // namespace reebkit::cli
