// A `reeb` built without MPI (REEBKIT_MPI=OFF) started by an MPI launcher:
// every process would index the whole collection on its own; say so instead.
#include "reeb/cluster.h"
#include "reebkit/core/error.h"

namespace reebkit::cli {
namespace {

[[noreturn]] void refuse() {
  throw Error(
      "started by an MPI launcher, but this reeb was built without MPI (configure with -DREEBKIT_MPI=ON, "
      "Debian packages libopenmpi-dev openmpi-bin; docs/cluster.md)");
}

}  // namespace

std::optional<ExtractionSummary> extract_collection_on_cluster(const std::vector<MeshInput>&,
                                                               const std::vector<PsbClass>&,
                                                               const std::filesystem::path&, const ExtractionOptions&) {
  refuse();
}

std::optional<PairwiseDistances> all_pairs_on_cluster(const std::vector<GraphRecord>&, const AllPairsOptions&) {
  refuse();
}

}  // namespace reebkit::cli
