#!/usr/bin/env bash
# Wall time of two builds of ilsa_smooth on the same mesh, taking turns, with
# every default: the time each tool reports for the smoothing ("time: X s",
# reading and writing left out), RUNS runs each, and the medians.
#
#   benchmark/compare_times.sh OLD_TOOL NEW_TOOL [MESH [THREADS [RUNS]]]
#
# OLD_TOOL is e.g. ilsa_smooth built from an earlier commit (a `git worktree`
# of it), NEW_TOOL the one built from the working tree. MESH defaults to the
# bundled horse, THREADS to 1, RUNS to 7. Prints each tool's times, its
# median, and NEW over OLD.
set -euo pipefail
old=${1:?usage: compare_times.sh OLD_TOOL NEW_TOOL [MESH [THREADS [RUNS]]]}
new=${2:?usage: compare_times.sh OLD_TOOL NEW_TOOL [MESH [THREADS [RUNS]]]}
here=$(cd "$(dirname "$0")/.." && pwd)
mesh=${3:-$here/data/meshes/horse.ply}
threads=${4:-1}
runs=${5:-7}

time_of() {
  "$1" "$mesh" --threads "$threads" --report summary 2>&1 | sed -n 's/^time: \([0-9.]*\) s.*/\1/p'
}
old_times=() new_times=()
for ((i = 0; i < runs; ++i)); do
  old_times+=("$(time_of "$old")")
  new_times+=("$(time_of "$new")")
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
old_median=$(median "${old_times[@]}")
new_median=$(median "${new_times[@]}")
echo "mesh $(basename "$mesh"), $threads thread(s), $runs runs each, taking turns"
echo "old: ${old_times[*]} s; median $old_median s"
echo "new: ${new_times[*]} s; median $new_median s"
awk -v o="$old_median" -v n="$new_median" 'BEGIN {printf "new / old: %.2f\n", n / o}'
