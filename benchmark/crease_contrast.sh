#!/usr/bin/env bash
# The crease contrast (user manual, "Crease contrast") on every bundled mesh,
# and every mesh of ../shared/data when it exists: one Markdown row per mesh,
# one cell per contrast with mean q / Hausdorff distance / crease deviation
# (along the crease lines the contrast and the open-crease rule keep) /
# deviation along every edge beyond the feature angle (the same with a
# contrast of 0 and no open-crease rule) / ridge vertices /
# fixed vertices (corner and boundary), the fidelity tolerance the default or
# the one given for the mesh.
#
#   benchmark/crease_contrast.sh TOOL "C1 C2 ..." [MESH_NAME=TOLERANCE ...]
#
# e.g. benchmark/crease_contrast.sh build/examples/Polygon_mesh_processing_ILSA/ilsa_smooth "0 5 8" cow=9.3e-3
# FLAGS, when set, are added to every run of the tool (e.g. FLAGS="--iterations 20
# --penalty-steps 2 --tangential 0": the iteration defaults before "Fewer, Longer Iterations").
set -uo pipefail
tool=${1:?usage: crease_contrast.sh TOOL "CONTRASTS" [MESH_NAME=TOLERANCE ...]}
contrasts=${2:?usage: crease_contrast.sh TOOL "CONTRASTS" [MESH_NAME=TOLERANCE ...]}
shift 2
declare -A tolerance seen
for spec in "$@"; do tolerance[${spec%%=*}]=${spec#*=}; done
here=$(cd "$(dirname "$0")/.." && pwd)
meshes=("$here"/data/meshes/*.off "$here"/data/meshes/*.ply)
if [ -d "$here/../shared/data" ]; then
  meshes+=("$here"/../shared/data/*.off "$here"/../shared/data/*.ply "$here"/../shared/data/*.stl)
fi
work=$(mktemp -d)
header="| mesh | tolerance |" rule="|---|---|"
for c in $contrasts; do header+=" contrast $c |"; rule+="---|"; done
echo "$header"; echo "$rule"
for mesh in "${meshes[@]}"; do
  [ -f "$mesh" ] || continue
  name=$(basename "${mesh%.*}")
  [ -n "${seen[$name]:-}" ] && continue
  seen[$name]=1
  tol=${tolerance[$name]:-default}
  # shellcheck disable=SC2206
  flags=(--threads 2 --report full ${FLAGS:-})
  [ "$tol" = default ] || flags+=(--fidelity-tolerance "$tol")
  row="| $name | $tol |"
  for c in $contrasts; do
    out=$("$tool" "$mesh" "$work/out.off" "${flags[@]}" --crease-contrast "$c" 2>&1) || { row+=" failed |"; continue; }
    q=$(sed -nE 's/^after : aspect ratio q min [0-9.]+ mean ([0-9.]+).*/\1/p' <<<"$out")
    h=$(sed -nE 's/.*Hausdorff ([0-9.e+-]+)[ ,].*/\1/p' <<<"$out")
    crease=$(sed -nE 's/.*crease deviation \([0-9]+ sharp edges, both ways\) max ([0-9.e+-]+).*/\1/p' <<<"$out")
    lines=$(sed -nE 's/^feature lines without the contrast: .* max ([0-9.e+-]+) mean.*/\1/p' <<<"$out")
    ridge=$(sed -nE 's/^vertices: .* ([0-9]+) ridge.*/\1/p' <<<"$out")
    fixed=$(sed -nE 's/^vertices: .* ([0-9]+) corner \([0-9]+ crease kinks\), ([0-9]+) boundary/\1+\2/p' <<<"$out")
    row+=" $q / $h / $crease / ${lines:-$crease} / $ridge / $((fixed)) |"
  done
  echo "$row"
done
rm -rf "$work"
