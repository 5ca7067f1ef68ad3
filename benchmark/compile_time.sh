#!/usr/bin/env bash
# Compile time a user pays: a minimal program calling smooth_surface_mesh_ilsa()
# on an Epick Surface_mesh against the same program calling CGAL's
# tangential_relaxation(), same compiler and flags, taking turns, median of N.
# The package's program is compiled twice: header-only (the default), and with
# CGAL_ILSA_COMPILED_CORE, where the core is compiled once for the whole
# project, from src/ilsa_core.cpp (user manual, "Compiling the Core Once"),
# which is timed too.
#
#   benchmark/compile_time.sh [N] [extra compiler flags...]
#
# Uses Debian's CGAL (/usr/include) unless CGAL_INCLUDE names another
# include directory (e.g. ../shared/cgal-6.1.1/include). Flags: -O2 -std=c++17.
# BASELINE_INCLUDE, when set, names the include directory of another version
# of the package (e.g. of a `git worktree` of an earlier commit): each run then
# also compiles the header-only program with it, in turn with the others, so
# that a change's effect is measured in one run.
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
ilsa_times=() core_user_times=() core_times=() peer_times=() baseline_times=()
baseline=${BASELINE_INCLUDE:-}
for ((i = 0; i < runs; ++i)); do
  if [ -n "$baseline" ]; then
    time_of "${common[@]}" -I"$baseline" "-DCGAL_ILSA_CGAL_PARAMETERS_INTERFACE=\"$interface\"" \
      "$here/benchmark/compile_time/ilsa_call.cpp"
    baseline_times+=("$seconds")
  fi
  time_of "${common[@]}" "${ilsa[@]}" "$here/benchmark/compile_time/ilsa_call.cpp"
  ilsa_times+=("$seconds")
  time_of "${common[@]}" "${ilsa[@]}" -DCGAL_ILSA_COMPILED_CORE "$here/benchmark/compile_time/ilsa_call.cpp"
  core_user_times+=("$seconds")
  time_of "${common[@]}" "$here/benchmark/compile_time/tangential_call.cpp"
  peer_times+=("$seconds")
  time_of "${common[@]}" "${ilsa[@]}" -DCGAL_ILSA_COMPILED_CORE "$here/src/ilsa_core.cpp"
  core_times+=("$seconds")
done
median_of() { printf '%s\n' "$@" | median; }
ilsa_median=$(median_of "${ilsa_times[@]}")
core_user_median=$(median_of "${core_user_times[@]}")
peer_median=$(median_of "${peer_times[@]}")
core_median=$(median_of "${core_times[@]}")
echo "smooth_surface_mesh_ilsa, header-only:        ${ilsa_times[*]} s (median $ilsa_median)"
echo "smooth_surface_mesh_ilsa, core compiled once: ${core_user_times[*]} s (median $core_user_median)"
echo "tangential_relaxation:                        ${peer_times[*]} s (median $peer_median)"
echo "src/ilsa_core.cpp, once per project:          ${core_times[*]} s (median $core_median)"
if [ -n "$baseline" ]; then
  baseline_median=$(median_of "${baseline_times[@]}")
  echo "header-only with $baseline: ${baseline_times[*]} s (median $baseline_median)"
  echo "ratio, header-only with the baseline: $(echo "scale=2; $baseline_median / $peer_median" | bc)"
fi
echo "ratio, header-only:        $(echo "scale=2; $ilsa_median / $peer_median" | bc)"
echo "ratio, core compiled once: $(echo "scale=2; $core_user_median / $peer_median" | bc)"
rm -rf "$out"
