// reeb eval DIST.matrix --cla CLASSES.cla -o REPORT/: the Princeton Shape
// Benchmark retrieval measures of one or more distance matrices (Shilane et
// al. 2004; definitions in reebkit/evaluation/retrieval_metrics.h), written as
// a Markdown report with the precision-recall curves as CSV and as a plot.
#include "reeb/cli.h"
#include "reebkit/core/error.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/evaluation/local_scaling.h"
#include "reebkit/evaluation/retrieval_metrics.h"
#include "reebkit/io/file_bytes.h"
#include "reebkit/io/psb_classes.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace reebkit::cli {

namespace {

struct Method {
  std::string name;
  std::filesystem::path matrix;
  RetrievalEvaluation result;
};

/// "path:NAME" -> (path, NAME); without ':NAME' the name is the file stem.
Method method_of(const std::string& spec) {
  const auto colon = spec.rfind(':');
  if (colon == std::string::npos || colon + 1 == spec.size() || spec.find('/', colon) != std::string::npos)
    return {std::filesystem::path(spec).stem().string(), spec, {}};
  return {spec.substr(colon + 1), spec.substr(0, colon), {}};
}

std::string fixed3(double v) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << v;
  return out.str();
}

std::string score_cells(const RetrievalScores& s) {
  return fixed3(s.nearest_neighbor) + " | " + fixed3(s.first_tier) + " | " + fixed3(s.second_tier) + " | " +
         fixed3(s.e_measure) + " | " + fixed3(s.dcg) + " |";
}

/// Micro and macro averages of every method, one Markdown table.
std::string summary_table(const std::vector<Method>& methods) {
  std::string out = "| method | average | NN | FT | ST | E | DCG |\n|---|---|---|---|---|---|---|\n";
  for (const Method& m : methods) {
    out += "| " + m.name + " | micro (" + std::to_string(m.result.queries.size()) + " queries) | " +
           score_cells(m.result.micro) + "\n";
    Index classes = 0;
    for (const ClassScores& c : m.result.classes) classes += c.queries > 0;
    out += "| " + m.name + " | macro (" + std::to_string(classes) + " classes) | " + score_cells(m.result.macro) + "\n";
  }
  return out;
}

std::string class_table(const RetrievalEvaluation& e) {
  std::string out = "| class | models | NN | FT | ST | E | DCG |\n|---|---|---|---|---|---|---|\n";
  for (const ClassScores& c : e.classes)
    out += "| " + c.name + " | " + std::to_string(c.size) + " | " +
           (c.queries > 0 ? score_cells(c.mean) : std::string("left out as queries (fewer than 3 models) |||||")) +
           "\n";
  return out;
}

/// method,curve,recall,precision: the micro and macro curves and one per query class.
std::string pr_csv(const std::vector<Method>& methods) {
  std::ostringstream out;
  out << "method,curve,recall,precision\n" << std::setprecision(6);
  const auto rows = [&out](const std::string& method, const std::string& curve, const std::vector<double>& recall,
                           const std::vector<double>& precision) {
    for (std::size_t l = 0; l < recall.size(); ++l)
      out << method << "," << curve << "," << recall[l] << "," << precision[l] << "\n";
  };
  for (const Method& m : methods) {
    rows(m.name, "micro", m.result.recall, m.result.micro.precision);
    rows(m.name, "macro", m.result.recall, m.result.macro.precision);
    for (const ClassScores& c : m.result.classes)
      if (c.queries > 0) rows(m.name, c.name, m.result.recall, c.mean.precision);
  }
  return out.str();
}

std::string report(const std::vector<Method>& methods, const std::string& cla) {
  std::ostringstream out;
  out << "# Retrieval evaluation\n\nClasses: `" << cla << "` (matrix rows in the order the .cla lists the models).\n\n";
  for (const Method& m : methods)
    out << "- " << m.name << ": `" << m.matrix.string() << "` (" << m.result.queries.size() << " queries)\n";
  out << "\nMeasures of the Princeton Shape Benchmark (Shilane et al. 2004): each query's own row ranks the other "
         "models by increasing distance, ties broken by model index, the query itself left out; classes with "
         "fewer than 3 models are not queries (their models stay in the rankings). NN: the first result is in the "
         "class; FT / ST: share of the K = |C| - 1 class members among the first K / 2K results; E: "
         "2 P R / (P + R) over the first 32 results (min(32, N - 1)); DCG: discounted cumulative gain (1 / log2 of "
         "the rank from rank 2) divided by that of a perfect ranking. Micro: mean over the queries; macro: mean over "
         "the classes of the class means.\n\n## Summary\n\n"
      << summary_table(methods)
      << "\n## Precision-recall\n\nInterpolated precision at the 20 recall levels 0.05, 0.10, ..., 1.00: P(r) is the "
         "highest precision reached at any recall >= r, averaged over the queries (micro) or over the class means "
         "(macro). Data: [pr.csv](pr.csv) (method, curve = micro, macro or a class, recall, precision).\n\n"
         "![precision-recall](pr.png)\n\n| recall |";
  for (const Method& m : methods) out << " " << m.name << " micro | " << m.name << " macro |";
  out << "\n|---|";
  for (std::size_t i = 0; i < methods.size(); ++i) out << "---|---|";
  out << "\n";
  for (std::size_t l = 0; l < methods.front().result.recall.size(); ++l) {
    out << "| " << fixed3(methods.front().result.recall[l]) << " |";
    for (const Method& m : methods)
      out << " " << fixed3(m.result.micro.precision[l]) << " | " << fixed3(m.result.macro.precision[l]) << " |";
    out << "\n";
  }
  for (const Method& m : methods) out << "\n## Per class: " << m.name << "\n\n" << class_table(m.result);
  return out.str();
}

