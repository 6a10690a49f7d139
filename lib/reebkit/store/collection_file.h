// The HDF5 file of an indexed collection (issue 4): one record per mesh with
// its attributed Reeb graph, in flat datasets with CSR offsets so that
// Python (h5py + numpy) reads it without reebkit. Layout: README, "The
// collection file". Written from one thread only.
#pragma once

#include "reebkit/attributes/graph_attributes.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace reebkit {

/// Version of the dataset layout, stored as the file attribute `layout`.
inline constexpr int kCollectionLayoutVersion = 2;

/// Integer columns of the `nodes` dataset.
enum NodeColumn : int { kNodeType, kNodeEnd, kNodeBirthVertex, kNodeVertexCount, kNodeColumnCount };
/// Columns of the `node_geometry` dataset (absolute, not invariant).
enum NodeGeometryColumn : int {
  kGeomArea, kGeomFqMin, kGeomFqMax, kGeomBarycenterX, kGeomBarycenterY, kGeomBarycenterZ, kGeomColumnCount
};
/// Columns of the `timings` dataset (milliseconds).
enum TimingColumn : int { kTimeLoad, kTimeGraph, kTimeFeatures, kTimeQuotient, kTimeReeb, kTimeAttributes, kTimeColumnCount };

/// One mesh of the collection and its attributed Reeb graph.
struct CollectionEntry {
  std::string name;           ///< the mesh as named on input (path relative to the input folder, or as given)
  std::string class_label;    ///< from the .cla file, "" when none
  std::uint64_t content_hash = 0;  ///< hash of the file's bytes (content_hash.h): what --resume compares
  std::int64_t vertices = 0;  ///< of the surface as read (hole filling excluded); 0 when failed
  std::int64_t faces = 0;
  bool ok = false;            ///< false: `error` says why; the graph arrays are empty
  std::string error;
  std::array<double, kTimeColumnCount> timings{};  ///< ms per TimingColumn

  // The graph (node ids local to this graph, vertex ids in the file's numbering).
  std::vector<std::int32_t> nodes;        ///< #nodes x kNodeColumnCount
  std::vector<double> node_geometry;      ///< #nodes x kGeomColumnCount
  std::vector<double> node_attributes;    ///< #nodes x kNodeAttributeCount
  std::vector<std::int32_t> edges;        ///< #edges x 2
  std::vector<double> edge_attributes;    ///< #edges x kEdgeAttributeCount
  std::vector<std::int32_t> feature_points;  ///< vertex ids (-1: a vertex added to close a hole)
  std::vector<std::int64_t> skeleton_offset; ///< #nodes + 1, into skeleton_points rows
  std::vector<double> skeleton_points;    ///< #points x 3
  std::vector<double> signature;          ///< kSignatureLength (NaN when failed)

  std::int32_t num_nodes() const { return static_cast<std::int32_t>(nodes.size() / kNodeColumnCount); }
  std::int32_t num_edges() const { return static_cast<std::int32_t>(edges.size() / 2); }
};

/// Where the file came from, stored as file attributes.
struct Provenance {
  std::string reebkit_version = REEBKIT_VERSION;
  std::string options;   ///< the analysis options, as JSON text
  std::string command;   ///< the command line that made the file
  std::string created;   ///< ISO 8601 date and time (UTC); filled by the writer when empty
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
  void append(CollectionEntry entry);
  /// Writes the buffered entries and makes the file consistent on disk.
  void checkpoint();
  /// Checkpoints and closes; throws on failure.
  void close();
  /// Entries written or buffered so far (existing ones included).
  std::int64_t size() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
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
  const std::vector<std::string>& names() const;
  const std::vector<std::string>& class_labels() const;
  /// size() x kSignatureLength, row-major.
  const std::vector<double>& signatures() const;
  /// Index of the entry called `name`, if any.
  std::optional<std::int64_t> find(const std::string& name) const;
  /// The whole entry i (graph included).
  CollectionEntry entry(std::int64_t i) const;
  /// Entries [first, first + count) in one read per dataset: much faster
  /// than entry() one by one (all of them: entries(0, size())).
  std::vector<CollectionEntry> entries(std::int64_t first, std::int64_t count) const;
  const Provenance& provenance() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace reebkit
