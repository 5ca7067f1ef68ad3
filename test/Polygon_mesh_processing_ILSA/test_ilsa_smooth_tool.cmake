# The ilsa_smooth tool: on bad input or flags a one-line error on stderr, a
# non-zero exit status and no output file; then each flag and message.
# Run with -DTOOL=... -DWORK=... -DDATA=... -DVERSION=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/garbage.off" "this is not a mesh\n")
file(WRITE "${WORK}/quads.off" "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n4 0 1 2 3\n4 1 4 5 2\n")
file(WRITE "${WORK}/nan.off" "OFF\n4 2 0\n0 0 0\n1 0 0\nnan 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
# Two triangles folded along the edge 0-2; files of crease edges for it.
file(WRITE "${WORK}/fold.off" "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0.5\n0 1 0\n3 0 1 2\n3 0 2 3\n")
file(WRITE "${WORK}/fold-creases.txt" "# the fold\n0 2\n\n")
file(WRITE "${WORK}/no-vertex.txt" "0 5\n")
file(WRITE "${WORK}/no-edge.txt" "1 3\n")
file(WRITE "${WORK}/one-index.txt" "0\n")

set(failures 0)
# expect_failure(name REGEX args...): the error message must match REGEX; an
# error found before smoothing must come before any quality figure is printed.
function(expect_failure name regex)
  set(output "${WORK}/${name}-out.off")
  execute_process(COMMAND "${TOOL}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(STRIP "${err}" err)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines extra_lines)
  set(printed_quality FALSE)
  if(out MATCHES "before:" AND NOT name STREQUAL "unwritable")
    set(printed_quality TRUE)
  endif()
  if(status EQUAL 0 OR NOT err MATCHES "^ilsa_smooth: error: " OR NOT err MATCHES "${regex}" OR extra_lines GREATER 0
     OR EXISTS "${output}" OR EXISTS "${WORK}/${name}-out.ilsa-partial.off" OR printed_quality)
    message(SEND_ERROR "${name}: status '${status}', stderr '${err}', stdout '${out}'")
    math(EXPR failures "${failures} + 1")
    set(failures ${failures} PARENT_SCOPE)
  else()
    message(STATUS "${name}: ${err}")
  endif()
endfunction()

function(fail what)
  message(SEND_ERROR "${what}")
  math(EXPR failures "${failures} + 1")
  set(failures ${failures} PARENT_SCOPE)
endfunction()

expect_failure(missing "cannot read" "${WORK}/does-not-exist.off" "${WORK}/missing-out.off")
expect_failure(garbage "cannot read" "${WORK}/garbage.off" "${WORK}/garbage-out.off")
expect_failure(quads "2 faces that are not triangles.*--triangulate" "${WORK}/quads.off" "${WORK}/quads-out.off")
expect_failure(nan "non-finite|cannot read" "${WORK}/nan.off" "${WORK}/nan-out.off")
expect_failure(bad_number "--iterations expects a number" "${DATA}/sphere_low.off" "${WORK}/bad_number-out.off"
               --iterations ten)
expect_failure(bad_worst "--worst expects a non-negative whole number" "${DATA}/sphere_low.off"
               "${WORK}/bad_worst-out.off" --worst -2)
expect_failure(unknown_option "unknown option '--frobnicate'" "${DATA}/sphere_low.off"
               "${WORK}/unknown_option-out.off" --frobnicate=3)
expect_failure(unwritable "cannot write" "${DATA}/sphere_low.off" "${WORK}/no-such-dir/unwritable-out.off")
expect_failure(switch_value "--paper takes no value" "${DATA}/sphere_low.off" "${WORK}/switch_value-out.off"
               --paper=1)
expect_failure(missing_value "--feature-angle expects a value" "${DATA}/sphere_low.off"
               "${WORK}/missing_value-out.off" --feature-angle)
expect_failure(two_crease_sources "--sharp-edges and --detect-sharp-edges both give the crease edges"
               "${WORK}/fold.off" "${WORK}/two_crease_sources-out.off" --sharp-edges "${WORK}/fold-creases.txt"
               --detect-sharp-edges 30)
expect_failure(crease_file_missing "--sharp-edges: cannot read '.*nothing.txt'" "${WORK}/fold.off"
               "${WORK}/crease_file_missing-out.off" --sharp-edges "${WORK}/nothing.txt")
expect_failure(crease_no_vertex "no-vertex.txt' line 1: no vertex 5" "${WORK}/fold.off"
               "${WORK}/crease_no_vertex-out.off" --sharp-edges "${WORK}/no-vertex.txt")
expect_failure(crease_no_edge "no-edge.txt' line 1: vertices 1 and 3 share no edge" "${WORK}/fold.off"
               "${WORK}/crease_no_edge-out.off" --sharp-edges "${WORK}/no-edge.txt")
expect_failure(crease_one_index "one-index.txt' line 1: expected two vertex indices, got '0'" "${WORK}/fold.off"
               "${WORK}/crease_one_index-out.off" --sharp-edges "${WORK}/one-index.txt")
expect_failure(detect_angle "--detect-sharp-edges expects an angle in \\[0, 180\\], got '200'" "${WORK}/fold.off"
               "${WORK}/detect_angle-out.off" --detect-sharp-edges 200)
expect_failure(bad_report "--report expects auto, summary or full" "${DATA}/sphere_low.off"
               "${WORK}/bad_report-out.off" --report=some)
expect_failure(color_not_ply "--color-by-quality writes colours to a PLY file" "${DATA}/sphere_low.off"
               "${WORK}/color_not_ply-out.off" --color-by-quality)
expect_failure(color_no_output "--color-by-type writes colours to a PLY file" "${DATA}/sphere_low.off"
               --color-by-type)
# Values the library rejects: the message names the flag, not the library's
# parameter, says the prefix once and gives the value.
foreach(case "feature-angle;--feature-angle=190" "quality-floor;--quality-floor;1"
             "fidelity-tolerance;--fidelity-tolerance=0" "min-gain;--min-gain=-1" "iterations;--iterations=200000")
  list(GET case 0 flag)
  list(REMOVE_AT case 0)
  expect_failure(range_${flag} "^ilsa_smooth: error: --${flag} must be [^\n]*, got -?[0-9]" "${DATA}/sphere_low.off"
                 "${WORK}/range_${flag}-out.off" ${case})
endforeach()

# A tool run; sets out, err and status in the caller.
macro(run_tool)
  execute_process(COMMAND "${TOOL}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
endmacro()

# expect_success(what STREAM REGEX args...): the run succeeds and its out or err matches REGEX.
function(expect_success what stream regex)
  run_tool(${ARGN})
  if(NOT status EQUAL 0 OR NOT ${stream} MATCHES "${regex}")
    fail("${what}: status '${status}', stdout '${out}', stderr '${err}'")
    set(failures ${failures} PARENT_SCOPE)
  endif()
endfunction()

# --option=value is --option value: the same output file. (--report summary:
# these checks do not read the Hausdorff distance, the costly part of a full report.)
run_tool("${DATA}/fandisk.off" "${WORK}/spaced.off" --iterations 3 --feature-angle 30 --no-progress --report summary)
run_tool("${DATA}/fandisk.off" "${WORK}/equals.off" --iterations=3 --feature-angle=30 --no-progress --report=summary)
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${WORK}/spaced.off" "${WORK}/equals.off"
                RESULT_VARIABLE different)
if(NOT status EQUAL 0 OR different)
  fail("--option=value: status '${status}', files differ: '${different}'")
endif()
# Without OUTPUT nothing is written, and the tool says so.
expect_success("no OUTPUT" out "nothing written: no OUTPUT file given\n$" "${DATA}/sphere_low.off" --iterations 1
               --no-progress)
# --triangulate splits the quads, then smooths: 4 triangles written.
run_tool("${WORK}/quads.off" "${WORK}/triangulated.off" --triangulate)
file(STRINGS "${WORK}/triangulated.off" header LIMIT_COUNT 2)
list(GET header 1 counts)
if(NOT status EQUAL 0 OR NOT out MATCHES "triangulated: 2 faces split, 4 triangles" OR NOT counts MATCHES "^6 4 ")
  fail("--triangulate: status '${status}', counts '${counts}', stdout '${out}'")
endif()
# Colours: a PLY with face colours (by q) and vertex colours (by type).
run_tool("${DATA}/fandisk.off" "${WORK}/colored.ply" --iterations 2 --color-by-quality --color-by-type --report summary)
file(READ "${WORK}/colored.ply" ply LIMIT 600)
if(NOT status EQUAL 0
   OR NOT ply MATCHES "element vertex 6475\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red"
   OR NOT ply MATCHES "element face 12946\nproperty list uchar int vertex_indices\nproperty uchar red")
  fail("--color-by-quality/--color-by-type: status '${status}', header '${ply}'")
endif()
# --report: summary skips the Hausdorff distance, full computes it, auto is full on a small mesh.
expect_success("--report summary" out "Hausdorff not computed \\(--report full\\)" "${DATA}/sphere_low.off"
               --iterations 1 --report=summary)
foreach(report full auto)
  expect_success("--report ${report}" out "Hausdorff [0-9]\\.[0-9]+e-0[0-9]" "${DATA}/sphere_low.off" --iterations 1
                 --report=${report})
endforeach()
# --progress: one line per iteration on stderr; --no-progress: nothing there.
expect_success("--progress" err "^\rILSA iteration 1 of at most 2\rILSA iteration 2 of at most 2\n$"
               "${DATA}/sphere_low.off" --iterations 2 --min-gain 0 --progress)
expect_success("--no-progress" err "^$" "${DATA}/sphere_low.off" --iterations 2 --no-progress)
# The user's crease edges: from a file (the fold's vertices slide along it,
# its ends are boundary vertices), or from CGAL's detect_sharp_edges().
expect_success("--sharp-edges" out "crease edges: 1 from '.*fold-creases.txt'\n.*crease deviation \\(1 sharp edges"
               "${WORK}/fold.off" --sharp-edges "${WORK}/fold-creases.txt")
expect_success("--detect-sharp-edges" out "crease edges: [1-9][0-9]* from detect_sharp_edges\\(\\) at 30"
               "${DATA}/fandisk.off" --iterations 1 --detect-sharp-edges 30 --report summary)
# --paper: the paper's variant runs.
expect_success("--paper" out "after : aspect ratio" "${DATA}/sphere_low.off" --iterations 1 --paper)
# --help lists the formats, then --version; --version prints the project's version.
expect_success("--help" out "\\.off \\.obj \\.ply \\.stl.*--version" --help)
expect_success("--version" out "^ilsa_smooth ${VERSION} \\(CGAL [0-9.]+\\)\n$" --version)
# STL holds 32-bit floats: the tool says so when it writes one.
expect_success(".stl" out "written: [^\n]*sphere.stl \\(STL stores 32-bit floats" "${DATA}/sphere_low.off"
               "${WORK}/sphere.stl" --iterations 1)

# And a run that succeeds writes the output, with every vertex.
execute_process(COMMAND "${TOOL}" "${DATA}/sphere_low.off" "${WORK}/ok.off" --iterations 2 RESULT_VARIABLE status)
file(STRINGS "${WORK}/ok.off" header LIMIT_COUNT 2)
list(GET header 1 counts)
if(NOT status EQUAL 0 OR NOT counts MATCHES "^589 1174")
  message(SEND_ERROR "successful run: status '${status}', counts '${counts}'")
  math(EXPR failures "${failures} + 1")
endif()
# --worst N lists N faces, the first being the one with the minimum after smoothing.
execute_process(COMMAND "${TOOL}" "${DATA}/sphere_low.off" --iterations 2 --worst 3 RESULT_VARIABLE status
                OUTPUT_VARIABLE out)
string(REGEX MATCHALL "worst face [0-9]+: q [0-9.]+ -> [0-9.]+" listed "${out}")
list(LENGTH listed count)
string(REGEX MATCH "after : aspect ratio q min ([0-9.]+)" after "${out}")
set(minimum "${CMAKE_MATCH_1}")
list(GET listed 0 first)
if(NOT status EQUAL 0 OR NOT count EQUAL 3 OR NOT first MATCHES "-> ${minimum}$")
  message(SEND_ERROR "--worst: status '${status}', ${count} faces listed, first '${first}', minimum '${minimum}'")
  math(EXPR failures "${failures} + 1")
endif()
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} tool check(s) failed")
endif()
