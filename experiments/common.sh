# What the retrieval experiment scripts share; sourced, never run:
#   source "$(dirname "$0")/common.sh"
#   experiment_arguments results/NAME "$@"

# experiment_arguments DEFAULT_REPORT BUILD_DIR [REPORT_DIR]: moves to the
# checkout and sets build (the build folder, relative to the checkout, so
# that the reports name their files as any other checkout would), source_dir
# (the checkout, absolute), report (REPORT_DIR, or DEFAULT_REPORT under the
# checkout), threads (THREADS, default 2) and the programs reeb and
# baselines of the build; prints the usage and exits on a wrong argument
# count.
experiment_arguments() {
  local default=$1
  shift
  if [ $# -lt 1 ] || [ $# -gt 2 ]; then
    echo "usage: $0 BUILD_DIR [REPORT_DIR]" >&2
    exit 2
  fi
  build=$(cd "$1" && pwd)
  source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  report=${2:-$source_dir/$default}
  report=$(realpath -m "$report")
  cd "$source_dir"
  build=$(realpath --relative-to=. "$build")
  threads=${THREADS:-2}
  reeb=$build/tools/reeb
  baselines=$build/experiments/baselines
}

# require_built FILE...: exits naming the first program not built.
require_built() {
  local f
  for f; do
    [ -x "$f" ] || { echo "$0: $f is missing: build the target $(basename "$f")" >&2; exit 1; }
  done
}

# require_unpacked FILE...: exits naming the first dataset file not unpacked.
require_unpacked() {
  local f
  for f; do
    [ -e "$f" ] || { echo "$0: $f is missing: run ctest --test-dir $build -R unpack_datasets" >&2; exit 1; }
  done
}

# step NAME COMMAND...: runs it and says how long it took.
step() {
  local name=$1 start=$SECONDS
  shift
  echo "== $name"
  "$@"
  echo "== $name: $((SECONDS - start)) s"
}

# all_distances NAME MESH_DIR CLA OUT [KEEP]: indexes MESH_DIR (classes CLA)
# into OUT/NAME.h5 and writes the all-pairs distances, rows in CLA order, of
# reebkit's graph matching (OUT/reebkit.matrix) and of the baselines
# (OUT/baseline-d2.matrix, -geodesic, -shape-dna; KEEP = 1 keeps those
# already there). Uses $reeb, $baselines and $threads.
all_distances() {
  local name=$1 meshes=$2 cla=$3 out=$4 keep=${5:-0}
  step "$name: index into attributed Reeb graphs" \
    "$reeb" index "$meshes" -o "$out/$name.h5" --classes "$cla" --threads "$threads"
  step "$name: reebkit all-pairs graph matching distances" \
    "$reeb" distances "$out/$name.h5" -o "$out/reebkit.matrix" --cla "$cla" --threads "$threads"
  if [ "$keep" = 1 ] && [ -e "$out/baseline-d2.matrix" ] && [ -e "$out/baseline-geodesic.matrix" ] &&
    [ -e "$out/baseline-shape-dna.matrix" ]; then
    echo "== $name: baselines kept from the last run"
  else
    step "$name: baselines: D2, geodesic histogram and Shape-DNA distances" \
      env OMP_NUM_THREADS="$threads" "$baselines" "$meshes" "$cla" "$out/baseline"
  fi
}

# The analysis the pose benchmarks' meshes are planned on (the leaves `reeb
# perturb --pose` turns, the parts body_shapes changes): layout 9's, pinned,
# since a benchmark must not move with the defaults of the method it
# measures. planning: NAME=VALUE, as body_shapes' --option takes them;
# planning_options: those as --option pairs; planning_flags: the same as
# reeb perturb's --name VALUE words.
planning=(geodesic=fmm epsilon=0.15 min_persistence=0.03 feature_site=extremum diameter_start=vertex level_lines=contour leaves=maxima)
planning_options=() planning_flags=""
for planned in "${planning[@]}"; do
  planning_options+=(--option "$planned")
  planned_name=${planned%%=*}
  planning_flags+=" --${planned_name//_/-} ${planned#*=}"
done

# SHREC 2007 Watertight's articulated classes, in the class file's order.
articulated="Human Ant Octopus Teddy Hand Armadillo Fourleg"

# shrec07_models CLASS: the model ids of CLASS in the SHREC07 class file
# $shrec_cla.
shrec07_models() {
  awk -v c="$1" 'NF == 3 && $1 == c { n = $3; next } n > 0 && NF == 1 { print $1; n-- }' "$shrec_cla"
}
