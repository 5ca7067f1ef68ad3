// Bad input: every case either throws ILSA_error and leaves the mesh exactly
// as it was, or is processed with no flipped face and no non-finite
// coordinate. The package's checks do not depend on NDEBUG: this test is
// built twice, with assertions on and with NDEBUG (ILSA_CHECK stays active).
#include "ilsa_test_utils.h"

#include <CGAL/Polygon_mesh_processing/repair.h>

#include <limits>

using namespace ilsa_test;

template <class Mesh> bool same_points(const Mesh& a, const Mesh& b) {
  const auto pa = points_of(a), pb = points_of(b);
  if (pa.size() != pb.size()) return false;
  for (std::size_t i = 0; i < pa.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!(pa[i][k] == pb[i][k]) && !(std::isnan(pa[i][k]) && std::isnan(pb[i][k]))) return false;
  return true;
}

// Runs `call` on a copy of `mesh`; it must throw ILSA_error and not touch the copy.
template <class Mesh, class Call> void expect_error(const Mesh& mesh, Call call, const char* what) {
  Mesh m = mesh;
  bool thrown = false;
  try {
    call(m);
  } catch (const PMP::ILSA_error& e) {
    thrown = true;
    std::cout << what << ": ILSA_error \"" << e.what() << "\"" << std::endl;
  }
  ILSA_CHECK(thrown);
  ILSA_CHECK(same_points(m, mesh));
}

