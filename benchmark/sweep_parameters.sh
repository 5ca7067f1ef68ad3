#!/usr/bin/env bash
# What each named parameter of smooth_surface_mesh_ilsa does to the bundled
# meshes (the user manual's parameter tables). Runs the ilsa_smooth tool over a
# grid of values on the given meshes and prints one line per run: mesh,
# parameters, q min, q mean, share of q < 0.3, minimum angle, flipped faces,
# CGAL's certified Hausdorff distance and the two-sided crease deviation
# (relative to the bounding-box diagonal), fixed vertices (of which crease
# kinks), iterations run, time.
#
#   benchmark/sweep_parameters.sh BUILD_DIR [MESH ...]
#
# Grids are set through the environment, e.g. TOL="3e-4 5e-4 1e-3" or PAPER="0 1";
# "default" leaves a parameter to the library.
set -euo pipefail
build=${1:?usage: sweep_parameters.sh BUILD_DIR [MESH ...]}
shift
tool="$build/examples/Polygon_mesh_processing_ILSA/ilsa_smooth"
here=$(cd "$(dirname "$0")/.." && pwd)
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=("$here"/data/meshes/*.off "$here"/data/meshes/*.ply)

ITERATIONS=${ITERATIONS:-"default"} # number_of_iterations (8)
GAIN=${GAIN:-"default"}             # ilsa_minimum_quality_gain (1e-4); 0: every iteration runs
ANGLE=${ANGLE:-"default"}           # ilsa_feature_angle (20, between face normals)
FLOOR=${FLOOR:-"default"}           # ilsa_quality_floor (0.5, or the input's minimum q if higher)
TOL=${TOL:-"default"}               # ilsa_fidelity_tolerance (5e-4 of the diagonal)
PAPER=${PAPER:-"0"}                 # ilsa_paper_variant: 0 or 1
THREADS=${THREADS:-""}              # threads of the tool; empty: its default (every core), 1: sequential

flag() { [ "$2" = default ] || echo "$1" "$2"; }
printf '%-22s %7s %6s %6s %7s %6s %5s | %7s %7s %7s %7s %4s %9s %9s %6s %6s %4s %7s\n' \
  mesh iter gain angle floor tol paper q_min q_mean 'q<0.3%' min_ang flip hausdorff crease fixed kinks ran time_s
for mesh in "${meshes[@]}"; do
for it in $ITERATIONS; do for gn in $GAIN; do for an in $ANGLE; do for fl in $FLOOR; do for tl in $TOL; do for pp in $PAPER; do
  # shellcheck disable=SC2046
  out=$("$tool" "$mesh" --report full --no-progress $(flag --iterations "$it") $(flag --min-gain "$gn") \
        $(flag --feature-angle "$an") $(flag --quality-floor "$fl") $(flag --fidelity-tolerance "$tl") \
        $([ "$pp" = 1 ] && echo --paper) $([ -z "$THREADS" ] || echo --threads "$THREADS"))
  after=$(grep '^after' <<<"$out")
  qmin=$(sed -E 's/.*q min ([0-9.]+).*/\1/' <<<"$after")
  qmean=$(sed -E 's/.*mean ([0-9.]+).*/\1/' <<<"$after")
  below=$(sed -E 's/.*q<0.3 ([0-9.]+) %.*/\1/' <<<"$after")
  angle=$(sed -E 's/.*min angle ([0-9.]+) deg.*/\1/' <<<"$after")
  secs=$(grep '^time' <<<"$out" | sed -E 's/time: ([0-9.]+) s.*/\1/')
  ran=$(grep '^time' <<<"$out" | sed -E 's/.* for ([0-9]+) iterations.*/\1/')
  flips=$(grep '^fidelity' <<<"$out" | sed -E 's/fidelity: ([0-9]+) flipped.*/\1/')
  haus=$(grep '^fidelity' <<<"$out" | sed -E 's/.*Hausdorff ([0-9.e+-]+)[ ,].*/\1/')
  crease=$(grep '^fidelity' <<<"$out" | sed -E 's/.*both ways\) max ([0-9.e+-]+) .*/\1/')
  fixed=$(grep '^vertices' <<<"$out" | sed -E 's/.* ([0-9]+) corner \(([0-9]+) crease kinks\), ([0-9]+) boundary/\1+\3/')
  kinks=$(grep '^vertices' <<<"$out" | sed -E 's/.*\(([0-9]+) crease kinks\).*/\1/')
  printf '%-22s %7s %6s %6s %7s %6s %5s | %7s %7s %7s %7s %4s %9s %9s %6s %6s %4s %7s\n' \
    "$(basename "$mesh")" "$it" "$gn" "$an" "$fl" "$tl" "$pp" "$qmin" "$qmean" "$below" "$angle" \
    "$flips" "$haus" "$crease" "$((fixed))" "$kinks" "$ran" "$secs"
done; done; done; done; done; done
done
