#!/usr/bin/env bash
# Where the compile time of a program calling the smoother goes: Clang's
# -ftime-trace of benchmark/compile_time/ilsa_call.cpp (header-only and with
# CGAL_ILSA_COMPILED_CORE) and of the same program calling CGAL's
# tangential_relaxation() (benchmark/compile_time.sh times them); same flags
# as compile_time.sh, -O2. Prints, per program, the front end (parsing and
# template instantiation) and the back end (optimisation and code generation),
# the headers whose parsing took longest and the costliest instantiations.
#
#   benchmark/compile_trace.sh [TOP]   (TOP: lines per list, default 8)
#
# Uses Debian's CGAL (/usr/include) unless CGAL_INCLUDE names another include
# directory. Needs clang++ (CXX overrides it) and python3.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
top=${1:-8}
cgal=${CGAL_INCLUDE:-/usr/include}
cxx=${CXX:-clang++}
interface="$cgal/CGAL/STL_Extension/internal/parameters_interface.h"
common=(-O2 -std=c++17 -frounding-math -DCGAL_EIGEN3_ENABLED -isystem /usr/include/eigen3 -ftime-trace
        -ftime-trace-granularity=100)
if [ -n "${CGAL_INCLUDE:-}" ]; then common+=(-isystem "$cgal"); fi
ilsa=(-I"$here/include" "-DCGAL_ILSA_CGAL_PARAMETERS_INTERFACE=\"$interface\"")
out=$(mktemp -d)
"$cxx" "${common[@]}" "${ilsa[@]}" -c "$here/benchmark/compile_time/ilsa_call.cpp" -o "$out/header_only.o"
"$cxx" "${common[@]}" "${ilsa[@]}" -DCGAL_ILSA_COMPILED_CORE -c "$here/benchmark/compile_time/ilsa_call.cpp" \
  -o "$out/compiled_core.o"
"$cxx" "${common[@]}" -c "$here/benchmark/compile_time/tangential_call.cpp" -o "$out/tangential.o"
python3 - "$out" "$top" <<'PY'
import json, sys
out, top = sys.argv[1], int(sys.argv[2])
for name, what in [("header_only", "smooth_surface_mesh_ilsa, header-only"),
                   ("compiled_core", "smooth_surface_mesh_ilsa, core compiled once"),
                   ("tangential", "tangential_relaxation")]:
    events = [e for e in json.load(open(f"{out}/{name}.json"))["traceEvents"] if e.get("ph") == "X"]
    total = {e["name"][6:]: e["dur"] / 1e6 for e in events if e["name"].startswith("Total ")}
    print(f"## {what}")
    print("whole %.2f s: front end %.2f s (parsing %.2f s, instantiating functions %.2f s), back end %.2f s" %
          (total.get("ExecuteCompiler", 0), total.get("Frontend", 0), total.get("Source", 0),
           total.get("InstantiateFunction", 0), total.get("Backend", 0)))
    # Headers: the outermost "Source" events (an include's time contains its own includes).
    sources, end = [], -1
    for e in sorted((e for e in events if e["name"] == "Source"), key=lambda e: e["ts"]):
        if e["ts"] >= end:
            sources.append(e)
            end = e["ts"] + e["dur"]
    print("headers parsed (outermost includes):")
    for e in sorted(sources, key=lambda e: -e["dur"])[:top]:
        print("  %.2f s %s" % (e["dur"] / 1e6, e["args"]["detail"]))
    print("function instantiations (each includes those it triggers):")
    for e in sorted((e for e in events if e["name"] == "InstantiateFunction"), key=lambda e: -e["dur"])[:top]:
        print("  %.2f s %s" % (e["dur"] / 1e6, e["args"]["detail"][:150]))
    print()
PY
rm -rf "$out"
