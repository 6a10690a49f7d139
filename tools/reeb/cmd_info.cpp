// reeb info collection.h5: what a collection file holds (counts, classes
// and how stable their graphs are, failures) and where it came from
// (provenance: version, command, analysis options, class file; layout
// version). The entries' outlines are read in one pass of batches.
#include "reeb/cli.h"
#include "reebkit/evaluation/graph_stability.h"
#include "reebkit/store/collection_file.h"

#include <cstdio>

#include <iostream>
#include <map>

namespace reebkit::cli {

int run_info(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string path;
  bool list = false;
  options.add_options()("collection", po::value(&path)->required(), "collection file written by reeb index")(
      "list", po::bool_switch(&list),
      "also list every entry: name, class, status (ok or failed), nodes, feature points, cycles, and whether "
      "its graph has its class's most common shape");
  po::positional_options_description positional;
  positional.add("collection", 1);
  po::variables_map vm;
  if (!parse(args, "reeb info collection.h5 [--list]", options, positional, vm)) return 0;

  const CollectionReader reader(path);
  const Provenance& provenance = reader.provenance();
  std::int64_t ok = 0, nodes = 0, edges = 0;
  std::map<std::string, std::int64_t> classes;
  std::vector<GraphShape> shapes;  // of the graphs built
  std::vector<std::string> labels;
  std::vector<std::pair<std::string, std::string>> failures;
  struct Row {
    std::string name, label;
    bool ok;
    GraphShape shape;
  };
  std::vector<Row> rows;
  reader.for_each_entry(
      [&](std::int64_t, const GraphRecord& e) {
        rows.push_back({e.name, e.class_label, e.ok, e.ok ? graph_shape(e) : GraphShape{}});
        if (e.ok) {
          ++ok;
          nodes += e.num_nodes();
          edges += e.num_edges();
          shapes.push_back(rows.back().shape);
          labels.push_back(e.class_label);
        } else {
          failures.emplace_back(e.name, e.error);
        }
        if (!e.class_label.empty()) ++classes[e.class_label];
      },
      EntryParts::Outline);
  const GraphStability stability = graph_stability(shapes, labels);
  std::map<std::string, const ClassStability*> of_class;
  for (const ClassStability& c : stability.classes) of_class[c.label] = &c;
  std::cout << path << ": reebkit collection, layout " << kCollectionLayoutVersion << "\n"
            << "  written by reebkit " << provenance.reebkit_version << " on " << provenance.created << "\n"
            << "  command: " << provenance.command << "\n"
            << "  options: " << provenance.options << "\n"
            << "  analysis options:";
  for (const NamedOption& option : provenance.analysis_options)
    std::cout << " " << option.name << "=" << option_text(option.value);
  std::cout << "\n";
  if (!provenance.classes.empty())
    std::cout << "  classes from " << provenance.classes_file << " (" << provenance.classes.size()
              << ", in its order)\n";
  std::cout << reader.size() << " meshes: " << ok << " ok, " << failures.size() << " failed; " << nodes << " nodes, "
            << edges << " edges\n";
  std::cout << classes.size() << " classes"
            << (classes.empty() ? ""
                                : " (meshes; graphs with the class's most common feature points / nodes / cycles):")
            << "\n";
  for (const auto& [name, count] : classes) {
    std::cout << "  " << name << "\t" << count;
    if (const auto it = of_class.find(name); it != of_class.end()) {
      const GraphShape& s = it->second->most_common;
      std::cout << "\t" << it->second->agreeing << " with " << s.features << " / " << s.nodes << " / " << s.cycles;
    }
    std::cout << "\n";
  }
  if (stability.members > 0) {
    char share[32];
    std::snprintf(share, sizeof share, "%.1f", 100.0 * stability.share());
    std::cout << "graphs with their class's most common shape: " << stability.agreeing << " of " << stability.members
              << " (" << share << " %)\n";
  }
  for (const auto& [name, reason] : failures) std::cout << "failed: " << name << ": " << reason << "\n";
  if (list) {
    // common: the entry's graph has its class's most common shape (yes, no;
    // - without a class or a graph).
    std::cout << "name\tclass\tstatus\tnodes\tfeatures\tcycles\tcommon\n";
    for (const Row& r : rows) {
      const auto it = of_class.find(r.label);
      const char* common = !r.ok || it == of_class.end() ? "-" : it->second->most_common == r.shape ? "yes" : "no";
      std::cout << r.name << "\t" << (r.label.empty() ? "-" : r.label) << "\t" << (r.ok ? "ok" : "failed") << "\t"
                << r.shape.nodes << "\t" << r.shape.features << "\t" << r.shape.cycles << "\t" << common << "\n";
    }
  }
  return 0;
}

}  // namespace reebkit::cli
