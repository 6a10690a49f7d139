// End to end: every `reeb` command that analyses a mesh offers every analysis
// option of the table (pipeline/analysis_options.h), and every command that
// matches graphs every matching option, each with the library's default.
#include "reebkit/matching/graph_matching.h"
#include "reebkit/pipeline/analysis_options.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace reebkit::test {
namespace {

/// `reeb <command> --help`.
std::string help(const std::string& command) {
  const auto [status, out] = run_command(std::string(REEB_BINARY) + " " + command + " --help");
  EXPECT_EQ(status, 0) << command << "\n" << out;
  return out;
}

/// "--name arg (=default)" as --help shows a flag.
std::string flag(std::string name, const OptionValue& default_value) {
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name + " arg (=" + option_text(default_value) + ")";
}

TEST(ReebOptionsCli, EveryAnalysingCommandOffersEveryAnalysisOptionWithTheLibraryDefault) {
  for (const char* command : {"features", "graph", "index", "match"}) {
    const std::string text = help(command);
    for (const AnalysisOptionField& field : analysis_option_fields())
      EXPECT_NE(text.find(flag(field.name, field.get(AnalysisOptions{}))), std::string::npos)
          << "reeb " << command << " --help lacks " << flag(field.name, field.get(AnalysisOptions{})) << "\n"
          << text;
  }
  // A query file is analysed with the collection's options: none to give.
  const std::string query = help("query");
  for (const AnalysisOptionField& field : analysis_option_fields())
    EXPECT_EQ(query.find(flag(field.name, field.get(AnalysisOptions{}))), std::string::npos) << field.name;
}

TEST(ReebOptionsCli, EveryMatchingCommandOffersEveryMatchingOptionWithTheLibraryDefault) {
  const MatchingOptions defaults;
  const std::vector<std::pair<std::string, OptionValue>> options = {
      {"attribute_weight", defaults.attribute_weight},
      {"structure_weight", defaults.structure_weight},
      {"edge_weight", defaults.edge_weight},
      {"profile_weight", defaults.profile_weight},
      {"shape_weight", defaults.shape_weight},
      {"geodesic_shape_weight", defaults.geodesic_shape_weight},
      {"global_shape_weight", defaults.global_shape_weight},
      {"global_geodesic_weight", defaults.global_geodesic_weight},
      {"unmatched_cost", defaults.unmatched_cost},
      {"min_node_weight", defaults.min_node_weight},
      {"refine_rounds", std::int64_t{defaults.refine_rounds}},
  };
  for (const char* command : {"match", "query", "distances"}) {
    const std::string text = help(command);
    for (const auto& [name, value] : options)
      EXPECT_NE(text.find(flag(name, value)), std::string::npos)
          << "reeb " << command << " --help lacks " << flag(name, value) << "\n"
          << text;
  }
}

TEST(ReebOptionsCli, AnAnalysisOptionOfTheWrongKindIsRejectedNamingIt) {
  const auto [status, out] = run_command(std::string(REEB_BINARY) + " features " +
                                         shell_quoted(embedded_dataset_dir() / "cow.off") + " --epsilon wide 2>&1");
  EXPECT_EQ(status, 2);
  EXPECT_NE(out.find("epsilon"), std::string::npos) << out;
}

}  // namespace
}  // namespace reebkit::test
