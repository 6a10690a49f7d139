#include "reebkit/retrieval/signature_index.h"

#include "reebkit/core/error.h"

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace reebkit {

namespace {
using FlannIndex = flann::NNIndex<flann::L2<double>>;
using KdTree = flann::KDTreeSingleIndex<flann::L2<double>>;
}  // namespace

struct SignatureIndex::Impl {
  int dimension = 0;
  std::vector<double> packed;          ///< the indexed signatures, when built here
  std::shared_ptr<const double> rows;  ///< the indexed signatures, packed (`packed` or given)
  std::vector<std::int64_t> row_of;    ///< packed row -> row of the input matrix
  std::unique_ptr<FlannIndex> index;

  /// The rows as FLANN takes them (which only reads them: the k-d tree does not reorder them).
  flann::Matrix<double> data() {
    return {const_cast<double*>(rows.get()), row_of.size(), static_cast<std::size_t>(dimension)};
  }
};

SignatureIndex::SignatureIndex(const std::vector<double>& signatures, int dimension,
                               const SignatureIndexOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (dimension < 1) throw InvalidArgument("signature index: dimension " + std::to_string(dimension) + " < 1");
  const std::size_t d = static_cast<std::size_t>(dimension);
  if (signatures.size() % d != 0)
    throw InvalidArgument("signature index: " + std::to_string(signatures.size()) + " values are not rows of " +
                          std::to_string(dimension));
  impl_->dimension = dimension;
  for (std::size_t r = 0; r < signatures.size() / d; ++r) {
    const auto begin = signatures.begin() + static_cast<std::ptrdiff_t>(r * d);
    if (std::any_of(begin, begin + dimension, [](double v) { return std::isnan(v); })) continue;
    impl_->packed.insert(impl_->packed.end(), begin, begin + dimension);
    impl_->row_of.push_back(static_cast<std::int64_t>(r));
  }
  impl_->rows = std::shared_ptr<const double>(impl_->packed.data(), [](const double*) {});  // owned by packed
  if (impl_->row_of.empty()) return;
  if (options.kind == SignatureIndexKind::Linear)
    impl_->index = std::make_unique<flann::LinearIndex<flann::L2<double>>>(impl_->data(), flann::LinearIndexParams());
  else
    impl_->index =
        std::make_unique<KdTree>(impl_->data(), flann::KDTreeSingleIndexParams(options.leaf_max_size, false));
  impl_->index->buildIndex();
}

SignatureIndex::SignatureIndex(std::shared_ptr<const double> rows, std::vector<std::int64_t> row_of, int dimension,
                               const std::vector<char>& saved)
    : impl_(std::make_unique<Impl>()) {
  if (dimension < 1) throw InvalidArgument("signature index: dimension " + std::to_string(dimension) + " < 1");
  impl_->dimension = dimension;
  impl_->rows = std::move(rows);
  impl_->row_of = std::move(row_of);
  if (impl_->row_of.empty()) return;
  auto tree = std::make_unique<KdTree>(impl_->data(), flann::KDTreeSingleIndexParams(10, false));
  FILE* in = fmemopen(const_cast<char*>(saved.data()), saved.size(), "rb");
  if (in == nullptr) throw InvalidArgument("signature index: cannot read the saved k-d tree");
  try {
    tree->loadIndex(in);
  } catch (const flann::FLANNException& e) {
    std::fclose(in);
    throw InvalidArgument(std::string("signature index: the saved k-d tree does not load: ") + e.what());
  }
  std::fclose(in);
  if (tree->size() != impl_->row_of.size() || tree->veclen() != static_cast<std::size_t>(dimension))
    throw InvalidArgument("signature index: the saved k-d tree indexes " + std::to_string(tree->size()) + " rows of " +
                          std::to_string(tree->veclen()) + ", not " + std::to_string(impl_->row_of.size()) + " of " +
                          std::to_string(dimension));
  impl_->index = std::move(tree);
}

SignatureIndex::~SignatureIndex() = default;
SignatureIndex::SignatureIndex(SignatureIndex&&) noexcept = default;
SignatureIndex& SignatureIndex::operator=(SignatureIndex&&) noexcept = default;

std::int64_t SignatureIndex::size() const { return static_cast<std::int64_t>(impl_->row_of.size()); }
int SignatureIndex::dimension() const { return impl_->dimension; }
const double* SignatureIndex::rows() const { return impl_->rows.get(); }
const std::vector<std::int64_t>& SignatureIndex::row_of() const { return impl_->row_of; }

std::vector<char> SignatureIndex::save() const {
  if (impl_->row_of.empty()) return {};
  if (dynamic_cast<const KdTree*>(impl_->index.get()) == nullptr)
    throw InvalidArgument("signature index: only a k-d tree is saved");
  char* buffer = nullptr;
  std::size_t bytes = 0;
  FILE* out = open_memstream(&buffer, &bytes);
  if (out == nullptr) throw InvalidArgument("signature index: cannot open a memory stream");
  impl_->index->saveIndex(out);
  std::fclose(out);
  std::vector<char> saved(buffer, buffer + bytes);
  std::free(buffer);  // NOLINT(cppcoreguidelines-no-malloc): open_memstream's buffer
  return saved;
}

std::vector<SignatureNeighbour> SignatureIndex::nearest(const std::vector<double>& query, std::int64_t count) const {
  if (query.size() != static_cast<std::size_t>(impl_->dimension))
    throw InvalidArgument("signature index: query of " + std::to_string(query.size()) + " values, expected " +
                          std::to_string(impl_->dimension));
  if (std::any_of(query.begin(), query.end(), [](double v) { return std::isnan(v); }))
    throw InvalidArgument("signature index: the query signature holds a NaN (a failed entry)");
  const std::size_t k = static_cast<std::size_t>(std::clamp<std::int64_t>(count, 0, size()));
  if (k == 0) return {};

  // Every row as near as the k-th, so that rows tied at the k-th distance
  // are chosen by increasing row whatever FLANN's order: the k + kTieMargin
  // nearest hold them all unless the last of those is tied too, and then a
  // radius search finds them. FLANN's L2 distances are squared.
  constexpr std::size_t kTieMargin = 8;
  const flann::Matrix<double> q(const_cast<double*>(query.data()), 1, query.size());
  std::vector<std::vector<std::size_t>> indices;
  std::vector<std::vector<double>> squared;
  const flann::SearchParams exact(flann::FLANN_CHECKS_UNLIMITED, 0.0f, true);
  const std::size_t wider = std::min(k + kTieMargin, static_cast<std::size_t>(size()));
  impl_->index->knnSearch(q, indices, squared, wider, exact);
  const double kth = squared.front()[k - 1];
  if (wider < static_cast<std::size_t>(size()) && squared.front().back() <= kth) {
    float radius = static_cast<float>(kth);  // FLANN takes a float radius: the first float above kth
    while (static_cast<double>(radius) <= kth) radius = std::nextafter(radius, std::numeric_limits<float>::infinity());
    impl_->index->radiusSearch(q, indices, squared, radius, exact);
  }

  std::vector<SignatureNeighbour> out;
  for (std::size_t i = 0; i < indices.front().size(); ++i)
    if (squared.front()[i] <= kth) out.push_back({impl_->row_of[indices.front()[i]], std::sqrt(squared.front()[i])});
  std::sort(out.begin(), out.end(), [](const SignatureNeighbour& a, const SignatureNeighbour& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.row < b.row;
  });
  out.resize(k);
  return out;
}

}  // namespace reebkit