// Smooths a copy; no exception, every coordinate finite, no face flipped.
template <class Mesh> Mesh expect_processed(const Mesh& mesh, const char* what) {
  Mesh m = mesh;
  const auto s = PMP::smooth_surface_mesh_ilsa(m);
  for (const Point& p : points_of(m)) ILSA_CHECK(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
  const auto n0 = face_normals_of(mesh), n1 = face_normals_of(m);
  std::size_t flipped = 0;
  for (std::size_t f = 0; f < n0.size(); ++f)
    if (n0[f].squared_length() > 0 && n0[f] * n1[f] < 0) ++flipped;
  std::cout << what << ": processed, " << s.number_of_moves << " moves, " << flipped << " flipped faces" << std::endl;
  ILSA_CHECK(flipped == 0);
  return m;
}

template <class Mesh> void test_non_triangle() {
  Mesh m;
  std::vector<Point> pts{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  std::vector<std::vector<std::size_t>> polygons{{0, 1, 2, 3}, {1, 4, 5, 2}};
  PMP::polygon_soup_to_polygon_mesh(pts, polygons, m);
  expect_error(
      m, [](Mesh& x) { PMP::smooth_surface_mesh_ilsa(x); }, "quad faces");
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, PMP::ILSA_vertex_type> t;
  expect_error(
      m, [&](Mesh& x) { PMP::classify_vertices_ilsa(x, boost::make_assoc_property_map(t)); },
      "quad faces (classification)");
  // The quality and fidelity summaries check their input as the smoother does.
  expect_error(
      m, [](Mesh& x) { PMP::mesh_quality_ilsa(x); }, "quad faces (quality summary)");
  expect_error(
      m, [](Mesh& x) { PMP::mesh_fidelity_ilsa(x, x); }, "quad faces (fidelity summary)");
}

template <class Mesh> void test_empty_and_tiny() {
  Mesh empty;
  const auto s = PMP::smooth_surface_mesh_ilsa(empty);
  ILSA_CHECK(s.number_of_iterations == 0 && is_empty(empty));
  std::cout << "empty mesh: no-op\n";

  Soup tri;
  tri.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.triangles = {{0, 1, 2}};
  const Mesh one = to_mesh<Mesh>(tri);
  Mesh m = one;
  const auto s1 = PMP::smooth_surface_mesh_ilsa(m);
  ILSA_CHECK(s1.number_of_boundary_vertices == 3 && s1.number_of_moves == 0 && same_points(m, one));
  std::cout << "single triangle: all boundary, unchanged\n";
}

void test_isolated_vertices() {
  Surface_mesh original = to_mesh<Surface_mesh>(cube(4));
  auto isolated = original.add_vertex(Point(5, 5, 5));
  perturb_on_surface(original, 0.3, 31);
  const Surface_mesh m = expect_processed(original, "isolated vertex");
  ILSA_CHECK(m.point(isolated) == Point(5, 5, 5));
  std::map<Surface_mesh::Vertex_index, PMP::ILSA_vertex_type> t;
  PMP::classify_vertices_ilsa(original, boost::make_assoc_property_map(t));
  ILSA_CHECK(t[isolated] == PMP::ILSA_vertex_type::Corner);
}

template <class Mesh> void test_components_and_self_intersection() {
  // Two cubes, the second overlapping the first: two components that intersect.
  Soup a = cube(4), b = cube(4);
  for (Point& p : b.points) p = Point(p.x() + 1., p.y() + 0.5, p.z() + 0.25);
  const std::size_t offset = a.points.size();
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  perturb_cube(a, 4, 0.2, 32);
  const Mesh original = to_mesh<Mesh>(a);
  const Mesh m = expect_processed(original, "two intersecting components");
  const auto r = check_invariants(original, m, [](std::size_t, const Point&) { return true; });
  ILSA_CHECK(r.max_distance <= 1e-9 && r.fixed_moved == 0);
}

template <class Mesh> void test_degenerate_faces() {
  // A grid whose vertex (2,2) sits exactly on the segment of its neighbours
  // (1,1)-(3,3): two zero-area faces. And a needle: a vertex 1e-9 off a segment.
  constexpr int n = 6;
  Soup s = grid(n);
  auto id = [](int i, int j) { return std::size_t(j * (n + 1) + i); };
  s.points[id(2, 2)] = CGAL::midpoint(s.points[id(1, 1)], s.points[id(3, 3)]);
  const Point needle_base = CGAL::midpoint(s.points[id(3, 4)], s.points[id(4, 5)]);
  s.points[id(4, 4)] = Point(needle_base.x() + 1e-9, needle_base.y(), 0);
  const Mesh original = to_mesh<Mesh>(s);
  ILSA_CHECK(PMP::mesh_quality_ilsa(original).number_of_degenerate_faces > 0);
  const Mesh m = expect_processed(original, "zero-area and needle faces");
  ILSA_CHECK(PMP::mesh_quality_ilsa(m).min_aspect_ratio > PMP::mesh_quality_ilsa(original).min_aspect_ratio);
  for (const Point& p : points_of(m)) ILSA_CHECK(p.z() == 0);
}

void test_duplicated_and_non_manifold_vertices() {
  // Non-manifold vertex: two half-disk fans in different planes sharing their
  // apex only (a Surface_mesh can hold it: the apex has two umbrellas).
  Surface_mesh m;
  const auto apex = m.add_vertex(Point(0, 0, 0));
  for (int side = 0; side < 2; ++side) {
    std::vector<Surface_mesh::Vertex_index> ring;
    for (int k = 0; k <= 3; ++k) {
      const double a = k * CGAL_PI / 3;
      ring.push_back(side == 0 ? m.add_vertex(Point(std::cos(a), std::sin(a), 0))
                               : m.add_vertex(Point(std::cos(a), 0, -std::sin(a))));
    }
    for (int k = 0; k < 3; ++k) {
      const auto f = m.add_face(apex, ring[k], ring[k + 1]);
      ILSA_CHECK(f != Surface_mesh::null_face());
    }
  }
  ILSA_CHECK(PMP::is_non_manifold_vertex(apex, m));
  const Surface_mesh r = expect_processed(m, "non-manifold vertex");
  ILSA_CHECK(r.point(apex) == m.point(apex));

  // Duplicated vertices: the grid's interior vertex (4, 4) is split into two
  // coincident vertices (a crack along part of its star); the other interior
  // vertices still move.
  Soup s = grid(8);
  const std::size_t split_vertex = 4 * 9 + 4, copy = s.points.size();
  s.points.push_back(s.points[split_vertex]);
  std::size_t split = 0;
  for (auto& tr : s.triangles)
    if ((tr[0] == split_vertex || tr[1] == split_vertex || tr[2] == split_vertex) && split < 3) {
      for (auto& i : tr)
        if (i == split_vertex) i = copy;
      ++split;
    }
  Surface_mesh cracked;
  PMP::polygon_soup_to_polygon_mesh(s.points, s.triangles, cracked);
  ILSA_CHECK(num_vertices(cracked) == 82);
  perturb_on_surface(cracked, 0.3, 35);
  const Surface_mesh smoothed = expect_processed(cracked, "duplicated vertices");
  ILSA_CHECK(!same_points(smoothed, cracked));
}

template <class Mesh> void test_non_finite() {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Soup s = grid(4);
    s.points[7] = Point(bad, 0.5, 0);
    const Mesh m = to_mesh<Mesh>(s);
    expect_error(
        m, [](Mesh& x) { PMP::smooth_surface_mesh_ilsa(x); },
        std::isnan(bad) ? "NaN coordinate" : "infinite coordinate");
    expect_error(
        m, [](Mesh& x) { PMP::mesh_quality_ilsa(x); }, "non-finite coordinate (quality summary)");
    expect_error(
        m, [](Mesh& x) { PMP::mesh_fidelity_ilsa(x, x); }, "non-finite coordinate (fidelity summary)");
  }
}

template <class Mesh> void test_constraints_and_ranges() {
  using vd = typename boost::graph_traits<Mesh>::vertex_descriptor;
  Mesh original = to_mesh<Mesh>(cube(4));
  perturb_on_surface(original, 0.3, 33);
  Mesh m = original;
  PMP::smooth_surface_mesh_ilsa(
      m, CGAL::parameters::vertex_is_constrained_map(CGAL::Static_boolean_property_map<vd, true>()));
  ILSA_CHECK(same_points(m, original));
  std::cout << "every vertex constrained: unchanged\n";

  std::vector<vd> none;
  PMP::smooth_surface_mesh_ilsa(none, m);
  ILSA_CHECK(same_points(m, original));
  std::cout << "empty vertex range: unchanged\n";

  // A vertex of another mesh.
  Mesh other = to_mesh<Mesh>(cube(6));
  std::vector<vd> foreign;
  for (auto v : vertices(other)) foreign.push_back(v);
  expect_error(
      original, [&](Mesh& x) { PMP::smooth_surface_mesh_ilsa(foreign, x); }, "vertices of another mesh");
}

// Translation by +1e7 and scaling by 1e-6: without the fidelity bound, the
// same result up to that map and the rounding of the coordinates. With it,
// the certificate cuts faces into pieces along the input's footprints, so the
// rounding can change a decision at the tolerance (user manual, "Known
// Limitations"): the results are then both certified and as good.
void test_offsets_and_scales() {
  Surface_mesh base = read_mesh<Surface_mesh>(data_file("fandisk.off"));
  perturb_on_surface(base, 0.3, 34);
  const double diagonal = bbox_diagonal(base), tolerance = PMP::internal::ILSA::defaults::fidelity_tolerance;
  for (double fidelity : {std::numeric_limits<double>::infinity(), tolerance}) {
    const auto np = CGAL::parameters::ilsa_fidelity_tolerance(fidelity);
    Surface_mesh reference = base;
    const auto reference_stats = PMP::smooth_surface_mesh_ilsa(reference, np);
    const double reference_q = PMP::mesh_quality_ilsa(reference).mean_aspect_ratio;
    for (const auto& map : std::vector<std::pair<double, double>>{{1., 1e7}, {1e-6, 0.}, {1e3, -1e4}}) {
      Surface_mesh m = base;
      for (auto v : vertices(m)) {
        const Point& p = m.point(v);
        m.point(v) =
            Point(map.first * p.x() + map.second, map.first * p.y() + map.second, map.first * p.z() + map.second);
      }
      const auto stats = PMP::smooth_surface_mesh_ilsa(m, np);
      double worst = 0;
      for (auto v : vertices(m)) {
        const Point& p = m.point(v);
        const Point back((p.x() - map.second) / map.first, (p.y() - map.second) / map.first,
                         (p.z() - map.second) / map.first);
        worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(back, reference.point(v))) / diagonal);
      }
      const double q = PMP::mesh_quality_ilsa(m).mean_aspect_ratio;
      std::cout << "fidelity tolerance " << fidelity << ", scale " << map.first << ", offset " << map.second
                << ": largest difference " << worst << " of the diagonal, mean q " << q << " (" << reference_q
                << "), certified " << stats.certified_distance << "\n";
      if (!std::isfinite(fidelity)) {
        // Input coordinates +1e7 carry about 2e-9 of absolute rounding.
        ILSA_CHECK(worst <= 1e-8);
      } else {
        ILSA_CHECK(stats.certified_distance <= tolerance && reference_stats.certified_distance <= tolerance);
        ILSA_CHECK(std::abs(q - reference_q) <= 1e-3);
      }
    }
  }
}

