#include "reebkit/core/parallel.h"

#include <exception>

namespace reebkit {

void run_side_by_side(const std::function<void()>& first, const std::function<void()>& second) {
  // An exception may not leave an OpenMP section: each part keeps its own.
  std::exception_ptr failed[2];
#pragma omp parallel sections num_threads(2)
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
