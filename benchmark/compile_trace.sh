#!/usr/bin/env bash
# Where the compile time of a program calling the smoother goes: Clang's
# -ftime-trace of benchmark/compile_time/ilsa_call.cpp (header-only and with
# CGAL_ILSA_COMPILED_CORE) and of the same program calling CGAL's
# tangential_relaxation() (benchmark/compile_time.sh times them); same flags
# as compile_time.sh, -O2. Prints, per program, the front end (parsing and
# template instantiation) and the back end (optimisation and code generation),
# the headers whose parsing took longest and the costliest instantiations;
# then the code the back end receives (LLVM IR before optimisation) by the
# namespace of the function it belongs to.
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
common=(-O2 -std=c++17 -frounding-math -DCGAL_EIGEN3_ENABLED -isystem /usr/include/eigen3)
if [ -n "${CGAL_INCLUDE:-}" ]; then common+=(-isystem "$cgal"); fi
ilsa=(-I"$here/include" "-DCGAL_ILSA_CGAL_PARAMETERS_INTERFACE=\"$interface\"")
out=$(mktemp -d)
programs=(header_only compiled_core tangential)
# Sets `args` to the flags and the source file of program $1.
args_of() {
  case $1 in
    header_only) args=("${ilsa[@]}" "$here/benchmark/compile_time/ilsa_call.cpp") ;;
    compiled_core) args=("${ilsa[@]}" -DCGAL_ILSA_COMPILED_CORE "$here/benchmark/compile_time/ilsa_call.cpp") ;;
    tangential) args=("$here/benchmark/compile_time/tangential_call.cpp") ;;
  esac
}
for name in "${programs[@]}"; do
  args_of "$name"
  "$cxx" "${common[@]}" -ftime-trace -ftime-trace-granularity=100 -c "${args[@]}" -o "$out/$name.o"
done
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
# The code handed to the back end: the same compilations stopped before the
# optimisation passes, as LLVM IR; instructions counted per function.
for name in "${programs[@]}"; do
  args_of "$name"
  "$cxx" "${common[@]}" -Xclang -disable-llvm-passes -S -emit-llvm "${args[@]}" -o "$out/$name.ll"
done
python3 - "$out" <<'PY'
import collections, re, subprocess, sys
out = sys.argv[1]
def functions(path):  # {mangled name: instructions}
    result, name = {}, None
    for line in open(path):
        if line.startswith("define "):
            name = re.search(r'@("[^"]+"|[^\s(]+)\(', line).group(1).strip('"')
            result[name] = 0
        elif name is not None:
            if line.startswith("}"):
                name = None
            elif line.startswith("  ") and not line.rstrip().endswith(":"):
                result[name] += 1
    return result
def without(text, open_, close):  # drops what lies between matching brackets
    kept, depth = [], 0
    for c in text:
        if c == open_:
            depth += 1
        elif c == close and depth:
            depth -= 1
        elif depth == 0:
            kept.append(c)
    return "".join(kept)
def origin(demangled):  # by the qualified name of the function, template arguments dropped
    name = demangled.replace("operator()", "operator_call").replace("operator<", "operator_lt")
    name = without(without(name.replace("operator>", "operator_gt"), "{", "}"), "<", ">")
    name = name.split("(")[0].split(" ")[-1]
    for prefix, what in [("CGAL::Polygon_mesh_processing::", "package, CGAL PMP"), ("Eigen::", "Eigen"),
                         ("CGAL::AABB", "CGAL AABB tree"), ("CGAL::Surface_mesh", "CGAL Surface_mesh"),
                         ("CGAL::Properties", "CGAL Surface_mesh"), ("CGAL::", "CGAL, other"), ("boost::", "Boost"),
                         ("std::", "standard library"), ("__gnu_cxx::", "standard library")]:
        if name.startswith(prefix):
            return what
    return "other"
print("## code handed to the back end (LLVM IR instructions before optimisation, by the function's namespace)")
for name, what in [("header_only", "smooth_surface_mesh_ilsa, header-only"),
                   ("compiled_core", "smooth_surface_mesh_ilsa, core compiled once"),
                   ("tangential", "tangential_relaxation")]:
    counts = functions(f"{out}/{name}.ll")
    names = list(counts)
    demangled = subprocess.run(["c++filt"], input="\n".join(names), capture_output=True, text=True).stdout.split("\n")
    instructions, how_many = collections.Counter(), collections.Counter()
    for mangled, readable in zip(names, demangled):
        instructions[origin(readable)] += counts[mangled]
        how_many[origin(readable)] += 1
    total = sum(instructions.values())
    print(f"{what}: {total} instructions in {len(names)} functions")
    for key, value in instructions.most_common():
        print("  %-20s %7d (%4.1f %%) in %5d functions" % (key, value, 100. * value / total, how_many[key]))
PY
rm -rf "$out"
