// Pins the end-to-end numbers on the embedded collection (datasets/, 8 CC0
// meshes), so that a refactor that changes a number fails in CI rather than
// being found by hand:
//  - indexed in-process (extract_collection, read back from the file): per
//    mesh the node, leaf and cycle counts of the Reeb graph (cycles = genus,
//    Tierny et al. 2006, section 4.2) and a hash of its attributes (node and
//    edge attributes, signature) rounded to 30 significant bits (about 1e-9
//    relative; the Laplace-Beltrami spectra to 20), so that last-bit noise
//    between platforms does not flip it;
//  - the demo's main job through the `reeb` binary (variants -> index ->
//    distances -> eval): NN and FT floors of the variants collection.
// When the Reeb graph or its attributes change on purpose, update kPinned
// (the one place) and say in the commit why the numbers moved.
#include "io/io_test_util.h"
#include "reebkit/collection/extract_collection.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/evaluation/retrieval_metrics.h"
#include "reebkit/io/psb_classes.h"
#include "reebkit/store/collection_file.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>

namespace reebkit::test {
namespace {

struct PinnedGraph {
  const char* name;
  std::int64_t nodes, leaves, cycles;
  std::uint64_t attribute_hash;
};

// The default analysis of each embedded mesh (cycles: anchor 4, helmet 3,
// eight 2, elk 1, the others 0 = their genus). Update here, and only here,
// when the graph or the attributes change on purpose.
constexpr PinnedGraph kPinned[] = {
    {"anchor.off", 15, 2, 4, 0x76c9ad3c49384716ull}, {"bunny.off", 5, 3, 0, 0xf30a63a9bf953a84ull},
    {"cactus.off", 7, 4, 0, 0x5a0452b6dccc2047ull},  {"cow.off", 17, 9, 0, 0x769017859032f8baull},
    {"eight.off", 9, 2, 2, 0x7a07bbf551d6a736ull},   {"elk.off", 14, 6, 1, 0xb25726fe1fe8114dull},
    {"hand.off", 3, 2, 0, 0x58a8e028447d5089ull},    {"helmet.off", 12, 2, 3, 0xc7e102e060c36ab8ull},
};

// Retrieval on the variants collection (48 meshes, 8 classes of 6), as the
// demo measures it: NN 0.979, FT 0.971 (233 of 240) since layout 16 (0.979 / 0.979 in
// layouts 14-15, 1.000 / 1.000 in layout 13): anchor_resampled, a finer
// copy of the 519-vertex anchor, lies nearer eight_posed1 than its own
// class, the saturated spectral terms of the two nearly tied (8.12 against
// 8.27; 8.26 against 8.23 in layout 13). It has three feature points where
// the rest of its class has two, and the search held to four passes puts
// them elsewhere: two more of its class fall out of the first tier, and
// every one but one is in the second (ST 0.979 -> 0.996).
constexpr double kNearestNeighborFloor = 0.979;
constexpr double kFirstTierFloor = 0.970;

/// FNV-1a over `value` rounded to `bits` significant bits (mantissa and exponent).
void hash_rounded(std::uint64_t& hash, double value, int bits = 30) {
  int exponent = 0;
  const double mantissa = std::frexp(value, &exponent);
  const std::int64_t words[2] = {std::llround(std::ldexp(mantissa, bits)), mantissa == 0.0 ? 0 : exponent};
  for (const std::int64_t word : words)
    for (int byte = 0; byte < 8; ++byte) {
      hash ^= static_cast<std::uint64_t>(word >> (8 * byte)) & 0xffu;
      hash *= 0x100000001b3ull;
    }
}

/// The Laplace-Beltrami spectra (node columns from kNodeSpectrum, signature
/// entries from kSigGlobalSpectrum) come from Lanczos iterations converged
/// to 1e-10: they are hashed to 20 bits (about 1e-6), the rest to 30.
std::uint64_t attribute_hash(const GraphRecord& record) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (std::size_t i = 0; i < record.node_attributes.size(); ++i)
    hash_rounded(hash, record.node_attributes[i], i % kNodeAttributeCount >= kNodeSpectrum ? 20 : 30);
  for (const double x : record.edge_attributes) hash_rounded(hash, x);
  for (std::size_t i = 0; i < record.signature.size(); ++i)
    hash_rounded(hash, record.signature[i], static_cast<int>(i) >= kSigGlobalSpectrum ? 20 : 30);
  return hash;
}

TEST(EmbeddedCollection, GraphCountsAndAttributeHashesArePinned) {
  const TempDir dir;
  ExtractionOptions options;
  options.threads = 2;
  const ExtractionSummary summary =
      extract_collection(list_mesh_inputs({embedded_dataset_dir().string()}), {}, dir / "c.h5", options);
  ASSERT_TRUE(summary.failed.empty()) << summary.failed.front().name << ": " << summary.failed.front().reason;
  const CollectionReader collection(dir / "c.h5");
  ASSERT_EQ(collection.size(), static_cast<std::int64_t>(std::size(kPinned)));
  std::ostringstream actual;  // the table to paste into kPinned when a change is intended
  for (std::int64_t i = 0; i < collection.size(); ++i) {
    const GraphRecord record = collection.entry(i);
    actual << "    {\"" << record.name << "\", " << record.num_nodes() << ", " << leaf_count(record) << ", "
           << independent_cycles(record) << ", 0x" << std::hex << attribute_hash(record) << std::dec << "ull},\n";
  }
  for (std::int64_t i = 0; i < collection.size(); ++i) {
    const PinnedGraph& want = kPinned[i];
    const GraphRecord record = collection.entry(i);
    SCOPED_TRACE(record.name);
    EXPECT_EQ(record.name, want.name);
    EXPECT_EQ(record.num_nodes(), want.nodes);
    EXPECT_EQ(leaf_count(record), want.leaves);
    EXPECT_EQ(independent_cycles(record), want.cycles);
    EXPECT_EQ(attribute_hash(record), want.attribute_hash);
  }
  if (HasFailure()) ADD_FAILURE() << "measured now:\n" << actual.str();
}

TEST(EmbeddedCollection, VariantsCollectionRetrievalFloors) {
  const TempDir dir;
  const std::string reeb = REEB_BINARY;
  const std::filesystem::path variants = dir / "variants", cla = variants / "variants.cla";
  for (const std::string& command :
       {reeb + " variants " + shell_quoted(embedded_dataset_dir()) + " -o " + shell_quoted(variants),
        reeb + " index " + shell_quoted(variants) + " -o " + shell_quoted(dir / "v.h5") + " --classes " +
            shell_quoted(cla) + " --threads 2",
        reeb + " distances " + shell_quoted(dir / "v.h5") + " -o " + shell_quoted(dir / "v.matrix") + " --cla " +
            shell_quoted(cla) + " --threads 2"}) {
    const auto [status, out] = run_command(command + " 2>&1");
    ASSERT_EQ(status, 0) << command << "\n" << out;
  }
  const std::vector<PsbClass> classes = read_psb_classes(cla);
  ASSERT_EQ(classes.size(), 8u);
  const RetrievalEvaluation evaluation = evaluate_retrieval(read_psb_matrix(dir / "v.matrix"), model_classes(classes));
  ASSERT_EQ(evaluation.queries.size(), 48u);
  EXPECT_GE(evaluation.micro.nearest_neighbor, kNearestNeighborFloor);
  EXPECT_GE(evaluation.micro.first_tier, kFirstTierFloor);
}

}  // namespace
}  // namespace reebkit::test
