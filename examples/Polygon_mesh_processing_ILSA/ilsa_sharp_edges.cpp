// Creases from PMP::detect_sharp_edges() handed to ILSA as an
// edge_is_constrained_map: kept in place (relax_constraints(false), CGAL's
// default), or with their vertices sliding along them (relax_constraints(true)).
//
//   ilsa_sharp_edges [INPUT [OUTPUT]]     (default: the bundled fandisk)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
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
  Mesh original;
  if (!CGAL::IO::read_polygon_mesh(input, original) || !CGAL::is_triangle_mesh(original)) {
    std::cerr << "Cannot read a triangle mesh from " << input << "\n";
    return 1;
  }
  // The same angle convention as ilsa_feature_angle: between face normals.
  auto sharp = original.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  PMP::detect_sharp_edges(original, 30., sharp);

  for (bool relax : {false, true}) {
    Mesh mesh = original; // a copy has the same edge indices and the property map
    // add_property_map() returns the copy's existing map (property_map() would
    // too, as a pair before CGAL 6 and as a std::optional since).
    const auto mesh_sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
    const auto s = PMP::smooth_surface_mesh_ilsa(
        mesh, CGAL::parameters::edge_is_constrained_map(mesh_sharp).relax_constraints(relax));
    // (The Hausdorff distance, the costly part of the summary, is not printed here.)
    const auto f = PMP::mesh_fidelity_ilsa(
        original, mesh, CGAL::parameters::edge_is_constrained_map(sharp).ilsa_compute_hausdorff_distance(false));
    std::cout << "relax_constraints(" << relax << "): " << s.number_of_ridge_vertices << " sliding crease vertices, "
              << f.number_of_sharp_edges << " crease edges, crease deviation " << f.max_crease_deviation
              << ", mean aspect ratio " << PMP::mesh_quality_ilsa(mesh).mean_aspect_ratio << "\n";
    if (relax && argc > 2 && !CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(17)))
      return 1;
  }
  return 0;
}
