// Smoothing a region: the vertex-range overload moves only the given
// vertices, here those within a ball around a vertex; all others stay put.
//
//   ilsa_region [INPUT [OUTPUT]]     (default: the bundled elephant)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Surface_mesh.h>

#include "ilsa_example_data.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

int main(int argc, char** argv) {
  const std::string input = argc > 1 ? argv[1] : ilsa_data_file("elephant.off");
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || !CGAL::is_triangle_mesh(mesh) || is_empty(mesh)) {
    std::cerr << "Cannot read a triangle mesh from " << input << "\n";
    return 1;
  }
  // The region: vertices within a fifth of the bounding-box diagonal of the first vertex.
  const auto box = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  const double radius = 0.2 * std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                        CGAL::square(box.zmax() - box.zmin()));
  const K::Point_3 center = mesh.point(*vertices(mesh).begin());
  std::vector<Mesh::Vertex_index> region;
  for (auto v : vertices(mesh))
    if (CGAL::squared_distance(mesh.point(v), center) < radius * radius) region.push_back(v);

  const Mesh original = mesh;
  const auto s = PMP::smooth_surface_mesh_ilsa(region, mesh);
  std::size_t moved_inside = 0, moved_outside = 0;
  std::vector<bool> in_region(num_vertices(mesh), false);
  for (auto v : region) in_region[v] = true;
  for (auto v : vertices(mesh))
    if (mesh.point(v) != original.point(v)) (in_region[v] ? moved_inside : moved_outside) += 1;
  std::cout << region.size() << " of " << num_vertices(mesh) << " vertices in the region, " << moved_inside
            << " moved (" << s.number_of_iterations << " iterations); outside the region, " << moved_outside
            << " moved\n";
  if (argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17))) return 1;
  return moved_outside == 0 && moved_inside > 0 ? 0 : 1;
}
