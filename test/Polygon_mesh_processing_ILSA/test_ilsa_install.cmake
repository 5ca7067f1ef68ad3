# The package used from another project, two ways (run with cmake -P):
#  MODE=install: `cmake --install` into a fresh prefix installs nothing that
#    would replace a file of CGAL's installation; a consumer project finds the
#    package with find_package(), builds, and smooths INPUT bit-identically to
#    the ilsa_smooth TOOL, both header-only and with the package's core
#    compiled once (CGAL::Polygon_mesh_processing_ILSA_core).
#  MODE=subdirectory: a parent project adds the source tree with
#    add_subdirectory() (see parent/CMakeLists.txt, which checks its settings);
#    the compile command of its program carries no warning flag of the package.
# Also: -DBUILD=<package build dir> -DSOURCE=<package source> -DWORK=<scratch dir>
#       -DCGAL_INCLUDE=<CGAL's include dirs> -DCXX=<compiler> -DINPUT=<mesh>
#       -DCGAL_DIR=<the CGAL configuration of the package's build>: the consumer
#       and the parent are configured with the same CGAL, and must find it.

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(here "${CMAKE_CURRENT_LIST_DIR}")

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
endfunction()

# expect_cgal(<build dir>): the project found the CGAL it was given.
function(expect_cgal build)
  file(STRINGS "${build}/CMakeCache.txt" found REGEX "^CGAL_DIR:")
  string(REGEX REPLACE "^CGAL_DIR:[A-Z]+=" "" found "${found}")
  get_filename_component(found "${found}" REALPATH)
  get_filename_component(given "${CGAL_DIR}" REALPATH)
  if(NOT found STREQUAL given)
    message(FATAL_ERROR "${build} found CGAL in '${found}', not in '${given}'")
  endif()
  message(STATUS "${build} uses the CGAL in ${given}")
endfunction()

if(MODE STREQUAL "install")
  set(prefix "${WORK}/prefix")
  run("cmake --install" "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${prefix}")
  file(GLOB_RECURSE installed RELATIVE "${prefix}" "${prefix}/*")
  list(LENGTH installed count)
  set(clashes "")
  foreach(cgal_include ${CGAL_INCLUDE})
    get_filename_component(cgal_prefix "${cgal_include}" DIRECTORY)
    foreach(file ${installed})
      if(EXISTS "${cgal_prefix}/${file}")
        list(APPEND clashes "${cgal_prefix}/${file}")
      endif()
    endforeach()
  endforeach()
  if(clashes OR count LESS 10)
    message(FATAL_ERROR "installed ${count} files; these would replace files of CGAL's installation: ${clashes}")
  endif()
  message(STATUS "installed ${count} files, none in place of a file of CGAL's installation")

  run("configuring the consumer" "${CMAKE_COMMAND}" -S "${here}/consumer" -B "${WORK}/consumer"
      "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_COMPILER=${CXX}" "-DCGAL_DIR=${CGAL_DIR}")
  expect_cgal("${WORK}/consumer")
  run("building the consumer" "${CMAKE_COMMAND}" --build "${WORK}/consumer")
  run("ilsa_smooth" "${TOOL}" "${INPUT}" "${WORK}/tool.off")
  foreach(consumer ilsa_consumer ilsa_consumer_compiled_core)
    run("${consumer}" "${WORK}/consumer/${consumer}" "${INPUT}" "${WORK}/${consumer}.off")
    run("comparing" "${CMAKE_COMMAND}" -E compare_files "${WORK}/${consumer}.off" "${WORK}/tool.off")
    message(STATUS "the output of ${consumer} equals ilsa_smooth's")
  endforeach()
elseif(MODE STREQUAL "subdirectory")
  run("configuring the parent" "${CMAKE_COMMAND}" -S "${here}/parent" -B "${WORK}/parent" "-DILSA_SOURCE_DIR=${SOURCE}"
      -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "-DCMAKE_CXX_COMPILER=${CXX}" "-DCGAL_DIR=${CGAL_DIR}")
  expect_cgal("${WORK}/parent")
  file(READ "${WORK}/parent/compile_commands.json" commands)
  if(NOT commands MATCHES "ilsa_consumer.cpp" OR commands MATCHES " -W" OR commands MATCHES " -O")
    message(FATAL_ERROR "the parent's compile command:\n${commands}")
  endif()
  message(STATUS "the parent's compile command gets no warning or optimisation flag")
else()
  message(FATAL_ERROR "MODE must be install or subdirectory")
endif()
