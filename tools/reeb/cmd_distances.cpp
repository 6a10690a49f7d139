// reeb distances collection.h5 -o dist.matrix: graph-matching distances
// between every pair of meshes of a collection, as the Princeton Shape
// Benchmark binary matrix and optionally the SHREC ASCII matrix (docs/command-line.md,
// "Query and distances").
#include "reeb/cli.h"
#include "reeb/cluster.h"
#include "reebkit/collection/progress.h"
#include "reebkit/core/error.h"
#include "reebkit/core/timer.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/retrieval/all_pairs.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>

namespace reebkit::cli {

namespace {

/// The rows of the matrix and how they are ordered: the models of the .cla
/// file `classes_path` in its order; without it, those of the classes the
/// collection was indexed with (reeb index --classes), so that a PSB tool
/// given that .cla reads the matrix right; else every entry in collection
/// order.
std::pair<std::vector<std::int64_t>, std::string> ordered_rows(const CollectionReader& collection,
                                                               const std::string& path,
                                                               const std::string& classes_path) {
  if (!classes_path.empty()) {
    try {
      return {matrix_rows(collection, read_psb_classes(classes_path)), ".cla order of " + classes_path};
    } catch (const Error& e) {
      throw Error(path + ": " + e.what() + " (classes from " + classes_path + ")");
    }
  }
  const Provenance& provenance = collection.provenance();
  if (provenance.classes.empty()) return {matrix_rows(collection), "collection order"};
  try {
    return {matrix_rows(collection, provenance.classes),
            ".cla order of " + provenance.classes_file + " (the classes the collection was indexed with)"};
  } catch (const Error& e) {
    return {matrix_rows(collection), "collection order (the classes of " + provenance.classes_file +
                                         " do not fit the collection: " + e.what() + ")"};
  }
}

}  // namespace

int run_distances(const std::vector<std::string>& args) {
  po::options_description options("options");
  std::string path, output, classes_path, ascii;
  AllPairsOptions all_pairs;
  options
      .add_options()("collection", po::value(&path)->required(),
                     "collection file written by reeb index")("output,o", po::value(&output)->required(),
                                                              "PSB binary matrix to write (float32, N x N, row-major)")(
          "cla", po::value(&classes_path),
          "rows in the order of the models of this PSB .cla file (default: the .cla the collection was indexed "
          "with, else collection order, every mesh)")("ascii", po::value(&ascii),
                                                      "also write the SHREC ASCII matrix (N lines of N numbers)")(
          "threads", po::value(&all_pairs.threads)->default_value(0), "threads (0: as many as OpenMP offers)");
  options.add(matching_options(all_pairs.matching));
  po::positional_options_description positional;
  positional.add("collection", 1);
  po::variables_map vm;
  if (!parse(args,
             "reeb distances collection.h5 -o dist.matrix [--cla classes.cla] [--ascii shrec.txt] [--threads N] "
             "[matching options]",
             options, positional, vm))
    return 0;
  check_outputs({output, ascii}, {path, classes_path});

  const CollectionReader collection(path);
  const auto [rows, order] = ordered_rows(collection, path, classes_path);
  // Under mpirun or srun every process computes a block of rows; process 0
  // prints and writes (docs/cluster.md).
  const bool first_process = launched_rank() == 0;
  if (first_process) std::cerr << "rows in the " << order << "\n";
  const std::string failed = failed_rows_warning(collection, rows);
  if (!failed.empty() && first_process) std::cerr << "warning: " << failed << "\n";
  Timer timer;
  std::optional<PairwiseDistances> result;
  if (launched_by_mpi()) {
    result = all_pairs_on_cluster(matrix_entries(collection, rows), all_pairs);
    if (!result) return 0;
  } else {
    ProgressBar bar = ProgressBar::for_stderr("matched", "pairs");
    all_pairs.progress = [&](std::int64_t matched, std::int64_t pairs) {
      ProgressState state;
      state.total = pairs;
      state.ok = matched;
      state.seconds = timer.elapsed() / 1000;
      bar(state);
    };
    result = all_pairs_distances(collection, rows, all_pairs);
    bar.clear();
  }
  const PairwiseDistances& distances = *result;
  const double seconds = timer.lap() / 1000;
  const std::int64_t n = distances.size();
  DistanceMatrix matrix(n, n);
  for (std::int64_t i = 0; i < n; ++i)
    for (std::int64_t j = 0; j < n; ++j) matrix(i, j) = static_cast<float>(distances(i, j));
  write_psb_matrix(output, matrix);
  std::cerr << std::fixed << std::setprecision(2) << n << " x " << n << " distances (" << n * (n - 1) / 2
            << " pairs) in " << seconds << " s\nwrote " << output << "\n";
  if (!ascii.empty()) {
    write_shrec_matrix(ascii, matrix);
    std::cerr << "wrote " << ascii << "\n";
  }
  return 0;
}

}  // namespace reebkit::cli
