#include "reebkit/io/psb_classes.h"

#include "io/io_test_util.h"
#include "reebkit/core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace reebkit::test {
namespace {

/// The message of the Error reading `text` as a .cla file throws ("" when none).
std::string cla_error(const TempDir& dir, const std::string& text) {
  std::ofstream(dir / "c.cla") << text;
  try {
    read_psb_classes(dir / "c.cla");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(PsbClasses, ReadsBlocksInOrder) {
  const TempDir dir;
  std::ofstream(dir / "c.cla") << "PSB 1\n3 5\n\nHuman 0 2\n1\n2\n\nCup 0 3\n21\n22\n23\n\nEmpty Cup 0\n";
  const std::vector<PsbClass> classes = read_psb_classes(dir / "c.cla");
  ASSERT_EQ(classes.size(), 3u);
  EXPECT_EQ(classes[0].name, "Human");
  EXPECT_EQ(classes[0].models, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(classes[1].models, (std::vector<std::string>{"21", "22", "23"}));
  EXPECT_EQ(classes[2].parent, "Cup");
  EXPECT_TRUE(classes[2].models.empty());
  const ClassMap map = class_map(classes);
  EXPECT_EQ(map.size(), 5u);
  EXPECT_EQ(class_of(map, "22.off"), "Cup");
  EXPECT_EQ(class_of(map, "sub/1.OFF"), "Human");
  EXPECT_EQ(class_of(map, "2"), "Human");
  EXPECT_EQ(class_of(map, "3.off"), "");
}

TEST(PsbClasses, ErrorsNameFileAndLine) {
  const TempDir dir;
  const std::string file = (dir / "c.cla").string();
  EXPECT_EQ(cla_error(dir, "PSB 2\n1 1\n"), file + ":1: not a PSB .cla file (expected the header 'PSB 1')");
  EXPECT_EQ(cla_error(dir, "PSB 1\n1 x\n"), file + ":2: number of models 'x' is not a count");
  EXPECT_EQ(cla_error(dir, "PSB 1\n1 2\nA 0 2\n1\n"),
            file + ":4: file ends where model 2 of 2 of class A was expected");
  EXPECT_EQ(cla_error(dir, "PSB 1\n2 2\nA 0 1\n1\nB 0 1\n1\n"), file + ":6: model 1 is already in class A");
  EXPECT_EQ(cla_error(dir, "PSB 1\n1 3\nA 0 2\n1\n2\n"), file + ":5: the classes list 2 models, the header says 3");
  EXPECT_EQ(cla_error(dir, "PSB 1\n1 1\nA 0 1\n1\nB 0 1\n"), file + ":5: more lines than the 1 classes of the header");
  EXPECT_EQ(cla_error(dir, "PSB 1\n1 1\nA 0\n"), file + ":3: expected '<class name> <parent> <number of models>'");
}

TEST(PsbClasses, Shrec07HasTwentyClassesOfTwenty) {
  REEBKIT_REQUIRE_DATASET(shrec, "shrec07_watertight");
  const std::vector<PsbClass> classes = read_psb_classes(shrec / "shrec07_watertight.cla");
  ASSERT_EQ(classes.size(), 20u);
  for (const PsbClass& c : classes) EXPECT_EQ(c.models.size(), 20u) << c.name;
  const ClassMap map = class_map(classes);
  // The README of the dataset: Human 1-20, ..., Fourleg 381-400.
  EXPECT_EQ(class_of(map, "1.off"), "Human");
  EXPECT_EQ(class_of(map, "140.off"), "Octopus");
  EXPECT_EQ(class_of(map, "400.off"), "Fourleg");
}

}  // namespace
}  // namespace reebkit::test
