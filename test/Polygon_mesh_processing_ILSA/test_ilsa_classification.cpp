// Vertex classification (paper §3) on shapes with known answers, on
// Surface_mesh and Polyhedron_3, and the user-constraint overrides.
#include "ilsa_test_utils.h"

#include <CGAL/Polygon_mesh_processing/detect_features.h>

using namespace ilsa_test;
using Type = PMP::ILSA_vertex_type;

template <class Mesh> void test_cube() {
  const int n = 6;
  Soup soup = cube(n);
  perturb_cube(soup, n, 0.3, 1); // tangential noise must not change the answer
  const Mesh m = to_mesh<Mesh>(soup);
  const auto types = types_of(m);
  const auto pts = points_of(m);
  std::size_t corners = 0, ridges = 0, smooth = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const int extremal = cube_extremal_coordinates(pts[i]);
    const Type expected = extremal == 3 ? Type::Corner : extremal == 2 ? Type::Ridge : Type::Smooth;
    assert(types[i] == expected);
    corners += types[i] == Type::Corner;
    ridges += types[i] == Type::Ridge;
    smooth += types[i] == Type::Smooth;
  }
  assert(corners == 8);
  assert(ridges == 12 * (n - 1));
  assert(smooth == 6 * (n - 1) * (n - 1));
}

template <class Mesh> void test_grid() {
  const int n = 8;
  Soup soup = grid(n);
  perturb_grid(soup, n, 0.3, 2);
  const Mesh m = to_mesh<Mesh>(soup);
  const auto types = types_of(m);
  const auto pts = points_of(m);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const bool border = pts[i].x() == 0 || pts[i].y() == 0 || pts[i].x() == 1 || pts[i].y() == 1;
    assert(types[i] == (border ? Type::Boundary : Type::Smooth));
  }
}

// Fandisk: counts with the paper's 160° rule, and every ridge
// vertex lies on exactly two edges that CGAL's own detect_sharp_edges finds.
template <class Mesh> void test_fandisk() {
  const Mesh m = read_mesh<Mesh>(data_file("fandisk.off"));
  std::map<std::string, std::size_t> counts;
  const auto types = types_of(m, &counts);
  // The paper's rule gives 823 ridge and 38 corner vertices; one ridge vertex
  // is a crease kink by default (checked below).
  assert(counts["ridge"] == 823 - 1);
  assert(counts["corner"] == 38 + 1);
  assert(counts["boundary"] == 0);

  using ed = typename boost::graph_traits<Mesh>::edge_descriptor;
  std::map<ed, bool> sharp;
  PMP::detect_sharp_edges(m, 20., boost::make_assoc_property_map(sharp));
  std::size_t i = 0;
  for (auto v : vertices(m)) {
    if (types[i++] != Type::Ridge) continue;
    std::size_t incident = 0;
    for (auto h : halfedges_around_target(v, m)) incident += sharp[edge(h, m)];
    assert(incident == 2);
  }

  // Candidates without a sharp edge: with the paper's rule fandisk has 2 of
  // them; smoothing them turns exactly those into smooth vertices.
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, Type> relaxed;
  const auto paper = CGAL::parameters::ilsa_crease_kink_angle(180.); // the paper's four-type rule, no kinks
  const auto s = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(relaxed),
                                             paper.ilsa_fix_unattached_candidates(false));
  assert(s.number_of_corner_vertices == 36);
  assert(s.number_of_ridge_vertices == 823);
  assert(s.number_of_kink_vertices == 0);

  // Kinks (user manual): one ridge vertex of the paper's rule, where the crease
  // folds back (its two sharp edges meet at about 19 degrees), becomes a corner.
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, Type> with_kinks;
  const auto k = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(with_kinks));
  const auto p = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(relaxed), paper);
  assert(k.number_of_kink_vertices == 1);
  assert(k.number_of_ridge_vertices == p.number_of_ridge_vertices - 1);
  assert(k.number_of_corner_vertices == p.number_of_corner_vertices + 1);
  for (auto v : vertices(m)) {
    if (with_kinks[v] == relaxed[v]) continue;
    assert(relaxed[v] == Type::Ridge && with_kinks[v] == Type::Corner);
    std::vector<Point> ends;
    for (auto h : halfedges_around_target(v, m))
      if (sharp[edge(h, m)]) ends.push_back(get(CGAL::vertex_point, m, source(h, m)));
    assert(ends.size() == 2);
    const Point& x = get(CGAL::vertex_point, m, v);
    const double c =
        (ends[0] - x) * (ends[1] - x) / std::sqrt((ends[0] - x).squared_length() * (ends[1] - x).squared_length());
    assert(c > std::cos(160. * 3.14159265358979323846 / 180.)); // the edges meet at less than 160 degrees
  }
}

