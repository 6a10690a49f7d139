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

  /// The same when a row may also be left unassigned at cost 0 (graph
  /// matching's deletions): the rows x (cols + rows) problem [cost | D], D
  /// with 0 on its diagonal (row i's own column cols + i) and forbidden
  /// elsewhere, without forming D. `assignment[i]` is -1 for a row left
  /// unassigned. Exactly the assignment solve() gives on the padded matrix
  /// with a forbidden cost far above the costs (the same steps, tested),
  /// in O(rows^2 cols) instead of O(rows^2 (cols + rows)): the own columns of
  /// other rows are never scanned. Any rows >= 0 (rows may exceed cols).
  /// \pre cost has rows * cols finite entries (row-major); throws
  ///      InvalidArgument on rows < 0 or cols < 0.
  double solve_or_leave(const double* cost, int rows, int cols, std::vector<std::int32_t>& assignment);

 private:
  /// Both, kOwnColumns selecting solve_or_leave's problem (a template: one
  /// loop each, without a test per step).
  template <bool kOwnColumns>
  double solve_rows(const double* cost, int rows, int cols, std::vector<std::int32_t>& assignment);

  std::vector<double> u_, v_, min_slack_;
  std::vector<std::int32_t> row_of_col_, way_, own_, tree_;
  std::vector<char> used_;
};

/// One-shot form of AssignmentSolver::solve on a row-major matrix.
double solve_assignment(const std::vector<double>& cost, int rows, int cols, std::vector<std::int32_t>& assignment);

}  // namespace reebkit
