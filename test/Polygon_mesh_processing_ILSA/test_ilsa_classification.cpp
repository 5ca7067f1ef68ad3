// Vertex classification (paper §3) on shapes with known answers, on
// Surface_mesh and Polyhedron_3, and the user-constraint overrides; the API's
// conventions: the feature angle as CGAL's detect_sharp_edges() takes it,
// relax_constraints, named parameters in any order, index maps, point types.
#include "ilsa_test_utils.h"

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_concepts.h>

#include <boost/concept/assert.hpp>

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
  // The paper's rule gives 823 ridge and 38 corner vertices; by default one
  // ridge vertex is a crease kink and the 2 candidates without a sharp edge
  // are smooth (both checked below).
  assert(counts["ridge"] == 823 - 1);
  assert(counts["corner"] == 38 + 1 - 2);
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
  // The paper's four-type rule: no crease contrast, no open-crease rule, no kinks.
  const auto paper = CGAL::parameters::ilsa_paper_variant(true);
  const auto s =
      classify_with_rules(m, rules(20., true, [](Rules& r) { r.fix_unattached_candidates = false; }), relaxed);
  assert(s.number_of_corner_vertices == 36);
  assert(s.number_of_ridge_vertices == 823);
  assert(s.number_of_kink_vertices == 0);

  // Kinks (user manual): one ridge vertex of the paper's rule, where the crease
  // folds back (its two sharp edges meet at about 19 degrees), becomes a corner.
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, Type> with_kinks;
  const auto k =
      classify_with_rules(m, rules(20., false, [](Rules& r) { r.fix_unattached_candidates = true; }), with_kinks);
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
    assert(c > std::cos(160. * CGAL_PI / 180.)); // the edges meet at less than 160 degrees
  }
}

// Horse with the paper's rule: 1698 ridge and 2792 corner vertices.
void test_horse_counts() {
  const Surface_mesh m = read_mesh<Surface_mesh>(data_file("horse.ply"));
  std::map<Surface_mesh::Vertex_index, Type> types;
  // The paper's classification, and with kink angles.
  auto paper_with_kinks = [](double feature_angle, double kink) {
    return rules(feature_angle, true, [kink](Rules& r) { r.kink_angle_degrees = kink; });
  };
  const auto s =
      PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(types), CGAL::parameters::ilsa_paper_variant(true));
  assert(s.number_of_ridge_vertices == 1698);
  assert(s.number_of_corner_vertices == 2792);
  assert(s.number_of_smooth_vertices == 48485 - 1698 - 2792);
  // The default kink rule turns ridge vertices into corners, nothing else; a
  // larger kink angle fewer.
  const auto k = classify_with_rules(m, paper_with_kinks(20., 20.), types);
  const auto k45 = classify_with_rules(m, paper_with_kinks(20., 45.), types);
  assert(k.number_of_kink_vertices > k45.number_of_kink_vertices && k45.number_of_kink_vertices > 0);
  assert(k.number_of_ridge_vertices + k.number_of_kink_vertices == 1698);
  assert(k.number_of_corner_vertices == 2792 + k.number_of_kink_vertices);
  // A larger feature angle finds fewer features.
  const auto s120 = classify_with_rules(m, paper_with_kinks(60., 60.), types);
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
      CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(constrained)).relax_constraints(true));
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
  for (double angle : {-10., 180., 181., std::nan("")}) {
    bool thrown = false;
    try {
      PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t), CGAL::parameters::ilsa_feature_angle(angle));
    } catch (const PMP::ILSA_error&) {
      thrown = true;
    }
    assert(thrown);
  }
}

// ilsa_feature_angle is the angle between face normals, as in detect_sharp_edges().
template <class Mesh> void test_feature_angle_convention() {
  const int n = 6;
  const Mesh m = to_mesh<Mesh>(cube(n)); // faces meet at 90 degrees between normals along the cube's edges
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, Type> t;
  const auto below =
      PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t), CGAL::parameters::ilsa_feature_angle(89.));
  const auto above =
      PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t), CGAL::parameters::ilsa_feature_angle(91.));
  assert(below.number_of_ridge_vertices == std::size_t(12 * (n - 1)));
  assert(above.number_of_ridge_vertices == 0);
  auto sharp_count = [&](const auto& mesh, double angle) {
    std::map<typename boost::graph_traits<std::decay_t<decltype(mesh)>>::edge_descriptor, bool> sharp;
    PMP::detect_sharp_edges(mesh, angle, boost::make_assoc_property_map(sharp));
    std::size_t count = 0;
    for (const auto& e : sharp) count += e.second;
    return count;
  };
  assert(sharp_count(m, 89.) == std::size_t(12 * n) && sharp_count(m, 91.) == 0);
  // The crease edges of mesh_fidelity_ilsa are detect_sharp_edges()' at every angle.
  const Mesh fandisk = read_mesh<Mesh>(data_file("fandisk.off"));
  for (double angle : {10., 20., 35., 50., 80.}) {
    const std::size_t ours =
        PMP::mesh_fidelity_ilsa(fandisk, fandisk,
                                CGAL::parameters::ilsa_feature_angle(angle).ilsa_compute_hausdorff_distance(false))
            .number_of_sharp_edges;
    std::cout << "fandisk, feature angle " << angle << ": " << ours << " sharp edges, detect_sharp_edges "
              << sharp_count(fandisk, angle) << std::endl;
    assert(ours > 0 && ours == sharp_count(fandisk, angle));
  }
}

