// What the two files of test_ilsa_mixed_build share (see
// test_ilsa_mixed_build.cpp): the mesh type and the functions of the package's
// half. Nothing here includes the package or CGAL's named parameters.
#ifndef TEST_ILSA_MIXED_BUILD_H
#define TEST_ILSA_MIXED_BUILD_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
// The named-parameter type both files build.
using Iterations = decltype(CGAL::parameters::number_of_iterations(3));

// The smoothed points of `input` with `np`.
std::vector<Kernel::Point_3> smooth_with(const Mesh& input, const Iterations& np);
// The same, with `number_of_iterations(3)` built in the package's file.
std::vector<Kernel::Point_3> smooth_with_own_parameters(const Mesh& input);
// The iterations run with parameters chained with the package's tags.
std::size_t iterations_of_chained_parameters(const Mesh& input);

#endif
