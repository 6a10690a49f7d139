#!/usr/bin/env bash
# `reeb graph` end to end on a 1M-face ASCII OFF: read, clean, feature
# points, f_q, Reeb graph, attributes and the JSON written, as a new process,
# on 1 and 2 threads (issue 23: <= 0.8 s and <= 0.5 s). The mesh is the
# embedded bunny subdivided four times (1-to-4 midpoint subdivision: 940,544
# faces), written once into BUILD_DIR/bench_graph/.
#
#   bash bench/graph_end_to_end.sh BUILD_DIR [RUNS]
#
# Prints each run's wall time and the median of RUNS (default 5) per thread
# count, with the load average (the machine may be shared).
set -euo pipefail
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 BUILD_DIR [RUNS]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
runs=${2:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
reeb=$build/tools/reeb
work=$build/bench_graph
mesh=$work/bunny_x4.off
mkdir -p "$work"
[ -s "$mesh" ] || "$reeb" perturb "$root/datasets/bunny.off" -o "$mesh" --subdivide 4 >/dev/null
echo "mesh: $mesh ($(sed -n 2p "$mesh" | awk '{print $2}') faces, $(stat -L -c %s "$mesh") bytes); load: $(cut -d' ' -f1-3 /proc/loadavg)"
for threads in 1 2; do
  times=()
  for ((k = 0; k < runs; ++k)); do
    start=$(date +%s.%N)
    OMP_NUM_THREADS=$threads "$reeb" graph "$mesh" -o "$work/graph.json" >/dev/null
    times+=("$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}')
  printf '%d thread(s): runs %s s; median %.3f s\n' "$threads" "$(printf '%.3f ' "${times[@]}")" "$median"
done
