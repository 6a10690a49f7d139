#include "reebkit/retrieval/query.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <string>

namespace reebkit {

std::vector<QueryResult> query_collection(const CollectionReader& collection, const SignatureIndex& index,
                                          const CollectionEntry& query, const QueryOptions& options) {
  if (!query.ok) throw InvalidArgument("query '" + query.name + "' has no graph: " + query.error);
  if (options.k < 1 || options.candidates < 1)
    throw InvalidArgument("query: need k >= 1 and candidates >= 1 (k = " + std::to_string(options.k) +
                          ", candidates = " + std::to_string(options.candidates) + ")");
  if (index.dimension() != kSignatureLength ||
      static_cast<std::size_t>(collection.size()) * kSignatureLength != collection.signatures().size())
    throw InvalidArgument("query: the signature index does not match the collection");

  std::vector<QueryResult> ranked;
  for (const SignatureNeighbour& n : index.nearest(query.signature, std::max(options.k, options.candidates))) {
    if (n.row >= collection.size()) throw InvalidArgument("query: the signature index does not match the collection");
    const CollectionEntry entry = collection.entry(n.row);
    ranked.push_back({n.row, entry.name, entry.class_label, match_graphs(query, entry, options.matching).distance,
                      n.distance});
  }
  std::sort(ranked.begin(), ranked.end(), [](const QueryResult& a, const QueryResult& b) {
    return a.distance != b.distance ? a.distance < b.distance : a.index < b.index;
  });
  if (ranked.size() > static_cast<std::size_t>(options.k)) ranked.resize(static_cast<std::size_t>(options.k));
  return ranked;
}

std::vector<QueryResult> query_collection(const CollectionReader& collection, const CollectionEntry& query,
                                          const QueryOptions& options) {
  return query_collection(collection, SignatureIndex(collection.signatures(), kSignatureLength), query, options);
}

}  // namespace reebkit
