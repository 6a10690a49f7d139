#include "reebkit/core/parallel.h"

#include <omp.h>

#include <exception>

namespace reebkit {

void run_side_by_side(const std::function<void()>& first, const std::function<void()>& second) {
  // An exception may not leave an OpenMP section: each part keeps its own.
  std::exception_ptr failed[2];
  // num_threads alone would override OMP_NUM_THREADS=1: the if clause keeps
  // one thread then.
#pragma omp parallel sections num_threads(2) if (omp_get_max_threads() > 1)
  {
#pragma omp section
    try {
      first();
    } catch (...) {
      failed[0] = std::current_exception();
    }
#pragma omp section
    try {
      second();
    } catch (...) {
      failed[1] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace reebkit
