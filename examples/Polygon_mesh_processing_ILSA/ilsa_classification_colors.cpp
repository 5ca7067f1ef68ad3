// The vertex types ILSA works with, written as a PLY file with vertex colours
// (smooth grey, ridge blue, corner red, boundary green) that mesh viewers show.
//
//   ilsa_classification_colors [INPUT [OUTPUT.ply]]     (default: the bundled fandisk, fandisk_types.ply)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/classify_vertices_ilsa.h>
#include <CGAL/Surface_mesh.h>

#include "ilsa_example_data.h"

#include <fstream>
#include <iostream>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

int main(int argc, char** argv) {
  const std::string input = argc > 1 ? argv[1] : ilsa_data_file("fandisk.off");
  const std::string output = argc > 2 ? argv[2] : "fandisk_types.ply";
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "Cannot read a triangle mesh from " << input << "\n";
    return 1;
  }
  auto types = mesh.add_property_map<Mesh::Vertex_index, PMP::ILSA_vertex_type>("v:ilsa_type").first;
  const auto s = PMP::classify_vertices_ilsa(mesh, types);

  auto colors = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  for (auto v : vertices(mesh)) {
    switch (types[v]) {
    case PMP::ILSA_vertex_type::Smooth:
      colors[v] = CGAL::IO::Color(190, 190, 190);
      break;
    case PMP::ILSA_vertex_type::Ridge:
      colors[v] = CGAL::IO::Color(30, 90, 220);
      break;
    case PMP::ILSA_vertex_type::Corner:
      colors[v] = CGAL::IO::Color(220, 30, 30);
      break;
    case PMP::ILSA_vertex_type::Boundary:
      colors[v] = CGAL::IO::Color(30, 170, 60);
      break;
    }
  }
  mesh.remove_property_map(types); // the PLY writer would write it as an unknown property
  std::ofstream out(output);
  if (!out || !CGAL::IO::write_PLY(out, mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << "Cannot write " << output << "\n";
    return 1;
  }
  std::cout << s.number_of_smooth_vertices << " smooth (grey), " << s.number_of_ridge_vertices << " ridge (blue), "
            << s.number_of_corner_vertices << " corner (red), " << s.number_of_boundary_vertices
            << " boundary (green) vertices written to " << output << "\n";
  return 0;
}
