# The same results with every supported CGAL (user manual, "Supported CGAL Versions and Compilers"): ilsa_smooth built against this build's CGAL (TOOL) and the same
# tool built against another CGAL (REFERENCE, e.g. Debian's 5.5.1 when this
# build uses 6.1.1) smooth every bundled mesh, and every mesh of the shared
# data folder when it exists, to the same file, byte for byte. Both tools must
# also name different CGAL versions in --version, so that the test cannot pass
# by comparing a build with itself.
# Run with -DTOOL=... -DREFERENCE=... -DDATA=... -DSHARED=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

function(run_tool tool input output)
  execute_process(COMMAND "${tool}" "${input}" "${output}" --threads 1 RESULT_VARIABLE status OUTPUT_QUIET
                  ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${tool} ${input} failed (${status}): ${err}")
  endif()
endfunction()

execute_process(COMMAND "${TOOL}" --version OUTPUT_VARIABLE this_version)
execute_process(COMMAND "${REFERENCE}" --version OUTPUT_VARIABLE reference_version)
string(STRIP "${this_version}" this_version)
string(STRIP "${reference_version}" reference_version)
string(REGEX MATCH "CGAL [0-9.]+" this_cgal "${this_version}")
string(REGEX MATCH "CGAL [0-9.]+" reference_cgal "${reference_version}")
if(NOT this_cgal OR NOT reference_cgal OR this_cgal STREQUAL reference_cgal)
  message(FATAL_ERROR "the two tools must use different CGALs: '${this_version}' and '${reference_version}'")
endif()
message(STATUS "comparing ${this_cgal} with ${reference_cgal}")

file(GLOB meshes "${DATA}/*.off" "${DATA}/*.ply")
if(EXISTS "${SHARED}")
  file(GLOB shared_meshes "${SHARED}/*.off" "${SHARED}/*.ply" "${SHARED}/*.stl")
  list(APPEND meshes ${shared_meshes})
else()
  message(STATUS "no shared data folder at ${SHARED}: the bundled meshes only")
endif()
list(LENGTH meshes count)
if(count LESS 6)
  message(FATAL_ERROR "found ${count} meshes in ${DATA}, expected the 6 bundled ones at least")
endif()

set(differ "")
foreach(mesh ${meshes})
  get_filename_component(name "${mesh}" NAME_WE)
  get_filename_component(folder "${mesh}" DIRECTORY)
  get_filename_component(folder "${folder}" NAME)
  set(stem "${WORK}/${folder}-${name}")
  run_tool("${TOOL}" "${mesh}" "${stem}-this.off")
  run_tool("${REFERENCE}" "${mesh}" "${stem}-reference.off")
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${stem}-this.off" "${stem}-reference.off"
                  RESULT_VARIABLE same)
  if(same EQUAL 0)
    message(STATUS "${folder}/${name}: identical")
  else()
    list(APPEND differ "${folder}/${name}")
  endif()
endforeach()
if(differ)
  message(FATAL_ERROR "${this_cgal} and ${reference_cgal} smooth these meshes differently: ${differ}")
endif()
message(STATUS "${count} meshes smoothed to the same bytes with ${this_cgal} and ${reference_cgal}")
