#include "reebkit/matching/assignment.h"

#include "reebkit/core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace reebkit {
namespace {

/// The optimum by trying every injection of rows into columns.
double brute_force(const std::vector<double>& cost, int rows, int cols) {
  std::vector<int> columns(static_cast<std::size_t>(cols));
  std::iota(columns.begin(), columns.end(), 0);
  double best = std::numeric_limits<double>::infinity();
  do {  // permutations of all columns; the first `rows` are the assignment
    double total = 0;
    for (int i = 0; i < rows; ++i)
      total += cost[static_cast<std::size_t>(i * cols + columns[static_cast<std::size_t>(i)])];
    best = std::min(best, total);
  } while (std::next_permutation(columns.begin(), columns.end()));
  return best;
}

void expect_valid(const std::vector<double>& cost, int rows, int cols, const std::vector<std::int32_t>& assignment,
                  double total) {
  ASSERT_EQ(assignment.size(), static_cast<std::size_t>(rows));
  std::vector<char> used(static_cast<std::size_t>(cols), 0);
  double sum = 0;
  for (int i = 0; i < rows; ++i) {
    const std::int32_t j = assignment[static_cast<std::size_t>(i)];
    ASSERT_GE(j, 0);
    ASSERT_LT(j, cols);
    EXPECT_FALSE(used[static_cast<std::size_t>(j)]) << "column " << j << " used twice";
    used[static_cast<std::size_t>(j)] = 1;
    sum += cost[static_cast<std::size_t>(i * cols + j)];
  }
  EXPECT_DOUBLE_EQ(sum, total);
}

TEST(Assignment, HandCheckedThreeByThree) {
  // Rows pick columns 1, 0, 2: 1 + 2 + 2 = 5; the next best permutations,
  // (0, 1, 2) and (2, 1, 0), cost 6.
  const std::vector<double> cost = {4, 1, 3, 2, 0, 5, 3, 2, 2};
  std::vector<std::int32_t> assignment;
  const double total = solve_assignment(cost, 3, 3, assignment);
  EXPECT_DOUBLE_EQ(total, 5.0);
  EXPECT_EQ(assignment, (std::vector<std::int32_t>{1, 0, 2}));
  EXPECT_DOUBLE_EQ(brute_force(cost, 3, 3), 5.0);
}

TEST(Assignment, IdentityIsOptimalOnZeroDiagonal) {
  const std::vector<double> cost = {0, 7, 9, 9, 7, 0, 9, 9, 9, 9, 0, 1, 9, 9, 1, 0};
  std::vector<std::int32_t> assignment;
  EXPECT_DOUBLE_EQ(solve_assignment(cost, 4, 4, assignment), 0.0);
  EXPECT_EQ(assignment, (std::vector<std::int32_t>{0, 1, 2, 3}));
}

TEST(Assignment, RectangularPicksTheCheapColumns) {
  // Two rows, four columns: row 0 -> column 3 (1), row 1 -> column 2 (1);
  // the cheapest columns of both rows collide on column 3 otherwise.
  const std::vector<double> cost = {5, 6, 4, 1, 8, 9, 1, 0.5};
  std::vector<std::int32_t> assignment;
  EXPECT_DOUBLE_EQ(solve_assignment(cost, 2, 4, assignment), 2.0);
  EXPECT_EQ(assignment, (std::vector<std::int32_t>{3, 2}));
}

TEST(Assignment, NegativeCostsAndEmptyProblem) {
  const std::vector<double> cost = {-1, -5, -3, -2};
  std::vector<std::int32_t> assignment;
  EXPECT_DOUBLE_EQ(solve_assignment(cost, 2, 2, assignment), -8.0);  // -5 + -3
  EXPECT_DOUBLE_EQ(solve_assignment({}, 0, 0, assignment), 0.0);
  EXPECT_TRUE(assignment.empty());
}

TEST(Assignment, EqualsBruteForceUpToSeven) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 10.0);
  std::uniform_int_distribution<int> small(0, 3);
  AssignmentSolver solver;  // reused across sizes: buffers must not leak state
  for (int trial = 0; trial < 200; ++trial) {
    const int cols = 1 + trial % 7;
    const int rows = 1 + trial / 7 % cols;
    std::vector<double> cost(static_cast<std::size_t>(rows * cols));
    // Every third matrix has many ties (small integers).
    for (double& c : cost) c = trial % 3 ? uniform(random) : small(random);
    std::vector<std::int32_t> assignment;
    const double total = solver.solve(cost.data(), rows, cols, assignment);
    expect_valid(cost, rows, cols, assignment, total);
    EXPECT_NEAR(total, brute_force(cost, rows, cols), 1e-9) << rows << " x " << cols << ", trial " << trial;
  }
}

TEST(Assignment, SolveOrLeaveIsSolveOnThePaddedMatrix) {
  // solve_or_leave on rows x cols == solve on [cost | D] (D: 0 on the
  // diagonal, forbidden elsewhere), assignment for assignment, ties
  // included (small integers), with rows above and below cols; and the
  // optimum is brute force's on the padded matrix.
  std::mt19937 random(9);
  std::uniform_real_distribution<double> uniform(-3.0, 2.0);
  std::uniform_int_distribution<int> small(-2, 1);
  AssignmentSolver solver, padded_solver;
  for (int trial = 0; trial < 3000; ++trial) {
    const int rows = trial % 9, cols = trial / 9 % 12;
    std::vector<double> cost(static_cast<std::size_t>(rows * cols));
    for (double& c : cost) c = trial % 2 ? uniform(random) : small(random);
    const int padded_cols = cols + rows;
    std::vector<double> padded(static_cast<std::size_t>(rows * padded_cols), 1e12);
    for (int i = 0; i < rows; ++i) {
      // iterators, not &cost[k]: with 0 columns `cost` is empty (UBSan: reference binding to null pointer)
      std::copy_n(cost.begin() + i * cols, cols, padded.begin() + i * padded_cols);
      padded[static_cast<std::size_t>(i * padded_cols + cols + i)] = 0.0;
    }
    std::vector<std::int32_t> got, want;
    const double total = solver.solve_or_leave(cost.data(), rows, cols, got);
    const double padded_total = padded_solver.solve(padded.data(), rows, padded_cols, want);
    for (std::int32_t& j : want)
      if (j >= cols) j = -1;
    ASSERT_EQ(got, want) << rows << " x " << cols << ", trial " << trial;
    EXPECT_EQ(total, padded_total);
    if (padded_cols <= 8) {
      EXPECT_NEAR(total, brute_force(padded, rows, padded_cols), 1e-9) << rows << " x " << cols;
    }
  }
  std::vector<std::int32_t> assignment;
  EXPECT_THROW(solver.solve_or_leave(nullptr, -1, 2, assignment), InvalidArgument);
}

TEST(Assignment, RejectsMoreRowsThanColumns) {
  std::vector<std::int32_t> assignment;
  EXPECT_THROW(solve_assignment(std::vector<double>(6, 1.0), 3, 2, assignment), InvalidArgument);
  EXPECT_THROW(solve_assignment(std::vector<double>(5, 1.0), 2, 3, assignment), InvalidArgument);
}

}  // namespace
}  // namespace reebkit
