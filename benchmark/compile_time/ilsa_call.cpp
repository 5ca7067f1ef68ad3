// Compile-time probe (benchmark/compile_time.sh): one call of the smoother on
// an Epick Surface_mesh, as a minimal user program would make it.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Surface_mesh.h>

int main() {
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  CGAL::Polygon_mesh_processing::smooth_surface_mesh_ilsa(mesh);
  return 0;
}
