#include "reebkit/reeb/level_line_lists.h"

#include <utility>

namespace reebkit {

LevelLineLists::LevelLineLists(const Mesh& mesh, Index elements)
    : mesh_(mesh),
      origin_(0.5 * (mesh.vertices.colwise().minCoeff() + mesh.vertices.colwise().maxCoeff()).transpose()),
      element_(static_cast<std::size_t>(elements)) {}

Index LevelLineLists::new_line(Index node) {
  Index line;
  if (free_lines_.empty()) {
    line = static_cast<Index>(head_.size());
    head_.push_back(kInvalidIndex);
    size_.push_back(0);
    sum_.push_back(Vec3::Zero());
    count_.push_back(0);
    node_.push_back(node);
  } else {
    line = free_lines_.back();
    free_lines_.pop_back();
    sum_[at(line)].setZero();  // drop the rounding left by its previous points
    count_[at(line)] = 0;
    node_[at(line)] = node;
  }
  return line;
}

void LevelLineLists::link(Index line, Index x) {
  Element& e = element_[at(x)];
  e.line = line;
  e.prev = kInvalidIndex;
  e.next = head_[at(line)];
  if (head_[at(line)] != kInvalidIndex) element_[at(head_[at(line)])].prev = x;
  head_[at(line)] = x;
  ++size_[at(line)];
}

void LevelLineLists::unlink(Index x) {
  Element& e = element_[at(x)];
  (e.prev == kInvalidIndex ? head_[at(e.line)] : element_[at(e.prev)].next) = e.next;
  if (e.next != kInvalidIndex) element_[at(e.next)].prev = e.prev;
  --size_[at(e.line)];
  e.line = kInvalidIndex;
}

Index LevelLineLists::merge(Index a, Index b) {
  if (size_[at(a)] < size_[at(b)]) std::swap(a, b);
  if (size_[at(b)] > 0) {
    Index tail = kInvalidIndex;
    for (Index x = head_[at(b)]; x != kInvalidIndex; x = element_[at(x)].next) {
      element_[at(x)].line = a;
      tail = x;
    }
    element_[at(tail)].next = head_[at(a)];
    if (head_[at(a)] != kInvalidIndex) element_[at(head_[at(a)])].prev = tail;
    head_[at(a)] = head_[at(b)];
  }
  size_[at(a)] += size_[at(b)];
  sum_[at(a)] += sum_[at(b)];
  count_[at(a)] += count_[at(b)];
  head_[at(b)] = kInvalidIndex;
  size_[at(b)] = 0;
  free_lines_.push_back(b);
  return a;
}

}  // namespace reebkit
