#!/usr/bin/env bash
# A setting measured on what the analysis defaults are chosen on (issue 22,
# docs/results.md): sections 2 and 3 of the robustness suite (the sampling
# variants of SHREC07, CGAL and TOSCA meshes, and the TOSCA poses; the same
# meshes as experiments/robustness.sh) under `robustness --option
# NAME=VALUE`..., then one table of the figures issue 22 aims at, for the
# suite's last full run (BUILD_DIR/robustness, the defaults) and every probe
# so far. About 7 minutes on 2 threads.
#
#   experiments/robustness_probe.sh BUILD_DIR NAME [--option NAME=VALUE]...
#   experiments/robustness_probe.sh build epsilon-0.18 --option epsilon=0.18
#
# NAME: the probe's folder, BUILD_DIR/robustness_probes/NAME (its CSV
# tables are derived from academic-use data: never committed). The option
# names are those of the analysis option table (pipeline/analysis_options.h;
# the command-line flags with `_` for `-`: epsilon, feature_site, ...,
# docs/command-line.md). No option measures today's defaults again.
# THREADS (default 2) sets the threads, PER_CLASS (default 5) the SHREC07
# meshes per class. The table reads the fast-marching rows (the default
# method; the program measures Dijkstra beside it).
set -euo pipefail

if [ $# -lt 2 ]; then
  echo "usage: $0 BUILD_DIR NAME [--option NAME=VALUE]..." >&2
  exit 2
fi
build=$(cd "$1" && pwd)
name=$2
shift 2
for ((k = 1; k <= $#; k += 2)); do
  if [ "${!k}" != --option ] || [ $((k + 1)) -gt $# ]; then
    echo "$0: expected --option NAME=VALUE pairs after NAME, got '${!k}'" >&2
    exit 2
  fi
done
source_dir=$(cd "$(dirname "$0")/.." && pwd)
export OMP_NUM_THREADS=${THREADS:-2}
per_class=${PER_CLASS:-5}
probes=$build/robustness_probes
# shellcheck source=experiments/robustness_sections.sh
source "$source_dir/experiments/robustness_sections.sh"

step() {  # step NAME COMMAND...: runs it, its output into the probe's log, and says how long it took
  local label=$1 start=$SECONDS
  shift
  echo "== $label"
  "$@" >> "$probes/$name/log" 2>&1 || { echo "$0: failed, see $probes/$name/log" >&2; exit 1; }
  echo "== $label: $((SECONDS - start)) s"
}

rm -rf "${probes:?}/$name"
mkdir -p "$probes/$name"
printf '%s\n' "$*" > "$probes/$name/options"
sampling_and_poses "$name" "$probes/$name" "$@"
touch "$probes/$name/complete"

folders=()
[ -e "$build/robustness/sampling_shrec07.csv" ] && folders+=("$build/robustness")
for d in "$probes"/*/; do [ -e "$d/complete" ] && folders+=("${d%/}"); done
/usr/bin/python3 "$source_dir/tools/figures/robustness_report.py" --compare "${folders[@]}"
