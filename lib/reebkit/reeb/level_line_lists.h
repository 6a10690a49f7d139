// The level lines of an incremental Reeb graph builder (Definition 6 in
// reeb_graph.cpp, contours in contour_lines.cpp): each line is a
// doubly-linked list of its elements (candidate vertices, or front
// triangles) threaded through one flat array of per-element records, which
// also hold the element's line id; line ids are recycled. A line also keeps
// its node of the dual graph and the sum and count of the points whose mean
// is its skeleton position (section 5.2), relative to the center of the
// mesh's bounding box to keep the sums small.
#pragma once

#include "reebkit/core/mesh.h"

#include <vector>

namespace reebkit {

class LevelLineLists {
 public:
  /// Lines over `elements` elements, points from `mesh`'s vertices.
  LevelLineLists(const Mesh& mesh, Index elements);

  /// A new empty line of `node`.
  Index new_line(Index node);
  /// Recycles an empty line.
  void free_line(Index line) { free_lines_.push_back(line); }

  /// Element x joins `line` (no point).
  void link(Index line, Index x);
  /// Element x leaves its line (no point).
  void unlink(Index x);
  /// Merges lines a and b by relabelling the smaller; returns the survivor
  /// (the other is recycled).
  Index merge(Index a, Index b);

  /// Adds vertex v's position to the points of `line` (sign +1) or removes it (-1).
  void add_point(Index line, Index v, int sign) {
    sum_[at(line)] += sign * (mesh_.vertices.row(v).transpose() - origin_);
    count_[at(line)] += sign;
  }
  /// The mean of the line's points.
  Vec3 center(Index line) const { return origin_ + sum_[at(line)] / static_cast<double>(count_[at(line)]); }
  Index points(Index line) const { return count_[at(line)]; }

  Index line_of(Index x) const { return element_[at(x)].line; }
  Index size(Index line) const { return size_[at(line)]; }
  Index node(Index line) const { return node_[at(line)]; }
  void set_node(Index line, Index node) { node_[at(line)] = node; }
  /// The per-element mark of LineSplitter (line_split.h).
  Index& search(Index x) { return element_[at(x)].search; }

 private:
  static std::size_t at(Index i) { return static_cast<std::size_t>(i); }

  const Mesh& mesh_;
  Vec3 origin_;
  struct Element {
    Index line = kInvalidIndex;
    Index next = kInvalidIndex;  // the line's element list
    Index prev = kInvalidIndex;
    Index search = -1;
  };
  std::vector<Element> element_;
  // Per line id.
  std::vector<Index> head_;
  std::vector<Index> size_;
  std::vector<Vec3> sum_;
  std::vector<Index> count_;
  std::vector<Index> node_;
  std::vector<Index> free_lines_;
};

}  // namespace reebkit
