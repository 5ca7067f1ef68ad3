#!/usr/bin/env bash
# Byte-identity check for changes that must not change results (clean-ups,
# speed work): smooths every bundled mesh, and every mesh of ../shared/data
# when it exists, with five parameter sets on 1 and 2 threads, with two builds
# of ilsa_smooth, and compares the output files byte for byte.
#
#   benchmark/compare_outputs.sh OLD_TOOL NEW_TOOL [WORK_DIR]
#
# OLD_TOOL is e.g. ilsa_smooth built from the commit before the change (a
# `git worktree` of it), NEW_TOOL the one built from the working tree. Prints
# one line per difference and a summary; exits 1 if any output differs or a
# run fails. NEW_FLAGS, when set, are given to NEW_TOOL only (before each
# set's, which win): with the flags that restore an earlier default, it checks that the
# earlier behaviour is still reachable. PAPER_FLAGS, when set, replace
# `--paper` in the fourth set (for an OLD_TOOL that spells the variant otherwise).
set -uo pipefail
old=${1:?usage: compare_outputs.sh OLD_TOOL NEW_TOOL [WORK_DIR]}
new=${2:?usage: compare_outputs.sh OLD_TOOL NEW_TOOL [WORK_DIR]}
work=${3:-$(mktemp -d)}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"

meshes=("$here"/data/meshes/*.off "$here"/data/meshes/*.ply)
if [ -d "$here/../shared/data" ]; then
  meshes+=("$here"/../shared/data/*.off "$here"/../shared/data/*.ply "$here"/../shared/data/*.stl)
fi
# The defaults; another feature angle; a looser floor without the fidelity
# bound; the paper's variant; no safety check and a fixed number of iterations.
sets=(""
      "--feature-angle 45"
      "--quality-floor 0.3 --fidelity-tolerance inf"
      "--paper"
      "--no-safety --iterations 4 --min-gain 0")
old_sets=("${sets[@]}")
old_sets[3]=${PAPER_FLAGS:---paper}

runs=0 differ=0 failed=0
for mesh in "${meshes[@]}"; do
  [ -f "$mesh" ] || continue
  name=$(basename "$(dirname "$mesh")")-$(basename "${mesh%.*}")
  for s in "${!sets[@]}"; do
    for threads in 1 2; do
      out="$work/$name-set$s-t$threads"
      # shellcheck disable=SC2086
      if ! "$old" "$mesh" "$out-old.off" --threads $threads ${old_sets[$s]} > /dev/null 2>&1 ||
         ! "$new" "$mesh" "$out-new.off" --threads $threads ${NEW_FLAGS:-} ${sets[$s]} > /dev/null 2>&1; then
        echo "failed: $name, set $s (${sets[$s]:-defaults}), $threads thread(s)"
        failed=$((failed + 1))
        continue
      fi
      runs=$((runs + 1))
      if ! cmp -s "$out-old.off" "$out-new.off"; then
        echo "differs: $name, set $s (${sets[$s]:-defaults}), $threads thread(s)"
        differ=$((differ + 1))
      fi
    done
  done
done
echo "compare_outputs: $runs outputs compared, $differ differ, $failed runs failed"
[ "$differ" -eq 0 ] && [ "$failed" -eq 0 ] && [ "$runs" -gt 0 ]
