#!/usr/bin/env bash
# What limits the smoothing, per mesh (user manual, "What Limits the
# Smoothing"): ilsa_smooth on every bundled mesh, and every mesh of
# ../shared/data when it exists, with the defaults or with the fidelity
# tolerance given for the mesh; prints one Markdown row per mesh: the vertices
# fixed by the classification (corner and boundary) and held to creases
# (ridge), the iterations run, the mean q, and the moves the safety check
# dropped and shortened, by test, summed over the iterations.
#
#   benchmark/what_limits.sh TOOL [MESH_NAME=TOLERANCE ...] [-- EXTRA TOOL FLAGS]
#
# e.g. benchmark/what_limits.sh build/examples/Polygon_mesh_processing_ILSA/ilsa_smooth horse=5.8e-3
# (MESH_NAME: the file name without its extension; the other meshes keep the default tolerance).
set -uo pipefail
tool=${1:?usage: what_limits.sh TOOL [MESH_NAME=TOLERANCE ...] [-- FLAGS]}
shift
declare -A tolerance
extra=()
while [ $# -gt 0 ]; do
  if [ "$1" = "--" ]; then shift; extra=("$@"); break; fi
  tolerance[${1%%=*}]=${1#*=}
  shift
done
here=$(cd "$(dirname "$0")/.." && pwd)
meshes=("$here"/data/meshes/*.off "$here"/data/meshes/*.ply)
if [ -d "$here/../shared/data" ]; then
  meshes+=("$here"/../shared/data/*.off "$here"/../shared/data/*.ply "$here"/../shared/data/*.stl)
fi
work=$(mktemp -d)
declare -A seen # a mesh of ../shared/data that is also bundled is run once
echo "| mesh | tolerance | fixed / ridge / all vertices | iterations | mean q | moves accepted | dropped: flip, floor, worsening (+ pre-test), fidelity, crease | shortened: flip, floor, fidelity, crease |"
echo "|---|---|---|---|---|---|---|---|"
for mesh in "${meshes[@]}"; do
  [ -f "$mesh" ] || continue
  name=$(basename "${mesh%.*}")
  [ -n "${seen[$name]:-}" ] && continue
  seen[$name]=1
  flags=("${extra[@]}")
  tol=default
  if [ -n "${tolerance[$name]:-}" ]; then tol=${tolerance[$name]}; flags+=(--fidelity-tolerance "$tol"); fi
  out=$("$tool" "$mesh" "$work/out.off" --threads 2 --report summary "${flags[@]}" 2>&1) || { echo "| $name | failed |"; continue; }
  python3 - "$name" "$tol" <<PY "$out"
import re, sys
name, tol, out = sys.argv[1], sys.argv[2], sys.argv[3]
def num(pattern):
    m = re.search(pattern, out)
    return m.group(1) if m else "?"
smooth, ridge, corner, boundary = (int(num(r"(\d+) " + w)) for w in ("smooth", "ridge", "corner", "boundary"))
total = smooth + ridge + corner + boundary
mean_q = num(r"after : aspect ratio q min [0-9.]+ mean ([0-9.]+)")
iterations = num(r"for (\d+) iterations")
accepted = num(r"moves: (\d+) accepted")
pre = num(r"\((\d+) of them before projection\)")
d = re.search(r"dropped (\d+) flip or collapse, (\d+) quality floor, (\d+) worsening, (\d+) fidelity, (\d+) crease", out)
s = re.search(r"shortened (\d+) flip or collapse, (\d+) quality floor, (\d+) worsening, (\d+) fidelity, (\d+) crease", out)
print(f"| {name} | {tol} | {corner + boundary} / {ridge} / {total} ({100 * (corner + boundary + ridge) / total:.1f} %) | "
      f"{iterations} | {mean_q} | {accepted} | {d[1]}, {d[2]}, {d[3]} (+ {pre}), {d[4]}, {d[5]} | "
      f"{s[1]}, {s[2]}, {s[4]}, {s[5]} |")
PY
done
rm -rf "$work"