// relax_constraints(false), CGAL's default: the ends of constrained edges are fixed.
void test_relax_constraints() {
  const Surface_mesh m = to_mesh<Surface_mesh>(cube(4));
  std::map<Surface_mesh::Edge_index, bool> constrained;
  for (auto e : edges(m)) {
    const Point &a = m.point(source(e, m)), &b = m.point(target(e, m));
    constrained[e] = a.x() == 1 && a.y() == 1 && b.x() == 1 && b.y() == 1;
  }
  std::map<Surface_mesh::Vertex_index, Type> t;
  const auto np = CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(constrained));
  const auto held = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t), np);
  for (auto v : vertices(m))
    if (m.point(v).x() == 1 && m.point(v).y() == 1) assert(t[v] == Type::Corner);
  const auto relaxed = PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(t), np.relax_constraints(true));
  assert(held.number_of_ridge_vertices == 0 && relaxed.number_of_ridge_vertices == 3);
  assert(held.number_of_corner_vertices == 5 && relaxed.number_of_corner_vertices == 2);
}

// Named parameters chain in any order, also for the quality functions.
template <class Mesh> void test_named_parameters() {
  Mesh m = read_mesh<Mesh>(data_file("sphere_low.off"));
  using vd = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::map<vd, Point> flattened; // the sphere squashed: worse triangles
  for (auto v : vertices(m)) {
    const Point& p = get(CGAL::vertex_point, m, v);
    flattened[v] = Point(p.x(), p.y(), 0.2 * p.z());
  }
  const auto vpm = boost::make_assoc_property_map(flattened);
  const auto a = PMP::mesh_quality_ilsa(m, CGAL::parameters::vertex_point_map(vpm).ilsa_quality_threshold(0.9));
  const auto b = PMP::mesh_quality_ilsa(m, CGAL::parameters::ilsa_quality_threshold(0.9).vertex_point_map(vpm));
  const auto c =
      PMP::mesh_quality_ilsa(faces(m), m, CGAL::parameters::ilsa_quality_threshold(0.9).vertex_point_map(vpm));
  const auto plain = PMP::mesh_quality_ilsa(m);
  assert(a.threshold == 0.9 && plain.threshold == 0.3);
  assert(a.mean_aspect_ratio == b.mean_aspect_ratio && b.mean_aspect_ratio == c.mean_aspect_ratio);
  assert(a.share_below_threshold == b.share_below_threshold && a.share_below_threshold > plain.share_below_threshold);
  assert(a.mean_aspect_ratio < plain.mean_aspect_ratio);

  Mesh x = m, y = m;
  PMP::smooth_surface_mesh_ilsa(
      x, CGAL::parameters::number_of_iterations(3).ilsa_quality_floor(0.4).relax_constraints(true));
  PMP::smooth_surface_mesh_ilsa(
      y, CGAL::parameters::relax_constraints(true).ilsa_quality_floor(0.4).number_of_iterations(3));
  assert(points_of(x) == points_of(y) && !(points_of(x) == points_of(m)));

  // mesh_fidelity_ilsa: the Hausdorff distance (CGAL's bounded-error one) is
  // repeatable, whatever the named parameters' order, and the caller's CGAL
  // default generator is left as it was.
  CGAL::get_default_random() = CGAL::Random(7);
  const auto f1 = PMP::mesh_fidelity_ilsa(m, x, CGAL::parameters::random_seed(3).ilsa_feature_angle(30.));
  const int drawn = CGAL::get_default_random().get_int(0, 1 << 30);
  const auto f2 = PMP::mesh_fidelity_ilsa(m, x, CGAL::parameters::ilsa_feature_angle(30.).random_seed(3));
  CGAL::get_default_random() = CGAL::Random(7);
  assert(drawn == CGAL::get_default_random().get_int(0, 1 << 30));
  assert(f1.hausdorff_distance > 0 && f1.hausdorff_distance == f2.hausdorff_distance);
}

