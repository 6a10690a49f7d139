#!/usr/bin/env bash
# Retrieval on SHREC 2007 Watertight (400 meshes, 20 classes of 20): reebkit's
# attributed Reeb graph matching next to two baselines (experiments/baselines:
# the D2 shape distribution of Osada et al. 2002 and a geodesic distance
# histogram), all evaluated by the same `reeb eval` in one report.
#
#   experiments/shrec07_retrieval.sh BUILD_DIR [REPORT_DIR]
#
# BUILD_DIR: a build with the targets reeb and baselines, and the datasets
# unpacked (ctest -R unpack_datasets). REPORT_DIR (default results/shrec07/):
# report.md, pr.csv, pr.png, pr.svg, failing_queries.png. The collection file and the distance
# matrices are derived from academic-use data: they stay in
# BUILD_DIR/shrec07_retrieval/ and are never committed. THREADS (default 2)
# sets the threads of every step. Every method is also evaluated after local
# scaling with its SCALING_K-th (default 10) nearest model (reeb eval
# --local-scaling).
set -euo pipefail

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 BUILD_DIR [REPORT_DIR]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
source_dir=$(cd "$(dirname "$0")/.." && pwd)
report=${2:-$source_dir/results/shrec07}
threads=${THREADS:-2}
scaling_k=${SCALING_K:-10}
data=$build/data/shrec07_watertight
cla=$data/shrec07_watertight.cla
work=$build/shrec07_retrieval
reeb=$build/tools/reeb
baselines=$build/experiments/baselines

for f in "$reeb" "$baselines"; do
  [ -x "$f" ] || { echo "$0: $f is missing: build the targets reeb and baselines" >&2; exit 1; }
done
[ -f "$cla" ] || { echo "$0: $cla is missing: run ctest --test-dir $build -R unpack_datasets" >&2; exit 1; }
mkdir -p "$work" "$report"

step() {  # step NAME COMMAND...: runs it and says how long it took
  local name=$1 start=$SECONDS
  shift
  echo "== $name"
  "$@"
  echo "== $name: $((SECONDS - start)) s"
}

step "index SHREC07 into attributed Reeb graphs" \
  "$reeb" index "$data" -o "$work/shrec07.h5" --classes "$cla" --threads "$threads"
step "reebkit: all-pairs graph matching distances" \
  "$reeb" distances "$work/shrec07.h5" -o "$work/reebkit.matrix" --cla "$cla" --threads "$threads"
step "baselines: D2 and geodesic histogram distances" \
  env OMP_NUM_THREADS="$threads" "$baselines" "$data" "$cla" "$work/baseline"
step "evaluation report" \
  "$reeb" eval "$work/reebkit.matrix" --name reebkit --cla "$cla" -o "$report" \
    --compare "$work/baseline-d2.matrix:D2" "$work/baseline-geodesic.matrix:geodesic-histogram" \
    --local-scaling "$scaling_k"
step "pictures of the worst reebkit queries" \
  /usr/bin/python3 "$source_dir/tools/figures/query_montage.py" "$work/reebkit.matrix" "$cla" "$data" \
    "$report/failing_queries.png" --queries 4 --results 4
echo "report: $report/report.md, failing queries: $report/failing_queries.png"
