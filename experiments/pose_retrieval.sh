#!/usr/bin/env bash
# Retrieval under pose (issues 12 and 21): collections of articulated shapes
# in several poses, each evaluated by `reeb eval` with reebkit's attributed
# Reeb graph matching next to three baselines (experiments/baselines: D2, a
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
#    1.000), which NN then does not measure;
#  - tosca-remeshed: the 54 TOSCA meshes and classes, every pose remeshed on
#    its own (`reeb perturb --remesh N --seed S`), so that no two poses share
#    a triangulation (within a TOSCA class they all share one);
#  - body-shape: synthetic people made from TOSCA's michael by
#    experiments/body_shapes (deform/proportions.h): PEOPLE (default 10)
#    people, each with 2-4 of michael's parts (arms, legs, head with the top
#    of the chest, torso) longer or thicker by factors drawn in FACTORS
#    (default 1.05:1.15, i.e. 5-15 %), each person in POSES_PER_PERSON
#    (default 10) of the 20 michael poses, drawn per person; class = person.
#    Every mesh is then remeshed on its own like tosca-remeshed;
#  - body-shape-wide: the same with other people (seed 7) whose parts differ
#    by factors in WIDE_FACTORS (default 1.15:1.35, i.e. 15-35 %): people
#    who differ as much as scanned people do, whose whole-surface spectra
#    (Shape-DNA) tell them apart nearly always, where body-shape's barely
#    differ;
#  - animal-shape: the same made from TOSCA's cat (seed 11, parts in
#    WIDE_FACTORS: tail, head with neck, four legs, torso), each cat in
#    POSES_PER_PERSON of the 11 cat poses: near classes of a four-legged
#    animal, which no collection above has;
#  - dog-shape, horse-shape: the same from TOSCA's dog (seed 13) and horse
#    (seed 17), each animal in all 8 poses of its shape.
# Remeshing: N is drawn uniformly in [REMESH_MIN, REMESH_MAX] (default 8000,
# 15000: the range of an independent collection of scanned bodies) and S is
# the CRC (cksum) of the mesh name, N = REMESH_MIN + S mod the range width:
# the same names give the same meshes on every run.
#
#   experiments/pose_retrieval.sh BUILD_DIR [REPORT_DIR]
#   COLLECTIONS="tosca-remeshed body-shape body-shape-wide" experiments/pose_retrieval.sh build
#
# BUILD_DIR: a build with the targets reeb and baselines (and body_shapes for
# body-shape), and the datasets unpacked (ctest -R unpack_datasets).
# COLLECTIONS (default all five) names the collections to build and
# evaluate; the others' files are left as they are. REPORT_DIR (default
# results/pose/): one folder per collection, each with report.md (ending
# with the graph stability of `reeb info`: per class, the graphs with its most
# common feature points / nodes / cycles), pr.csv, pr.png, pr.svg (the
# body-shape ones also people.txt: each person's changes and poses). The meshes, class files, collection files and distance
# matrices are derived from academic-use data: they stay in
# BUILD_DIR/pose_retrieval/NAME/ and are never committed (the remeshed and
# body-shape meshes in meshes/, the class file NAME.cla). THREADS (default 2)
# sets the threads of every step. Every method is also evaluated after local
# scaling with its SCALING_K-th (default 10) nearest model (reeb eval
# --local-scaling), as in shrec07_retrieval.sh. REUSE=1 keeps the meshes,
# class file and baseline matrices of each collection whose last run
# completed and redoes only reebkit's index, distances and report (about
# 25 s a collection): for re-runs while reebkit's settings change (the
# generation settings POSES, PEOPLE, POSES_PER_PERSON, FACTORS,
# WIDE_FACTORS, REMESH_* then have no effect).
# Time on 2 threads of a shared machine: tosca-remeshed about 5 min (86 s
# remeshing), body-shape and body-shape-wide about 3 min each (1 min making
# and remeshing the people), animal-shape about 1.5 min, the Shape-DNA
# baseline most of the rest
# (docs/results.md).
set -euo pipefail
# shellcheck source=experiments/common.sh
source "$(dirname "$0")/common.sh"

