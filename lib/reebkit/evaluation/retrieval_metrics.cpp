#include "reebkit/evaluation/retrieval_metrics.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace reebkit {
namespace {

/// For each position of the ranking of `query`, whether the model there is in
/// the query's class (Shilane et al. 2004: query left out, ties by index).
std::vector<char> relevance(const DistanceMatrix& distances, const ModelClasses& classes, Index query) {
  const auto n = static_cast<Index>(distances.rows());
  std::vector<Index> ranking;
  ranking.reserve(static_cast<std::size_t>(n - 1));
  for (Index j = 0; j < n; ++j)
    if (j != query) ranking.push_back(j);
  const auto row = distances.row(query);
  std::sort(ranking.begin(), ranking.end(),
            [&row](Index a, Index b) { return row(a) < row(b) || (row(a) == row(b) && a < b); });
  const Index c = classes.of_model[static_cast<std::size_t>(query)];
  std::vector<char> rel(ranking.size());
  for (std::size_t k = 0; k < ranking.size(); ++k) rel[k] = classes.of_model[static_cast<std::size_t>(ranking[k])] == c;
  return rel;
}

/// Relevant models among the first `depth` of the ranking.
double hits(const std::vector<char>& rel, std::size_t depth) {
  return std::accumulate(rel.begin(), rel.begin() + static_cast<std::ptrdiff_t>(std::min(depth, rel.size())), 0.0);
}

/// The measures of one ranking with `k` relevant models (see the header).
RetrievalScores score(const std::vector<char>& rel, std::size_t k, const RetrievalOptions& options) {
  RetrievalScores s;
  const auto kd = static_cast<double>(k);
  s.nearest_neighbor = rel.front();
  s.first_tier = hits(rel, k) / kd;
  s.second_tier = hits(rel, 2 * k) / kd;
  const std::size_t m = std::min(static_cast<std::size_t>(options.e_measure_depth), rel.size());
  s.e_measure = 2.0 * hits(rel, m) / (static_cast<double>(m) + kd);

  double dcg = 0, ideal = 0;
  for (std::size_t i = 0; i < rel.size(); ++i) {
    const double discount = i == 0 ? 1.0 : 1.0 / std::log2(static_cast<double>(i + 1));
    if (rel[i]) dcg += discount;
    if (i < k) ideal += discount;
  }
  s.dcg = dcg / ideal;

  // precision j / p_j of the j-th hit, then P(r_l) = max over j with j / K >= l / L.
  std::vector<double> at_hit;
  for (std::size_t i = 0; i < rel.size(); ++i)
    if (rel[i]) at_hit.push_back(static_cast<double>(at_hit.size() + 1) / static_cast<double>(i + 1));
  const auto levels = static_cast<std::size_t>(options.recall_levels);
  s.precision.assign(levels, 0.0);
  double best = 0;
  std::size_t j = at_hit.size();  // hits j..K taken into `best` so far (1-based j)
  for (std::size_t l = levels; l >= 1; --l) {
    while (j >= 1 && j * levels >= l * k) best = std::max(best, at_hit[--j]);
    s.precision[l - 1] = best;
  }
  return s;
}

void accumulate(RetrievalScores& sum, const RetrievalScores& s) {
  sum.nearest_neighbor += s.nearest_neighbor;
  sum.first_tier += s.first_tier;
  sum.second_tier += s.second_tier;
  sum.e_measure += s.e_measure;
  sum.dcg += s.dcg;
  sum.precision.resize(s.precision.size(), 0.0);
  for (std::size_t i = 0; i < s.precision.size(); ++i) sum.precision[i] += s.precision[i];
}

RetrievalScores mean(const RetrievalScores& sum, std::size_t count, std::size_t levels) {
  RetrievalScores m = sum;
  m.precision.resize(levels, 0.0);
  if (count == 0) return m;
  const auto n = static_cast<double>(count);
  m.nearest_neighbor /= n;
  m.first_tier /= n;
  m.second_tier /= n;
  m.e_measure /= n;
  m.dcg /= n;
  for (double& p : m.precision) p /= n;
  return m;
}

}  // namespace

ModelClasses model_classes(const std::vector<PsbClass>& classes) {
  ModelClasses out;
  for (const PsbClass& c : classes) {
    out.of_model.insert(out.of_model.end(), c.models.size(), static_cast<Index>(out.names.size()));
    out.names.push_back(c.name);
  }
  return out;
}

RetrievalEvaluation evaluate_retrieval(const DistanceMatrix& distances, const ModelClasses& classes,
                                       const RetrievalOptions& options) {
  const auto n = static_cast<Index>(classes.of_model.size());
  if (distances.rows() != n || distances.cols() != n)
    throw InvalidArgument("evaluate_retrieval: the distance matrix is " + std::to_string(distances.rows()) + " x " +
                          std::to_string(distances.cols()) + ", the classes list " + std::to_string(n) + " models");
  if (options.e_measure_depth < 1 || options.recall_levels < 1 || options.min_class_size < 2)
    throw InvalidArgument("evaluate_retrieval: e_measure_depth and recall_levels must be >= 1, min_class_size >= 2");
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j)
      if (std::isnan(distances(i, j)))
        throw InvalidArgument("evaluate_retrieval: distance (" + std::to_string(i) + ", " + std::to_string(j) +
                              ") is not a number");

  RetrievalEvaluation out;
  const auto levels = static_cast<std::size_t>(options.recall_levels);
  for (std::size_t l = 1; l <= levels; ++l) out.recall.push_back(static_cast<double>(l) / static_cast<double>(levels));
  out.classes.resize(classes.names.size());
  for (std::size_t c = 0; c < classes.names.size(); ++c) out.classes[c].name = classes.names[c];
  for (const Index c : classes.of_model) ++out.classes[static_cast<std::size_t>(c)].size;

  std::vector<Index> query_models;
  for (Index q = 0; q < n; ++q)
    if (out.classes[static_cast<std::size_t>(classes.of_model[static_cast<std::size_t>(q)])].size >=
        options.min_class_size)
      query_models.push_back(q);
  if (query_models.empty())
    throw InvalidArgument("evaluate_retrieval: no class has the " + std::to_string(options.min_class_size) +
                          " models a query class needs");

  out.queries.resize(query_models.size());
  const auto count = static_cast<std::ptrdiff_t>(query_models.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    const Index q = query_models[static_cast<std::size_t>(i)];
    const Index c = classes.of_model[static_cast<std::size_t>(q)];
    const auto k = static_cast<std::size_t>(out.classes[static_cast<std::size_t>(c)].size - 1);
    out.queries[static_cast<std::size_t>(i)] = {q, c, score(relevance(distances, classes, q), k, options)};
  }

  std::vector<RetrievalScores> class_sums(classes.names.size());
  RetrievalScores micro_sum;
  for (const QueryScores& q : out.queries) {
    accumulate(class_sums[static_cast<std::size_t>(q.class_id)], q.scores);
    accumulate(micro_sum, q.scores);
    ++out.classes[static_cast<std::size_t>(q.class_id)].queries;
  }
  out.micro = mean(micro_sum, out.queries.size(), levels);
  RetrievalScores macro_sum;
  std::size_t query_classes = 0;
  for (std::size_t c = 0; c < classes.names.size(); ++c) {
    ClassScores& cs = out.classes[c];
    cs.mean = mean(class_sums[c], static_cast<std::size_t>(cs.queries), levels);
    if (cs.queries == 0) continue;
    accumulate(macro_sum, cs.mean);
    ++query_classes;
  }
  out.macro = mean(macro_sum, query_classes, levels);
  return out;
}

}  // namespace reebkit
