#!/usr/bin/env bash
# A query as a new process against a large collection with its query file
# (docs/benchmarks.md, "Query and all-pairs distances"; the collection from
# `retrieval_bench shrec07.h5 SIZE COLLECTION`, which keeps it):
#  1. `reeb query COLLECTION NAME` five times: wall time from process start
#     and peak RSS;
#  2. Python: `reebkit.Collection(COLLECTION).query(NAME)` in a new
#     interpreter, from its start, then the median of 50 warm queries (the
#     graphs of 50 SHREC07 meshes, each queried once before) in that process.
# Needs /usr/bin/time (Debian package `time`).
#
#   bash bench/query_cold.sh COLLECTION [BUILD_DIR]      (default: build)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
collection=$1
build=$(cd "${2:-$root/build}" && pwd)
name=17.off

echo "== $collection: reeb query as a new process, load $(cut -d' ' -f1-3 /proc/loadavg)"
for run in 1 2 3 4 5; do
  /usr/bin/time -f "run $run: %e s wall, peak RSS %M KB" "$build/tools/reeb" query "$collection" "$name" -k 10 \
    2>&1 >/dev/null | tail -2
done

echo "== Python: reebkit.Collection.query"
PYTHONPATH=$build/python /usr/bin/python3 - "$collection" "$name" <<'EOF'
import time
start = time.perf_counter()
import sys
import reebkit
path, name = sys.argv[1], sys.argv[2]
c = reebkit.Collection(path)
first = c.query(name, k=10)
print("first query %.3f s from the interpreter's start (%s at %.4f)" % (time.perf_counter() - start, first[0]["name"],
                                                                        first[0]["distance"]))
graphs = [c["%d.off" % i] for i in range(1, 401, 8)]
for g in graphs:  # warm: each query once before the timed ones (the pages of the query file it reads mapped)
    c.query(g, k=10)
ms = []
for g in graphs:
    t = time.perf_counter()
    c.query(g, k=10)
    ms.append(1000 * (time.perf_counter() - t))
ms.sort()
print("warm: %d queries, median %.2f ms, 90th percentile %.2f ms, max %.2f ms" % (len(ms), ms[len(ms) // 2],
                                                                                  ms[len(ms) * 9 // 10], ms[-1]))
EOF
