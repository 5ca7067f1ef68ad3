# Usage requirements of the header-only target CGAL::Polygon_mesh_processing_ILSA,
# shared by the source tree (CMakeLists.txt) and the installed package
# (Polygon_mesh_processing_ILSAConfig.cmake). CGAL and Eigen3 must be found
# before; TBB is used when found.

include(CGAL_Eigen3_support)
if(TBB_FOUND)
  include(CGAL_TBB_support)
endif()

# The package extends CGAL's named-parameter list: its
# CGAL/STL_Extension/internal/parameters_interface.h is found before CGAL's and
# includes CGAL's original by this path (see that header).
if(NOT ILSA_CGAL_PARAMETERS_INTERFACE)
  find_file(ILSA_CGAL_PARAMETERS_INTERFACE CGAL/STL_Extension/internal/parameters_interface.h
            PATHS ${CGAL_INCLUDE_DIRS} NO_DEFAULT_PATH DOC "CGAL's own named-parameter list")
  mark_as_advanced(ILSA_CGAL_PARAMETERS_INTERFACE)
endif()
if(NOT ILSA_CGAL_PARAMETERS_INTERFACE)
  message(FATAL_ERROR "Polygon_mesh_processing_ILSA: CGAL/STL_Extension/internal/parameters_interface.h "
                      "is not in CGAL's include directories (${CGAL_INCLUDE_DIRS})")
endif()

# ilsa_set_usage_requirements(<target> <include directory of the package>)
function(ilsa_set_usage_requirements target include_dir)
  # BEFORE: the package's named-parameter list must shadow CGAL's.
  target_include_directories(${target} BEFORE INTERFACE "${include_dir}")
  target_compile_definitions(${target} INTERFACE "CGAL_ILSA_CGAL_PARAMETERS_INTERFACE=\"${ILSA_CGAL_PARAMETERS_INTERFACE}\"")
  target_compile_features(${target} INTERFACE cxx_std_17)
  target_link_libraries(${target} INTERFACE CGAL::CGAL CGAL::Eigen3_support)
  # With TBB, smooth_surface_mesh_ilsa<CGAL::Parallel_tag> runs its sweeps in parallel.
  if(TARGET CGAL::TBB_support)
    target_link_libraries(${target} INTERFACE CGAL::TBB_support)
  endif()
endfunction()

# ilsa_add_core_library(<target> <source> <package target>): the package's
# core compiled once, from src/ilsa_core.cpp (user manual, "Compiling the Core Once"), with the flags of the project that builds it. A program that links
# <target> defines CGAL_ILSA_COMPILED_CORE and so compiles only the part of the
# package that depends on its mesh type. Built only when a target links it.
function(ilsa_add_core_library target source package_target)
  add_library(${target} STATIC EXCLUDE_FROM_ALL "${source}")
  target_link_libraries(${target} PUBLIC ${package_target})
  target_compile_definitions(${target} PUBLIC CGAL_ILSA_COMPILED_CORE)
endfunction()
