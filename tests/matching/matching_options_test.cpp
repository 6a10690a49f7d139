// The table of the matching options (matching/matching_options.h): one row
// per field of MatchingOptions, each reading and setting its own field, and
// a value out of its range refused by the library's entry points.
#include "reebkit/matching/matching_options.h"

#include "reebkit/attributes/graph_attributes.h"
#include "reebkit/core/error.h"
#include "reebkit/mesh/shapes.h"
#include "reebkit/pipeline/mesh_record.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <type_traits>
#include <utility>

namespace reebkit::test {
namespace {

/// Converts to anything: T{Any{}, Any{}, ...} compiles for up to as many
/// Any as the aggregate T has fields.
struct Any {
  template <typename T>
  operator T() const {  // NOLINT(google-explicit-constructor): the point
    return T{};
  }
};

template <typename T, typename Indices, typename = void>
struct BraceConstructible : std::false_type {};
template <typename T, std::size_t... I>
struct BraceConstructible<T, std::index_sequence<I...>, std::void_t<decltype(T{(void(I), Any{})...})>>
    : std::true_type {};

/// The number of fields of the aggregate T.
template <typename T, std::size_t N = 0>
constexpr std::size_t field_count() {
  if constexpr (BraceConstructible<T, std::make_index_sequence<N + 1>>::value)
    return field_count<T, N + 1>();
  else
    return N;
}

TEST(MatchingOptions, TheTableHasARowPerFieldEachSettingItsOwnField) {
  const auto& fields = matching_option_fields();
  std::set<std::string> names;
  for (const MatchingOptionField& field : fields) {
    EXPECT_TRUE(names.insert(field.name).second) << field.name;
    EXPECT_FALSE(field.help.empty()) << field.name;
    MatchingOptions options;
    const OptionValue value = field.get(options);
    // The default is in the option's range, and a value just inside it sets only this row's field.
    EXPECT_NO_THROW(field.check(options)) << field.name;
    const OptionValue other = std::holds_alternative<double>(value) ? OptionValue(std::get<double>(value) + 0.5)
                                                                    : OptionValue(std::get<std::int64_t>(value) + 1);
    field.set(options, other);
    EXPECT_EQ(field.get(options), other) << field.name;
    for (const MatchingOptionField& row : fields) {
      if (row.name != field.name) {
        EXPECT_EQ(row.get(options), row.get(MatchingOptions{})) << field.name << " sets " << row.name;
      }
    }
  }
  EXPECT_EQ(fields.size(), field_count<MatchingOptions>()) << "a field of MatchingOptions has no row";
}

TEST(MatchingOptions, AValueOutOfItsRangeIsRefusedNamingTheOption) {
  const MeshAnalysis analysis = analyze_mesh(make_star(StarOptions{3, 2}));
  const GraphRecord a = make_graph_record(analysis, compute_attributes(analysis));
  for (const MatchingOptionField& field : matching_option_fields()) {
    const bool number = std::holds_alternative<double>(field.get(MatchingOptions{}));
    for (const OptionValue& bad :
         {number ? OptionValue(-1.0) : OptionValue(std::int64_t{-1}),
          number ? OptionValue(std::numeric_limits<double>::quiet_NaN()) : OptionValue(std::int64_t{-1})}) {
      MatchingOptions options;
      field.set(options, bad);
      const std::string message = thrown_message<InvalidArgument>([&] { match_graphs(a, a, options); });
      EXPECT_NE(message.find("matching option " + field.name + ": "), std::string::npos) << message;
      EXPECT_NE(message.find("is out of its range"), std::string::npos) << message;
    }
  }
  // A distance is never negative under options in range.
  MatchingOptions zero_cost_terms;
  for (const MatchingOptionField& field : matching_option_fields())
    if (std::holds_alternative<double>(field.get(zero_cost_terms)) && field.range.holds(0.0))
      field.set(zero_cost_terms, 0.0);
  EXPECT_GE(match_graphs(a, a, zero_cost_terms).distance, 0.0);
}

TEST(MatchingOptions, NameEqualsValueSetsAnOptionByTheTable) {
  MatchingOptions options;
  set_option_text(matching_option_fields(), options, "unmatched_cost=2.5");
  set_option_text(matching_option_fields(), options, "refine_rounds=3");
  EXPECT_EQ(options.unmatched_cost, 2.5);
  EXPECT_EQ(options.refine_rounds, 3);
  for (const char* bad : {"unmatched_cost", "no_such=1", "refine_rounds=1.5", "edge_weight=-1", "edge_weight=x"}) {
    const std::string message =
        thrown_message<InvalidArgument>([&] { set_option_text(matching_option_fields(), options, bad); });
    EXPECT_EQ(message.rfind(std::string(bad) + ": ", 0), 0u) << message;
  }
  EXPECT_EQ(options.unmatched_cost, 2.5);
}

}  // namespace
}  // namespace reebkit::test
