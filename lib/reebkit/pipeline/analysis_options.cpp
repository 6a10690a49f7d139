#include "reebkit/pipeline/analysis_options.h"

#include "reebkit/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace reebkit {
namespace {

OptionValue to_value(double x) { return x; }
OptionValue to_value(Geodesic method) { return std::string(geodesic_name(method)); }
OptionValue to_value(LevelLines lines) { return std::string(level_lines_name(lines)); }
template <typename T, typename = std::enable_if_t<std::is_integral_v<T>>>
OptionValue to_value(T x) {
  return static_cast<std::int64_t>(x);
}

void from_value(const OptionValue& value, double& x, const std::string&) { x = std::get<double>(value); }
void from_value(const OptionValue& value, Geodesic& method, const std::string&) {
  method = parse_geodesic(std::get<std::string>(value));
}
void from_value(const OptionValue& value, LevelLines& lines, const std::string&) {
  lines = parse_level_lines(std::get<std::string>(value));
}
template <typename T, typename = std::enable_if_t<std::is_integral_v<T>>>
void from_value(const OptionValue& value, T& x, const std::string& name) {
  const std::int64_t v = std::get<std::int64_t>(value);
  if (v < std::numeric_limits<T>::min() || v > std::numeric_limits<T>::max())
    throw InvalidArgument("analysis option " + name + ": " + std::to_string(v) + " is out of range");
  x = static_cast<T>(v);
}

/// The values a numeric option may take: [lowest, highest], or (lowest,
/// highest] when `above_lowest`.
struct Range {
  double lowest = -std::numeric_limits<double>::infinity();
  double highest = std::numeric_limits<double>::infinity();
  bool above_lowest = false;

  bool holds(double x) const { return (above_lowest ? x > lowest : x >= lowest) && x <= highest; }
  std::string text() const {
    const auto bound = [](double x) { return std::isinf(x) ? std::string("inf") : option_text(x); };
    return (above_lowest ? "(" : "[") + bound(lowest) + ", " + bound(highest) + (std::isinf(highest) ? ")" : "]");
  }
};

/// The row of the option `member` of the part `group` of AnalysisOptions,
/// whose values lie in `range` (a text option: any its parser accepts).
template <typename Group, typename T>
AnalysisOptionField field(const char* name, const char* help, Group AnalysisOptions::*group, T Group::*member,
                          Range range = {}) {
  return {name, help, [=](const AnalysisOptions& o) { return to_value((o.*group).*member); },
          [=, name = std::string(name)](AnalysisOptions& o, const OptionValue& value) {
            const OptionValue kind = to_value(T{});
            if (value.index() != kind.index())
              throw InvalidArgument("analysis option " + name + ": expected " + option_kind(kind) + ", got " +
                                    option_kind(value) + " '" + option_text(value) + "'");
            from_value(value, (o.*group).*member, name);
          },
          [=, name = std::string(name)](const AnalysisOptions& o) {
            if constexpr (std::is_arithmetic_v<T>) {
              const T value = (o.*group).*member;
              if (!range.holds(static_cast<double>(value)))
                throw InvalidArgument("analysis option " + name + ": " + option_text(to_value(value)) +
                                      " is out of its range " + range.text());
            }
          }};
}

}  // namespace

const std::vector<AnalysisOptionField>& analysis_option_fields() {
  using A = AnalysisOptions;
  static const std::vector<AnalysisOptionField> fields = {
      field("max_hole_loop", "close each boundary loop no longer than this fraction of sqrt(surface area) before "
            "the analysis (0: keep every hole)", &A::holes, &HoleFillingOptions::max_loop_length, Range{0}),
      field("epsilon", "relaxation radius of the extrema intersection, eq. (6) (fraction of the geodesic diameter)",
            &A::features, &FeatureOptions::epsilon, Range{0, 1, true}),
      field("geodesic", "geodesic distances: dijkstra (shortest edge paths) or fmm (fast marching across the "
            "triangles, less sensitive to the sampling)", &A::features, &FeatureOptions::geodesic),
      field("min_persistence", "drop the extrema of f1 and f2 whose topological persistence is below this "
            "fraction of the geodesic diameter before the relaxed intersection (0: every local extremum, as the "
            "paper)", &A::features, &FeatureOptions::min_persistence, Range{0, 1}),
      field("start_vertex", "start vertex v_r of the diameter search, eq. (2) (index in the cleaned mesh)",
            &A::features, &FeatureOptions::start_vertex, Range{0}),
      field("max_extra_sweeps", "extra passes per diameter sweep at most (0: the paper's single double sweep)",
            &A::features, &FeatureOptions::max_extra_sweeps, Range{0}),
      field("extra_seeds", "further diameter sweeps from farthest-point seeds", &A::features,
            &FeatureOptions::extra_seeds, Range{0}),
      field("level_lines", "what a level line is: contour (the connected curves of the propagation front, exact "
            "topology) or paper (Definition 6: connected sets of candidate vertices)", &A::reeb,
            &ReebOptions::level_lines),
      field("skeleton_levels", "levels of f the skeleton is thinned to (a point per level a line absorbs)",
            &A::reeb, &ReebOptions::skeleton_levels, Range{1}),
  };
  return fields;
}

void check_analysis_options(const AnalysisOptions& options) {
  for (const AnalysisOptionField& f : analysis_option_fields()) f.check(options);
}

std::vector<NamedOption> named_analysis_options(const AnalysisOptions& options) {
  std::vector<NamedOption> out;
  for (const AnalysisOptionField& f : analysis_option_fields()) out.push_back({f.name, f.get(options)});
  return out;
}

AnalysisOptions analysis_options_from(const std::vector<NamedOption>& named) {
  AnalysisOptions options;
  // Files written before level_lines existed were analysed with Definition 6.
  if (!named.empty() && std::none_of(named.begin(), named.end(),
                                     [](const NamedOption& option) { return option.name == "level_lines"; }))
    options.reeb.level_lines = LevelLines::Paper;
  for (const NamedOption& option : named) {
    const auto& fields = analysis_option_fields();
    const auto f = std::find_if(fields.begin(), fields.end(),
                                [&](const AnalysisOptionField& field) { return field.name == option.name; });
    if (f == fields.end()) throw InvalidArgument("unknown analysis option '" + option.name + "'");
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
