#!/usr/bin/env bash
# One-parameter-at-a-time study behind the defaults in the user manual: each
# block varies one parameter around the defaults on the given meshes.
#
#   benchmark/sweep_defaults.sh BUILD_DIR [MESH ...]
set -euo pipefail
build=${1:?usage: sweep_defaults.sh BUILD_DIR [MESH ...]}
shift
here=$(cd "$(dirname "$0")" && pwd)
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=("$here"/../data/meshes/horse.ply "$here"/../data/meshes/fandisk.off "$here"/../data/meshes/elephant.off)
sweep() { echo "## $1"; shift; env "$@" "$here/sweep_parameters.sh" "$build" "${meshes[@]}"; echo; }
sweep "number_of_iterations" ITERATIONS="5 8 10 20"
sweep "number_of_relaxation_steps" STEPS="1 2 3 6"
sweep "ilsa_penalty_steps" PSTEPS="2 4 6 8"
sweep "ilsa_tangential_displacement" TANGENT="0 1"
sweep "ilsa_tangential_sweeps" TSWEEPS="0 1"
sweep "ilsa_penalty_gauss_seidel" GS="0 1"
sweep "ilsa_relaxation (relax1)" RELAX1="0.2 0.5 0.8"
sweep "ilsa_penalty_relaxation (relax2)" RELAX2="0.2 0.5 0.8 1"
sweep "ilsa_penalty_mu" MU="0.1 1 10"
sweep "ilsa_length_weight" WL="0 1 2"
sweep "ilsa_area_weight" WA="0 0.1 1"
sweep "ilsa_quality_floor" FLOOR="0 0.3 0.5 0.7 default"
sweep "ilsa_fidelity_tolerance" TOL="1e-4 2e-4 3e-4 5e-4 inf"
sweep "ilsa_reject_worsening_moves" REJECT="0 1"
sweep "ilsa_crease_kink_angle" KINK="default 45 180"
sweep "ilsa_retry_distance" RETRY="0 0.01 0.03 0.05 0.1"
