#!/usr/bin/env bash
# Graph stability under pose and resampling, a benchmark to choose the
# graph's defaults on (issue 22). The robustness suite's TOSCA poses
# (experiments/robustness.sh) hold 49 pose pairs on which every setting of
# the feature points keeps 95-98 % of the node counts; this one is harder:
# every model of SHREC 2007 Watertight's articulated classes (Human, Ant,
# Octopus, Teddy, Hand, Armadillo, Fourleg; 140 models) in POSES (default 4)
# random poses, `reeb perturb --pose 100 x ID + K --pose-leaves LEAVES
# --pose-degrees DEGREES` (K = 1..POSES; the four largest limbs, LEAVES
# default 4, of the pinned planning analysis of experiments/common.sh
# turned by DEGREES, default 30:60; with pose_retrieval.sh's two limbs by
# 20-35 degrees, 97.5 % of eq. (6)'s graphs keep their model's shape), each
# pose remeshed on its own to N vertices, N drawn in [REMESH_MIN, REMESH_MAX]
# (default 4000, 8000) from the CRC of its name. One class per model: `reeb
# info` then prints the share of graphs with their model's most common
# feature points / nodes / cycles (evaluation/graph_stability.h), the same
# question as the held-out pose collections of pose_retrieval.sh ask, on
# other shapes.
#
#   experiments/pose_stability.sh BUILD_DIR [NAME [ANALYSIS OPTION...]]
#   experiments/pose_stability.sh build confirmed --feature-rule confirmed
#
# The meshes (derived from academic-use data: never committed) are made
# once (again when POSES, LEAVES, DEGREES or the REMESH range change) into
# BUILD_DIR/pose_stability/meshes, with the class file
# models.cla; each run indexes them with the analysis options given (reeb
# index's, e.g. --epsilon 0.18) into BUILD_DIR/pose_stability/NAME.h5
# (default NAME: default) and prints `reeb info`'s stability per model
# class to NAME.txt, then the share per SHREC07 class; the terminal gets the
# total and that line. THREADS (default 2).
set -euo pipefail
# shellcheck source=experiments/common.sh
source "$(dirname "$0")/common.sh"

if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [NAME [ANALYSIS OPTION...]]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
name=${2:-default}
shift $(($# < 2 ? $# : 2))
threads=${THREADS:-2}
remesh_min=${REMESH_MIN:-4000}
remesh_max=${REMESH_MAX:-8000}
poses=${POSES:-4}
leaves=${LEAVES:-4}
degrees=${DEGREES:-30:60}
reeb=$build/tools/reeb
shrec=$build/data/shrec07_watertight
shrec_cla=$shrec/shrec07_watertight.cla
work=$build/pose_stability
require_built "$reeb"
require_unpacked "$shrec_cla"

made="poses $poses leaves $leaves degrees $degrees remesh $remesh_min-$remesh_max"
if [ "$(cat "$work/complete" 2> /dev/null)" != "$made" ]; then
  rm -rf "$work"
  mkdir -p "$work/meshes" "$work/correspondence"
  models=$(for class in $articulated; do shrec07_models "$class"; done)
  { printf 'PSB 1\n%d %d\n' "$(echo "$models" | wc -l)" "$(($(echo "$models" | wc -l) * poses))"
    for id in $models; do
      printf '\nm%s 0 %d\n' "$id" "$poses"
      for k in $(seq 1 "$poses"); do echo "${id}_pose$k"; done
    done; } > "$work/models.cla"
  for id in $models; do
    for k in $(seq 1 "$poses"); do
      crc=$(printf '%s' "${id}_pose$k" | cksum | cut -d ' ' -f 1)
      echo "$id ${id}_pose$k $((100 * id + k)) $((remesh_min + crc % (remesh_max - remesh_min + 1))) $crc"
    done
  done > "$work/jobs.txt"
  echo "making $(wc -l < "$work/jobs.txt") posed and remeshed meshes in $work/meshes"
  # shellcheck disable=SC2016,SC2086
  SHREC=$shrec WORK=$work LEAVES=$leaves DEGREES=$degrees PLANNING_FLAGS=$planning_flags xargs -P "$threads" -L 1 bash -c \
    '"$0" perturb "$SHREC/$1.off" -o "$WORK/meshes/$2.off" --pose "$3" --remesh "$4" --seed "$5" \
       --pose-leaves "$LEAVES" --pose-degrees "$DEGREES" --correspondence "$WORK/correspondence/$2.corr" \
       $PLANNING_FLAGS > /dev/null' "$reeb" < "$work/jobs.txt"
  echo "$made" > "$work/complete"
fi

"$reeb" index "$work/meshes" -o "$work/$name.h5" --classes "$work/models.cla" --threads "$threads" "$@" > /dev/null
"$reeb" info "$work/$name.h5" > "$work/$name.txt"
# The same share per SHREC07 class, from reeb info's line per model
# ("  m<id>  <graphs>  <kept> with ..."), added to NAME.txt.
per_class=$(for class in $articulated; do
  printf '%s %s\n' "$class" "$(shrec07_models "$class" | tr '\n' ' ')"
done | awk -v info="$work/$name.txt" '
  BEGIN { while ((getline line < info) > 0) if (split(line, f, /[ \t]+/) >= 4 && f[2] ~ /^m[0-9]+$/) { graphs[substr(f[2], 2)] = f[3]; kept[substr(f[2], 2)] = f[4] } }
  { g = 0; k = 0; for (i = 2; i <= NF; ++i) { g += graphs[$i]; k += kept[$i] } out = out sep $1 " " k " / " g; sep = ", " }
  END { print "per class: " out }')
tail -n 1 "$work/$name.txt"
echo "$per_class" | tee -a "$work/$name.txt"
