// Points and polylines as Wavefront OBJ text: `v` records numbered from 1
// over the whole file, `l` records through them, grouped by `o` objects.
// MeshLab, Blender and tools/figures/render_mesh.py --lines read it. Used
// for the Reeb graph and its topological skeleton (`reeb graph --obj`,
// Tierny et al. 2006, section 5.2, figures 9 and 10a) and the two matched
// graphs of `reeb match --obj`.
#pragma once

#include "reebkit/core/mesh.h"

#include <ostream>
#include <string_view>
#include <vector>

namespace reebkit {

class ObjLinesWriter {
 public:
  /// Writes to `out`, coordinates with 17 significant digits (read back exactly).
  explicit ObjLinesWriter(std::ostream& out);

  /// A `#` comment line; `text` must not hold a line break.
  ObjLinesWriter& comment(std::string_view text);
  /// Starts the object `name`: the lines after it belong to it.
  ObjLinesWriter& object(std::string_view name);
  /// A vertex; returns its OBJ number (1 for the first of the file).
  Index point(const Vec3& p);
  /// A polyline through the vertices numbered `points` (OBJ numbers). Throws
  /// InvalidArgument for fewer than two points or a number not yet written.
  ObjLinesWriter& line(const std::vector<Index>& points);
  /// Vertices written so far: the next one gets number points() + 1.
  Index points() const { return points_; }

 private:
  std::ostream& out_;
  Index points_ = 0;
};

}  // namespace reebkit
