#include "reeb/cli.h"

#include "reebkit/core/error.h"
#include "reebkit/core/option_table.h"
#include "reebkit/core/timer.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/matching/matching_options.h"
#include "reebkit/pipeline/analysis_options.h"
#include "reebkit/store/collection_file.h"

#include <algorithm>
#include <cctype>
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

/// One flag per row of `fields` (core/option_table.h), each defaulting to
/// its value in `options` and setting it once the options are parsed; a
/// value out of the option's range throws InvalidArgument then, before any
/// input is read.
template <typename Options>
po::options_description table_options(const char* title, const std::vector<OptionField<Options>>& fields,
                                      Options& options) {
  po::options_description out(title);
  for (const OptionField<Options>& field : fields) {
    const OptionValue current = field.get(options);
    const auto set = [&options, &field](const auto& value) { field.set_checked(options, OptionValue(value)); };
    std::visit(
        [&](const auto& value) {
          using T = std::decay_t<decltype(value)>;
          out.add_options()(flag_name(field.name).c_str(),
                            po::value<T>()->default_value(value, option_text(current))->notifier(set),
                            field.described().c_str());
        },
        current);
  }
  return out;
}

}  // namespace

bool parse(const std::vector<std::string>& args, const std::string& usage, const po::options_description& options,
           const po::positional_options_description& positional, po::variables_map& vm) {
  po::options_description all(options);
  all.add_options()("help,h", "show this help")("verbose", "on a failure of HDF5, also print its error stack");
  po::store(po::command_line_parser(args).options(all).positional(positional).run(), vm);
  if (vm.count("help")) {
    std::cout << "usage: " << usage << "\n\n" << all << "\n";
    return false;
  }
  for (const auto& [name, value] : vm) {
    const auto* text = boost::any_cast<std::string>(&value.value());
    const po::option_description* option = all.find_nothrow(name, false);
    if (text && text->empty() && !value.defaulted() && option && option->semantic()->min_tokens() > 0)
      throw po::error("the option '--" + name + "' is given an empty value");
  }
  try {
    po::notify(vm);
  } catch (const po::required_option& missing) {
    // A positional argument left out is named as the usage line names it, not as its hidden option.
    const unsigned named = std::min(positional.max_total_count(), 16u);
    for (unsigned i = 0; i < named; ++i) {
      const std::string& name = positional.name_for_position(i);
      if (missing.get_option_name() == "--" + name) {
        std::string argument = name;
        std::transform(argument.begin(), argument.end(), argument.begin(), ::toupper);
        throw po::error("the argument " + argument + " is missing");
      }
    }
    throw;
  }
  print_hdf5_error_stacks(vm.count("verbose") > 0);
  return true;
}

void check_outputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  check_output_files({outputs.begin(), outputs.end()}, {inputs.begin(), inputs.end()});
}

po::options_description analysis_options(AnalysisOptions& analysis) {
  return table_options("analysis options (a collection keeps those it was indexed with)", analysis_option_fields(),
                       analysis);
}

std::vector<std::string> given_analysis_options(const po::variables_map& vm) {
  std::vector<std::string> given;
  for (const AnalysisOptionField& field : analysis_option_fields()) {
    const auto it = vm.find(flag_name(field.name));
    if (it != vm.end() && !it->second.defaulted()) given.push_back(field.name);
  }
  return given;
}

std::filesystem::path output_folder(const std::string& path) {
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_directory(path, error))
    throw Error(path + ": is a file, not a folder (-o names the folder of the outputs)");
  std::filesystem::create_directories(path, error);
  if (error) throw Error(path + ": cannot create the folder: " + error.message());
  return path;
}

void add_components_option(po::options_description& options, bool& all_components) {
  options.add_options()("all-components", po::bool_switch(&all_components),
                        "process every connected component (default: the largest only)");
}

po::options_description matching_options(MatchingOptions& matching) {
  return table_options("matching options (matching/graph_matching.h)", matching_option_fields(), matching);
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
