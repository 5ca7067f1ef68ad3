// ILSA on a CGAL::Polyhedron_3: any triangle FaceGraph works the same way.
//
//   ilsa_polyhedron [INPUT [OUTPUT]]     (default: the bundled fandisk)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Polyhedron_3.h>

#include "ilsa_example_data.h"

#include <iostream>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Polyhedron_3<K>;

int main(int argc, char** argv) {
  const std::string input = argc > 1 ? argv[1] : ilsa_data_file("fandisk.off");
  Polyhedron mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "Cannot read a triangle mesh from " << input << "\n";
    return 1;
  }
  const double before = PMP::mesh_quality_ilsa(mesh).mean_aspect_ratio;
  const auto s = PMP::smooth_surface_mesh_ilsa(mesh);
  const double after = PMP::mesh_quality_ilsa(mesh).mean_aspect_ratio;
  std::cout << "Polyhedron_3: mean aspect ratio " << before << " -> " << after << " in " << s.number_of_iterations
            << " iterations\n";
  if (argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17))) return 1;
  return after > before ? 0 : 1;
}
