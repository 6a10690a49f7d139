#include "reebkit/core/parallel.h"

#include "support/test_support.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <stdexcept>

namespace reebkit::test {
namespace {

// How many threads the team running the two parts had, as each part saw it.
struct Teams {
  int first = 0, second = 0;
};

Teams teams_at(int max_threads) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(max_threads);
  Teams seen;
  run_side_by_side([&] { seen.first = omp_get_num_threads(); }, [&] { seen.second = omp_get_num_threads(); });
  omp_set_num_threads(before);
  return seen;
}

TEST(RunSideBySide, UsesTwoThreadsOnlyWhereTheyAreAllowed) {
  // OMP_NUM_THREADS=1 (or omp_set_num_threads(1)) keeps a single thread: a
  // one-thread benchmark measures one thread.
  const Teams one = teams_at(1);
  EXPECT_EQ(one.first, 1);
  EXPECT_EQ(one.second, 1);
  const Teams two = teams_at(2);
  EXPECT_EQ(two.first, 2);
  EXPECT_EQ(two.second, 2);
}

TEST(RunSideBySide, RunsBothPartsAndRethrowsTheFirstFailure) {
  const int before = omp_get_max_threads();
  for (const int threads : {1, 2}) {
    omp_set_num_threads(threads);
    bool second_ran = false;
    EXPECT_EQ(thrown_message<std::runtime_error>([&] {
                run_side_by_side([] { throw std::runtime_error("first"); },
                                 [&] {
                                   second_ran = true;
                                   throw std::runtime_error("second");
                                 });
              }),
              "first");
    EXPECT_TRUE(second_ran) << threads << " thread(s)";
  }
  omp_set_num_threads(before);
}

}  // namespace
}  // namespace reebkit::test
