#!/usr/bin/env bash
# reeb index benchmark (docs/command-line.md, "Indexing a collection"):
#  1. all 400 SHREC 2007 meshes with their .cla, 1 then 2 threads: wall and
#     CPU time, speed-up, share of the time spent writing the HDF5 file;
#  2. memory: peak RSS indexing 1,000, 5,000 and 10,000 generated small
#     meshes (bench/make_collection), which should stay flat.
# Needs /usr/bin/time (Debian package `time`) and the unpacked datasets
# (ctest --test-dir BUILD -R unpack_datasets).
#
#   bash bench/index_bench.sh [BUILD_DIR]      (default: build)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
reeb=$build/tools/reeb
shrec=$build/data/shrec07_watertight
scratch=$(mktemp -d "${TMPDIR:-/tmp}/index_bench.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

# index OUTPUT ARGS...: prints "wall_s cpu_s peak_rss_kb write_s" of one run.
index() {
  local out=$1
  shift
  /usr/bin/time -f "%e %U %S %M" -o "$scratch/time" "$reeb" index "$@" -o "$out" >/dev/null 2>"$scratch/log"
  local write
  write=$(sed -n 's/^writing the file: \([0-9.]*\) s.*/\1/p' "$scratch/log")
  awk -v w="$write" '{ printf "%s %.2f %s %s\n", $1, $2 + $3, $4, w }' "$scratch/time"
}

echo "== SHREC 2007: $(ls "$shrec"/*.off | wc -l) meshes, $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-8s %8s %8s %10s %8s %8s\n" threads wall_s cpu_s peak_MB write_s write_%
declare -A wall
for t in 1 2; do
  read -r w c m s < <(index "$scratch/shrec$t.h5" "$shrec" --classes "$shrec/shrec07_watertight.cla" --threads "$t")
  wall[$t]=$w
  awk -v t="$t" -v w="$w" -v c="$c" -v m="$m" -v s="$s" \
    'BEGIN { printf "%-8s %8.2f %8.2f %10.1f %8.2f %8.1f\n", t, w, c, m / 1024, s, 100 * s / w }'
done
awk -v a="${wall[1]}" -v b="${wall[2]}" 'BEGIN { printf "speed-up 1 -> 2 threads: %.2fx\n", a / b }'

echo "== memory: generated small meshes, 2 threads"
"$build/bench/make_collection" "$scratch/gen" 10000
printf "%-8s %8s %10s %8s\n" meshes wall_s peak_MB write_%
for n in 1000 5000 10000; do
  printf '%05d.off\n' $(seq 0 $((n - 1))) > "$scratch/gen/list$n.txt"
  read -r w c m s < <(index "$scratch/gen$n.h5" "$scratch/gen/list$n.txt" --threads 2)
  awk -v n="$n" -v w="$w" -v m="$m" -v s="$s" 'BEGIN { printf "%-8s %8.2f %10.1f %8.1f\n", n, w, m / 1024, 100 * s / w }'
done
