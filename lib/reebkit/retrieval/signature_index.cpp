#include "reebkit/retrieval/signature_index.h"

#include "reebkit/core/error.h"

#include <flann/flann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace reebkit {

struct SignatureIndex::Impl {
  int dimension = 0;
  std::vector<double> rows;           ///< the indexed signatures, packed
  std::vector<std::int64_t> row_of;   ///< packed row -> row of the input matrix
  std::unique_ptr<flann::Index<flann::L2<double>>> index;
};

SignatureIndex::SignatureIndex(const std::vector<double>& signatures, int dimension,
                               const SignatureIndexOptions& options)
    : impl_(std::make_unique<Impl>()) {
  if (dimension < 1) throw InvalidArgument("signature index: dimension " + std::to_string(dimension) + " < 1");
  const std::size_t d = static_cast<std::size_t>(dimension);
  if (signatures.size() % d != 0)
    throw InvalidArgument("signature index: " + std::to_string(signatures.size()) +
                          " values are not rows of " + std::to_string(dimension));
  impl_->dimension = dimension;
  for (std::size_t r = 0; r < signatures.size() / d; ++r) {
    const auto begin = signatures.begin() + static_cast<std::ptrdiff_t>(r * d);
    if (std::any_of(begin, begin + dimension, [](double v) { return std::isnan(v); })) continue;
    impl_->rows.insert(impl_->rows.end(), begin, begin + dimension);
    impl_->row_of.push_back(static_cast<std::int64_t>(r));
  }
  if (impl_->row_of.empty()) return;
  const flann::Matrix<double> data(impl_->rows.data(), impl_->row_of.size(), d);
  const flann::IndexParams params = options.kind == SignatureIndexKind::Linear
                                        ? flann::IndexParams(flann::LinearIndexParams())
                                        : flann::IndexParams(flann::KDTreeSingleIndexParams(options.leaf_max_size));
  impl_->index = std::make_unique<flann::Index<flann::L2<double>>>(data, params);
  impl_->index->buildIndex();
}

SignatureIndex::~SignatureIndex() = default;
SignatureIndex::SignatureIndex(SignatureIndex&&) noexcept = default;

std::int64_t SignatureIndex::size() const { return static_cast<std::int64_t>(impl_->row_of.size()); }
int SignatureIndex::dimension() const { return impl_->dimension; }

std::vector<SignatureNeighbour> SignatureIndex::nearest(const std::vector<double>& query, std::int64_t count) const {
  if (query.size() != static_cast<std::size_t>(impl_->dimension))
    throw InvalidArgument("signature index: query of " + std::to_string(query.size()) + " values, expected " +
                          std::to_string(impl_->dimension));
  if (std::any_of(query.begin(), query.end(), [](double v) { return std::isnan(v); }))
    throw InvalidArgument("signature index: the query signature holds a NaN (a failed entry)");
  const std::size_t k = static_cast<std::size_t>(std::clamp<std::int64_t>(count, 0, size()));
  if (k == 0) return {};

  // The k nearest, then every row as near as the k-th, so that rows tied at
  // the k-th distance are chosen by increasing row whatever FLANN's order.
  // FLANN's L2 distances are squared.
  const flann::Matrix<double> q(const_cast<double*>(query.data()), 1, query.size());
  std::vector<std::vector<std::size_t>> indices;
  std::vector<std::vector<double>> squared;
  const flann::SearchParams exact(flann::FLANN_CHECKS_UNLIMITED, 0.0f, true);
  impl_->index->knnSearch(q, indices, squared, k, exact);
  const double kth = squared.front().back();
  float radius = static_cast<float>(kth);  // FLANN takes a float radius: the first float above kth
  while (static_cast<double>(radius) <= kth) radius = std::nextafter(radius, std::numeric_limits<float>::infinity());
  impl_->index->radiusSearch(q, indices, squared, radius, exact);

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