// The requirements the reference manual lists, checked on the types it names,
// and what follows from them: any integer index maps (in any order), a point
// type of another kernel constructible from three doubles.
void test_requirements() {
  using Polyhedron_with_id = CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3>;
  BOOST_CONCEPT_ASSERT((boost::concepts::VertexListGraph<Surface_mesh>));
  BOOST_CONCEPT_ASSERT((boost::concepts::EdgeListGraph<Surface_mesh>));
  BOOST_CONCEPT_ASSERT((CGAL::concepts::FaceListGraph<Surface_mesh>));
  BOOST_CONCEPT_ASSERT((CGAL::concepts::HalfedgeGraph<Surface_mesh>));
  BOOST_CONCEPT_ASSERT((boost::concepts::VertexListGraph<Polyhedron>));
  BOOST_CONCEPT_ASSERT((boost::concepts::EdgeListGraph<Polyhedron>));
  BOOST_CONCEPT_ASSERT((CGAL::concepts::FaceListGraph<Polyhedron>));
  BOOST_CONCEPT_ASSERT((CGAL::concepts::HalfedgeGraph<Polyhedron>));

  const Surface_mesh input = read_mesh<Surface_mesh>(data_file("fandisk.off"));
  Surface_mesh expected = input;
  PMP::smooth_surface_mesh_ilsa(expected, CGAL::parameters::number_of_iterations(3));

  // Index maps numbering the elements backwards give the same result.
  Polyhedron_with_id p = to_mesh<Polyhedron_with_id>(soup_of(input));
  std::map<Polyhedron_with_id::Vertex_handle, int> vertex_ids;
  std::map<Polyhedron_with_id::Facet_handle, long> face_ids;
  for (auto v : vertices(p)) vertex_ids[v] = int(num_vertices(p) - 1 - vertex_ids.size());
  for (auto f : faces(p)) face_ids[f] = long(num_faces(p) - 1 - face_ids.size());
  PMP::smooth_surface_mesh_ilsa(p, CGAL::parameters::number_of_iterations(3)
                                       .vertex_index_map(boost::make_assoc_property_map(vertex_ids))
                                       .face_index_map(boost::make_assoc_property_map(face_ids)));
  assert(points_of(p) == points_of(expected));

  // An index map that is not one to one is rejected, the mesh untouched.
  Polyhedron_with_id q = to_mesh<Polyhedron_with_id>(soup_of(input));
  std::map<Polyhedron_with_id::Vertex_handle, int> twice;
  for (auto v : vertices(q)) twice[v] = int(twice.size() / 2);
  bool thrown = false;
  try {
    PMP::smooth_surface_mesh_ilsa(q, CGAL::parameters::vertex_index_map(boost::make_assoc_property_map(twice)));
  } catch (const PMP::ILSA_error& e) {
    thrown = std::string(e.what()).find("vertex_index_map") != std::string::npos;
  }
  assert(thrown && points_of(q) == points_of(input));

  // A Surface_mesh with a removed face (indices with a gap until
  // collect_garbage()) gives the result of the collected mesh.
  Surface_mesh with_gap = input;
  CGAL::Euler::remove_face(halfedge(*std::prev(faces(with_gap).end()), with_gap), with_gap);
  assert(with_gap.has_garbage());
  Surface_mesh collected = with_gap;
  collected.collect_garbage();
  PMP::smooth_surface_mesh_ilsa(with_gap, CGAL::parameters::number_of_iterations(3));
  PMP::smooth_surface_mesh_ilsa(collected, CGAL::parameters::number_of_iterations(3));
  assert(points_of(with_gap) == points_of(collected) && !(points_of(collected) == points_of(input)));

  // Another kernel's point type: the computation runs in double either way.
  using SC = CGAL::Simple_cartesian<double>;
  CGAL::Surface_mesh<SC::Point_3> s; // the same vertices and faces, in the same order
  for (auto v : vertices(input)) s.add_vertex(SC::Point_3(input.point(v).x(), input.point(v).y(), input.point(v).z()));
  for (auto f : faces(input)) {
    std::vector<CGAL::Surface_mesh<SC::Point_3>::Vertex_index> corners;
    for (auto v : vertices_around_face(halfedge(f, input), input)) corners.emplace_back(std::size_t(v));
    s.add_face(corners);
  }
  PMP::smooth_surface_mesh_ilsa(s, CGAL::parameters::number_of_iterations(3));
  const auto e = points_of(expected);
  std::size_t i = 0, same = 0;
  for (auto v : vertices(s)) {
    const auto& pt = s.point(v);
    same += pt.x() == e[i].x() && pt.y() == e[i].y() && pt.z() == e[i].z();
    ++i;
  }
  assert(same == e.size());
  std::cout << "requirements: index maps, Simple_cartesian points: same result" << std::endl;
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
  test_feature_angle_convention<Surface_mesh>();
  test_feature_angle_convention<Polyhedron>();
  test_relax_constraints();
  test_named_parameters<Surface_mesh>();
  test_named_parameters<Polyhedron>();
  test_requirements();
  std::cout << "test_ilsa_classification: all checks passed\n";
  return 0;
}
