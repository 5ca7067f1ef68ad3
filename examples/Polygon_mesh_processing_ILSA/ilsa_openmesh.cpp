// ILSA on an OpenMesh mesh through CGAL's graph traits. OpenMesh's default
// mesh stores float points, and CGAL 5.5.1's default point map for OpenMesh
// writes through float: this example uses a double-precision mesh and a point
// map that keeps its precision.
//
//   ilsa_openmesh [INPUT [OUTPUT]]     (default: the bundled fandisk; OFF, OBJ, STL, PLY as OpenMesh reads them)
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>

#include "ilsa_example_data.h"

#include <iostream>
#include <string>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct Double_traits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Double_traits>;

// Reads and writes the mesh's double points as CGAL points.
struct Double_point_map {
  using key_type = boost::graph_traits<Mesh>::vertex_descriptor;
  using value_type = K::Point_3;
  using reference = value_type;
  using category = boost::read_write_property_map_tag;
  Mesh* mesh;
  friend value_type get(const Double_point_map& m, key_type v) {
    const auto& p = m.mesh->point(v);
    return value_type(p[0], p[1], p[2]);
  }
  friend void put(const Double_point_map& m, key_type v, const value_type& p) {
    m.mesh->set_point(v, Mesh::Point(p.x(), p.y(), p.z()));
  }
};

int main(int argc, char** argv) {
  const std::string input = argc > 1 ? argv[1] : ilsa_data_file("fandisk.off");
  Mesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, input) || mesh.n_faces() == 0) {
    std::cerr << "Cannot read a mesh from " << input << "\n";
    return 1;
  }
  const Double_point_map points{&mesh};
  const auto np = CGAL::parameters::vertex_point_map(points);
  const double before = PMP::mesh_quality_ilsa(mesh, np).mean_aspect_ratio;
  try {
    PMP::smooth_surface_mesh_ilsa(mesh, np);
  } catch (const PMP::ILSA_error& e) { // e.g. a face that is not a triangle
    std::cerr << e.what() << "\n";
    return 1;
  }
  const double after = PMP::mesh_quality_ilsa(mesh, np).mean_aspect_ratio;
  std::cout << "OpenMesh: mean aspect ratio " << before << " -> " << after << "\n";
  if (argc > 2) {
    OpenMesh::IO::Options precision;
    if (!OpenMesh::IO::write_mesh(mesh, argv[2], precision, 17)) return 1;
  }
  return after > before ? 0 : 1;
}
