// Nearest neighbours among graph signatures: the pre-filter of
// query by example. Each entry of a collection has a fixed-length signature
// (attributes/graph_attributes.h, kSignatureLength entries in [0,1]); the
// candidates for graph matching are the entries whose signatures are nearest
// to the query's in the Euclidean distance. FLANN (Muja and Lowe 2014) with
// an exact, deterministic index: a linear scan or a single k-d tree searched
// without approximation. The k-d tree keeps the rows in their order (FLANN's
// `reorder` off), so that its saved form (save()) is the tree alone and
// loads over rows kept elsewhere (mapped from a query file:
// store/collection_file.h, QueryFile).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

namespace reebkit {

enum class SignatureIndexKind {
  Linear,        ///< flann::LinearIndexParams: every row compared
  KdTreeSingle,  ///< flann::KDTreeSingleIndexParams, searched exactly (eps = 0)
};

struct SignatureIndexOptions {
  SignatureIndexKind kind = SignatureIndexKind::KdTreeSingle;  ///< both exact; the k-d tree is faster
  int leaf_max_size = 10;                                      ///< points per k-d tree leaf (FLANN's default)
};

struct SignatureNeighbour {
  std::int64_t row = 0;   ///< row of the signature matrix (the collection index)
  double distance = 0.0;  ///< Euclidean distance between the signatures
};

/// An index over the rows of a signature matrix. Rows holding a NaN (failed
/// entries) are left out. Building copies the rows; the index is read-only
/// afterwards and may be searched from several threads.
class SignatureIndex {
 public:
  /// `signatures`: rows x `dimension`, row-major. Throws InvalidArgument when
  /// the size is not a multiple of `dimension` or `dimension` < 1.
  SignatureIndex(const std::vector<double>& signatures, int dimension, const SignatureIndexOptions& options = {});
  /// The k-d tree that save() wrote, over `rows`: row_of.size() x
  /// `dimension` values, the rows without NaN of a signature matrix, packed
  /// (e.g. mapped from a query file: store/collection_file.h), kept alive by
  /// the index; `row_of` their rows in that matrix. Not built anew. Throws
  /// InvalidArgument when `saved` is not such a tree of as many rows.
  SignatureIndex(std::shared_ptr<const double> rows, std::vector<std::int64_t> row_of, int dimension,
                 const std::vector<char>& saved);
  ~SignatureIndex();
  SignatureIndex(SignatureIndex&&) noexcept;
  SignatureIndex& operator=(SignatureIndex&&) noexcept;

  /// Indexed rows (rows without NaN).
  std::int64_t size() const;
  int dimension() const;
  /// The indexed rows (packed, size() x dimension()) and their rows in the
  /// signature matrix, as the loading constructor takes them.
  const double* rows() const;
  const std::vector<std::int64_t>& row_of() const;
  /// The k-d tree as bytes (FLANN's serialization), for the loading
  /// constructor. Throws InvalidArgument for a linear index.
  std::vector<char> save() const;
  /// The min(count, size()) rows nearest to `query` (dimension() entries),
  /// by increasing distance, ties by increasing row. Throws InvalidArgument
  /// on a query of the wrong length or holding a NaN.
  std::vector<SignatureNeighbour> nearest(const std::vector<double>& query, std::int64_t count) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace reebkit