template <class Mesh> void test_invalid_parameters() {
  const Mesh m = to_mesh<Mesh>(cube(3));
  auto fails = [&](auto np, const char* what) {
    expect_error(
        m, [&](Mesh& x) { PMP::smooth_surface_mesh_ilsa(x, np); }, what);
  };
  fails(CGAL::parameters::ilsa_feature_angle(-5.), "negative feature angle");
  fails(CGAL::parameters::ilsa_quality_floor(1.), "quality floor 1");
  fails(CGAL::parameters::ilsa_fidelity_tolerance(0.), "fidelity tolerance 0");
  fails(CGAL::parameters::ilsa_fidelity_tolerance(-1e-3), "negative fidelity tolerance");
  fails(CGAL::parameters::ilsa_fidelity_tolerance(std::numeric_limits<double>::quiet_NaN()), "NaN fidelity tolerance");
  fails(CGAL::parameters::number_of_iterations(-3), "negative iterations");
  fails(CGAL::parameters::number_of_iterations(1000000000), "absurd iterations");
  fails(CGAL::parameters::ilsa_minimum_quality_gain(-1e-4), "negative minimum gain");
  fails(CGAL::parameters::ilsa_minimum_quality_gain(std::nan("")), "NaN minimum gain");
  fails(CGAL::parameters::ilsa_feature_angle(180.), "feature angle 180");

  // The summaries check their parameters as the smoother does.
  auto summary_fails = [&](auto summary, const char* what) {
    bool thrown = false;
    try {
      summary();
    } catch (const PMP::ILSA_error& e) {
      thrown = true;
      std::cout << what << ": ILSA_error: " << e.what() << "\n";
    }
    ILSA_CHECK(thrown);
  };
  summary_fails([&] { PMP::mesh_quality_ilsa(m, CGAL::parameters::ilsa_quality_threshold(1.5)); },
                "quality threshold 1.5");
  summary_fails([&] { PMP::mesh_quality_ilsa(m, CGAL::parameters::ilsa_quality_threshold(std::nan(""))); },
                "NaN quality threshold");
  summary_fails([&] { PMP::mesh_fidelity_ilsa(m, m, CGAL::parameters::ilsa_feature_angle(-1.)); },
                "fidelity summary, negative feature angle");
}

int main() {
  test_non_triangle<Surface_mesh>();
  test_non_triangle<Polyhedron>();
  test_empty_and_tiny<Surface_mesh>();
  test_empty_and_tiny<Polyhedron>();
  test_isolated_vertices();
  test_components_and_self_intersection<Surface_mesh>();
  test_components_and_self_intersection<Polyhedron>();
  test_degenerate_faces<Surface_mesh>();
  test_degenerate_faces<Polyhedron>();
  test_duplicated_and_non_manifold_vertices();
  test_non_finite<Surface_mesh>();
  test_non_finite<Polyhedron>();
  test_constraints_and_ranges<Surface_mesh>();
  test_constraints_and_ranges<Polyhedron>();
  test_offsets_and_scales();
  test_invalid_parameters<Surface_mesh>();
  test_invalid_parameters<Polyhedron>();
  std::cout << "test_ilsa_bad_input: all checks passed" << std::endl;
  return 0;
}
