#include "reebkit/evaluation/graph_stability.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "store/collection_entries.h"

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

// A collection file gives the figures of its graphs' shapes and classes
// (failed entries and entries without a class left out), across more than
// one batch of the reader.
TEST(GraphStability, OfACollectionFileEqualsThatOfItsGraphs) {
  test::TempDir dir;
  std::vector<GraphShape> shapes;
  std::vector<std::string> labels;
  {
    CollectionWriter writer(dir / "c.h5", test::test_provenance(), false);
    for (std::int64_t i = 0; i < 1100; ++i) {
      const GraphRecord e = test::make_entry(i);
      writer.append(e);
      if (e.ok) shapes.push_back(graph_shape(e)), labels.push_back(e.class_label);
    }
    writer.close();
  }
  const GraphStability expected = graph_stability(shapes, labels);
  ASSERT_EQ(expected.classes.size(), 5u);  // make_entry's "class 0" .. "class 4"
  ASSERT_GT(expected.agreeing, 0);
  const GraphStability read = graph_stability(CollectionReader(dir / "c.h5"));
  ASSERT_EQ(read.classes.size(), expected.classes.size());
  for (std::size_t k = 0; k < read.classes.size(); ++k) {
    EXPECT_EQ(read.classes[k].label, expected.classes[k].label);
    EXPECT_EQ(read.classes[k].members, expected.classes[k].members);
    EXPECT_EQ(read.classes[k].most_common, expected.classes[k].most_common);
    EXPECT_EQ(read.classes[k].agreeing, expected.classes[k].agreeing);
  }
  EXPECT_EQ(read.members, expected.members);
  EXPECT_EQ(read.agreeing, expected.agreeing);
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
