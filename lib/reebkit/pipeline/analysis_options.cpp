#include "reebkit/pipeline/analysis_options.h"

#include "reebkit/core/error.h"

#include <algorithm>

namespace reebkit {

// The text options' values (option_table.h): their names, found by
// argument-dependent lookup.
static OptionValue option_value_of(Geodesic method) { return std::string(geodesic_name(method)); }
static OptionValue option_value_of(LevelLines lines) { return std::string(level_lines_name(lines)); }
static OptionValue option_value_of(Leaves leaves) { return std::string(leaves_name(leaves)); }
static OptionValue option_value_of(FeatureSite site) { return std::string(feature_site_name(site)); }
static OptionValue option_value_of(FeatureRule rule) { return std::string(feature_rule_name(rule)); }
static void set_from_option(const OptionValue& value, FeatureRule& rule) {
  rule = parse_feature_rule(std::get<std::string>(value));
}
static OptionValue option_value_of(DiameterStart start) { return std::string(diameter_start_name(start)); }
static void set_from_option(const OptionValue& value, DiameterStart& start) {
  start = parse_diameter_start(std::get<std::string>(value));
}
static void set_from_option(const OptionValue& value, FeatureSite& site) {
  site = parse_feature_site(std::get<std::string>(value));
}
static void set_from_option(const OptionValue& value, Geodesic& method) {
  method = parse_geodesic(std::get<std::string>(value));
}
static void set_from_option(const OptionValue& value, LevelLines& lines) {
  lines = parse_level_lines(std::get<std::string>(value));
}
static void set_from_option(const OptionValue& value, Leaves& leaves) {
  leaves = parse_leaves(std::get<std::string>(value));
}

namespace {

/// The row of an analysis option.
template <typename Access>
AnalysisOptionField field(const char* name, const char* help, Access access, OptionRange range = {}) {
  return option_field<AnalysisOptions>("analysis option", name, help, access, range);
}

}  // namespace

const std::vector<AnalysisOptionField>& analysis_option_fields() {
  // A table, one option per row.
  // clang-format off
  static const std::vector<AnalysisOptionField> fields = {
      field("max_hole_loop", "close each boundary loop no longer than this fraction of sqrt(surface area) before "
            "the analysis (0: keep every hole)",
            [](auto& o) -> auto& { return o.holes.max_loop_length; }, OptionRange{0}),
      field("epsilon", "relaxation radius of the extrema intersection, eq. (6) (fraction of the geodesic diameter; the "
            "paper's 0.05 parts the toes of a paw, 0.15 keeps one point per limb)",
            [](auto& o) -> auto& { return o.features.epsilon; }, OptionRange{0, 1, true}),
      field("geodesic", "geodesic distances of f1, f2, f_q and the attributes: fmm (fast marching across the "
            "triangles, the default: less sensitive to sampling and pose) or dijkstra (shortest edge paths)",
            [](auto& o) -> auto& { return o.features.geodesic; }),
      field("min_persistence", "drop the extrema of f1 and f2 whose topological persistence is below this "
            "fraction of the geodesic diameter before the relaxed intersection (0: every local extremum, as the "
            "paper)", [](auto& o) -> auto& { return o.features.min_persistence; }, OptionRange{0, 1}),
      field("start_vertex", "start vertex v_r of the diameter search under diameter_start vertex, eq. (2) (index "
            "in the cleaned mesh)",
            [](auto& o) -> auto& { return o.features.start_vertex; }, OptionRange{0}),
      field("diameter_start", "where the diameter search starts: centroid (v_s1 is the vertex farthest from the "
            "area centroid, the default: the same however the mesh is numbered) or vertex (a pass from "
            "start_vertex, layout 10 and before)",
            [](auto& o) -> auto& { return o.features.start; }),
      field("max_extra_sweeps", "extra passes per diameter sweep at most (0: the paper's single double sweep)",
            [](auto& o) -> auto& { return o.features.max_extra_sweeps; }, OptionRange{0}),
      field("extra_seeds", "further diameter sweeps from farthest-point seeds",
            [](auto& o) -> auto& { return o.features.extra_seeds; }, OptionRange{0}),
      field("max_search_passes", "full passes for the diameter ends, f1 and f2 together at most (0: no limit, layout 15 "
            "and before)",
            [](auto& o) -> auto& { return o.features.max_search_passes; }, OptionRange{0}),
      field("protrusion_persistence",
            "also make a feature point of every extremum of f1 or f2 persisting at least this fraction of the "
            "diameter that lies more than 2 epsilon from every feature point (0: off, eq. 6 alone)",
            [](auto& o) -> auto& { return o.features.protrusion_persistence; }, OptionRange{0, 1}),
      field("feature_site", "where the feature point of a pair of extrema of eq. (6) lies: tips (the centre of "
            "the extrema of f1 and f2 persisting at least 0.01 x the diameter within epsilon / 2 of the pair's "
            "midpoint, the fingertips of a hand, the default: steadier under pose), midpoint (halfway between the "
            "extremum of f1 and that of f2, layouts 10-14) or extremum (on the extremum the greedy order takes, "
            "layout 9 and before)",
            [](auto& o) -> auto& { return o.features.site; }),
      field("feature_rule", "how the feature points are chosen: intersection (eq. 6, the relaxed intersection of "
            "the extrema of f1 and f2, the default) or center (the diameter ends and the maxima of the distance "
            "from the centre of the diameter persisting at least tip_persistence and within epsilon of an extremum "
            "of f1 or f2, epsilon apart) or confirmed (the points of eq. 6 that lie within epsilon of such a "
            "maximum, and the diameter ends) or average (the diameter ends and the maxima of the mean geodesic "
            "distance from average_sources sources persisting at least tip_persistence, epsilon apart)",
            [](auto& o) -> auto& { return o.features.rule; }),
      field("average_sources", "feature_rule average: the geodesic functions averaged (from the diameter ends "
            "and farthest-point samples after them)",
            [](auto& o) -> auto& { return o.features.average_sources; }, OptionRange{3}),
      field("tip_persistence", "feature_rule center, confirmed or average: the persistence, as a fraction of the "
            "geodesic diameter, from which a maximum of the distance from the centre (of the mean) is a tip",
            [](auto& o) -> auto& { return o.features.tip_persistence; }, OptionRange{0, 1}),
      field("level_lines", "what a level line is: contour (the connected curves of the propagation front, exact "
            "topology) or paper (Definition 6: connected sets of candidate vertices)",
            [](auto& o) -> auto& { return o.reeb.level_lines; }),
      field("leaves", "which terminations of the propagation end a leaf: maxima (those at a local maximum of f_q; "
            "a pit the front closed around is cancelled with its split) or propagation (every one)",
            [](auto& o) -> auto& { return o.reeb.leaves; }),
      field("skeleton_levels", "levels of f the skeleton is thinned to (a point per level a line absorbs)",
            [](auto& o) -> auto& { return o.reeb.skeleton_levels; }, OptionRange{1}),
      field("region_spectra", "1: compute the Laplace-Beltrami spectra of the regions (node columns spectrum_*), "
            "which the r term of the matching cost compares; 0, the default: zeros, about a tenth less time",
            [](auto& o) -> auto& { return o.spectra.regions; }, OptionRange{0, 1}),
  };
  // clang-format on
  return fields;
}

void check_analysis_options(const AnalysisOptions& options) { check_options(analysis_option_fields(), options); }

std::vector<NamedOption> named_analysis_options(const AnalysisOptions& options) {
  return named_options(analysis_option_fields(), options);
}

AnalysisOptions analysis_options_from(const std::vector<NamedOption>& named) {
  AnalysisOptions options;
  // Files written before an option existed were analysed as it was then:
  // level_lines with Definition 6, leaves with every termination, the
  // feature points on their extrema, the diameter search from vertex 0, the
  // regions' spectra computed, no bound on the passes of the search.
  const auto lacks = [&named](const char* name) {
    return !named.empty() &&
           std::none_of(named.begin(), named.end(), [name](const NamedOption& option) { return option.name == name; });
  };
  if (lacks("level_lines")) options.reeb.level_lines = LevelLines::Paper;
  if (lacks("leaves")) options.reeb.leaves = Leaves::Propagation;
  if (lacks("feature_site")) options.features.site = FeatureSite::Extremum;
  if (lacks("diameter_start")) options.features.start = DiameterStart::Vertex;
  if (lacks("region_spectra")) options.spectra.regions = true;
  if (lacks("max_search_passes")) options.features.max_search_passes = 0;
  for (const NamedOption& option : named) {
    const AnalysisOptionField* f = find_option(analysis_option_fields(), option.name);
    if (!f) throw InvalidArgument("unknown analysis option '" + option.name + "'");
    f->set(options, option.value);
  }
  return options;
}

std::vector<OptionDifference> analysis_option_differences(const AnalysisOptions& first, const AnalysisOptions& second) {
  std::vector<OptionDifference> out;
  for (const AnalysisOptionField& f : analysis_option_fields()) {
    const OptionValue a = f.get(first), b = f.get(second);
    if (a != b) out.push_back({f.name, option_text(a), option_text(b)});
  }
  return out;
}

}  // namespace reebkit
