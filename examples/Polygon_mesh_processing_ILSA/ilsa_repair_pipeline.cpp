// From a polygon soup to a smoothed mesh: repair the soup, orient it, build a
// mesh, triangulate its faces, then smooth it with ILSA.
//
//   ilsa_repair_pipeline [INPUT [OUTPUT]]     (default: the bundled shark part; any polygon file CGAL reads)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include "ilsa_example_data.h"

#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

int main(int argc, char** argv) {
  const std::string input = argc > 1 ? argv[1] : ilsa_data_file("mech-holes-shark.off");
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(input, points, polygons) || polygons.empty()) {
    std::cerr << "Cannot read a polygon soup from " << input << "\n";
    return 1;
  }
  PMP::repair_polygon_soup(points, polygons); // duplicate points and polygons, degenerate polygons
  PMP::orient_polygon_soup(points, polygons); // consistent orientation, non-manifold vertices duplicated
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    std::cerr << "The soup does not describe a polygon mesh after repair\n";
    return 1;
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  PMP::triangulate_faces(mesh);

  const auto before = PMP::mesh_quality_ilsa(mesh);
  const auto s = PMP::smooth_surface_mesh_ilsa(mesh);
  const auto after = PMP::mesh_quality_ilsa(mesh);
  std::cout << polygons.size() << " polygons -> " << num_faces(mesh) << " triangles; mean aspect ratio "
            << before.mean_aspect_ratio << " -> " << after.mean_aspect_ratio << ", min " << before.min_aspect_ratio
            << " -> " << after.min_aspect_ratio << " (" << s.number_of_boundary_vertices
            << " boundary vertices fixed)\n";
  if (argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17))) return 1;
  return after.mean_aspect_ratio > before.mean_aspect_ratio ? 0 : 1;
}
