#!/usr/bin/env bash
# Retrieval on SHREC 2007 Watertight (400 meshes, 20 classes of 20): reebkit's
# attributed Reeb graph matching next to three baselines (experiments/baselines:
# the D2 shape distribution of Osada et al. 2002, a geodesic distance
# histogram and the Shape-DNA of Reuter et al. 2006), all evaluated by the
# same `reeb eval` in one report.
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
# --local-scaling). REUSE=1 keeps the baseline matrices of the last run and
# redoes only reebkit's index, distances and report (for re-runs while
# reebkit's settings change).
set -euo pipefail
# shellcheck source=experiments/common.sh
source "$(dirname "$0")/common.sh"

experiment_arguments results/shrec07 "$@"
scaling_k=${SCALING_K:-10}
data=$build/data/shrec07_watertight
cla=$data/shrec07_watertight.cla
work=$build/shrec07_retrieval

require_built "$reeb" "$baselines"
require_unpacked "$cla"
mkdir -p "$work" "$report"

all_distances shrec07 "$data" "$cla" "$work" "${REUSE:-0}"
step "evaluation report" \
  "$reeb" eval "$work/reebkit.matrix" --name reebkit --cla "$cla" -o "$report" \
    --compare "$work/baseline-d2.matrix:D2" "$work/baseline-geodesic.matrix:geodesic-histogram" \
      "$work/baseline-shape-dna.matrix:Shape-DNA" \
    --local-scaling "$scaling_k"
step "pictures of the worst reebkit queries" \
  /usr/bin/python3 "$source_dir/tools/figures/query_montage.py" "$work/reebkit.matrix" "$cla" "$data" \
    "$report/failing_queries.png" --queries 4 --results 4
echo "report: $report/report.md, failing queries: $report/failing_queries.png"
