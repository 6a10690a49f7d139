// The matching options (MatchingOptions, matching/graph_matching.h) by name:
// one table (core/option_table.h) from which the command line offers them
// (`--attribute-weight` for attribute_weight), Python takes them as keywords
// of reebkit.MatchingOptions, their ranges are checked and the docs list
// them. Adding a matching option is one row of the table
// (matching_options.cpp).
#pragma once

#include "reebkit/core/option_table.h"
#include "reebkit/matching/graph_matching.h"

#include <vector>

namespace reebkit {

/// A row of the table.
using MatchingOptionField = OptionField<MatchingOptions>;

/// Every matching option, in the order --help lists them.
const std::vector<MatchingOptionField>& matching_option_fields();

/// Throws InvalidArgument naming the first option out of its range (a
/// negative weight, a cost <= 0, NaN): before any graph is matched, since
/// such a value gives negative or meaningless distances.
void check_matching_options(const MatchingOptions& options);

}  // namespace reebkit
