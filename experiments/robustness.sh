#!/usr/bin/env bash
# The robustness suite: the invariance and robustness claims of Tierny et al.
# 2006 (sections 4.1.2, 5.1, 5.3) measured on SHREC 2007 Watertight, the
# closed CGAL meshes and TOSCA, as one report with plots.
#
#   experiments/robustness.sh BUILD_DIR [REPORT_DIR]
#
# BUILD_DIR: a build with the target robustness and the datasets unpacked
# (ctest -R unpack_datasets). REPORT_DIR (default results/robustness/):
# report.md and its PNG plots. The measured tables (CSV) are derived from
# academic-use data: they stay in BUILD_DIR/robustness/ and are never
# committed. THREADS (default 2) sets the threads; PER_CLASS (default 5) the
# SHREC07 meshes per class in the sampling section; SIMILARITIES (default 5)
# the random similarities per SHREC07 mesh.
set -euo pipefail

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 BUILD_DIR [REPORT_DIR]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
source_dir=$(cd "$(dirname "$0")/.." && pwd)
report=${2:-$source_dir/results/robustness}
export OMP_NUM_THREADS=${THREADS:-2}
per_class=${PER_CLASS:-5}
similarities=${SIMILARITIES:-5}
work=$build/robustness
# shellcheck source=experiments/robustness_sections.sh
source "$source_dir/experiments/robustness_sections.sh"
mkdir -p "$work" "$report"
start_all=$SECONDS

step() {  # step NAME COMMAND...: runs it and says how long it took
  local name=$1 start=$SECONDS
  shift
  echo "== $name"
  "$@"
  echo "== $name: $((SECONDS - start)) s"
  printf '%s\t%s\n' "$name" "$((SECONDS - start))" >> "$work/steps.tsv"
}
printf 'step\tseconds\n' > "$work/steps.tsv"
git -C "$source_dir" rev-parse --short HEAD > "$work/commit" 2>/dev/null || echo "?" > "$work/commit"

step "1, 4, 5: every SHREC07 mesh: similarities, graphs, hand-picked points" \
  "$robustness" rigid "$work" "$shrec" "$cla" "$similarities"
sampling_and_poses "today's defaults" "$work"
# The defaults of earlier layouts, side by side with today's in the report.
mkdir -p "$work/layout8"
step "3: TOSCA poses, the feature points of layout 8 (epsilon 0.05, persistence 0.01, on the extrema)" \
  "$robustness" --option epsilon=0.05 --option min_persistence=0.01 --option feature_site=extremum \
  tosca "$work/layout8" "$data/tosca_dev"
sampling_and_poses "the diameter search of layout 10 (from vertex 0)" "$work/layout10" --option diameter_start=vertex
sampling_and_poses "the feature points of layout 14 (halfway between their two extrema)" "$work/layout14" \
  --option feature_site=midpoint
sampling_and_poses "the diameter search of layout 15 (no bound on its passes)" "$work/layout15" \
  --option max_search_passes=0
step "6: timing" env OMP_NUM_THREADS=1 "$robustness" timing "$work" "$data/tosca_dev/michael0.off" 2000 10000 40000 100000
printf 'total\t%s\n' "$((SECONDS - start_all))" >> "$work/steps.tsv"
step "report and plots" /usr/bin/python3 "$source_dir/tools/figures/robustness_report.py" "$work" "$report"
echo "report: $report/report.md"
