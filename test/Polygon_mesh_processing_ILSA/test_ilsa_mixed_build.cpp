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

#include <cstdlib>
#include <iostream>
#include <string>

#define ILSA_CHECK(condition)                                                                                          \
  do {                                                                                                                 \
    if (!(condition)) {                                                                                                \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition "\n";                                  \
      std::exit(1);                                                                                                    \
    }                                                                                                                  \
  } while (false)

int main() {
  Mesh input;
  const std::string file = std::string(ILSA_DATA_DIR) + "/fandisk.off";
  ILSA_CHECK(CGAL::IO::read_polygon_mesh(file, input) && !is_empty(input));

  // CGAL's own smoother, its parameters from CGAL's list.
  Mesh relaxed = input;
  CGAL::Polygon_mesh_processing::tangential_relaxation(relaxed, CGAL::parameters::number_of_iterations(3));
  bool relaxation_moved = false;
  for (auto v : vertices(input)) relaxation_moved = relaxation_moved || relaxed.point(v) != input.point(v);
  ILSA_CHECK(relaxation_moved);

  // ILSA with parameters built here and with the same parameters built there.
  const std::vector<Kernel::Point_3> from_here = smooth_with(input, CGAL::parameters::number_of_iterations(3));
  const std::vector<Kernel::Point_3> from_there = smooth_with_own_parameters(input);
  ILSA_CHECK(from_here.size() == num_vertices(input));
  ILSA_CHECK(from_here == from_there);
  std::size_t moved = 0;
  std::size_t i = 0;
  for (auto v : vertices(input)) moved += from_here[i++] != input.point(v) ? 1 : 0;
  ILSA_CHECK(moved > num_vertices(input) / 2);

  // The package's tags chain in the package's file.
  ILSA_CHECK(iterations_of_chained_parameters(input) == 3);
  std::cout << "mixed build: " << moved << " of " << num_vertices(input)
            << " vertices moved, same points from both files' parameters\n";
  return 0;
}
