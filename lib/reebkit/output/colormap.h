// Colors for figures and colored meshes: a perceptually uniform map for
// scalar fields and a categorical palette for segments.
#pragma once

#include "reebkit/core/types.h"

#include <vector>

namespace reebkit {

/// Viridis color (RGB in [0,1]) of t in [0,1] (clamped).
Vec3 viridis(double t);

/// A distinct color for category k (segments, graph nodes); repeats after 20.
Vec3 category_color(int k);

/// #values x 3 colors of `values` mapped linearly from [lo, hi] to viridis.
Points colorize(const std::vector<double>& values, double lo, double hi);

}  // namespace reebkit
