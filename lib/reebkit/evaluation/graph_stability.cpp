#include "reebkit/evaluation/graph_stability.h"

#include "reebkit/core/error.h"

#include <map>

namespace reebkit {

GraphShape graph_shape(const GraphRecord& record) {
  return {static_cast<std::int64_t>(record.feature_points.size()), record.num_nodes(), independent_cycles(record)};
}

GraphStability graph_stability(const std::vector<GraphShape>& shapes, const std::vector<std::string>& labels) {
  if (shapes.size() != labels.size())
    throw InvalidArgument("graph_stability: " + std::to_string(shapes.size()) + " graph shapes for " +
                          std::to_string(labels.size()) + " class labels");
  std::map<std::string, std::map<GraphShape, std::int64_t>> count;  // ordered: labels, then shapes
  for (std::size_t i = 0; i < shapes.size(); ++i)
    if (!labels[i].empty()) ++count[labels[i]][shapes[i]];
  GraphStability out;
  for (const auto& [label, by_shape] : count) {
    ClassStability c{label, 0, {}, 0};
    for (const auto& [shape, members] : by_shape) {
      c.members += members;
      if (members > c.agreeing) c.most_common = shape, c.agreeing = members;  // strict: the smallest of equals
    }
    out.members += c.members;
    out.agreeing += c.agreeing;
    out.classes.push_back(std::move(c));
  }
  return out;
}

GraphStability graph_stability(const CollectionReader& collection) {
  std::vector<GraphShape> shapes;
  std::vector<std::string> labels;
  collection.for_each_entry(
      [&](std::int64_t, const GraphRecord& e) {
        if (e.ok) shapes.push_back(graph_shape(e)), labels.push_back(e.class_label);
      },
      EntryParts::Outline);
  return graph_stability(shapes, labels);
}

}  // namespace reebkit
