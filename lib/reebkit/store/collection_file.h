// The HDF5 file of an indexed collection: one record per mesh with its
// attributed Reeb graph, in flat datasets with CSR offsets so that Python
// (h5py + numpy) reads it without reebkit, and where it came from: the
// analysis options (named, typed), the classes and the command. Layout:
// docs/collection-file.md. Written from one thread only.
#pragma once

#include "reebkit/attributes/graph_record.h"
#include "reebkit/core/option_value.h"
#include "reebkit/core/version.h"
#include "reebkit/io/psb_classes.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace reebkit {

/// Version of the dataset layout, stored as the file attribute `layout`.
/// 3: the groups `analysis_options` and `classes`. 4: no variable-length
/// strings (names, classes and errors as UTF-8 bytes + offsets, string
/// attributes fixed-length): HDF5 reads variable-length strings from its
/// global heap trusting the stored lengths. 5: the pose-invariant
/// attributes (node_attr 34 columns, signature 64). 6: the Laplace-Beltrami
/// spectra (node_attr 40 columns, signature 80). 7: the same columns; the
/// default geodesic method fast marching, whose fields the attributes now
/// use too (the main axis, the region extents), and similarity-invariant
/// spectra. 8: the same columns; the whole surface's spectrum (`dna_*`) on
/// a finer copy (SpectraOptions::global_vertices). 9: the same columns; the
/// feature points of eq. (6) at epsilon 0.15 and min_persistence 0.03 by
/// default (one point per prominent component), so other graphs. 10: the
/// same columns; each feature point halfway between its extrema of f1 and
/// f2 (FeatureSite::Midpoint) by default, so other graphs. 11: the same
/// columns; the diameter search starts at the vertex farthest from the area
/// centroid (DiameterStart::Centroid) by default, not at vertex 0, so other
/// graphs. 12: the same columns; f_q keeps the diameter ends' distance
/// fields and measures only the other feature points' Voronoi cells
/// (quotient_function.h), so the attributes differ where two cells meet.
/// 13: signature 112: the whole surface's heat kernel distribution
/// (`heat_t*_*`, mesh/heat_kernel.h).
/// 14: the same columns, with every spectrum (`dna_*`, `heat_*`,
/// `spectrum_*`) computed on the intrinsic Delaunay triangulation of its
/// coarse copy (mesh/intrinsic_delaunay.h).
/// 15: the same columns; the feature points other than the diameter ends
/// at the centre of their tips (FeatureSite::Tips, features/feature_points.h),
/// and the spectra of a surface without a frame of its own on the surface as
/// given (attributes/region_spectra.h).
/// 16: the same columns; the diameter search held to four full passes
/// (FeatureOptions::max_search_passes, features/feature_points.h).
inline constexpr int kCollectionLayoutVersion = 16;

/// Where the file came from: file attributes, and two groups.
struct Provenance {
  std::string reebkit_version = REEBKIT_VERSION;
  std::string options;  ///< the analysis options, as JSON text
  /// The analysis options by name, each a typed attribute of the group
  /// `analysis_options` (the store does not interpret them: see
  /// pipeline/analysis_options.h).
  std::vector<NamedOption> analysis_options;
  std::string command;  ///< the command line that made the file
  std::string created;  ///< ISO 8601 date and time (UTC); filled by the writer when empty
  /// The classes the meshes were labelled from, in the order of their .cla
  /// file (the group `classes`; empty: none), and that file.
  std::vector<PsbClass> classes;
  std::string classes_file;
};

/// Appends entries to a collection file. Entries are buffered and written in
/// batches; checkpoint() makes every entry appended so far durable: after a
/// crash, kill -9 or power loss at any moment, the file opens and holds
/// exactly the entries of the last completed checkpoint. HDF5 handles are
/// kept open between batches.
class CollectionWriter {
 public:
  /// Creates `path` (replacing it), or with `resume` opens the existing file
  /// and keeps its entries (a missing file starts a new one).
  /// Throws Error naming the file when it cannot be created or is not a
  /// collection file of this layout version.
  CollectionWriter(const std::filesystem::path& path, const Provenance& provenance, bool resume);
  ~CollectionWriter();  ///< checkpoints and closes (errors are swallowed: call close() to see them)
  CollectionWriter(const CollectionWriter&) = delete;
  CollectionWriter& operator=(const CollectionWriter&) = delete;

  /// Names and content hashes of the entries the file already held when
  /// opened with resume (for skipping finished meshes), in file order.
  const std::vector<std::pair<std::string, std::uint64_t>>& existing() const;

