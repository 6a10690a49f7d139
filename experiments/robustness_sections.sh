# What experiments/robustness.sh and experiments/robustness_probe.sh share;
# sourced, never run. Expects data (BUILD_DIR/data), shrec and cla (the
# SHREC07 folder and class file), per_class, robustness (the program) and a
# function `step NAME COMMAND...`.
# shellcheck shell=bash disable=SC2154  # the variables above come from the caller

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
