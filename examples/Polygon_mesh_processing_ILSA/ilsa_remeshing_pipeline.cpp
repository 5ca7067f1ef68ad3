// A remeshing pipeline: isotropic remeshing with the sharp edges protected,
// then ILSA on the remeshed surface, the same sharp edges kept as creases.
//
//   ilsa_remeshing_pipeline [INPUT [OUTPUT]]     (default: the bundled fandisk)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Surface_mesh.h>

#include "ilsa_example_data.h"

#include <iostream>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

int main(int argc, char** argv) {
  const std::string input = argc > 1 ? argv[1] : ilsa_data_file("fandisk.off");
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(input, mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "Cannot read a triangle mesh from " << input << "\n";
    return 1;
  }
  // Sharp edges: face normals more than 20 degrees apart (ILSA's default feature angle).
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(mesh, 20., sharp);

  // Remeshing splits and collapses edges; split sharp edges stay marked.
  double length = 0;
  for (auto e : edges(mesh)) length += PMP::edge_length(e, mesh);
  length /= double(num_edges(mesh));
  PMP::isotropic_remeshing(faces(mesh), length, mesh,
                           CGAL::parameters::number_of_iterations(3).edge_is_constrained_map(sharp));
  const auto remeshed = PMP::mesh_quality_ilsa(mesh);

  // ILSA: the crease vertices slide along the sharp edges (relax_constraints),
  // every vertex stays on the remeshed surface.
  PMP::smooth_surface_mesh_ilsa(mesh, CGAL::parameters::edge_is_constrained_map(sharp).relax_constraints(true));
  const auto smoothed = PMP::mesh_quality_ilsa(mesh);
  std::cout << "remeshed: " << num_faces(mesh) << " faces, mean aspect ratio " << remeshed.mean_aspect_ratio << ", min "
            << remeshed.min_aspect_ratio << "\nafter ILSA: mean " << smoothed.mean_aspect_ratio << ", min "
            << smoothed.min_aspect_ratio << "\n";
  if (argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17))) return 1;
  return smoothed.mean_aspect_ratio >= remeshed.mean_aspect_ratio ? 0 : 1;
}
