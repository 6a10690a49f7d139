#!/usr/bin/env bash
# Retrieval under pose (issue 12): two collections of articulated shapes in
# several poses, each evaluated by `reeb eval` with reebkit's attributed Reeb
# graph matching next to three baselines (experiments/baselines: D2, a
# geodesic distance histogram, Shape-DNA):
#  - tosca: the 54 TOSCA meshes of ../shared/datasets/tosca_dev (cat 11,
#    centaur 6, dog 9, horse 8, michael 20; the class is the file name
#    without its trailing number), the same shape in different poses;
#  - shrec07-pose: the 140 meshes of SHREC 2007 Watertight's articulated
#    classes (Human, Ant, Octopus, Teddy, Hand, Armadillo, Fourleg; 20 each),
#    each in POSES (default 1) random poses made by `reeb perturb --pose SEED`
#    (up to two of the four largest limbs turned by 20-35 degrees; the seed
#    is 100 x model id + pose number), the original not included: classes of
#    20 x POSES, the original classes. With one pose every query's class
#    holds other shapes only; with two the other pose of the same mesh is
#    every query's nearest neighbour for reebkit and Shape-DNA alike (NN
#    1.000), which NN then does not measure.
#
#   experiments/pose_retrieval.sh BUILD_DIR [REPORT_DIR]
#
# BUILD_DIR: a build with the targets reeb and baselines, and the datasets
# unpacked (ctest -R unpack_datasets). REPORT_DIR (default results/pose/):
# tosca/ and shrec07-pose/, each with report.md, pr.csv, pr.png, pr.svg. The
# posed meshes, class files, collection files and distance matrices are
# derived from academic-use data: they stay in BUILD_DIR/pose_retrieval/ and
# are never committed. THREADS (default 2) sets the threads of every step.
set -euo pipefail
# shellcheck source=experiments/common.sh
source "$(dirname "$0")/common.sh"

experiment_arguments results/pose "$@"
poses=${POSES:-1}
tosca=$build/data/tosca_dev
shrec=$build/data/shrec07_watertight
shrec_cla=$shrec/shrec07_watertight.cla
work=$build/pose_retrieval
articulated="Human Ant Octopus Teddy Hand Armadillo Fourleg"
tosca_classes="cat centaur dog horse michael"

require_built "$reeb" "$baselines"
require_unpacked "$tosca/cat0.off" "$shrec_cla"
rm -rf "$work"
mkdir -p "$work/tosca" "$work/shrec07-pose/meshes" "$work/shrec07-pose/correspondence" "$report"

# tosca_classes_file OUT: the PSB class file of the TOSCA meshes, a class per
# file name prefix (dog.off and dog0.off .. dog7.off are "dog").
tosca_classes_file() {
  local out=$1 name models total=0 blocks=""
  for name in $tosca_classes; do
    models=$(cd "$tosca" && ls | sed -n "s/^\($name[0-9]*\)\.off\$/\1/p" | sort -V)
    [ -n "$models" ] || { echo "$0: no $name*.off in $tosca" >&2; exit 1; }
    total=$((total + $(echo "$models" | wc -l)))
    blocks+=$'\n'"$name 0 $(echo "$models" | wc -l)"$'\n'"$models"$'\n'
  done
  printf 'PSB 1\n%d %d\n%s' "$(echo $tosca_classes | wc -w)" "$total" "$blocks" > "$out"
}

# shrec07_models CLASS: the model ids of CLASS in the SHREC07 class file.
shrec07_models() {
  awk -v c="$1" 'NF == 3 && $1 == c { n = $3; next } n > 0 && NF == 1 { print $1; n-- }' "$shrec_cla"
}

# shrec07_pose_collection: the posed meshes and their class file.
shrec07_pose_collection() {
  local dir=$work/shrec07-pose class id k total=0 blocks="" names
  for class in $articulated; do
    names=""
    for id in $(shrec07_models "$class"); do
      for k in $(seq 1 "$poses"); do
        echo "$id $k $((100 * id + k))" >> "$dir/jobs.txt"
        names+="${id}_pose$k"$'\n'
      done
    done
    [ -n "$names" ] || { echo "$0: no class $class in $shrec_cla" >&2; exit 1; }
    total=$((total + $(printf '%s' "$names" | wc -l)))
    blocks+=$'\n'"$class 0 $(printf '%s' "$names" | wc -l)"$'\n'"$names"
  done
  printf 'PSB 1\n%d %d\n%s' "$(echo $articulated | wc -w)" "$total" "$blocks" > "$dir/shrec07-pose.cla"
  # shellcheck disable=SC2016
  xargs -P "$threads" -L 1 bash -c \
    '"$0" perturb "$1/$3.off" -o "$2/meshes/$3_pose$4.off" --pose "$5" --correspondence "$2/correspondence/$3_pose$4.corr" > /dev/null' \
    "$reeb" "$shrec" "$dir" < "$dir/jobs.txt"
  echo "$total posed meshes in $dir/meshes"
}

# evaluate NAME MESH_DIR CLA: index, all-pairs distances, baselines, report.
evaluate() {
  local name=$1 meshes=$2 cla=$3 out=$work/$1
  all_distances "$name" "$meshes" "$cla" "$out"
  step "$name: evaluation report" \
    "$reeb" eval "$out/reebkit.matrix" --name reebkit --cla "$cla" -o "$report/$name" \
      --compare "$out/baseline-shape-dna.matrix:Shape-DNA" "$out/baseline-geodesic.matrix:geodesic-histogram" \
        "$out/baseline-d2.matrix:D2"
}

step "TOSCA class file" tosca_classes_file "$work/tosca/tosca.cla"
evaluate tosca "$tosca" "$work/tosca/tosca.cla"
step "SHREC07 articulated classes in $poses poses each" shrec07_pose_collection
evaluate shrec07-pose "$work/shrec07-pose/meshes" "$work/shrec07-pose/shrec07-pose.cla"
echo "reports: $report/tosca/report.md, $report/shrec07-pose/report.md"
