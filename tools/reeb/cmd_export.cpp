// reeb export collection.h5 NAME --json: one graph of a collection file as
// the JSON document of `reeb graph` (docs/formats.md).
#include "reeb/cli.h"
#include "reebkit/core/error.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/output/reeb_graph_export.h"
#include "reebkit/store/collection_file.h"

#include <iostream>
#include <sstream>

namespace reebkit::cli {

int run_export(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string path, name, output;
  bool json = false;
  options.add_options()("collection", po::value(&path)->required(), "collection file written by reeb index")(
      "name", po::value(&name)->required(), "the mesh's name in the collection (as reeb info --list lists them)")(
      "json", po::bool_switch(&json),
      "write the graph as JSON (the only format)")("output,o", po::value(&output),
                                                   "write to this file instead of standard output");
  po::positional_options_description positional;
  positional.add("collection", 1).add("name", 1);
  po::variables_map vm;
  if (!parse(args, "reeb export collection.h5 NAME --json [-o graph.json]", options, positional, vm)) return 0;
  if (!json) throw po::error("say the format: --json");
  check_outputs({output}, {path});

  const CollectionReader reader(path);
  const auto index = reader.find(name);
  if (!index) throw Error(path + ": no mesh named '" + name + "' (reeb info --list lists them)");
  const GraphRecord entry = reader.entry(*index);
  if (!entry.ok) throw Error(path + ": mesh '" + name + "' failed when indexed: " + entry.error);
  if (output.empty()) {
    write_reeb_graph_json(std::cout, name, {entry});
    return 0;
  }
  std::ostringstream out;
  write_reeb_graph_json(out, name, {entry});
  write_file_bytes(output, out.str());
  std::cerr << "wrote " << output << "\n";
  return 0;
}

}  // namespace reebkit::cli
