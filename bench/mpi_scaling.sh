#!/usr/bin/env bash
# bench/mpi_scaling.sh BUILD [MESHES]: reeb index and reeb distances on
# SHREC07 (400 meshes; or the folder MESHES) with 1 and 2 MPI processes of
# one OpenMP thread each, back to back: wall times, speed-ups, the merge of
# the shards, and the per-mesh, per-pair and merge costs that docs/cluster.md
# projects from. Every figure is printed with the machine's load (uptime).
# Needs a build with MPI (REEBKIT_MPI=ON) and python3-h5py for the check.
# SHREC07 is unpacked into BUILD/data by `ctest --test-dir BUILD -R unpack_datasets`.
set -euo pipefail

build=$(cd "${1:?usage: bench/mpi_scaling.sh BUILD [MESHES]}" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
meshes=${2:-$build/data/shrec07_watertight}
reeb=$build/tools/reeb
[ -x "$reeb" ] || { echo "no $reeb: build the target reeb first" >&2; exit 1; }
[ -d "$meshes" ] || { echo "no $meshes: run ctest --test-dir $build -R unpack_datasets" >&2; exit 1; }
grep -q '^REEBKIT_MPI:BOOL=ON' "$build/CMakeCache.txt" || { echo "$build is built without MPI" >&2; exit 1; }

cores=$(nproc --all)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One thread per process, processes not pinned (the machine is shared).
mpi() { local p=$1; shift; mpirun -np "$p" --bind-to none "$@"; }
load() { uptime | sed 's/.*load average: /load /'; }
now() { date +%s.%N; }
count=$(find "$meshes" -maxdepth 1 -name '*.off' | wc -l)

echo "reeb index and reeb distances on $count meshes of $meshes, 1 OpenMP thread per process"
echo "cores: $cores; $(mpirun --version | head -1)"
declare -A index_s merge_s dist_s
for p in 1 2; do
  t0=$(now)
  mpi "$p" "$reeb" index "$meshes" -o "$work/c$p.h5" --threads 1 >"$work/index$p.log" 2>&1
  index_s[$p]=$(echo "$(now) - $t0" | bc -l)
  merge_s[$p]=$(sed -n 's/^merging the shards: \([0-9.]*\) s.*/\1/p' "$work/index$p.log")
  printf 'index     %d process(es): %7.2f s (merge %.2f s)   [%s]\n' "$p" "${index_s[$p]}" "${merge_s[$p]}" "$(load)"
  grep '^process 0' "$work/index$p.log" | sed 's/^/          /'
done
for p in 1 2; do
  t0=$(now)
  mpi "$p" "$reeb" distances "$work/c1.h5" -o "$work/d$p.matrix" --threads 1 >"$work/dist$p.log" 2>&1
  dist_s[$p]=$(echo "$(now) - $t0" | bc -l)
  printf 'distances %d process(es): %7.2f s (%s)   [%s]\n' "$p" "${dist_s[$p]}" \
    "$(sed -n 's/.*pairs) in \([0-9.]*\) s/\1 s computing and gathering/p' "$work/dist$p.log")" "$(load)"
  grep '^process 0' "$work/dist$p.log" | sed 's/^/          /'
done

/usr/bin/python3 "$root/tests/cluster/compare_collections.py" "$work/c1.h5" "$work/c2.h5" | sed 's/^/check: index 1 vs 2 processes: /'
cmp -s "$work/d1.matrix" "$work/d2.matrix" && echo "check: distances 1 vs 2 processes: identical bytes" ||
  echo "check: distances 1 vs 2 processes: DIFFER"
# CPU seconds of the computing processes (reeb prints them for each one):
# under load the wall times depend on the scheduler, the CPU times much less.
cpu() { grep '^process 0' "$1" | grep -o 'CPU [0-9.]*' | awk -v how="$2" '
  { c = $2; sum += c; if (c > max) max = c } END { print (how == "max" ? max : sum) }'; }
printf 'CPU: index %.2f s at 1 process, %.2f s at 2 in all: speed-up on 2 free cores about %.2f (2 x 1-process CPU / 2-process CPU)\n' \
  "$(cpu "$work/index1.log" sum)" "$(cpu "$work/index2.log" sum)" \
  "$(echo "2 * $(cpu "$work/index1.log" sum) / $(cpu "$work/index2.log" sum)" | bc -l)"
printf 'CPU: distances %.2f s at 1 process, the slower of 2 processes %.2f s: speed-up of the computing on 2 free cores about %.2f\n' \
  "$(cpu "$work/dist1.log" sum)" "$(cpu "$work/dist2.log" max)" \
  "$(echo "$(cpu "$work/dist1.log" sum) / $(cpu "$work/dist2.log" max)" | bc -l)"
pairs=$((count * (count - 1) / 2))
printf 'speed-up 1 -> 2 processes: index %.2f, distances %.2f\n' \
  "$(echo "${index_s[1]} / ${index_s[2]}" | bc -l)" "$(echo "${dist_s[1]} / ${dist_s[2]}" | bc -l)"
printf 'costs: %.1f ms of CPU per mesh (index), %.2f us of CPU per pair (distances), %.2f ms per mesh (merge at 2 processes, wall)\n' \
  "$(echo "1000 * $(cpu "$work/index1.log" sum) / $count" | bc -l)" \
  "$(echo "1000000 * $(cpu "$work/dist1.log" sum) / $pairs" | bc -l)" "$(echo "1000 * ${merge_s[2]} / $count" | bc -l)"
printf 'collection file: %d bytes (%d per mesh)\n' "$(stat -c %s "$work/c2.h5")" "$(($(stat -c %s "$work/c2.h5") / count))"
