// Compile-time probe (benchmark/compile_time.sh): the same program calling
// CGAL's tangential_relaxation() instead.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Surface_mesh.h>

int main() {
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> mesh;
  CGAL::Polygon_mesh_processing::tangential_relaxation(mesh);
  return 0;
}
