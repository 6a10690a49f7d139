#include "reebkit/evaluation/graph_stability.h"

#include "reebkit/core/error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace reebkit {
namespace {

// Two classes counted by hand: "cat" has 3 of its 4 graphs alike, "dog" one
// shape twice and another once; the graph without a class counts nowhere.
TEST(GraphStability, CountsEachClassesMostCommonShape) {
  const GraphShape six{6, 11, 0}, five{5, 9, 0}, seven{7, 13, 0}, seven_loop{7, 14, 1};
  const GraphStability s = graph_stability({six, seven, six, five, six, seven_loop, seven, seven_loop},
                                           {"cat", "dog", "cat", "cat", "cat", "dog", "", "dog"});
  ASSERT_EQ(s.classes.size(), 2u);
  EXPECT_EQ(s.classes[0].label, "cat");
  EXPECT_EQ(s.classes[0].members, 4);
  EXPECT_EQ(s.classes[0].agreeing, 3);
  EXPECT_EQ(s.classes[0].most_common, six);
  EXPECT_EQ(s.classes[1].label, "dog");
  EXPECT_EQ(s.classes[1].members, 3);
  EXPECT_EQ(s.classes[1].agreeing, 2);
  EXPECT_EQ(s.classes[1].most_common, seven_loop);
  EXPECT_EQ(s.members, 7);
  EXPECT_EQ(s.agreeing, 5);
  EXPECT_DOUBLE_EQ(s.share(), 5.0 / 7.0);
}

// Ties go to the smallest shape whatever the order of the graphs, so that
// the figure does not depend on how the collection lists its meshes.
TEST(GraphStability, TiesGoToTheSmallestShapeInAnyOrder) {
  const GraphShape a{5, 9, 0}, b{5, 10, 1};
  for (const auto& shapes : {std::vector<GraphShape>{a, b}, std::vector<GraphShape>{b, a}}) {
    const GraphStability s = graph_stability(shapes, {"c", "c"});
    ASSERT_EQ(s.classes.size(), 1u);
    EXPECT_EQ(s.classes[0].most_common, a);
    EXPECT_EQ(s.classes[0].agreeing, 1);
  }
}

TEST(GraphStability, NoClassesNoMembersAndMismatchedSizesRefused) {
  const GraphStability none = graph_stability({{3, 5, 0}}, {""});
  EXPECT_TRUE(none.classes.empty());
  EXPECT_EQ(none.members, 0);
  EXPECT_EQ(none.share(), 0.0);
  EXPECT_THROW(graph_stability({{3, 5, 0}}, {}), InvalidArgument);
}

}  // namespace
}  // namespace reebkit
