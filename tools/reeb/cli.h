// Shared plumbing of the `reeb` subcommands.
#pragma once

#include "reebkit/matching/graph_matching.h"
#include "reebkit/mesh/load_mesh.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <boost/program_options.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace reebkit::cli {

namespace po = boost::program_options;

/// A subcommand: its name, a one-line summary, and its entry point, which
/// receives the arguments after the subcommand name and returns an exit code.
struct Command {
  const char* name;
  const char* summary;
  std::function<int(const std::vector<std::string>&)> run;
};

/// Every subcommand, in the order `reeb --help` lists them.
const std::vector<Command>& commands();

/// Parses `args` against `options` (+ positional), handling --help: returns
/// false when help was printed and the command should exit 0. Default
/// values are shown as the library writes them (shortest exact form).
/// Every command also takes --verbose: a failure of HDF5 then prints HDF5's
/// error stack too (print_hdf5_error_stacks).
bool parse(const std::vector<std::string>& args, const std::string& usage, const po::options_description& options,
           const po::positional_options_description& positional, po::variables_map& vm);

/// The options of the analysis of a mesh: one flag per analysis option
/// (pipeline/analysis_options.h; --min-persistence for min_persistence),
/// each defaulting to its value in `analysis` (the library's default unless
/// the command changed it) and setting it once the options are parsed; a
/// value out of the option's range throws InvalidArgument then, before any
/// mesh is read.
po::options_description analysis_options(AnalysisOptions& analysis);

/// The names of the analysis options given on the command line (not left
/// at their default), in table order.
std::vector<std::string> given_analysis_options(const po::variables_map& vm);

/// Checks the non-empty paths of `outputs` with check_output_files (each
/// one's folder exists and is writable, it is none of `inputs`, no two name
/// one file), before any work.
void check_outputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

/// The output folder `path` (-o of eval and variants), created with its
/// parents when missing, before any work. Throws Error naming `path` when
/// it is a file or cannot be created.
std::filesystem::path output_folder(const std::string& path);

/// --all-components: every connected component, not the largest only.
void add_components_option(po::options_description& options, bool& all_components);

/// The options of graph matching: one flag per row of
/// matching_option_fields (matching/matching_options.h; --attribute-weight
/// for attribute_weight), each defaulting to its value in `matching`; a
/// value out of the option's range throws InvalidArgument once parsed.
po::options_description matching_options(MatchingOptions& matching);

/// A mesh read and cleaned for a subcommand, and the time that took.
struct LoadedMesh {
  CleanedMesh cleaned;
  double milliseconds = 0;
};

/// Reads and cleans `path` (every component, or only the largest): cleanup
/// warnings go to stderr, the read time to stdout.
LoadedMesh load_for_command(const std::string& path, bool all_components);

// Subcommand entry points, one source file each (cmd_<name>.cpp).
int run_features(const std::vector<std::string>& args);
int run_graph(const std::vector<std::string>& args);
int run_deform(const std::vector<std::string>& args);
int run_index(const std::vector<std::string>& args);
int run_info(const std::vector<std::string>& args);
int run_export(const std::vector<std::string>& args);
int run_match(const std::vector<std::string>& args);
int run_eval(const std::vector<std::string>& args);
int run_query(const std::vector<std::string>& args);
int run_distances(const std::vector<std::string>& args);
int run_variants(const std::vector<std::string>& args);
int run_perturb(const std::vector<std::string>& args);

}  // namespace reebkit::cli
