// The analysis options (AnalysisOptions, pipeline/analyze_mesh.h) by name:
// one table of the options that change a mesh's Reeb graph, which the
// command line offers (`--min-persistence` for min_persistence) and the
// collection file stores (typed attributes of the group
// `analysis_options`), so that a collection remembers how it was analysed,
// `reeb query MESH` analyses a mesh file the same way and `reeb index
// --resume` refuses other options. Adding an analysis option is one row of
// the table (analysis_options.cpp); an option of a new enum type also needs
// its option_value_of / set_from_option pair there (its name as text, as
// Geodesic's).
#pragma once

#include "reebkit/core/option_table.h"
#include "reebkit/pipeline/analyze_mesh.h"

#include <functional>
#include <string>
#include <vector>

namespace reebkit {

/// A row of the table (core/option_table.h).
using AnalysisOptionField = OptionField<AnalysisOptions>;

/// Every analysis option, in the order --help and `reeb info` list them.
const std::vector<AnalysisOptionField>& analysis_option_fields();

/// Checks every option's range (AnalysisOptionField::check), so that a
/// collection is refused before any mesh is read rather than failing every mesh.
void check_analysis_options(const AnalysisOptions& options);

/// `options` by name, in table order.
std::vector<NamedOption> named_analysis_options(const AnalysisOptions& options);

/// The analysis options `named` gives, the defaults for those it lacks (a
/// file written before an option existed was analysed with its default, but
/// for level_lines: a non-empty set without it predates the contour lines
/// and means paper).
/// Throws InvalidArgument naming an unknown option or a value of the wrong kind.
AnalysisOptions analysis_options_from(const std::vector<NamedOption>& named);

/// An option whose value differs between two sets, as text.
struct OptionDifference {
  std::string name, first, second;
};

/// The options whose values differ between `first` and `second`, in table order.
std::vector<OptionDifference> analysis_option_differences(const AnalysisOptions& first, const AnalysisOptions& second);

}  // namespace reebkit
