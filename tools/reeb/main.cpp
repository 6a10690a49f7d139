// reeb: invariant high-level Reeb graphs of 3D meshes, from the command line.
#include "reeb/cli.h"
#include "reeb/cluster.h"
#include "reebkit/core/error.h"
#include "reebkit/core/version.h"

#include <malloc.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace reebkit::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> all = {
      {"features", "feature points and quotient function f_q of a mesh", run_features},
      {"graph", "high-level Reeb graph, segmentation and skeleton of a mesh", run_graph},
      {"deform", "turn the component of a Reeb graph node (a limb) about where it attaches", run_deform},
      {"index", "index a collection of meshes into one HDF5 file of attributed Reeb graphs", run_index},
      {"info", "what a collection file holds: counts, classes, graph stability, failures, provenance", run_info},
      {"export", "one graph of a collection file as the JSON of reeb graph", run_export},
      {"match", "graph-matching distance and node correspondence of two meshes or collection entries", run_match},
      {"eval", "retrieval measures (NN, FT, ST, E, DCG, precision-recall) of distance matrices, as a report", run_eval},
      {"query", "the meshes of a collection nearest to a mesh: signature pre-filter, graph matching rerank", run_query},
      {"distances", "graph-matching distances of every pair of a collection, as a PSB .matrix", run_distances},
      {"variants", "a collection with classes: each mesh plus rotated, resampled, re-posed and noisy copies",
       run_variants},
      {"perturb", "a rotated, rescaled, posed, decimated, remeshed, subdivided or noisy variant and its correspondence",
       run_perturb},
  };
  return all;
}

}  // namespace reebkit::cli

namespace {

constexpr const char* kHugePages = "glibc.malloc.hugetlb";

/// A large mesh is analysed in arrays of hundreds of megabytes, most written
/// once, and on 4 KiB pages the page faults of their first writes take a
/// good part of the time (docs/benchmarks.md: `reeb graph` on a 1M-face mesh).
/// glibc backs what it allocates with transparent huge pages when its
/// tunable glibc.malloc.hugetlb is 1 (glibc >= 2.35; the kernel's THP mode
/// `madvise` or `always`), and reads its tunables only when a program
/// starts: so reeb starts itself again with it, once, unless GLIBC_TUNABLES
/// sets it already (glibc.malloc.hugetlb=0: 4 KiB pages). Only the commands
/// that analyse one mesh or two, which may be large (and --version, which
/// shows it): `reeb index` works through many meshes, mostly small, in a
/// heap it reuses, where huge pages gain nothing and cost a little; and a
/// new start costs the loading of reeb's libraries again, which a query
/// answered from a collection file would feel. Where the new start fails,
/// reeb goes on as it is.
void restart_with_huge_pages(int argc, char** argv) {
  static const char* const kAnalysing[] = {"features", "graph", "deform", "match", "variants", "perturb", "--version"};
  if (argc < 2 || std::none_of(std::begin(kAnalysing), std::end(kAnalysing),
                               [&](const char* command) { return std::strcmp(argv[1], command) == 0; }))
    return;
  const char* set = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = set != nullptr ? set : "";
  if (tunables.find(kHugePages) != std::string::npos) return;
  const std::string wanted = (tunables.empty() ? "" : tunables + ":") + kHugePages + "=1";
  if (::setenv("GLIBC_TUNABLES", wanted.c_str(), 1) != 0) return;
  ::execv("/proc/self/exe", argv);
  if (set != nullptr)
    ::setenv("GLIBC_TUNABLES", set, 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
}

/// `reeb index` analyses mesh after mesh, each in arrays of its own size
/// that are freed when it is written. By default glibc gives freed memory
/// back to the kernel (its trim threshold, 128 KiB, and its mmap threshold,
/// which serves large arrays from pages of their own), and the next mesh
/// faults the same pages in again, cleared. Kept in the heap they are reused
/// as they are: one page fault in ten on SHREC07 (docs/benchmarks.md,
/// "Indexing"). The memory is the largest mesh's, held until the process ends.
void keep_freed_memory(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "index") != 0) return;
  constexpr int kKeep = 1 << 30;  // 1 GiB: larger arrays still come from pages of their own
  ::mallopt(M_MMAP_THRESHOLD, kKeep);
  ::mallopt(M_TRIM_THRESHOLD, kKeep);
}

void print_usage() {
  std::cout << "reeb " << REEBKIT_VERSION
            << " - invariant high-level Reeb graphs of 3D meshes (Tierny et al. 2006)\n\n"
               "usage: reeb <command> [options]   (reeb <command> --help for details)\n\ncommands:\n";
  for (const auto& c : reebkit::cli::commands()) std::cout << "  " << c.name << "\t" << c.summary << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  restart_with_huge_pages(argc, argv);
  keep_freed_memory(argc, argv);
  // Past a file-size limit (ulimit -f), a write fails with EFBIG, reported
  // and cleaned up as any write error, instead of the signal killing the
  // process without a word and leaving its partial output and lock.
  std::signal(SIGXFSZ, SIG_IGN);
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    print_usage();
    return argc < 2 ? 2 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    std::cout << "reeb " << REEBKIT_VERSION << "\nGLIBC_TUNABLES=" << (tunables != nullptr ? tunables : "") << "\n";
    return 0;
  }
  const std::vector<std::string> args(argv + 2, argv + argc);
  for (const auto& c : reebkit::cli::commands()) {
    if (c.name != std::string(argv[1])) continue;
    try {
      const int status = c.run(args);
      // What was printed must have reached its destination (a full disk, a closed pipe).
      std::cout.flush();
      if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout))
        throw reebkit::Error(std::string("standard output: write failed: ") + std::strerror(errno));
      return status;
    } catch (const boost::program_options::error& e) {
      // Every process of an MPI job parses the same command line: one says what is wrong with it.
      if (reebkit::cli::launched_rank() == 0)
        std::cerr << "reeb " << c.name << ": " << e.what() << " (see reeb " << c.name << " --help)\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "reeb " << c.name << ": error: " << e.what() << "\n";
      // Leave without the libraries' exit handlers: HDF5 1.10 crashes in
      // them on a file it failed to close after a write error (a full disk
      // while the file was being created), which CollectionWriter lets go
      // of. Every output is closed or abandoned by now.
      std::cout.flush();
      std::fflush(nullptr);
      std::_Exit(1);
    }
  }
  std::cerr << "reeb: unknown command '" << argv[1] << "'\n";
  print_usage();
  return 2;
}
