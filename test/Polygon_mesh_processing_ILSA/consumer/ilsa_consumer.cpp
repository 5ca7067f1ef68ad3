// Smooths INPUT with the default parameters and writes OUTPUT as ilsa_smooth
// does (17 significant digits): the install test compares the two files.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: ilsa_consumer INPUT OUTPUT\n";
    return 2;
  }
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(argv[1], mesh)) return 1;
  CGAL::Polygon_mesh_processing::smooth_surface_mesh_ilsa<CGAL::Parallel_if_available_tag>(mesh);
  return CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17)) ? 0 : 1;
}