experiment_arguments results/pose "$@"
poses=${POSES:-1}
collections=${COLLECTIONS:-tosca shrec07-pose tosca-remeshed body-shape body-shape-wide animal-shape dog-shape horse-shape}
remesh_min=${REMESH_MIN:-8000}
remesh_max=${REMESH_MAX:-15000}
people=${PEOPLE:-10}
poses_per_person=${POSES_PER_PERSON:-10}
factors=${FACTORS:-1.05:1.15}
wide_factors=${WIDE_FACTORS:-1.15:1.35}
tosca=$build/data/tosca_dev
shrec=$build/data/shrec07_watertight
shrec_cla=$shrec/shrec07_watertight.cla
work=$build/pose_retrieval
body_shapes=$build/experiments/body_shapes
tosca_classes="cat centaur dog horse michael"

for name in $collections; do
  case $name in
    tosca | shrec07-pose | tosca-remeshed) ;;
    body-shape | body-shape-wide | animal-shape | dog-shape | horse-shape) require_built "$body_shapes" ;;
    *) echo "$0: unknown collection '$name' in COLLECTIONS (tosca, shrec07-pose, tosca-remeshed, body-shape, body-shape-wide, animal-shape, dog-shape, horse-shape)" >&2
       exit 2 ;;
  esac
done
require_built "$reeb" "$baselines"
require_unpacked "$tosca/cat0.off" "$shrec_cla"
# A collection is reused (REUSE=1) when its last run completed.
reused() { [ "${REUSE:-0}" = 1 ] && [ -e "$work/$1/complete" ]; }
for name in $collections; do
  if reused "$name"; then
    rm -f "$work/$name/$name.h5" "$work/$name/reebkit.matrix"
  else
    rm -rf "${work:?}/$name"
    mkdir -p "$work/$name"
  fi
done
mkdir -p "$report"

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

# shrec07_pose_collection: the posed meshes and their class file.
shrec07_pose_collection() {
  local dir=$work/shrec07-pose class id k total=0 blocks="" names
  mkdir -p "$dir/meshes" "$dir/correspondence"
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
  # The leaves turned are those of the planning graph (above).
  # shellcheck disable=SC2016,SC2086
  PLANNING_FLAGS=$planning_flags xargs -P "$threads" -L 1 bash -c \
    '"$0" perturb "$1/$3.off" -o "$2/meshes/$3_pose$4.off" --pose "$5" --correspondence "$2/correspondence/$3_pose$4.corr" \
       $PLANNING_FLAGS > /dev/null' \
    "$reeb" "$shrec" "$dir" < "$dir/jobs.txt"
  echo "$total posed meshes in $dir/meshes"
}

# remesh_each DIR SOURCE...: every SOURCE mesh remeshed on its own into
# DIR/meshes/NAME.off (NAME: the file name without its extension) by reeb
# perturb --remesh N --seed S, S = cksum of NAME, N = REMESH_MIN + S mod
# (REMESH_MAX - REMESH_MIN + 1); the draws go to DIR/remesh.txt (source,
# name, N, S) and the correspondences to DIR/correspondence/.
remesh_each() {
  local dir=$1 source name crc
  shift
  mkdir -p "$dir/meshes" "$dir/correspondence"
  for source; do
    name=$(basename "${source%.*}")
    crc=$(printf '%s' "$name" | cksum | cut -d ' ' -f 1)
    echo "$source $name $((remesh_min + crc % (remesh_max - remesh_min + 1))) $crc"
  done > "$dir/remesh.txt"
  # shellcheck disable=SC2016
  xargs -P "$threads" -L 1 bash -c \
    '"$0" perturb "$2" -o "$1/meshes/$3.off" --remesh "$4" --seed "$5" --correspondence "$1/correspondence/$3.corr" > /dev/null' \
    "$reeb" "$dir" < "$dir/remesh.txt"
  echo "$# meshes remeshed to $remesh_min-$remesh_max vertices in $dir/meshes"
}

