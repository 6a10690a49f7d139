# What experiments/robustness.sh and experiments/robustness_probe.sh share;
# sourced, never run. Expects build (the build folder), per_class and, when
# sampling_and_poses runs, a function `step NAME COMMAND...`; sets data,
# shrec, cla (the SHREC07 folder and class file) and robustness (the
# program), and exits naming what is missing.
# shellcheck shell=bash disable=SC2154  # build and per_class come from the caller

data=$build/data
shrec=$data/shrec07_watertight
cla=$shrec/shrec07_watertight.cla
robustness=$build/experiments/robustness
[ -x "$robustness" ] || { echo "$0: $robustness is missing: build the target robustness" >&2; exit 1; }
for d in "$cla" "$data/tosca_dev" "$data/cgal_meshes"; do
  [ -e "$d" ] || { echo "$0: $d is missing: run ctest --test-dir $build -R unpack_datasets" >&2; exit 1; }
done

# Closed CGAL meshes with a shape (500-20,000 vertices, one component), and
# one pose per TOSCA class.
cgal=()
for m in anchor_dense bear bull cactus camel couplingdown cow dino elephant elk femur hand homer knot1 man \
         rotor_small triceratops turbine; do
  cgal+=("$data/cgal_meshes/$m.off")
done
tosca=()
for m in cat0 centaur0 dog0 horse0 michael0; do tosca+=("$data/tosca_dev/$m.off"); done

# sampling_and_poses LABEL FOLDER [--option NAME=VALUE]...: sections 2 and 3
# of the suite, what its defaults are chosen on: the sampling variants of
# SHREC07 (per_class meshes per class), of the CGAL meshes and of one pose
# per TOSCA class, then the TOSCA poses, into FOLDER, under the options.
sampling_and_poses() {
  local label=$1 folder=$2
  shift 2
  local run=("$robustness" "$@")
  mkdir -p "$folder"
  step "2: $label: sampling, SHREC07 ($per_class per class)" "${run[@]}" shrec-sample "$folder" "$shrec" "$cla" "$per_class"
  step "2: $label: sampling, closed CGAL meshes" "${run[@]}" sampling "$folder" cgal "${cgal[@]}"
  step "2: $label: sampling, TOSCA (one pose per class)" "${run[@]}" sampling "$folder" tosca "${tosca[@]}"
  step "3: $label: TOSCA poses" "${run[@]}" tosca "$folder" "$data/tosca_dev"
}
