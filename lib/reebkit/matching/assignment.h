// Linear assignment: the cheapest way to give each row of a cost matrix its
// own column. Shortest augmenting paths with dual potentials (Jonker and
// Volgenant 1987; the Hungarian method of Kuhn 1955 and Munkres 1957 in its
// O(rows^2 cols) form), for the node matching of graph_matching.h.
#pragma once

#include <cstdint>
#include <vector>

namespace reebkit {

/// Reusable buffers of the solver, so that solving many small problems
/// allocates nothing once they have grown to the largest size.
class AssignmentSolver {
 public:
  /// Solves min sum_i cost[i * cols + assignment[i]] over assignments of the
  /// `rows` rows to distinct columns. Costs must be finite (use a large
  /// finite value to forbid a pair). Returns the total cost; `assignment`
  /// (resized to rows) receives each row's column.
  /// \pre 0 <= rows <= cols, cost has rows * cols entries (row-major);
  ///      throws InvalidArgument otherwise.
  double solve(const double* cost, int rows, int cols, std::vector<std::int32_t>& assignment);

 private:
  std::vector<double> u_, v_, min_slack_;
  std::vector<std::int32_t> row_of_col_, way_;
  std::vector<char> used_;
};

/// One-shot form of AssignmentSolver::solve on a row-major matrix.
double solve_assignment(const std::vector<double>& cost, int rows, int cols, std::vector<std::int32_t>& assignment);

}  // namespace reebkit
