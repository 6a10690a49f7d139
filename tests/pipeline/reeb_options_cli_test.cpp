// End to end: every `reeb` command that analyses a mesh offers every analysis
// option of the table (pipeline/analysis_options.h), and every command that
// matches graphs every matching option, each with the library's default.
#include "reebkit/matching/matching_options.h"
#include "reebkit/pipeline/analysis_options.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

namespace reebkit::test {
namespace {

/// `reeb <command> --help`.
std::string help(const std::string& command) {
  const auto [status, out] = run_command(std::string(REEB_BINARY) + " " + command + " --help");
  EXPECT_EQ(status, 0) << command << "\n" << out;
  return out;
}

/// "--min-persistence" for min_persistence.
std::string flag_name(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

/// "--name arg (=default)" as --help shows a flag.
std::string flag(const std::string& name, const OptionValue& default_value) {
  return flag_name(name) + " arg (=" + option_text(default_value) + ")";
}

/// `text` with every run of white space as one space (--help wraps its lines).
std::string one_line(const std::string& text) {
  std::string out;
  for (const char c : text)
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += c;
    else if (!out.empty() && out.back() != ' ')
      out += ' ';
  return out;
}

/// The row of `field` in the docs' tables of options (docs/command-line.md).
template <typename Options>
std::string docs_row(const OptionField<Options>& field) {
  const std::string values = field.values();
  return "| `" + flag_name(field.name) + "` | " + option_text(field.get(Options{})) + " | " +
         (values.empty() ? "—" : values) + " | " + field.help + " |";
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
  for (const char* command : {"match", "query", "distances"}) {
    const std::string text = help(command);
    for (const MatchingOptionField& field : matching_option_fields())
      EXPECT_NE(text.find(flag(field.name, field.get(MatchingOptions{}))), std::string::npos)
          << "reeb " << command << " --help lacks " << flag(field.name, field.get(MatchingOptions{})) << "\n"
          << text;
  }
}

TEST(ReebOptionsCli, EveryFlagIsDescribedByItsRowWithItsValues) {
  const std::string text = one_line(help("match"));
  const auto expect_described = [&](const auto& field, const OptionValue& default_value) {
    const std::string line = flag(field.name, default_value) + " " + field.described();
    EXPECT_NE(text.find(line), std::string::npos) << "reeb match --help lacks " << line << "\n" << text;
  };
  for (const AnalysisOptionField& field : analysis_option_fields())
    expect_described(field, field.get(AnalysisOptions{}));
  for (const MatchingOptionField& field : matching_option_fields())
    expect_described(field, field.get(MatchingOptions{}));
  EXPECT_NE(text.find("--unmatched-cost arg (=1) cost of deleting or inserting a node, per unit of node weight; "
                      "values in (0, inf)"),
            std::string::npos)
      << text;
}

// Before: docs/command-line.md listed the options by hand, their ranges in
// prose that no test read.
TEST(ReebOptionsCli, TheDocsTablesOfOptionsAreTheLibraryTablesRowByRow) {
  std::ifstream docs(std::string(REEBKIT_SOURCE_DIR) + "/docs/command-line.md");
  ASSERT_TRUE(docs) << "cannot read docs/command-line.md";
  std::vector<std::string> rows;  // of the docs' tables of options, in order
  for (std::string line; std::getline(docs, line);)
    if (line.rfind("| `--", 0) == 0) rows.push_back(line);
  std::vector<std::string> expected;
  for (const AnalysisOptionField& field : analysis_option_fields()) expected.push_back(docs_row(field));
  for (const MatchingOptionField& field : matching_option_fields()) expected.push_back(docs_row(field));
  std::string tables;
  for (const std::string& row : expected) tables += row + "\n";
  EXPECT_EQ(rows, expected) << "docs/command-line.md: the rows of its two tables of options (analysis, then "
                               "matching) are, from pipeline/analysis_options.cpp and "
                               "matching/matching_options.cpp:\n"
                            << tables;
}

TEST(ReebOptionsCli, AnAnalysisOptionOfTheWrongKindIsRejectedNamingIt) {
  const auto [status, out] = run_command(std::string(REEB_BINARY) + " features " +
                                         shell_quoted(embedded_dataset_dir() / "cow.off") + " --epsilon wide 2>&1");
  EXPECT_EQ(status, 2);
  EXPECT_NE(out.find("epsilon"), std::string::npos) << out;
}

// Before: --structure-weight -100 gave negative distances and reordered
// rankings, --unmatched-cost -5 a distance of -5, nan was taken.
TEST(ReebOptionsCli, AMatchingOptionOutOfItsRangeIsRefusedBeforeAnyMeshIsRead) {
  const std::string cow = shell_quoted(embedded_dataset_dir() / "cow.off");
  for (const std::string option : {"--structure-weight -100", "--unmatched-cost -5", "--unmatched-cost 0",
                                   "--attribute-weight nan", "--profile-weight inf", "--refine-rounds -1"}) {
    const auto [status, out] =
        run_command(std::string(REEB_BINARY) + " match " + cow + " " + cow + " " + option + " 2>&1");
    EXPECT_EQ(status, 1) << option << "\n" << out;
    const std::string name = option.substr(2, option.find(' ') - 2);
    std::string field = name;
    std::replace(field.begin(), field.end(), '-', '_');
    EXPECT_NE(out.find("reeb match: error: matching option " + field + ": "), std::string::npos) << out;
    EXPECT_NE(out.find("is out of its range"), std::string::npos) << out;
    EXPECT_EQ(out.find("read and cleaned"), std::string::npos) << out;
  }
}

// Before: "the option '--mesh' is required"; `-o ""` exited 0 writing nothing.
TEST(ReebOptionsCli, AMissingArgumentIsNamedAsTheUsageNamesItAndAnEmptyValueIsRefused) {
  const std::string reeb = REEB_BINARY;
  const auto [missing, missing_out] = run_command(reeb + " features 2>&1");
  EXPECT_EQ(missing, 2) << missing_out;
  EXPECT_NE(missing_out.find("reeb features: the argument MESH is missing"), std::string::npos) << missing_out;
  const auto [second, second_out] =
      run_command(reeb + " match " + shell_quoted(embedded_dataset_dir() / "cow.off") + " 2>&1");
  EXPECT_EQ(second, 2) << second_out;
  EXPECT_NE(second_out.find("the argument B is missing"), std::string::npos) << second_out;
  const auto [empty, empty_out] =
      run_command(reeb + " features " + shell_quoted(embedded_dataset_dir() / "cow.off") + " -o '' 2>&1");
  EXPECT_EQ(empty, 2) << empty_out;
  EXPECT_NE(empty_out.find("the option '--output' is given an empty value"), std::string::npos) << empty_out;
  EXPECT_EQ(empty_out.find("read and cleaned"), std::string::npos) << empty_out;
  const auto [bare, bare_out] = run_command(reeb + " 2>&1");
  EXPECT_EQ(bare, 2) << bare_out;
  EXPECT_NE(bare_out.find("usage: reeb <command>"), std::string::npos) << bare_out;
}

// reeb starts itself again with glibc's transparent huge pages for its
// allocations (tools/reeb/main.cpp), once, and leaves a choice already made.
TEST(ReebOptionsCli, ReebRunsWithHugePagesForItsAllocationsUnlessToldOtherwise) {
  const std::string reeb = REEB_BINARY;
  const auto [status, out] = run_command("env -u GLIBC_TUNABLES " + reeb + " --version");
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("GLIBC_TUNABLES=glibc.malloc.hugetlb=1\n"), std::string::npos) << out;
  const auto [kept, kept_out] = run_command("GLIBC_TUNABLES=glibc.malloc.check=0 " + reeb + " --version");
  EXPECT_NE(kept_out.find("GLIBC_TUNABLES=glibc.malloc.check=0:glibc.malloc.hugetlb=1\n"), std::string::npos)
      << kept_out;
  const auto [off, off_out] = run_command("GLIBC_TUNABLES=glibc.malloc.hugetlb=0 " + reeb + " --version");
  EXPECT_NE(off_out.find("GLIBC_TUNABLES=glibc.malloc.hugetlb=0\n"), std::string::npos) << off_out;
}

}  // namespace
}  // namespace reebkit::test
