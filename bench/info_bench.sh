#!/usr/bin/env bash
# What a collection holds, as a new process, against a large collection (the
# one `retrieval_bench COLLECTION.h5 SIZE OUT.h5` writes, which keeps it):
#  1. `reeb info COLLECTION` three times: wall time and peak RSS;
#  2. Python: `reebkit.Collection(COLLECTION).graph_stability()`, from the
#     interpreter's start.
# Both read the entries' outlines in batches (EntryParts::Outline). Needs
# /usr/bin/time (Debian package `time`).
#
#   bash bench/info_bench.sh COLLECTION [BUILD_DIR]      (default: build)
set -euo pipefail
if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 COLLECTION [BUILD_DIR]" >&2
  exit 2
fi
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
collection=$1
build=$(cd "${2:-$root/build}" && pwd)

echo "== $collection: reeb info as a new process, load $(cut -d' ' -f1-3 /proc/loadavg)"
for run in 1 2 3; do
  /usr/bin/time -f "run $run: %e s wall, peak RSS %M KB" "$build/tools/reeb" info "$collection" 2>&1 >/dev/null |
    tail -1
done

echo "== Python: reebkit.Collection.graph_stability"
PYTHONPATH=$build/python /usr/bin/python3 - "$collection" <<'PY'
import time
start = time.perf_counter()
import sys
import reebkit
s = reebkit.Collection(sys.argv[1]).graph_stability()
print("%.3f s from the interpreter's start: %d of %d graphs with their class's most common shape"
      % (time.perf_counter() - start, s["agreeing"], s["members"]))
PY
