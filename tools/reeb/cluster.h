// reeb index and reeb distances across the processes of an MPI job
// (mpirun, srun: docs/cluster.md). The library stays free of MPI: this
// module hands the work out and gathers it; the library computes it
// (extract_shard and merge_shards, upper_triangle_rows).
#pragma once

#include "reebkit/collection/extract_collection.h"
#include "reebkit/retrieval/all_pairs.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace reebkit::cli {

/// Whether an MPI launcher (mpirun, srun) started this process: its
/// environment says so (OMPI_COMM_WORLD_SIZE, PMIX_RANK, PMI_RANK).
bool launched_by_mpi();
/// This process's rank in the launcher's job (from the environment), 0 when
/// not launched by MPI: the process that prints and writes.
int launched_rank();

/// reeb index across the processes of the job. Every process checks the
/// inputs and options (check_extraction); process 0 takes the lock of
/// `output` and plans the job (plan_sharded_job; a refusal ends every
/// process cleanly), hands the inputs to compute out in input order to
/// whichever process asks (its own threads one at a time, the others in
/// chunks that shrink with what is left: no static split), and each
/// process computes them with its threads into its own shard
/// (extract_shard); process 0 then merges the shards into `output`
/// (merge_shards). A process that fails aborts the job (MPI_Abort):
/// every shard keeps the entries of its last checkpoint, and the same
/// command with options.resume goes on from there. Returns the job's
/// summary on process 0, nothing on the others. Throws Error in a build
/// without MPI.
std::optional<ExtractionSummary> extract_collection_on_cluster(const std::vector<MeshInput>& inputs,
                                                               const std::vector<PsbClass>& classes,
                                                               const std::filesystem::path& output,
                                                               const ExtractionOptions& options);

/// all_pairs_distances(entries) across the processes of the job: process r
/// computes the block r of balanced_row_blocks (upper_triangle_rows) with
/// its threads and sends it to process 0, which assembles the matrix: the
/// same matrix as one process computes, bit for bit. Returns it on process
/// 0, nothing on the others. Throws Error in a build without MPI.
std::optional<PairwiseDistances> all_pairs_on_cluster(const std::vector<GraphRecord>& entries,
                                                      const AllPairsOptions& options);

}  // namespace reebkit::cli
