#!/usr/bin/env bash
# Compile time a user pays: a minimal program calling smooth_surface_mesh_ilsa()
# on an Epick Surface_mesh against the same program calling CGAL's
# tangential_relaxation(), same compiler and flags, alternating, median of N.
#
#   benchmark/compile_time.sh [N] [extra compiler flags...]
#
# Uses Debian's CGAL (/usr/include) unless CGAL_INCLUDE names another
# include directory (e.g. ../shared/cgal-6.1.1/include). Flags: -O2 -std=c++17.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-3}
shift || true
cgal=${CGAL_INCLUDE:-/usr/include}
cxx=${CXX:-g++}
interface="$cgal/CGAL/STL_Extension/internal/parameters_interface.h"
common=(-O2 -std=c++17 -frounding-math -DCGAL_EIGEN3_ENABLED -isystem /usr/include/eigen3 "$@")
if [ -n "${CGAL_INCLUDE:-}" ]; then common+=(-isystem "$cgal"); fi
ilsa=(-I"$here/include" "-DCGAL_ILSA_CGAL_PARAMETERS_INTERFACE=\"$interface\"")
out=$(mktemp -d)
seconds=0
time_of() { # sets `seconds` to the time one compilation takes; stops the script if it fails
  local start end
  start=$(date +%s.%N)
  "$cxx" "$@" -c -o "$out/probe.o"
  end=$(date +%s.%N)
  seconds=$(echo "$end - $start" | bc)
}
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
ilsa_times=() peer_times=()
for ((i = 0; i < runs; ++i)); do
  time_of "${common[@]}" "${ilsa[@]}" "$here/benchmark/compile_time/ilsa_call.cpp"
  ilsa_times+=("$seconds")
  time_of "${common[@]}" "$here/benchmark/compile_time/tangential_call.cpp"
  peer_times+=("$seconds")
done
ilsa_median=$(printf '%s\n' "${ilsa_times[@]}" | median)
peer_median=$(printf '%s\n' "${peer_times[@]}" | median)
echo "smooth_surface_mesh_ilsa: ${ilsa_times[*]} s (median $ilsa_median)"
echo "tangential_relaxation:    ${peer_times[*]} s (median $peer_median)"
echo "ratio: $(echo "scale=2; $ilsa_median / $peer_median" | bc)"
rm -rf "$out"
