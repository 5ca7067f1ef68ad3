// A program whose translation units do not all see the package's list of named
// parameters (user manual, "Using the Package", mixed builds): this file is
// compiled without the package's include directory, so it reads CGAL's own
// list; test_ilsa_mixed_build_package.cpp is compiled with it. Both build the
// same named-parameter type (`number_of_iterations`), whose class has the
// `ilsa_*` member functions in one file only. The program must link, and the
// smoothing must give the same points whichever file built its parameters.

#include "test_ilsa_mixed_build.h"

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>

#ifdef CGAL_ILSA_NAMED_PARAMETERS_INTERFACE
#error "this file must be compiled with CGAL's own list of named parameters"
#endif

#include <cassert>
#include <iostream>
#include <string>

int main() {
  Mesh input;
  const std::string file = std::string(ILSA_DATA_DIR) + "/fandisk.off";
  const bool read = CGAL::IO::read_polygon_mesh(file, input);
  assert(read && !is_empty(input));

  // CGAL's own smoother, its parameters from CGAL's list.
  Mesh relaxed = input;
  CGAL::Polygon_mesh_processing::tangential_relaxation(relaxed, CGAL::parameters::number_of_iterations(3));
  bool relaxation_moved = false;
  for (auto v : vertices(input)) relaxation_moved = relaxation_moved || relaxed.point(v) != input.point(v);
  assert(relaxation_moved);

  // ILSA with parameters built here and with the same parameters built there.
  const std::vector<Kernel::Point_3> from_here = smooth_with(input, CGAL::parameters::number_of_iterations(3));
  const std::vector<Kernel::Point_3> from_there = smooth_with_own_parameters(input);
  assert(from_here.size() == num_vertices(input));
  assert(from_here == from_there);
  std::size_t moved = 0;
  std::size_t i = 0;
  for (auto v : vertices(input)) moved += from_here[i++] != input.point(v) ? 1 : 0;
  assert(moved > num_vertices(input) / 2);

  // The package's tags chain in the package's file.
  assert(iterations_of_chained_parameters(input) == 3);
  std::cout << "mixed build: " << moved << " of " << num_vertices(input)
            << " vertices moved, same points from both files' parameters\n";
  return 0;
}