/// Draws the micro curves of every method (tools/figures/pr_plot.py) into
/// a temporary folder, then puts pr.png and pr.svg in `dir` (write_file_bytes).
void plot(const std::filesystem::path& csv, const std::filesystem::path& dir) {
  const std::filesystem::path scratch =
      std::filesystem::temp_directory_path() / ("reeb_eval_" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  const std::string command = std::string("/usr/bin/python3 '") + REEBKIT_PR_PLOT_SCRIPT + "' '" + csv.string() +
                              "' '" + (scratch / "pr.png").string() + "' '" + (scratch / "pr.svg").string() + "'";
  const bool plotted = std::system(command.c_str()) == 0;
  if (plotted)
    for (const char* figure : {"pr.png", "pr.svg"}) write_file_bytes(dir / figure, read_file_bytes(scratch / figure));
  std::filesystem::remove_all(scratch);
  if (!plotted) throw Error((dir / "pr.png").string() + ": plotting failed (" + command + ")");
}

}  // namespace

int run_eval(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string matrix_path, cla_path, out_dir, name;
  std::vector<std::string> compare;
  bool no_plot = false;
  int scaling_k = 0;
  options.add_options()("matrix", po::value(&matrix_path)->required(),
                        "distance matrix: PSB binary (float32 N x N) or SHREC ASCII, told apart by the contents")(
      "cla", po::value(&cla_path)->required(),
      "classes of the models, PSB .cla (rows in its model order)")("output,o", po::value(&out_dir)->required(),
                                                                   "report folder: report.md, pr.csv, pr.png, pr.svg")(
      "name", po::value(&name), "name of the method in the report (default: the matrix file name)")(
      "compare", po::value(&compare)->multitoken(), "other methods' matrices as PATH[:NAME], evaluated alike")(
      "local-scaling", po::value(&scaling_k)->default_value(0),
      "also evaluate every matrix after local scaling with the K-th nearest model (evaluation/local_scaling.h; 0: "
      "off)")("no-plot", po::bool_switch(&no_plot),
              "skip pr.png / pr.svg (they need /usr/bin/python3 with matplotlib)");
  po::positional_options_description positional;
  positional.add("matrix", 1);
  po::variables_map vm;
  if (!parse(args,
             "reeb eval DIST.matrix --cla CLASSES.cla -o REPORT/ [--name METHOD] [--compare M.matrix:NAME ...] "
             "[--local-scaling K]",
             options, positional, vm))
    return 0;

  const std::filesystem::path dir = output_folder(out_dir);
  const ModelClasses classes = model_classes(read_psb_classes(cla_path));
  std::vector<Method> methods{method_of(matrix_path)};
  if (!name.empty()) methods.front().name = name;
  for (const std::string& spec : compare) methods.push_back(method_of(spec));
  if (scaling_k < 0)
    throw InvalidArgument("reeb eval: --local-scaling must be >= 0 (0: off), not " + std::to_string(scaling_k));
  std::vector<Method> scaled;
  for (Method& m : methods) {
    const DistanceMatrix distances = read_distance_matrix(m.matrix);
    if (static_cast<std::size_t>(distances.rows()) != classes.of_model.size())
      throw Error(m.matrix.string() + ": " + std::to_string(distances.rows()) + " x " +
                  std::to_string(distances.rows()) + " distances, but " + cla_path + " lists " +
                  std::to_string(classes.of_model.size()) + " models");
    m.result = evaluate_retrieval(distances, classes);
    if (scaling_k > 0)
      scaled.push_back({m.name + " + local scaling (k = " + std::to_string(scaling_k) + ")", m.matrix,
                        evaluate_retrieval(local_scaling(distances, scaling_k), classes)});
  }
  methods.insert(methods.end(), scaled.begin(), scaled.end());

  write_file_bytes(dir / "pr.csv", pr_csv(methods));
  write_file_bytes(dir / "report.md", report(methods, cla_path));
  if (!no_plot) plot(dir / "pr.csv", dir);
  std::cout << summary_table(methods) << "wrote " << (dir / "report.md").string() << ", pr.csv"
            << (no_plot ? "" : ", pr.png, pr.svg") << "\n";
  return 0;
}

}  // namespace reebkit::cli
