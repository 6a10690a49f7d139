#include "reeb/cli.h"

#include "reebkit/core/option_value.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/store/collection_file.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace reebkit::cli {

namespace {

/// "min_persistence" -> "min-persistence".
std::string flag_name(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

/// A value stored in `field`, its current value the default, shown in its shortest exact form.
template <typename T>
po::typed_value<T>* defaulted(T* field) {
  if constexpr (std::is_integral_v<T>)
    return po::value(field)->default_value(*field, option_text(static_cast<std::int64_t>(*field)));
  else
    return po::value(field)->default_value(*field, option_text(*field));
}

}  // namespace

bool parse(const std::vector<std::string>& args, const std::string& usage,
           const po::options_description& options, const po::positional_options_description& positional,
           po::variables_map& vm) {
  po::options_description all(options);
  all.add_options()("help,h", "show this help")("verbose", "on a failure of HDF5, also print its error stack");
  po::store(po::command_line_parser(args).options(all).positional(positional).run(), vm);
  if (vm.count("help")) {
    std::cout << "usage: " << usage << "\n\n" << all << "\n";
    return false;
  }
  po::notify(vm);
  print_hdf5_error_stacks(vm.count("verbose") > 0);
  return true;
}

void check_outputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  const std::vector<std::filesystem::path> input_paths(inputs.begin(), inputs.end());
  for (const std::string& output : outputs)
    if (!output.empty()) check_output_file(output, input_paths);
}

po::options_description analysis_options(AnalysisOptions& analysis) {
  po::options_description options("analysis options (a collection keeps those it was indexed with)");
  for (const AnalysisOptionField& field : analysis_option_fields()) {
    const OptionValue current = field.get(analysis);
    const auto set = [&analysis, &field](const auto& value) {
      field.set(analysis, OptionValue(value));
      field.check(analysis);  // out of range: an error before any mesh is read
    };
    std::visit(
        [&](const auto& value) {
          using T = std::decay_t<decltype(value)>;
          options.add_options()(flag_name(field.name).c_str(),
                                po::value<T>()->default_value(value, option_text(current))->notifier(set),
                                field.help.c_str());
        },
        current);
  }
  return options;
}

std::vector<std::string> given_analysis_options(const po::variables_map& vm) {
  std::vector<std::string> given;
  for (const AnalysisOptionField& field : analysis_option_fields()) {
    const auto it = vm.find(flag_name(field.name));
    if (it != vm.end() && !it->second.defaulted()) given.push_back(field.name);
  }
  return given;
}

void add_components_option(po::options_description& options, bool& all_components) {
  options.add_options()("all-components", po::bool_switch(&all_components),
                        "process every connected component (default: the largest only)");
}

po::options_description matching_options(MatchingOptions& matching) {
  po::options_description options("matching options (matching/graph_matching.h)");
  options.add_options()
      ("attribute-weight", defaulted(&matching.attribute_weight),
       "weight of a: node attribute differences (area, f_q range, extent, radius)")
      ("structure-weight", defaulted(&matching.structure_weight),
       "weight of s: local structure (degree, start and end types, neighbour area)")
      ("edge-weight", defaulted(&matching.edge_weight), "weight of e: edge inconsistency of the correspondence")
      ("profile-weight", defaulted(&matching.profile_weight), "weight of p: radius profiles of the regions")
      ("shape-weight", defaulted(&matching.shape_weight), "weight of h: Euclidean shape histograms of the regions")
      ("geodesic-shape-weight", defaulted(&matching.geodesic_shape_weight),
       "weight of h_g: geodesic histograms of the regions")
      ("global-shape-weight", defaulted(&matching.global_shape_weight),
       "weight of g: D2 shape distributions of the whole surfaces")
      ("global-geodesic-weight", defaulted(&matching.global_geodesic_weight),
       "weight of g_g: geodesic histograms of the whole surfaces")
      ("spectrum-weight", defaulted(&matching.spectrum_weight),
       "weight of r: Laplace-Beltrami spectra of the regions")
      ("global-spectrum-weight", defaulted(&matching.global_spectrum_weight),
       "weight of g_s: Laplace-Beltrami spectra of the whole surfaces")
      ("unmatched-cost", defaulted(&matching.unmatched_cost),
       "cost of deleting or inserting a node, per unit of node weight")
      ("min-node-weight", defaulted(&matching.min_node_weight),
       "added to a node's relative area, so that area-less nodes still count")
      ("refine-rounds", defaulted(&matching.refine_rounds), "rounds of edge-consistency refinement");
  return options;
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
