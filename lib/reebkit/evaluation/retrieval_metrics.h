// Retrieval measures of the Princeton Shape Benchmark (Shilane, Min, Kazhdan,
// Funkhouser, "The Princeton Shape Benchmark", SMI 2004, section 4.3), computed
// from a distance matrix and the class of every model.
//
// For a query q of class C (|C| models, K = |C| - 1 of them other than q), the
// ranking lists the N - 1 other models by increasing distance d(q, .), ties
// broken by increasing model index; q itself is left out. With rel_k = 1 when
// the k-th model of the ranking (k = 1..N-1) is in C:
//  - Nearest Neighbor  NN  = rel_1;
//  - First Tier        FT  = (rel_1 + ... + rel_K) / K;
//  - Second Tier       ST  = (rel_1 + ... + rel_2K) / K (the ranking ends at N - 1);
//  - E-measure         E   = 2 P R / (P + R) over the first m = min(32, N - 1)
//                            models, P = r / m, R = r / K, r = rel_1 + ... + rel_m
//                            (= 2 r / (m + K); 0 when r = 0); a perfect ranking has
//                            E = 2 K / (m + K), 1 only when K = m;
//  - DCG = (rel_1 + sum_{k>=2} rel_k / log2 k) / (1 + sum_{k=2..K} 1 / log2 k),
//    normalized by the DCG of a ranking that lists the K class members first;
//  - precision-recall: the j-th member of C found, at rank p_j, has recall j / K
//    and precision j / p_j; the curve gives at the 20 recall levels
//    r = 0.05, 0.10, ..., 1.00 the interpolated precision
//    P(r) = max { j / p_j : j / K >= r } (the highest precision at any recall >= r).
// Queries are the models of classes with at least 3 models (PSB: classes of size
// <= 2 are left out as queries; their models stay in every ranking). Micro
// averages are means over the queries, macro averages means over the classes of
// their class means.
#pragma once

#include "reebkit/core/types.h"
#include "reebkit/evaluation/distance_matrix.h"
#include "reebkit/io/psb_classes.h"

#include <string>
#include <vector>

namespace reebkit {

/// The class of every row of a distance matrix.
struct ModelClasses {
  std::vector<std::string> names;  ///< class names, in .cla order
  std::vector<Index> of_model;     ///< class of model i (index into names)
};

/// Rows in .cla order: the models of the first class in the order listed, then
/// those of the second class, and so on.
ModelClasses model_classes(const std::vector<PsbClass>& classes);

struct RetrievalOptions {
  Index e_measure_depth = 32;  ///< E-measure over the first 32 retrieved (PSB)
  Index min_class_size = 3;    ///< classes with fewer models are not queries (PSB)
  Index recall_levels = 20;    ///< precision at recall 1/20, 2/20, ..., 1 (PSB)
};

/// The measures of one query, or their mean over several.
struct RetrievalScores {
  double nearest_neighbor = 0;
  double first_tier = 0;
  double second_tier = 0;
  double e_measure = 0;
  double dcg = 0;
  std::vector<double> precision;  ///< interpolated precision at each recall level
};

struct QueryScores {
  Index model = 0;
  Index class_id = 0;
  RetrievalScores scores;
};

struct ClassScores {
  std::string name;
  Index size = 0;        ///< models in the class
  Index queries = 0;     ///< 0 when the class is too small to be a query
  RetrievalScores mean;  ///< mean over the class's queries (zeros when none)
};

struct RetrievalEvaluation {
  std::vector<double> recall;        ///< the recall levels of every precision curve
  std::vector<QueryScores> queries;  ///< in model order
  std::vector<ClassScores> classes;  ///< in .cla order, the left-out classes too
  RetrievalScores micro;             ///< mean over the queries
  RetrievalScores macro;             ///< mean over the classes that have queries
};

/// The PSB measures of the ranking of every query by `distances` (N x N, row =
/// query). Throws InvalidArgument when the matrix is not N x N for the N
/// models of `classes`, holds a NaN, or no class is large enough to be a query.
RetrievalEvaluation evaluate_retrieval(const DistanceMatrix& distances, const ModelClasses& classes,
                                       const RetrievalOptions& options = {});

}  // namespace reebkit
