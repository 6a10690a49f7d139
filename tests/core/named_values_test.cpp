#include "reebkit/core/named_values.h"

#include "support/test_support.h"

#include <gtest/gtest.h>

namespace reebkit::test {
namespace {

enum class Colour { Red, Green, Blue, Unnamed };

constexpr NamedValues<Colour, 3> kColours{"colour",
                                          {{{Colour::Red, "red"}, {Colour::Green, "green"}, {Colour::Blue, "blue"}}}};

TEST(NamedValues, NamesAndParsesEveryValue) {
  for (const Colour c : {Colour::Red, Colour::Green, Colour::Blue}) EXPECT_EQ(kColours.parse(kColours.name(c)), c);
  EXPECT_STREQ(kColours.name(Colour::Green), "green");
}

TEST(NamedValues, AnUnknownNameListsTheAcceptedOnes) {
  EXPECT_EQ(thrown_message<InvalidArgument>([] { kColours.parse("Red"); }),
            "unknown colour 'Red' (expected red, green or blue)");
  EXPECT_EQ(thrown_message<InvalidArgument>([] { kColours.name(Colour::Unnamed); }), "unknown colour 3");
}

}  // namespace
}  // namespace reebkit::test
