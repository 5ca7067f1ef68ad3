// The half of test_ilsa_mixed_build compiled with the package's include
// directory first (see test_ilsa_mixed_build.cpp).

#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>

#include "test_ilsa_mixed_build.h"

#ifndef CGAL_ILSA_NAMED_PARAMETERS_INTERFACE
#error "this file must be compiled with the package's list of named parameters"
#endif

std::vector<Kernel::Point_3> smooth_with(const Mesh& input, const Iterations& np) {
  Mesh mesh = input;
  CGAL::Polygon_mesh_processing::smooth_surface_mesh_ilsa(mesh, np);
  std::vector<Kernel::Point_3> points;
  for (auto v : vertices(mesh)) points.push_back(mesh.point(v));
  return points;
}

std::vector<Kernel::Point_3> smooth_with_own_parameters(const Mesh& input) {
  return smooth_with(input, CGAL::parameters::number_of_iterations(3));
}

std::size_t iterations_of_chained_parameters(const Mesh& input) {
  Mesh mesh = input;
  return CGAL::Polygon_mesh_processing::smooth_surface_mesh_ilsa(
             mesh, CGAL::parameters::number_of_iterations(3).ilsa_minimum_quality_gain(0.))
      .number_of_iterations;
}