# body_shape_collection NAME FACTORS SEED SHAPE POSES: the people made from
# the TOSCA shape SHAPE, each in POSES poses (full resolution, in people/,
# with people.txt saying what each person's proportions are), remeshed.
body_shape_collection() {
  local name=$1 dir=$work/$1
  "$body_shapes" "${planning_options[@]}" "$tosca" "$dir/people" --shape "$4" --people "$people" --poses "$5" \
    --factors "$2" --seed "$3" --cla "$dir/$name.cla"
  remesh_each "$dir" "$dir"/people/*.ply
  rm "$dir"/people/*.ply
}

# evaluate NAME MESH_DIR CLA: index, all-pairs distances, baselines (kept
# when reused), report; then marks the collection complete.
evaluate() {
  local name=$1 meshes=$2 cla=$3 out=$work/$1 keep=0
  if reused "$name"; then keep=1; fi
  all_distances "$name" "$meshes" "$cla" "$out" "$keep"
  step "$name: evaluation report" \
    "$reeb" eval "$out/reebkit.matrix" --name reebkit --cla "$cla" -o "$report/$name" \
      --compare "$out/baseline-shape-dna.matrix:Shape-DNA" "$out/baseline-geodesic.matrix:geodesic-histogram" \
        "$out/baseline-d2.matrix:D2" \
      --local-scaling "${SCALING_K:-10}"
  graph_stability_section "$out/$name.h5" >> "$report/$name/report.md"
  touch "$out/complete"
}

# graph_stability_section COLLECTION: a report section with the class lines
# of `reeb info`: per class, how many of its graphs have its most common
# (feature points, nodes, cycles), i.e. a graph that pose and sampling left
# unchanged (issue 22), measured without correspondences.
graph_stability_section() {
  echo
  echo "## Graph stability"
  echo
  echo "From \`reeb info\`: per class, its meshes and how many of their Reeb graphs have the class's"
  echo "most common feature points / nodes / independent cycles."
  echo
  echo '```'
  "$reeb" info "$1" | sed -n '/^[0-9]* classes/,$p' | grep -v '^failed: '
  echo '```'
}

for name in $collections; do
  if reused "$name"; then
    echo "== $name: meshes, class file and baselines kept from the last run (REUSE=1)"
  else
    case $name in
      shrec07-pose) step "SHREC07 articulated classes in $poses poses each" shrec07_pose_collection ;;
      tosca-remeshed)
        tosca_classes_file "$work/tosca-remeshed/tosca-remeshed.cla"
        step "TOSCA, every pose remeshed" remesh_each "$work/tosca-remeshed" "$tosca"/*.off ;;
      body-shape)
        step "$people people made from michael, $poses_per_person poses each, remeshed" \
          body_shape_collection body-shape "$factors" 1 michael "$poses_per_person" ;;
      body-shape-wide)
        step "$people other people made from michael, parts $wide_factors, $poses_per_person poses each, remeshed" \
          body_shape_collection body-shape-wide "$wide_factors" 7 michael "$poses_per_person" ;;
      animal-shape)
        step "$people cats of other proportions, parts $wide_factors, $poses_per_person poses each, remeshed" \
          body_shape_collection animal-shape "$wide_factors" 11 cat "$poses_per_person" ;;
      dog-shape)
        step "$people dogs of other proportions, parts $wide_factors, 8 poses each, remeshed" \
          body_shape_collection dog-shape "$wide_factors" 13 dog 8 ;;
      horse-shape)
        step "$people horses of other proportions, parts $wide_factors, 8 poses each, remeshed" \
          body_shape_collection horse-shape "$wide_factors" 17 horse 8 ;;
    esac
  fi
  case $name in
    tosca)
      step "TOSCA class file" tosca_classes_file "$work/tosca/tosca.cla"
      evaluate tosca "$tosca" "$work/tosca/tosca.cla" ;;
    shrec07-pose)
      evaluate shrec07-pose "$work/shrec07-pose/meshes" "$work/shrec07-pose/shrec07-pose.cla" ;;
    tosca-remeshed)
      evaluate tosca-remeshed "$work/tosca-remeshed/meshes" "$work/tosca-remeshed/tosca-remeshed.cla" ;;
    body-shape | body-shape-wide | animal-shape | dog-shape | horse-shape)
      evaluate "$name" "$work/$name/meshes" "$work/$name/$name.cla"
      cp "$work/$name/people/people.txt" "$report/$name/people.txt" ;;
  esac
  echo "report: $report/$name/report.md"
done
