#include "reebkit/pipeline/analysis_options.h"

#include "reebkit/core/error.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <set>

namespace reebkit::test {
namespace {

/// Options with every table entry away from its default.
AnalysisOptions changed() {
  AnalysisOptions o;
  o.holes.max_loop_length = 0.5;
  o.features.epsilon = 0.1;
  o.features.geodesic = Geodesic::Dijkstra;
  o.features.min_persistence = 0.02;
  o.features.start_vertex = 7;
  o.features.max_extra_sweeps = 1;
  o.features.extra_seeds = 0;
  o.features.max_search_passes = 3;
  o.features.protrusion_persistence = 0.05;
  o.features.site = FeatureSite::Extremum;
  o.features.rule = FeatureRule::Center;
  o.features.average_sources = 5;
  o.features.tip_persistence = 0.06;
  o.features.start = DiameterStart::Vertex;
  o.reeb.level_lines = LevelLines::Paper;
  o.reeb.leaves = Leaves::Propagation;
  o.reeb.skeleton_levels = 50;
  o.spectra.regions = true;
  return o;
}

TEST(AnalysisOptions, TheTableNamesEachOptionOnceAndReadsItsMember) {
  std::set<std::string> names;
  for (const AnalysisOptionField& f : analysis_option_fields()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_FALSE(f.help.empty()) << f.name;
    EXPECT_EQ(f.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_"), std::string::npos) << f.name;
    // Every row reads a member of its own: the changed options differ from the defaults in each.
    EXPECT_NE(f.get(changed()), f.get(AnalysisOptions{})) << f.name;
  }
  const std::vector<NamedOption> named = named_analysis_options(changed());
  ASSERT_EQ(named.size(), analysis_option_fields().size());
  EXPECT_EQ(named[1].name, "epsilon");
  EXPECT_EQ(named[1].value, OptionValue(0.1));
  EXPECT_EQ(named[2].value, OptionValue(std::string("dijkstra")));
  EXPECT_EQ(named[4].value, OptionValue(std::int64_t{7}));
}

TEST(AnalysisOptions, NamedOptionsRoundTrip) {
  const AnalysisOptions back = analysis_options_from(named_analysis_options(changed()));
  EXPECT_TRUE(analysis_option_differences(back, changed()).empty());
  EXPECT_EQ(back.features.geodesic, Geodesic::Dijkstra);
  EXPECT_EQ(back.features.start_vertex, 7);
  EXPECT_EQ(back.reeb.skeleton_levels, 50);
  EXPECT_EQ(back.holes.max_loop_length, 0.5);
  EXPECT_EQ(back.reeb.level_lines, LevelLines::Paper);
  // Options a file lacks keep their defaults, but for level_lines, leaves,
  // feature_site, diameter_start, region_spectra and max_search_passes: a
  // file that predates them was analysed with Definition 6, every
  // termination of the propagation, the feature points on their extrema, the
  // diameter search from vertex 0, the regions' spectra and no bound on the
  // search's passes.
  EXPECT_EQ(analysis_options_from({{"epsilon", 0.2}}).reeb.level_lines, LevelLines::Paper);
  EXPECT_EQ(analysis_options_from({{"epsilon", 0.2}}).reeb.leaves, Leaves::Propagation);
  EXPECT_EQ(analysis_options_from({{"epsilon", 0.2}}).features.site, FeatureSite::Extremum);
  EXPECT_EQ(analysis_options_from({{"epsilon", 0.2}}).features.start, DiameterStart::Vertex);
  EXPECT_TRUE(analysis_options_from({{"epsilon", 0.2}}).spectra.regions);
  EXPECT_EQ(analysis_options_from({{"epsilon", 0.2}}).features.max_search_passes, 0);
  EXPECT_EQ(analysis_options_from({}).features.max_search_passes, 4);
  EXPECT_FALSE(analysis_options_from({}).spectra.regions);
  EXPECT_EQ(analysis_options_from({}).reeb.level_lines, LevelLines::Contour);
  EXPECT_EQ(analysis_options_from({}).reeb.leaves, Leaves::Maxima);
  EXPECT_EQ(analysis_options_from({}).features.site, FeatureSite::Tips);
  EXPECT_EQ(analysis_options_from({}).features.start, DiameterStart::Centroid);
  const AnalysisOptions partial = analysis_options_from({{"epsilon", 0.2},
                                                         {"level_lines", std::string("contour")},
                                                         {"leaves", std::string("maxima")},
                                                         {"feature_site", std::string("tips")},
                                                         {"diameter_start", std::string("centroid")},
                                                         {"region_spectra", std::int64_t{0}},
                                                         {"max_search_passes", std::int64_t{4}}});
  EXPECT_EQ(partial.features.epsilon, 0.2);
  const auto differences = analysis_option_differences(partial, AnalysisOptions{});
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_EQ(differences[0].name, "epsilon");
  EXPECT_EQ(differences[0].first, "0.2");
  EXPECT_EQ(differences[0].second, "0.15");
}

TEST(AnalysisOptions, DifferencesListEveryChangedOptionInTableOrderWithBothValues) {
  AnalysisOptions other;
  other.features.geodesic = Geodesic::Dijkstra;
  other.features.min_persistence = 0;
  const auto differences = analysis_option_differences(AnalysisOptions{}, other);
  ASSERT_EQ(differences.size(), 2u);
  EXPECT_EQ(differences[0].name, "geodesic");
  EXPECT_EQ(differences[0].first, "fmm");
  EXPECT_EQ(differences[0].second, "dijkstra");
  EXPECT_EQ(differences[1].name, "min_persistence");
  EXPECT_EQ(differences[1].first, "0.03");
  EXPECT_EQ(differences[1].second, "0");
  EXPECT_EQ(analysis_option_differences(changed(), changed()).size(), 0u);
  EXPECT_EQ(analysis_option_differences(AnalysisOptions{}, changed()).size(), analysis_option_fields().size());
}

TEST(AnalysisOptions, RejectsUnknownNamesWrongKindsAndBadValues) {
  EXPECT_NE(thrown_message<InvalidArgument>([] {
              analysis_options_from({{"epsilom", 0.1}});
            }).find("unknown analysis option 'epsilom'"),
            std::string::npos);
  const std::string kind = thrown_message<InvalidArgument>([] {
    analysis_options_from({{"epsilon", std::string("wide")}});
  });
  EXPECT_NE(kind.find("epsilon: expected number, got text 'wide'"), std::string::npos) << kind;
  EXPECT_NE(thrown_message<InvalidArgument>([] {
              analysis_options_from({{"start_vertex", 1.5}});
            }).find("start_vertex"),
            std::string::npos);
  const std::string range = thrown_message<InvalidArgument>([] {
    analysis_options_from({{"start_vertex", std::int64_t{1} << 40}});
  });
  EXPECT_NE(range.find("start_vertex: 1099511627776 is out of range"), std::string::npos) << range;
  EXPECT_NE(thrown_message<InvalidArgument>([] {
              analysis_options_from({{"geodesic", std::string("heat")}});
            }).find("unknown geodesic method 'heat'"),
            std::string::npos);
}

TEST(OptionValue, TextIsShortestExactForm) {
  EXPECT_EQ(option_text(0.05), "0.05");
  EXPECT_EQ(option_text(1.6), "1.6");
  EXPECT_EQ(option_text(1e-300), "1e-300");
  EXPECT_EQ(option_text(std::int64_t{-3}), "-3");
  EXPECT_EQ(option_text(std::string("fmm")), "fmm");
  EXPECT_EQ(std::stod(option_text(0.1 + 0.2)), 0.1 + 0.2);
  EXPECT_STREQ(option_kind(std::int64_t{1}), "integer");
  EXPECT_STREQ(option_kind(1.0), "number");
  EXPECT_STREQ(option_kind(std::string()), "text");
}

}  // namespace
}  // namespace reebkit::test
