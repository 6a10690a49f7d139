// The PSB retrieval measures on hand-computed toy rankings (Shilane et al.
// 2004): every expected value below is worked out in the comments from the
// definitions in retrieval_metrics.h, never copied from a run.
#include "reebkit/evaluation/retrieval_metrics.h"

#include "reebkit/core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace reebkit::test {
namespace {

constexpr double kTol = 1e-12;

/// A matrix whose row q ranks the models as rankings[q] lists them:
/// d(q, q) = `self`, d(q, rankings[q][k]) = k + 1.
DistanceMatrix from_rankings(const std::vector<std::vector<Index>>& rankings, float self = 0.0f) {
  const auto n = static_cast<Eigen::Index>(rankings.size());
  DistanceMatrix d = DistanceMatrix::Constant(n, n, self);
  for (Eigen::Index q = 0; q < n; ++q)
    for (std::size_t k = 0; k < rankings[static_cast<std::size_t>(q)].size(); ++k)
      d(q, rankings[static_cast<std::size_t>(q)][k]) = static_cast<float>(k + 1);
  return d;
}

/// Class i has sizes[i] models, numbered consecutively.
ModelClasses classes_of_sizes(const std::vector<Index>& sizes) {
  std::vector<PsbClass> psb;
  Index next = 0;
  for (std::size_t c = 0; c < sizes.size(); ++c) {
    PsbClass pc{"class" + std::to_string(c), "0", {}};
    for (Index i = 0; i < sizes[c]; ++i) pc.models.push_back(std::to_string(next++));
    psb.push_back(pc);
  }
  return model_classes(psb);
}

// Seven models: A = {0, 1, 2} (K = 2), B = {3, 4, 5, 6} (K = 3); N - 1 = 6, so
// the E-measure looks at m = min(32, 6) = 6 models.
const std::vector<std::vector<Index>> kToy = {
    {3, 1, 4, 5, 2, 6},  // q0 (A): rel 0 1 0 0 1 0
    {0, 2, 3, 4, 5, 6},  // q1 (A): perfect
    {3, 4, 5, 6, 0, 1},  // q2 (A): rel 0 0 0 0 1 1, the worst
    {4, 5, 6, 0, 1, 2},  // q3 (B): perfect
    {3, 0, 5, 1, 2, 6},  // q4 (B): rel 1 0 1 0 0 1
    {3, 4, 6, 0, 1, 2},  // q5 (B): perfect
    {0, 1, 2, 3, 4, 5},  // q6 (B): rel 0 0 0 1 1 1, the worst
};

/// Distance `inside` between models of one class, `across` between classes.
DistanceMatrix block_matrix(const ModelClasses& classes, float inside, float across) {
  const auto n = static_cast<Eigen::Index>(classes.of_model.size());
  DistanceMatrix d(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      d(i, j) = classes.of_model[std::size_t(i)] == classes.of_model[std::size_t(j)] ? inside : across;
  return d;
}

const QueryScores& query(const RetrievalEvaluation& e, Index model) {
  for (const QueryScores& q : e.queries)
    if (q.model == model) return q;
  throw std::runtime_error("no query " + std::to_string(model));
}

TEST(RetrievalMetrics, ModelClassesFollowTheClaOrder) {
  const ModelClasses c = model_classes({{"cup", "0", {"7", "2"}}, {"ant", "0", {"1"}}, {"fish", "0", {"5", "3", "4"}}});
  EXPECT_EQ(c.names, (std::vector<std::string>{"cup", "ant", "fish"}));
  EXPECT_EQ(c.of_model, (std::vector<Index>{0, 0, 1, 2, 2, 2}));
}

TEST(RetrievalMetrics, NearestNeighborFirstAndSecondTierOnToyRankings) {
  const RetrievalEvaluation e = evaluate_retrieval(from_rankings(kToy), classes_of_sizes({3, 4}));
  ASSERT_EQ(e.queries.size(), 7u);
  // q0: rel 0 1 0 0 1 0, K = 2: NN = 0; FT = 1 hit in the top 2 / 2; ST = 1 hit in the top 4 / 2.
  EXPECT_EQ(query(e, 0).scores.nearest_neighbor, 0.0);
  EXPECT_NEAR(query(e, 0).scores.first_tier, 0.5, kTol);
  EXPECT_NEAR(query(e, 0).scores.second_tier, 0.5, kTol);
  // q2: both members last (positions 5, 6): nothing in the top 2 or top 4.
  EXPECT_EQ(query(e, 2).scores.first_tier, 0.0);
  EXPECT_EQ(query(e, 2).scores.second_tier, 0.0);
  // q4: rel 1 0 1 0 0 1, K = 3: NN = 1; FT = 2 of the top 3 / 3; ST = 3 of the top 6 / 3.
  EXPECT_EQ(query(e, 4).scores.nearest_neighbor, 1.0);
  EXPECT_NEAR(query(e, 4).scores.first_tier, 2.0 / 3.0, kTol);
  EXPECT_NEAR(query(e, 4).scores.second_tier, 1.0, kTol);
  // q6: rel 0 0 0 1 1 1: NN = FT = 0 but the top 6 hold all three: ST = 1.
  EXPECT_EQ(query(e, 6).scores.nearest_neighbor, 0.0);
  EXPECT_EQ(query(e, 6).scores.first_tier, 0.0);
  EXPECT_NEAR(query(e, 6).scores.second_tier, 1.0, kTol);

  // Micro NN: q0..q6 = 0 1 0 1 1 1 0 -> 4/7; macro: A 1/3, B 3/4 -> 13/24.
  EXPECT_NEAR(e.micro.nearest_neighbor, 4.0 / 7.0, kTol);
  EXPECT_NEAR(e.macro.nearest_neighbor, 13.0 / 24.0, kTol);
  // FT: q0..q6 = 1/2 1 0 1 2/3 1 0 -> micro 25/6 / 7 = 25/42;
  // class means A = 1/2, B = (1 + 2/3 + 1 + 0) / 4 = 2/3 -> macro 7/12.
  EXPECT_NEAR(e.micro.first_tier, 25.0 / 42.0, kTol);
  EXPECT_NEAR(e.classes[0].mean.first_tier, 0.5, kTol);
  EXPECT_NEAR(e.classes[1].mean.first_tier, 2.0 / 3.0, kTol);
  EXPECT_NEAR(e.macro.first_tier, 7.0 / 12.0, kTol);
  EXPECT_EQ(e.classes[0].queries, 3);
  EXPECT_EQ(e.classes[1].queries, 4);
  EXPECT_EQ(e.classes[1].size, 4);
}

TEST(RetrievalMetrics, EMeasureOnToyRankings) {
  const DistanceMatrix d = from_rankings(kToy);
  const ModelClasses classes = classes_of_sizes({3, 4});
  const RetrievalEvaluation e = evaluate_retrieval(d, classes);
  // q0: m = 6, r = 2, P = 2/6, R = 2/2: E = 2 P R / (P + R) = (2/3) / (4/3) = 1/2.
  EXPECT_NEAR(query(e, 0).scores.e_measure, 0.5, kTol);
  // q3 (perfect, K = 3): P = 3/6, R = 1: E = 1 / (3/2) = 2/3.
  EXPECT_NEAR(query(e, 3).scores.e_measure, 2.0 / 3.0, kTol);
  // q4 with the E-measure over the first 2 only: r = 1, P = 1/2, R = 1/3: E = (1/3) / (5/6) = 2/5.
  RetrievalOptions two;
  two.e_measure_depth = 2;
  EXPECT_NEAR(query(evaluate_retrieval(d, classes, two), 4).scores.e_measure, 0.4, kTol);
  // q2 over the first 2: r = 0 -> E = 0.
  EXPECT_EQ(query(evaluate_retrieval(d, classes, two), 2).scores.e_measure, 0.0);
}

TEST(RetrievalMetrics, DiscountedCumulativeGainOnToyRankings) {
  const RetrievalEvaluation e = evaluate_retrieval(from_rankings(kToy), classes_of_sizes({3, 4}));
  // q0: hits at positions 2 and 5: 1/log2(2) + 1/log2(5); ideal (K = 2): 1 + 1/log2(2) = 2.
  EXPECT_NEAR(query(e, 0).scores.dcg, (1.0 + 1.0 / std::log2(5.0)) / 2.0, kTol);
  // q4: hits at 1, 3, 6: 1 + 1/log2(3) + 1/log2(6); ideal (K = 3): 1 + 1 + 1/log2(3).
  EXPECT_NEAR(query(e, 4).scores.dcg,
              (1.0 + 1.0 / std::log2(3.0) + 1.0 / std::log2(6.0)) / (2.0 + 1.0 / std::log2(3.0)), kTol);
  // q6: hits at 4, 5, 6.
  EXPECT_NEAR(query(e, 6).scores.dcg,
              (1.0 / std::log2(4.0) + 1.0 / std::log2(5.0) + 1.0 / std::log2(6.0)) / (2.0 + 1.0 / std::log2(3.0)),
              kTol);
  EXPECT_NEAR(query(e, 3).scores.dcg, 1.0, kTol);
}

TEST(RetrievalMetrics, InterpolatedPrecisionRecallOnToyRankings) {
  const RetrievalEvaluation e = evaluate_retrieval(from_rankings(kToy), classes_of_sizes({3, 4}));
  ASSERT_EQ(e.recall.size(), 20u);
  EXPECT_NEAR(e.recall.front(), 0.05, kTol);
  EXPECT_NEAR(e.recall.back(), 1.0, kTol);
  for (std::size_t l = 0; l < 20; ++l) {
    const double r = e.recall[l];
    // q0: hits (recall 1/2, precision 1/2) and (1, 2/5): P(r) = 1/2 up to r = 0.5, then 2/5.
    EXPECT_NEAR(query(e, 0).scores.precision[l], r <= 0.5 + 1e-9 ? 0.5 : 0.4, kTol) << r;
    // q4: hits (1/3, 1), (2/3, 2/3), (1, 1/2): 1 up to 0.30, 2/3 for 0.35..0.65, 1/2 from 0.70.
    EXPECT_NEAR(query(e, 4).scores.precision[l], r < 1.0 / 3.0 ? 1.0 : r < 2.0 / 3.0 ? 2.0 / 3.0 : 0.5, kTol) << r;
    // q6: hits (1/3, 1/4), (2/3, 2/5), (1, 1/2): the max at recall >= r is always 1/2.
    EXPECT_NEAR(query(e, 6).scores.precision[l], 0.5, kTol) << r;
    // q2: hits at 5 and 6: (1/2, 1/5), (1, 1/3) -> 1/3 everywhere.
    EXPECT_NEAR(query(e, 2).scores.precision[l], 1.0 / 3.0, kTol) << r;
  }
  // Micro at recall 1: q0..q6 = 2/5 1 1/3 1 1/2 1 1/2 -> 71/15 / 7;
  // macro: A (2/5 + 1 + 1/3) / 3 = 26/45, B (1 + 1/2 + 1 + 1/2) / 4 = 3/4.
  EXPECT_NEAR(e.micro.precision.back(), 71.0 / 15.0 / 7.0, kTol);
  EXPECT_NEAR(e.classes[0].mean.precision.back(), 26.0 / 45.0, kTol);
  EXPECT_NEAR(e.macro.precision.back(), (26.0 / 45.0 + 0.75) / 2.0, kTol);
}

TEST(RetrievalMetrics, TheQueryIsLeftOutOfItsOwnRanking) {
  const ModelClasses classes = classes_of_sizes({3, 4});
  const RetrievalEvaluation zero = evaluate_retrieval(from_rankings(kToy, 0.0f), classes);
  // Self-distance above every other: if q ranked itself it would change nothing at the top but
  // shift the tail; below every other it would take the nearest neighbour slot.
  for (const float self : {-5.0f, 99.0f, 3.0f}) {
    const RetrievalEvaluation e = evaluate_retrieval(from_rankings(kToy, self), classes);
    for (std::size_t i = 0; i < e.queries.size(); ++i) {
      EXPECT_EQ(e.queries[i].scores.nearest_neighbor, zero.queries[i].scores.nearest_neighbor) << self;
      EXPECT_EQ(e.queries[i].scores.dcg, zero.queries[i].scores.dcg) << self;
      EXPECT_EQ(e.queries[i].scores.precision, zero.queries[i].scores.precision) << self;
    }
  }
}

TEST(RetrievalMetrics, TiesAreBrokenByIndex) {
  // Every distance equal: each query ranks the others by index. A = {0, 1, 2}:
  // q0 sees 1 2 3 4 5 6, q1 sees 0 2 ..., q2 sees 0 1 ...: NN = FT = 1.
  // B = {3..6}: the three A models come first: NN = FT = 0, ST = 3/3 (top 6 hold B's other 3).
  const RetrievalEvaluation e = evaluate_retrieval(DistanceMatrix::Constant(7, 7, 1.0f), classes_of_sizes({3, 4}));
  for (const QueryScores& q : e.queries) {
    const double expected = q.class_id == 0 ? 1.0 : 0.0;
    EXPECT_EQ(q.scores.nearest_neighbor, expected) << q.model;
    EXPECT_EQ(q.scores.first_tier, expected) << q.model;
  }
  EXPECT_NEAR(query(e, 5).scores.second_tier, 1.0, kTol);
  EXPECT_NEAR(e.micro.nearest_neighbor, 3.0 / 7.0, kTol);
  EXPECT_NEAR(e.macro.nearest_neighbor, 0.5, kTol);
}

TEST(RetrievalMetrics, PerfectMatrixGivesOneEverywhereButTheBoundedEMeasure) {
  // Classes of 3, 4 and 5 models (N = 12), distance 0 inside a class, 1 across.
  const std::vector<Index> sizes = {3, 4, 5};
  const ModelClasses classes = classes_of_sizes(sizes);
  const RetrievalEvaluation e = evaluate_retrieval(block_matrix(classes, 0.0f, 1.0f), classes);
  for (const QueryScores& q : e.queries) {
    EXPECT_EQ(q.scores.nearest_neighbor, 1.0);
    EXPECT_EQ(q.scores.first_tier, 1.0);
    EXPECT_EQ(q.scores.second_tier, 1.0);
    EXPECT_NEAR(q.scores.dcg, 1.0, kTol);
    for (const double p : q.scores.precision) EXPECT_EQ(p, 1.0);
    // m = min(32, 11) = 11 retrieved, all K in them: E = 2 K / (11 + K).
    const double k = sizes[std::size_t(q.class_id)] - 1;
    EXPECT_NEAR(q.scores.e_measure, 2 * k / (11 + k), kTol);
  }
  EXPECT_EQ(e.micro.nearest_neighbor, 1.0);
  EXPECT_EQ(e.macro.first_tier, 1.0);
  EXPECT_NEAR(e.macro.dcg, 1.0, kTol);
}

TEST(RetrievalMetrics, ReversedMatrixGivesTheWorstValues) {
  // Distance 1 inside a class, 0 across: every class member comes after the
  // N - 1 - K others, at positions N - K .. N - 1 (N = 12).
  const std::vector<Index> sizes = {3, 4, 5};
  const ModelClasses classes = classes_of_sizes(sizes);
  const RetrievalEvaluation e = evaluate_retrieval(block_matrix(classes, 1.0f, 0.0f), classes);
  for (const QueryScores& q : e.queries) {
    const int k = sizes[std::size_t(q.class_id)] - 1;
    const int others = 11 - k;
    EXPECT_EQ(q.scores.nearest_neighbor, 0.0);
    EXPECT_EQ(q.scores.first_tier, 0.0);
    // The top 2K hold max(0, 2K - others) members.
    EXPECT_NEAR(q.scores.second_tier, std::max(0, 2 * k - others) / double(k), kTol);
    double dcg = 0, ideal = 1;
    for (int j = 1; j <= k; ++j) dcg += 1.0 / std::log2(double(others + j));
    for (int j = 2; j <= k; ++j) ideal += 1.0 / std::log2(double(j));
    EXPECT_NEAR(q.scores.dcg, dcg / ideal, kTol);
    // The j-th hit has precision j / (others + j), largest at j = K: K / 11 at every recall.
    for (const double p : q.scores.precision) EXPECT_NEAR(p, k / 11.0, kTol);
  }
}

TEST(RetrievalMetrics, ClassesOfTwoOrFewerAreNoQueriesButStayInTheRankings) {
  // A = {0, 1, 2}, B = {3, 4, 5}, C = {6, 7}. q0 ranks the C models first:
  // they count as misses (NN = 0, FT = 0, ST = 2/2 with hits at 3 and 4).
  const std::vector<std::vector<Index>> rankings = {{6, 7, 1, 2, 3, 4, 5}, {0, 2, 3, 4, 5, 6, 7}, {0, 1, 3, 4, 5, 6, 7},
                                                    {4, 5, 0, 1, 2, 6, 7}, {3, 5, 0, 1, 2, 6, 7}, {3, 4, 0, 1, 2, 6, 7},
                                                    {7, 0, 1, 2, 3, 4, 5}, {6, 0, 1, 2, 3, 4, 5}};
  const RetrievalEvaluation e = evaluate_retrieval(from_rankings(rankings), classes_of_sizes({3, 3, 2}));
  ASSERT_EQ(e.queries.size(), 6u);
  for (const QueryScores& q : e.queries) EXPECT_LT(q.model, 6);
  EXPECT_EQ(e.classes[2].queries, 0);
  EXPECT_EQ(e.classes[2].size, 2);
  EXPECT_EQ(query(e, 0).scores.nearest_neighbor, 0.0);
  EXPECT_EQ(query(e, 0).scores.first_tier, 0.0);
  EXPECT_NEAR(query(e, 0).scores.second_tier, 1.0, kTol);
  // Macro over A (NN 2/3) and B (NN 1) only; micro over the 6 queries: 5/6.
  EXPECT_NEAR(e.macro.nearest_neighbor, (2.0 / 3.0 + 1.0) / 2.0, kTol);
  EXPECT_NEAR(e.micro.nearest_neighbor, 5.0 / 6.0, kTol);
}

TEST(RetrievalMetrics, RejectsMismatchedSizesNaNsAndNoQueries) {
  EXPECT_THROW(evaluate_retrieval(DistanceMatrix::Zero(6, 6), classes_of_sizes({3, 4})), InvalidArgument);
  DistanceMatrix nan = DistanceMatrix::Zero(7, 7);
  nan(2, 5) = std::nanf("");
  EXPECT_THROW(evaluate_retrieval(nan, classes_of_sizes({3, 4})), InvalidArgument);
  EXPECT_THROW(evaluate_retrieval(DistanceMatrix::Zero(4, 4), classes_of_sizes({2, 2})), InvalidArgument);
}

}  // namespace
}  // namespace reebkit::test
