#include "reebkit/matching/assignment.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <limits>
#include <string>

namespace reebkit {

double AssignmentSolver::solve(const double* cost, int rows, int cols, std::vector<std::int32_t>& assignment) {
  if (rows < 0 || rows > cols)
    throw InvalidArgument("solve_assignment: needs 0 <= rows <= columns, got " + std::to_string(rows) + " x " +
                          std::to_string(cols));
  return solve_rows<false>(cost, rows, cols, assignment);
}

double AssignmentSolver::solve_or_leave(const double* cost, int rows, int cols, std::vector<std::int32_t>& assignment) {
  if (rows < 0 || cols < 0)
    throw InvalidArgument("solve_or_leave: needs rows, columns >= 0, got " + std::to_string(rows) + " x " +
                          std::to_string(cols));
  return solve_rows<true>(cost, rows, cols, assignment);
}

// Rows are added one at a time; each addition grows a shortest-path tree of
// alternating paths over the reduced costs cost - u - v (Dijkstra without a
// heap: O(cols) per step) until it reaches a free column, then augments and
// updates the potentials so that reduced costs stay >= 0. Column 0 of the
// internal arrays is a virtual column holding the row being added.
//
// With own columns (solve_or_leave), solve() on [cost | D] step for step:
// internal columns 1..cols are the given ones, cols + k the own column of
// row k (1-based). An own column is reachable only from its row, so (1) its
// slack is finite only once its row has been scanned in the current
// addition, and D's forbidden entries never win a minimum: only the own
// columns of the rows scanned so far (own_, in increasing order as solve()
// meets them) take part; (2) an own column taken by its row is never
// reached again (the row can only be reached through that column), so own
// columns are never in the tree and their v stays 0.
template <bool kOwnColumns>
double AssignmentSolver::solve_rows(const double* cost, int rows, int cols, std::vector<std::int32_t>& assignment) {
  const auto n = static_cast<std::size_t>(cols) + 1;  // the given columns and the virtual one
  const std::size_t all = n + (kOwnColumns ? static_cast<std::size_t>(rows) : 0);
  u_.assign(static_cast<std::size_t>(rows) + 1, 0.0);
  v_.assign(n, 0.0);
  row_of_col_.assign(all, 0);  // 1-based row of each column, 0 = free
  way_.assign(all, 0);
  min_slack_.resize(all);
  used_.resize(n);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int i = 1; i <= rows; ++i) {
    row_of_col_[0] = i;
    std::size_t j0 = 0;
    std::fill(min_slack_.begin(), min_slack_.begin() + static_cast<std::ptrdiff_t>(n), kInf);
    std::fill(used_.begin(), used_.end(), char{0});
    if constexpr (kOwnColumns) own_.clear();
    tree_.clear();
    do {
      used_[j0] = 1;
      tree_.push_back(static_cast<std::int32_t>(j0));
      const int i0 = row_of_col_[j0];
      const double* row = cost + static_cast<std::ptrdiff_t>(i0 - 1) * cols;
      const double ui0 = u_[static_cast<std::size_t>(i0)];
      double delta = kInf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j < n; ++j) {
        if (used_[j]) continue;
        const double reduced = row[j - 1] - ui0 - v_[j];
        if (reduced < min_slack_[j]) {
          min_slack_[j] = reduced;
          way_[j] = static_cast<std::int32_t>(j0);
        }
        if (min_slack_[j] < delta) {
          delta = min_slack_[j];
          j1 = j;
        }
      }
      if constexpr (kOwnColumns) {
        const auto mine = static_cast<std::int32_t>(n) + i0 - 1;  // i0's own column
        own_.insert(std::upper_bound(own_.begin(), own_.end(), mine), mine);
        for (const std::int32_t j : own_) {
          const auto uj = static_cast<std::size_t>(j);
          if (j == mine) {
            min_slack_[uj] = 0.0 - ui0;  // its cost 0, its v 0
            way_[uj] = static_cast<std::int32_t>(j0);
          }
          if (min_slack_[uj] < delta) {
            delta = min_slack_[uj];
            j1 = uj;
          }
        }
      }
      for (const std::int32_t j : tree_) {
        u_[static_cast<std::size_t>(row_of_col_[static_cast<std::size_t>(j)])] += delta;
        v_[static_cast<std::size_t>(j)] -= delta;
      }
      // When j1 is free the addition ends here and the slacks are not read
      // again (reset by the next): only the potentials need the update.
      if (row_of_col_[j1] != 0) {
        for (std::size_t j = 0; j < n; ++j)
          if (!used_[j]) min_slack_[j] -= delta;
        if constexpr (kOwnColumns)
          for (const std::int32_t j : own_) min_slack_[static_cast<std::size_t>(j)] -= delta;
      }
      j0 = j1;
    } while (row_of_col_[j0] != 0);
    do {  // augment along the path back to the virtual column
      const auto j1 = static_cast<std::size_t>(way_[j0]);
      row_of_col_[j0] = row_of_col_[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  assignment.assign(static_cast<std::size_t>(rows), -1);  // -1: a row on its own column
  double total = 0.0;
  for (std::size_t j = 1; j < n; ++j) {
    if (row_of_col_[j] == 0) continue;
    const int i = row_of_col_[j] - 1;
    assignment[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(j - 1);
    total += cost[static_cast<std::ptrdiff_t>(i) * cols + static_cast<std::ptrdiff_t>(j - 1)];
  }
  return total;
}

double solve_assignment(const std::vector<double>& cost, int rows, int cols, std::vector<std::int32_t>& assignment) {
  if (cost.size() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols))
    throw InvalidArgument("solve_assignment: " + std::to_string(cost.size()) + " costs for a " + std::to_string(rows) +
                          " x " + std::to_string(cols) + " matrix");
  AssignmentSolver solver;
  return solver.solve(cost.data(), rows, cols, assignment);
}

}  // namespace reebkit
