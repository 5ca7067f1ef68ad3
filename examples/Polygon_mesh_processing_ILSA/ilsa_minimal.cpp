// Minimal use of the package: read a mesh, smooth it with ILSA, write it.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include "ilsa_example_data.h"

#include <iostream>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

int main(int argc, char** argv) {
  const std::string input = argc > 1 ? argv[1] : ilsa_data_file("fandisk.off");
  const std::string output = argc > 2 ? argv[2] : "fandisk_smoothed.off";

  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "Cannot read a triangle mesh from " << input << "\n";
    return 1;
  }
  try {
    PMP::smooth_surface_mesh_ilsa(mesh, CGAL::parameters::number_of_iterations(10).ilsa_feature_angle(20.));
  } catch (const PMP::ILSA_error& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  if (!CGAL::IO::write_polygon_mesh(output, mesh, CGAL::parameters::stream_precision(17))) return 1;
  std::cout << "Smoothed mesh written to " << output << "\n";
  return 0;
}
