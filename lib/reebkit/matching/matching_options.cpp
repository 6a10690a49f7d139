#include "reebkit/matching/matching_options.h"

namespace reebkit {

namespace {

/// The row of a matching option.
template <typename Access>
MatchingOptionField field(const char* name, const char* help, Access access, OptionRange range) {
  return option_field<MatchingOptions>("matching option", name, help, access, range);
}

}  // namespace

const std::vector<MatchingOptionField>& matching_option_fields() {
  const OptionRange weight{0};  // a term's weight: 0 leaves the term out
  // A table, one option per row.
  // clang-format off
  static const std::vector<MatchingOptionField> fields = {
      field("attribute_weight", "weight of a: node attribute differences (area, f_q range, extent, radius)",
            [](auto& o) -> auto& { return o.attribute_weight; }, weight),
      field("structure_weight", "weight of s: local structure (degree, start and end types, neighbour area)",
            [](auto& o) -> auto& { return o.structure_weight; }, weight),
      field("edge_weight", "weight of e: edge inconsistency of the correspondence",
            [](auto& o) -> auto& { return o.edge_weight; }, weight),
      field("profile_weight", "weight of p: radius profiles of the regions",
            [](auto& o) -> auto& { return o.profile_weight; }, weight),
      field("shape_weight", "weight of h: Euclidean shape histograms of the regions",
            [](auto& o) -> auto& { return o.shape_weight; }, weight),
      field("geodesic_shape_weight", "weight of h_g: geodesic histograms of the regions",
            [](auto& o) -> auto& { return o.geodesic_shape_weight; }, weight),
      field("global_shape_weight", "weight of g: D2 shape distributions of the whole surfaces",
            [](auto& o) -> auto& { return o.global_shape_weight; }, weight),
      field("global_geodesic_weight", "weight of g_g: geodesic histograms of the whole surfaces",
            [](auto& o) -> auto& { return o.global_geodesic_weight; }, weight),
      field("spectrum_weight", "weight of r: Laplace-Beltrami spectra of the regions",
            [](auto& o) -> auto& { return o.spectrum_weight; }, weight),
      field("global_spectrum_weight", "weight of g_s: Laplace-Beltrami spectra of the whole surfaces",
            [](auto& o) -> auto& { return o.global_spectrum_weight; }, weight),
      field("global_spectrum_eigenvalues", "how many of the lowest eigenvalues g_s compares",
            [](auto& o) -> auto& { return o.global_spectrum_eigenvalues; }, OptionRange{1, kGlobalSpectrumLength}),
      field("global_spectrum_scale", "g_s = d / (d + scale), d the root mean square log ratio of the eigenvalues",
            [](auto& o) -> auto& { return o.global_spectrum_scale; }, OptionRange{0, OptionRange{}.highest, true}),
      field("global_heat_weight", "weight of g_h: heat kernel distributions of the whole surfaces",
            [](auto& o) -> auto& { return o.global_heat_weight; }, weight),
      field("global_heat_scale", "g_h = d / (d + scale), d the mean difference of the heat kernel quantiles",
            [](auto& o) -> auto& { return o.global_heat_scale; }, OptionRange{0, OptionRange{}.highest, true}),
      field("unmatched_cost", "cost of deleting or inserting a node, per unit of node weight",
            [](auto& o) -> auto& { return o.unmatched_cost; }, OptionRange{0, OptionRange{}.highest, true}),
      field("min_node_weight", "added to a node's relative area, so that area-less nodes still count",
            [](auto& o) -> auto& { return o.min_node_weight; }, OptionRange{0}),
      field("refine_rounds", "rounds of edge-consistency refinement",
            [](auto& o) -> auto& { return o.refine_rounds; }, OptionRange{0}),
  };
  // clang-format on
  return fields;
}

void check_matching_options(const MatchingOptions& options) { check_options(matching_option_fields(), options); }

}  // namespace reebkit