  /// Buffers an entry; entries are written in append order.
  void append(GraphRecord entry);
  /// Writes the buffered entries and makes the file consistent on disk.
  void checkpoint();
  /// Checkpoints and closes; throws on failure.
  void close();
  // A write that fails (disk full, file size limit, I/O error) throws one
  // Error naming the file and the system's reason, and closes the writer:
  // the file keeps the entries of its last checkpoint, later calls throw.
  /// Entries written or buffered so far (existing ones included).
  std::int64_t size() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Whether an HDF5 failure also prints HDF5's own error stack to stderr
/// (`reeb --verbose`); off by default: the Error's message says it all.
void print_hdf5_error_stacks(bool on);

/// What CollectionReader::entries() reads of each entry.
enum class EntryParts {
  Whole,  ///< every field
  /// The entry's name, class, status, error, content hash and sizes, and its
  /// graph's nodes, edges and feature points; not the node and edge
  /// attributes, node geometry, skeletons, timings and signature (left empty
  /// or zero): what counting graphs needs, a fraction of the bytes.
  Outline,
};

/// Reads a collection file.
class CollectionReader {
 public:
  /// Throws Error naming the file when it is missing, unreadable or not a
  /// collection file of this layout version.
  explicit CollectionReader(const std::filesystem::path& path);
  ~CollectionReader();
  CollectionReader(CollectionReader&&) noexcept;

  std::int64_t size() const;
  // The per-entry columns are read on first use (the first of them may
  // throw Error naming the file, as the constructor would).
  const std::vector<std::string>& names() const;
  const std::vector<std::string>& class_labels() const;
  /// Entry i's name and class, without reading every entry's (throws
  /// InvalidArgument for i out of range).
  std::string name(std::int64_t i) const;
  std::string class_label(std::int64_t i) const;
  /// The entries' content hashes (what resume compares).
  const std::vector<std::uint64_t>& content_hashes() const;
  /// size() x kSignatureLength, row-major.
  const std::vector<double>& signatures() const;
  /// Index of the entry called `name`, if any.
  std::optional<std::int64_t> find(const std::string& name) const;
  /// The whole entry i (graph included).
  GraphRecord entry(std::int64_t i) const;
  /// Entries [first, first + count) in one read per dataset: much faster
  /// than entry() one by one (all of them: entries(0, size())).
  std::vector<GraphRecord> entries(std::int64_t first, std::int64_t count, EntryParts parts = EntryParts::Whole) const;
  /// Calls visit(i, entry i) for every entry in order, reading `batch`
  /// entries at a time with entries(): one pass over a collection of any
  /// size in the memory of `batch` graphs. Throws InvalidArgument for a
  /// batch below 1.
  void for_each_entry(const std::function<void(std::int64_t, const GraphRecord&)>& visit,
                      EntryParts parts = EntryParts::Whole, std::int64_t batch = 512) const;
  const Provenance& provenance() const;

 private:
  friend class QueryFile;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// What query by example needs of a collection, beside it so that a query
/// reads that and not the whole collection: COLLECTION with the extension
/// `.query.h5` (docs/collection-file.md, "The query file"). Every dataset is
/// contiguous and unfiltered: the saved pre-filter index loads in one read,
/// and the signature rows and CSR copies of `nodes`, `node_attr` and `edges`
/// are mapped read-only (mmap: the pages a query touches are read, and the
/// system's page cache is shared by the processes that query the
/// collection), so that a candidate's graph is read when it is one. Written
/// for one state of the collection (its `count` and `created`); another
/// state ignores it.
class QueryFile {
 public:
  /// Where the query file of `collection` lies.
  static std::filesystem::path path_of(const std::filesystem::path& collection);
  /// Writes the query file of `collection` (temp file + rename): the
  /// signature rows without NaN, packed (`rows`, row-major, kSignatureLength
  /// columns), their entries (`row_of`, increasing), `saved_index` (opaque
  /// bytes) and every entry's nodes and edges. Throws Error naming the file.
  static void write(const CollectionReader& collection, const double* rows, const std::vector<std::int64_t>& row_of,
                    const std::vector<char>& saved_index);
  /// The query file of `collection`, its offsets read; nullopt when there is
  /// none or it was written for another state of the collection. Throws
  /// Error naming the file when it is there but unreadable.
  static std::optional<QueryFile> open(const CollectionReader& collection);
  QueryFile(QueryFile&&) noexcept;
  QueryFile& operator=(QueryFile&&) noexcept;
  ~QueryFile();

  /// The packed signature rows (row_of().size() x kSignatureLength), mapped;
  /// the mapping lasts while a copy of the pointer does.
  std::shared_ptr<const double> rows() const;
  /// The rows' entries and the saved index, one read each (as write() took them).
  const std::vector<std::int64_t>& row_of() const;
  std::vector<char> saved_index() const;
  /// Entries `entries` (each in row_of()) with what graph matching reads
  /// (ok, signature, nodes, node_attributes, edges; the other members
  /// empty), copied from the mapped rows; in the order of `entries`.
  std::vector<GraphRecord> graphs(const std::vector<std::int64_t>& entries) const;

 private:
  QueryFile();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace reebkit
