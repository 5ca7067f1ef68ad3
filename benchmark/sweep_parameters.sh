#!/usr/bin/env bash
# Parameter sweep behind the defaults of smooth_surface_mesh_ilsa (see the user
# manual). Runs the ilsa_smooth tool over a grid of parameter values on the
# given meshes and prints one line per run: mesh, parameters, q min, q mean,
# share of q < 0.3, minimum angle, flipped faces, Hausdorff distance and
# two-sided crease deviation (relative to the bounding-box diagonal), fixed
# vertices (of which crease kinks), time.
#
#   benchmark/sweep_parameters.sh BUILD_DIR [MESH ...]
#
# Grids can be overridden through the environment, e.g. ITERATIONS="10 20".
set -euo pipefail
build=${1:?usage: sweep_parameters.sh BUILD_DIR [MESH ...]}
shift
tool="$build/examples/Polygon_mesh_processing_ILSA/ilsa_smooth"
here=$(cd "$(dirname "$0")/.." && pwd)
meshes=("$@")
[ ${#meshes[@]} -gt 0 ] || meshes=("$here"/data/meshes/*.off "$here"/data/meshes/*.ply)

ITERATIONS=${ITERATIONS:-"default"} # number_of_iterations: "default": the library's (8; 20 before "Fewer, Longer Iterations")
STEPS=${STEPS:-"2"}
PSTEPS=${PSTEPS:-"default"} # ilsa_penalty_steps: "default": the library's (8); "steps": as many as STEPS (the paper)
TANGENT=${TANGENT:-"1"} # ilsa_tangential_displacement: 1 (the default) or 0 (the paper's)
GS=${GS:-"0"} # ilsa_penalty_gauss_seidel: 0 (the default: the paper's Jacobi sweeps) or 1
TSWEEPS=${TSWEEPS:-"1"} # ilsa_tangential_sweeps: 1 (the default) or 0 (normal components dropped once, after the sweeps)
RELAX1=${RELAX1:-"0.5"}
RELAX2=${RELAX2:-"0.8"}
MU=${MU:-"1"}
WL=${WL:-"1"}
WA=${WA:-"0.1"}
ANGLE=${ANGLE:-"20"}   # ilsa_feature_angle: between face normals
UNATTACHED=${UNATTACHED:-"default"} # ilsa_fix_unattached_candidates: "default": the library's (0); 1: the paper's rule
FLOOR=${FLOOR:-"default"} # "default": the library's (0.5, or the input's minimum q if higher)
TOL=${TOL:-"5e-4"}
REJECT=${REJECT:-"1"} # 1: drop moves that lower the star's mean quality (the default), 0: the paper's acceptance
KINK=${KINK:-"default"} # "default": the library's (the feature angle); 180: the paper's rule (no kinks)
GAIN=${GAIN:-"1e-4"} # stop once an iteration raises the mean q by less; 0: no such stop
REMAINING=${REMAINING:-"2e-3"} # stop once an iteration's gain times the iterations left is below; 0: no such stop
THREADS=${THREADS:-""} # threads of the tool; empty: its default (every core), 1: sequential
CONTRAST=${CONTRAST:-"default"} # ilsa_crease_contrast: "default": the library's; 0: the paper's rule
MINOPEN=${MINOPEN:-"default"} # ilsa_minimum_open_crease_edges: "default": the library's (20); 0: the paper's rule
RETRY=${RETRY:-"0.03"} # retry distance of moves dropped as worsening (mean edge lengths); 0: retried in the next iteration

printf '%-22s %7s %5s %6s %3s %3s %2s %6s %6s %6s %5s %5s %6s %7s %7s %7s %6s %3s %7s %6s %6s %6s | %7s %7s %7s %7s %4s %9s %9s %6s %6s %5s %7s\n' \
  mesh iter steps psteps tan tsw gs relax1 relax2 mu wl wa angle fix open floor tol rej kink gain remain retry q_min q_mean 'q<0.3%' min_ang flip hausdorff crease fixed kinks ran time_s
for mesh in "${meshes[@]}"; do
for it in $ITERATIONS; do for st in $STEPS; do for ps in $PSTEPS; do for tg in $TANGENT; do for tw in $TSWEEPS; do for gs in $GS; do for r1 in $RELAX1; do for r2 in $RELAX2; do
for mu in $MU; do for wl in $WL; do for wa in $WA; do for an in $ANGLE; do for fx in $UNATTACHED; do for fl in $FLOOR; do for tl in $TOL; do for rj in $REJECT; do for kk in $KINK; do for gn in $GAIN; do for rg in $REMAINING; do for rt in $RETRY; do for mo in $MINOPEN; do
  # shellcheck disable=SC2046
  out=$("$tool" "$mesh" $([ "$it" = default ] || echo --iterations "$it") --relaxation-steps "$st" \
        $([ "$ps" = default ] || echo --penalty-steps "$([ "$ps" = steps ] && echo "$st" || echo "$ps")") --tangential "$tg" --tangential-sweeps "$tw" --gauss-seidel "$gs" --relax1 "$r1" --relax2 "$r2" --mu "$mu" \
        --wl "$wl" --wa "$wa" --feature-angle "$an" $([ "$fx" = default ] || echo --fix-unattached "$fx") $([ "$mo" = default ] || echo --min-open-crease-edges "$mo") --fidelity-tolerance "$tl" --reject-worsening "$rj" --min-gain "$gn" --min-remaining-gain "$rg" --retry-distance "$rt" \
        $([ -z "$THREADS" ] || echo --threads "$THREADS") $([ "$CONTRAST" = default ] || echo --crease-contrast "$CONTRAST") \
        $([ "$fl" = default ] || echo --quality-floor "$fl") $([ "$kk" = default ] || echo --kink-angle "$kk"))
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
  printf '%-22s %7s %5s %6s %3s %3s %2s %6s %6s %6s %5s %5s %6s %7s %7s %7s %6s %3s %7s %6s %6s %6s | %7s %7s %7s %7s %4s %9s %9s %6s %6s %5s %7s\n' \
    "$(basename "$mesh")" "$it" "$st" "$ps" "$tg" "$tw" "$gs" "$r1" "$r2" "$mu" "$wl" "$wa" "$an" "$fx" "$mo" "$fl" "$tl" "$rj" "$kk" "$gn" "$rg" "$rt" "$qmin" "$qmean" "$below" "$angle" \
    "$flips" "$haus" "$crease" "$((fixed))" "$kinks" "$ran" "$secs"
done; done; done; done; done; done; done; done; done; done; done; done; done; done; done; done; done; done; done; done; done
done
