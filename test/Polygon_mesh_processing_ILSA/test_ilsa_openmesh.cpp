// ILSA on an OpenMesh TriMesh_ArrayKernelT through CGAL's graph traits: the
// same result as on a Surface_mesh, and the smoothing invariants (the
// fidelity certificate among them).
#include "ilsa_test_utils.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>

using namespace ilsa_test;
namespace ilsa = CGAL::Polygon_mesh_processing::internal::ILSA;

struct Double_traits : public OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point; // full precision, like the CGAL meshes
  typedef OpenMesh::Vec3d Normal;
};
using Open_mesh = OpenMesh::TriMesh_ArrayKernelT<Double_traits>;
using om_vertex = boost::graph_traits<Open_mesh>::vertex_descriptor;

// CGAL 5.5.1's default OpenMesh point map writes points through float
// (properties_OpenMesh.h casts them); this map keeps the mesh's double precision.
struct Full_precision_point_map {
  using key_type = om_vertex;
  using value_type = Point;
  using reference = Point;
  using category = boost::read_write_property_map_tag;
  Open_mesh* mesh;
  friend Point get(const Full_precision_point_map& m, key_type v) {
    const auto& p = m.mesh->point(v);
    return Point(p[0], p[1], p[2]);
  }
  friend void put(const Full_precision_point_map& m, key_type v, const Point& p) {
    m.mesh->set_point(v, Open_mesh::Point(p.x(), p.y(), p.z()));
  }
};

Open_mesh build(const Soup& soup) {
  Open_mesh om;
  std::vector<Open_mesh::VertexHandle> handles;
  for (const Point& p : soup.points) handles.push_back(om.add_vertex(Open_mesh::Point(p.x(), p.y(), p.z())));
  for (const auto& t : soup.triangles) om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  return om;
}

int main() {
  Surface_mesh sm = read_mesh<Surface_mesh>(data_file("fandisk.off"));
  perturb_on_surface(sm, 0.3, 21);
  Soup soup = soup_of(sm);
  Open_mesh om = build(soup);
  assert(num_vertices(om) == num_vertices(sm) && num_faces(om) == num_faces(sm));
  const Open_mesh original = om;
  Open_mesh om_default_map = om;

  const auto np = CGAL::parameters::number_of_iterations(10);
  const auto s_om = PMP::smooth_surface_mesh_ilsa(om, np.vertex_point_map(Full_precision_point_map{&om}));
  PMP::smooth_surface_mesh_ilsa(om_default_map, np);
  const auto s_sm = PMP::smooth_surface_mesh_ilsa(sm, np);
  assert(s_om.number_of_ridge_vertices == s_sm.number_of_ridge_vertices);
  assert(s_om.number_of_corner_vertices == s_sm.number_of_corner_vertices);
  assert(s_om.number_of_moves > 0);

  const double diagonal = bbox_diagonal(sm);
  const double difference = max_difference(points_of(om), points_of(sm));
  const double float_difference = max_difference(points_of(om_default_map), points_of(sm));
  std::cout << "OpenMesh vs Surface_mesh: max difference " << difference
            << " (default point map, through float: " << float_difference << ")" << std::endl;
  assert(difference <= 1e-12 * diagonal);
  assert(float_difference <= 1e-6 * diagonal);

  // The fidelity certificate on this mesh type: CGAL's bounded-error distance
  // (within hausdorff_error above the true one) and ILSA's bound within the
  // default tolerance, up to the write-back of normalised coordinates.
  const auto f = PMP::mesh_fidelity_ilsa(original, om);
  const double tolerance = ilsa::defaults::fidelity_tolerance;
  std::cout << "OpenMesh: flipped " << f.number_of_flipped_faces << ", max distance " << f.max_vertex_distance
            << ", Hausdorff " << f.hausdorff_distance << " (ILSA's bound " << s_om.certified_distance << ", tolerance "
            << tolerance << ")" << std::endl; // flushed: an assertion below may abort
  assert(f.number_of_flipped_faces == 0);
  assert(f.max_vertex_distance <= 1e-9);
  assert(f.hausdorff_distance <= tolerance + f.hausdorff_error + 1e-12);
  assert(s_om.certified_distance <= tolerance);
  assert(PMP::mesh_quality_ilsa(om).mean_aspect_ratio > PMP::mesh_quality_ilsa(original).mean_aspect_ratio);
  std::cout << "test_ilsa_openmesh: all checks passed\n";
  return 0;
}