// Horse with the paper's rule: 1698 ridge and 2792 corner vertices.
void test_horse_counts() {
  const Surface_mesh m = read_mesh<Surface_mesh>(data_file("horse.ply"));
  std::map<Surface_mesh::Vertex_index, Type> types;
  const auto s = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(types),
                                             CGAL::parameters::ilsa_crease_kink_angle(180.));
  assert(s.number_of_ridge_vertices == 1698);
  assert(s.number_of_corner_vertices == 2792);
  assert(s.number_of_smooth_vertices == 48485 - 1698 - 2792);
  // The default kink rule turns ridge vertices into corners, nothing else; a
  // larger kink angle fewer.
  const auto k = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(types));
  const auto k45 = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(types),
                                               CGAL::parameters::ilsa_crease_kink_angle(45.));
  assert(k.number_of_kink_vertices > k45.number_of_kink_vertices && k45.number_of_kink_vertices > 0);
  assert(k.number_of_ridge_vertices + k.number_of_kink_vertices == 1698);
  assert(k.number_of_corner_vertices == 2792 + k.number_of_kink_vertices);
  // A smaller feature angle finds fewer features.
  const auto s120 =
      PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(types), CGAL::parameters::ilsa_feature_angle(120.));
  assert(s120.number_of_ridge_vertices + s120.number_of_corner_vertices <
         s.number_of_ridge_vertices + s.number_of_corner_vertices);
}

// User constraints override the detection.
template <class Mesh> void test_user_constraints() {
  using vd = typename boost::graph_traits<Mesh>::vertex_descriptor;
  using ed = typename boost::graph_traits<Mesh>::edge_descriptor;
  const int n = 4;
  const Mesh m = to_mesh<Mesh>(cube(n));

  // A constrained smooth vertex becomes a corner.
  std::map<vd, bool> fixed;
  vd face_center = *vertices(m).begin();
  for (auto v : vertices(m))
    if (cube_extremal_coordinates(get(CGAL::vertex_point, m, v)) == 1) face_center = v;
  fixed[face_center] = true;
  std::map<vd, Type> t1;
  PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t1),
                              CGAL::parameters::vertex_is_constrained_map(boost::make_assoc_property_map(fixed)));
  assert(t1[face_center] == Type::Corner);

  // Constrained edges replace the sharp edges: only the cube edge x = y = 1 is
  // marked; its inner vertices are ridges, its ends corners, all else smooth.
  std::map<ed, bool> constrained;
  for (auto e : edges(m)) {
    const Point& a = get(CGAL::vertex_point, m, source(e, m));
    const Point& b = get(CGAL::vertex_point, m, target(e, m));
    constrained[e] = a.x() == 1 && a.y() == 1 && b.x() == 1 && b.y() == 1;
  }
  std::map<vd, Type> t2;
  const auto s = PMP::classify_vertices_ilsa(
      m, boost::make_assoc_property_map(t2),
      CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(constrained)));
  for (auto v : vertices(m)) {
    const Point& p = get(CGAL::vertex_point, m, v);
    const bool on_edge = p.x() == 1 && p.y() == 1;
    const bool end = on_edge && std::abs(p.z()) == 1;
    assert(t2[v] == (end ? Type::Corner : on_edge ? Type::Ridge : Type::Smooth));
  }
  assert(s.number_of_ridge_vertices == std::size_t(n - 1));
  assert(s.number_of_corner_vertices == 2);
}

void test_parameter_check() {
  const Surface_mesh m = to_mesh<Surface_mesh>(cube(2));
  std::map<Surface_mesh::Vertex_index, Type> t;
  for (double angle : {0., -10., 181., std::nan("")}) {
    bool thrown = false;
    try {
      PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t), CGAL::parameters::ilsa_feature_angle(angle));
    } catch (const PMP::ILSA_error&) {
      thrown = true;
    }
    assert(thrown);
  }
  for (double kink : {-1., 181., std::nan("")}) {
    bool thrown = false;
    try {
      PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t), CGAL::parameters::ilsa_crease_kink_angle(kink));
    } catch (const PMP::ILSA_error&) {
      thrown = true;
    }
    assert(thrown);
  }
}

int main() {
  test_cube<Surface_mesh>();
  test_cube<Polyhedron>();
  test_grid<Surface_mesh>();
  test_grid<Polyhedron>();
  test_fandisk<Surface_mesh>();
  test_fandisk<Polyhedron>();
  test_horse_counts();
  test_user_constraints<Surface_mesh>();
  test_user_constraints<Polyhedron>();
  test_parameter_check();
  std::cout << "test_ilsa_classification: all checks passed\n";
  return 0;
}
