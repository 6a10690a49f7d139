// Two independent parts of one computation run side by side: the pipeline
// uses it inside one mesh (analyze_mesh: the graph beside the spectra's
// surface; compute_attributes: the spectra beside the other attributes).
#pragma once

#include <functional>

namespace reebkit {

/// Runs `first` and `second`, each on its own OpenMP thread where a second
/// one is free, one after the other where none is (one thread, or inside an
/// active parallel region such as reeb index's workers). Both always run to
/// their end; then the exception of `first`, else that of `second`, is
/// thrown again.
void run_side_by_side(const std::function<void()>& first, const std::function<void()>& second);

}  // namespace reebkit
