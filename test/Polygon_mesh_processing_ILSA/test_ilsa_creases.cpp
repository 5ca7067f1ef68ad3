// Creases keep their shape (user manual, "Crease Kinks" and "Fidelity Certificate"): a vertex where a crease turns by
// more than the kink angle stays bit-identical, like a corner; a gently curved crease still lets its vertices slide;
// the input's sharp edges and the same edges of the result stay within the fidelity tolerance of each other, both ways
// (mesh_fidelity_ilsa). Also with the creases given through edge_is_constrained_map.
//
// The meshes are height fields z = s·dist((x, y), R) over a square, R a convex
// region of the plane: flat inside R, rising at slope s outside, smooth
// (C1) away from the boundary of R, which is the only crease. The boundary is
// a polyline with bends of chosen angles; the triangulation (constrained
// Delaunay) has it as edges.
#include "ilsa_test_utils.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>

using namespace ilsa_test;

namespace {

using P2 = K::Point_2;
const double pi = CGAL_PI;
// The default fidelity tolerance, of the bounding-box diagonal, and the rounding of the write-back.
const double tolerance = PMP::internal::ILSA::defaults::fidelity_tolerance + 1e-12;

struct Crease_mesh {
  Soup soup;
  std::vector<P2> corners;                                    // the bends of the crease polyline, in order
  std::vector<std::size_t> kinks;                             // vertices where the crease turns by more than 20 degrees
  std::vector<std::size_t> crease;                            // every vertex of the crease polyline
  std::set<std::pair<std::size_t, std::size_t>> crease_edges; // vertex pairs, lower index first
};

double distance_to_segment(const P2& p, const P2& a, const P2& b) {
  return std::sqrt(CGAL::squared_distance(p, K::Segment_2(a, b)));
}

// Distance from `p` to the convex polygon `R` (counterclockwise; two points
// make a wedge with its apex at R[1] and rays through R[0] and R[2]).
double distance_to_region(const P2& p, const std::vector<P2>& R, bool wedge) {
  const std::size_t n = R.size();
  bool inside = true;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + (wedge ? 1 : 0) < n; ++i) {
    const P2 &a = R[i], &b = R[(i + 1) % n];
    inside = inside && CGAL::orientation(a, b, p) != CGAL::RIGHT_TURN;
    d = (std::min)(d, distance_to_segment(p, a, b));
  }
  return inside ? 0. : d;
}

// The crease polyline `corners` (closed unless `wedge`), sampled every `h`,
// constrained into a Delaunay triangulation of the square [-1, 1]² with grid
// points `h` apart, lifted to z = slope · dist(., R).
Crease_mesh make_crease_mesh(const std::vector<P2>& corners, bool wedge, double h, double slope = 1.) {
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K>;
  CDT cdt;
  Crease_mesh r;
  r.corners = corners;
  const std::size_t n = corners.size(), segments = wedge ? n - 1 : n;
  std::vector<std::vector<CDT::Vertex_handle>> polyline(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    const P2 &a = corners[i], &b = corners[(i + 1) % n];
    const int steps = (std::max)(1, int(std::ceil(std::sqrt(CGAL::squared_distance(a, b)) / h)));
    for (int k = 0; k <= steps; ++k) // the ends exactly: consecutive segments share them
      polyline[i].push_back(cdt.insert(k == 0 ? a : k == steps ? b : a + (double(k) / steps) * (b - a)));
    for (int k = 0; k < steps; ++k) cdt.insert_constraint(polyline[i][k], polyline[i][k + 1]);
  }
  const int cells = int(std::round(2. / h));
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const P2 p(-1. + 2. * i / cells, -1. + 2. * j / cells);
      bool near = false;
      for (std::size_t s = 0; s < segments; ++s)
        near = near || distance_to_segment(p, corners[s], corners[(s + 1) % n]) < 0.4 * h;
      if (!near) cdt.insert(p);
    }
  std::map<CDT::Vertex_handle, std::size_t> index;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    const P2& p = v->point();
    index[v] = r.soup.points.size();
    r.soup.points.emplace_back(p.x(), p.y(), slope * distance_to_region(p, corners, wedge));
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    r.soup.triangles.push_back({index[f->vertex(0)], index[f->vertex(1)], index[f->vertex(2)]});
  // Bends sharper than 20 degrees of turning: the kinks; every sample: the crease.
  for (std::size_t i = 0; i < segments; ++i) {
    for (std::size_t k = 0; k + 1 < polyline[i].size(); ++k) {
      std::size_t a = index[polyline[i][k]], b = index[polyline[i][k + 1]];
      r.crease_edges.insert({(std::min)(a, b), (std::max)(a, b)});
      r.crease.push_back(a);
    }
  }
  if (wedge) r.crease.push_back(index[polyline.back().back()]); // a closed polyline ends where it starts
  for (std::size_t i = wedge ? 1 : 0; i < (wedge ? n - 1 : n); ++i) {
    const auto u = corners[i] - corners[(i + n - 1) % n], w = corners[(i + 1) % n] - corners[i];
    const double turn = std::acos(u * w / std::sqrt(u.squared_length() * w.squared_length())) * 180. / pi;
    if (turn > 20.) r.kinks.push_back(index[polyline[i].front()]);
  }
  return r;
}

// A wedge whose crease bends once, at the origin, by `angle` degrees between
// its two edges (180 = straight), symmetric about the x axis.
Crease_mesh wedge(double angle, double h) {
  const double a = angle * pi / 360.;
  return make_crease_mesh({P2(std::cos(a), -std::sin(a)), P2(0, 0), P2(std::cos(a), std::sin(a))}, true, h);
}

// A triangle with interior angles 20, 60 and 100 degrees.
Crease_mesh triangle_region(double h) {
  const double A = 20 * pi / 180, B = 60 * pi / 180, C = 100 * pi / 180;
  const double b = std::sin(B) / std::sin(C); // side lengths by the sine rule, |AB| = 1
  const P2 pA(-0.6, -0.3), pB(0.4, -0.3), pC(-0.6 + b * std::cos(A), -0.3 + b * std::sin(A));
  return make_crease_mesh({pA, pB, pC}, false, h);
}

// A regular 40-gon of radius 0.6: a gently curved crease (9 degrees per bend).
Crease_mesh circle_region(double h) {
  std::vector<P2> c;
  for (int i = 0; i < 40; ++i) c.emplace_back(0.6 * std::cos(2 * pi * i / 40), 0.6 * std::sin(2 * pi * i / 40));
  return make_crease_mesh(c, false, h);
}

struct Outcome {
  std::size_t kinks_moved = 0, crease_moved = 0, flipped = 0, kink_vertices = 0;
  double crease_deviation = 0;
};

// The crease edges of `cm` as an edge map of `m` (built from `cm.soup`: the
// soup's vertex i is the mesh's i-th vertex).
template <class Mesh>
std::map<typename boost::graph_traits<Mesh>::edge_descriptor, bool> crease_map(const Crease_mesh& cm, const Mesh& m) {
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> id;
  for (auto v : vertices(m)) id.emplace(v, id.size());
  std::map<typename boost::graph_traits<Mesh>::edge_descriptor, bool> constrained;
  for (auto e : edges(m)) {
    const std::size_t a = id.at(source(e, m)), b = id.at(target(e, m));
    constrained[e] = cm.crease_edges.count({(std::min)(a, b), (std::max)(a, b)}) > 0;
  }
  return constrained;
}

// With constrained edges, `relax` is relax_constraints: true lets their vertices slide.
template <class Mesh>
Outcome smooth(const Crease_mesh& cm, bool constrained_edges, const char* what, bool relax = true) {
  const Mesh original = to_mesh<Mesh>(cm.soup);
  Mesh m = original;
  auto constrained = crease_map(cm, m);
  PMP::ILSA_statistics s;
  if (constrained_edges)
    s = PMP::smooth_surface_mesh_ilsa(
        m, CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(constrained))
               .relax_constraints(relax));
  else
    s = PMP::smooth_surface_mesh_ilsa(m);
  const auto before = points_of(original), after = points_of(m);
  Outcome o;
  o.kink_vertices = s.number_of_kink_vertices;
  for (std::size_t v : cm.kinks) o.kinks_moved += !(before[v] == after[v]);
  for (std::size_t v : cm.crease) o.crease_moved += !(before[v] == after[v]);
  // The crease edges the deviation compares: with the map, the map's edges.
  auto original_creases = crease_map(cm, original);
  const auto no_hausdorff = CGAL::parameters::ilsa_compute_hausdorff_distance(false); // (not checked here)
  const auto f =
      constrained_edges
          ? PMP::mesh_fidelity_ilsa(
                original, m, no_hausdorff.edge_is_constrained_map(boost::make_assoc_property_map(original_creases)))
          : PMP::mesh_fidelity_ilsa(original, m, no_hausdorff);
  if (constrained_edges) assert(f.number_of_sharp_edges == cm.crease_edges.size());
  o.flipped = f.number_of_flipped_faces;
  o.crease_deviation = f.max_crease_deviation;
  std::cout << what << (constrained_edges ? " (edge_is_constrained_map)" : "") << ": " << cm.kinks.size() << " kinks, "
            << o.kinks_moved << " moved; " << s.number_of_kink_vertices << " kink vertices; " << o.crease_moved
            << " of " << cm.crease.size() << " crease vertices moved; crease deviation " << o.crease_deviation
            << "; flipped " << o.flipped << "; mean q " << PMP::mesh_quality_ilsa(original).mean_aspect_ratio << " -> "
            << PMP::mesh_quality_ilsa(m).mean_aspect_ratio << std::endl;
  assert(s.number_of_moves > 0);
  return o;
}

template <class Mesh> void test_kinks_stay_and_creases_keep_shape() {
  const double h = 0.07;
  for (bool constrained : {false, true}) {
    for (double angle : {20., 60., 120., 170.}) {
      const Crease_mesh cm = wedge(angle, h);
      assert(cm.kinks.size() == (angle < 160. ? 1u : 0u));
      const Outcome o = smooth<Mesh>(cm, constrained, ("wedge " + std::to_string(int(angle))).c_str());
      assert(o.kinks_moved == 0);
      assert(o.kink_vertices >= cm.kinks.size());
      assert(o.flipped == 0);
      assert(o.crease_deviation <= tolerance);
    }
    const Crease_mesh triangle = triangle_region(h);
    assert(triangle.kinks.size() == 3);
    const Outcome t = smooth<Mesh>(triangle, constrained, "triangle 20/60/100");
    assert(t.kinks_moved == 0);
    assert(t.flipped == 0);
    assert(t.crease_deviation <= tolerance);

    // Gently curved: no kink, the crease vertices slide, within the tolerance.
    const Crease_mesh circle = circle_region(h);
    assert(circle.kinks.empty());
    const Outcome c = smooth<Mesh>(circle, constrained, "40-gon");
    assert(c.kink_vertices == 0);
    assert(c.crease_moved > circle.crease.size() / 4);
    assert(c.flipped == 0);
    assert(c.crease_deviation <= tolerance);
    if (constrained) {
      // CGAL's default, relax_constraints(false): the constrained edges stay, the rest is smoothed.
      const Outcome held = smooth<Mesh>(circle, true, "40-gon, relax_constraints(false)", false);
      assert(held.crease_moved == 0 && held.crease_deviation <= 1e-15); // rounding of the sampled points
      assert(held.flipped == 0);
    }
  }
}

// Each of the two mechanisms alone. Without the fidelity bound, the kink rule
// keeps the tip of a sharp wedge and the paper's variant lets it slide along
// the crease; without the kink rule, the crease bound keeps the crease within
// the tolerance.
void test_kink_rule_and_crease_bound_alone() {
  const Crease_mesh cm = wedge(60., 0.07);
  const Surface_mesh original = to_mesh<Surface_mesh>(cm.soup);
  const double unbounded = std::numeric_limits<double>::infinity();
  // The kink rule is the package's (the paper's variant has none).
  auto tip_moved = [&](bool paper) {
    Surface_mesh m = original;
    auto creases = crease_map(cm, m);
    const auto s =
        PMP::smooth_surface_mesh_ilsa(m, CGAL::parameters::ilsa_paper_variant(paper)
                                             .ilsa_fidelity_tolerance(unbounded)
                                             .edge_is_constrained_map(boost::make_assoc_property_map(creases))
                                             .relax_constraints(true));
    assert((s.number_of_kink_vertices == 0) == paper);
    return !(points_of(m)[cm.kinks[0]] == points_of(original)[cm.kinks[0]]);
  };
  assert(!tip_moved(false));
  assert(tip_moved(true));

  for (const Crease_mesh& c : {cm, triangle_region(0.07)}) {
    const Surface_mesh input = to_mesh<Surface_mesh>(c.soup);
    Surface_mesh m = input;
    const auto paper = CGAL::parameters::ilsa_paper_variant(true);
    PMP::smooth_surface_mesh_ilsa(m, paper);
    const double deviation =
        PMP::mesh_fidelity_ilsa(input, m, paper.ilsa_compute_hausdorff_distance(false)).max_crease_deviation;
    std::cout << "kink rule off: crease deviation " << deviation << std::endl;
    assert(deviation <= tolerance);
  }
}

// The vertex-range overload: every fifth crease vertex of the 40-gon is
// held (outside the range), its crease neighbours move; the bound holds.
template <class Mesh> void test_vertex_range() {
  const Crease_mesh cm = circle_region(0.07);
  const Mesh original = to_mesh<Mesh>(cm.soup);
  Mesh m = original;
  std::set<std::size_t> held;
  for (std::size_t k = 0; k < cm.crease.size(); k += 5) held.insert(cm.crease[k]);
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> range;
  std::size_t i = 0;
  for (auto v : vertices(m))
    if (!held.count(i++)) range.push_back(v);
  const auto s = PMP::smooth_surface_mesh_ilsa(range, m);
  assert(s.number_of_moves > 0);
  const auto before = points_of(original), after = points_of(m);
  std::size_t crease_moved = 0;
  for (std::size_t v : cm.crease) {
    if (held.count(v)) assert(before[v] == after[v]);
    crease_moved += !(before[v] == after[v]);
  }
  const double deviation =
      PMP::mesh_fidelity_ilsa(original, m, CGAL::parameters::ilsa_compute_hausdorff_distance(false))
          .max_crease_deviation;
  std::cout << "vertex range: " << crease_moved << " crease vertices moved, crease deviation " << deviation
            << std::endl;
  assert(crease_moved > 0);
  assert(deviation <= tolerance);
}

// The measure is two-sided: a crease cut short (its tip moved along one of its
// own edges, so every smoothed point still lies on the input crease) shows.
void test_two_sided_measure() {
  const Crease_mesh cm = wedge(60., 0.07);
  const Surface_mesh original = to_mesh<Surface_mesh>(cm.soup);
  Surface_mesh cut = original;
  const std::size_t tip = cm.kinks[0];
  // The tip's crease neighbours: the first samples along the two rays.
  std::vector<std::size_t> ends;
  for (const auto& e : cm.crease_edges)
    if (e.first == tip || e.second == tip) ends.push_back(e.first == tip ? e.second : e.first);
  assert(ends.size() == 2);
  const auto p = points_of(original);
  const Point moved = p[tip] + 0.5 * (p[ends[0]] - p[tip]);
  put(CGAL::vertex_point, cut, *std::next(vertices(cut).begin(), std::ptrdiff_t(tip)), moved);
  // The input tip's distance to the smoothed crease: to the segment moved-ends[1].
  const double expected = std::sqrt(CGAL::squared_distance(p[tip], K::Segment_3(moved, p[ends[1]])));
  const double diagonal = bbox_diagonal(original);
  // The wedge's crease only (its cone has more edges with a small dihedral angle).
  auto creases = crease_map(cm, original);
  const auto np = CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(creases))
                      .ilsa_compute_hausdorff_distance(false);
  const auto f = PMP::mesh_fidelity_ilsa(original, cut, np);
  std::cout << "cut tip: crease deviation " << f.max_crease_deviation << ", expected " << expected / diagonal
            << std::endl;
  assert(std::abs(f.max_crease_deviation - expected / diagonal) <= 1e-12);
  assert(f.mean_crease_deviation > 0 && f.mean_crease_deviation < f.max_crease_deviation);
  assert(f.number_of_sharp_edges == cm.crease_edges.size());
  assert(PMP::mesh_fidelity_ilsa(original, original, np).max_crease_deviation <= 1e-15); // rounding only
}

// The crease contrast (user manual, "Crease Contrast"): the creases of a CAD
// model stay creases (the fandisk keeps its ridge vertices), the curvature of
// a coarse organic mesh is no longer taken for creases (the elephant's
// corners drop to less than a third); 0 is the paper's rule. The other rules
// of the classification as in the paper. Smoothed, the elephant's feature
// lines are fewer by default than with the paper's variant, both within the
// tolerance, and its mean q higher.
template <class Mesh> void test_crease_contrast() {
  auto types = [](const Mesh& m, double contrast) {
    std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, PMP::ILSA_vertex_type> map;
    return classify_with_rules(m, rules(20., true, [contrast](Rules& r) { r.crease_contrast = contrast; }), map);
  };
  const Mesh fandisk = read_mesh<Mesh>(data_file("fandisk.off"));
  const Mesh elephant = read_mesh<Mesh>(data_file("elephant.off"));
  const auto paper_cad = types(fandisk, 0.), contrasted_cad = types(fandisk, 5.);
  const auto paper_organic = types(elephant, 0.), contrasted_organic = types(elephant, 5.);
  std::cout << "crease contrast 5: fandisk ridge " << paper_cad.number_of_ridge_vertices << " -> "
            << contrasted_cad.number_of_ridge_vertices << ", corner " << paper_cad.number_of_corner_vertices << " -> "
            << contrasted_cad.number_of_corner_vertices << "; elephant corner "
            << paper_organic.number_of_corner_vertices << " -> " << contrasted_organic.number_of_corner_vertices
            << ", smooth " << paper_organic.number_of_smooth_vertices << " -> "
            << contrasted_organic.number_of_smooth_vertices << std::endl;
  assert(contrasted_cad.number_of_ridge_vertices == paper_cad.number_of_ridge_vertices &&
         contrasted_cad.number_of_corner_vertices == paper_cad.number_of_corner_vertices);
  assert(3 * contrasted_organic.number_of_corner_vertices < paper_organic.number_of_corner_vertices);
  assert(contrasted_organic.number_of_smooth_vertices > 2 * paper_organic.number_of_smooth_vertices);

  auto smoothed = [](const Mesh& input, bool paper) {
    Mesh m = input;
    PMP::smooth_surface_mesh_ilsa(m, CGAL::parameters::ilsa_paper_variant(paper));
    return m;
  };
  const Mesh paper_smoothed = smoothed(elephant, true), default_smoothed = smoothed(elephant, false);
  const auto crease_lines = [](const Mesh& original, const Mesh& m, bool paper) {
    return PMP::mesh_fidelity_ilsa(original, m,
                                   CGAL::parameters::ilsa_paper_variant(paper).ilsa_compute_hausdorff_distance(false));
  };
  const auto paper_lines = crease_lines(elephant, paper_smoothed, true);
  const auto default_lines = crease_lines(elephant, default_smoothed, false);
  const double paper_q = PMP::mesh_quality_ilsa(paper_smoothed).mean_aspect_ratio;
  const double default_q = PMP::mesh_quality_ilsa(default_smoothed).mean_aspect_ratio;
  std::cout << "elephant, paper's variant -> defaults: feature edges " << paper_lines.number_of_sharp_edges << " -> "
            << default_lines.number_of_sharp_edges << ", crease deviation " << paper_lines.max_crease_deviation
            << " -> " << default_lines.max_crease_deviation << ", mean q " << paper_q << " -> " << default_q
            << std::endl;
  const double tolerance = PMP::internal::ILSA::defaults::fidelity_tolerance + 1e-12; // rounding of the write-back
  assert(2 * default_lines.number_of_sharp_edges < paper_lines.number_of_sharp_edges);
  assert(paper_lines.max_crease_deviation <= tolerance && default_lines.max_crease_deviation <= tolerance);
  assert(default_q > paper_q);
  // The CAD model's crease lines are all kept.
  assert(crease_lines(fandisk, fandisk, false).number_of_sharp_edges ==
         crease_lines(fandisk, fandisk, true).number_of_sharp_edges);
}

// The open-crease rule alone (internal/ILSA/feature_lines.h): which connected
// sets of flagged edges it clears.
void test_open_line_rule() {
  using Edge = std::array<std::size_t, 2>;
  auto run = [](std::size_t n, const std::vector<Edge>& edges, std::vector<unsigned char> flags,
                std::vector<unsigned char> border, std::size_t minimum) {
    border.resize(n, 0);
    PMP::internal::ILSA::drop_short_open_lines(
        n, [&edges](std::size_t e) { return edges[e]; }, [&border](std::size_t v) { return border[v] != 0; }, flags,
        minimum);
    return flags;
  };
  using Flags = std::vector<unsigned char>;
  const std::vector<Edge> path{{0, 1}, {1, 2}, {2, 3}};
  assert(run(4, path, {1, 1, 1}, {}, 4) == Flags({0, 0, 0})); // open, 3 edges < 4
  assert(run(4, path, {1, 1, 1}, {}, 3) == Flags({1, 1, 1})); // 3 edges, not fewer than 3
  for (std::size_t off : {0, 1}) assert(run(4, path, {1, 1, 1}, {}, off) == Flags({1, 1, 1}));
  assert(run(4, path, {1, 1, 1}, {1, 0, 0, 1}, 20) == Flags({1, 1, 1})); // from border to border
  assert(run(4, path, {1, 1, 1}, {1, 0, 0, 0}, 20) == Flags({0, 0, 0})); // one loose end is enough
  assert(run(4, path, {1, 0, 1}, {}, 2) == Flags({0, 0, 0}));            // two sets of one edge
  const std::vector<Edge> loop{{0, 1}, {1, 2}, {2, 0}};
  assert(run(3, loop, {1, 1, 1}, {}, 20) == Flags({1, 1, 1})); // closed
  assert(run(3, loop, {1, 1, 0}, {}, 20) == Flags({0, 0, 0})); // the same, opened
  // A T of three edges with loose ends, and a separate edge; unflagged edges stay so.
  const std::vector<Edge> t{{0, 1}, {1, 2}, {1, 3}, {4, 5}, {3, 4}};
  assert(run(6, t, {1, 1, 1, 1, 0}, {}, 3) == Flags({1, 1, 1, 0, 0}));
  assert(run(6, t, {1, 1, 1, 1, 1}, {}, 3) == Flags({1, 1, 1, 1, 1})); // joined: one set of five
  std::cout << "open-crease rule: short open sets cleared, closed and border-to-border ones kept" << std::endl;
}

// The open-crease rule in the classification and the fidelity summary (user
// manual, "Open Crease Lines"): the creases of a CAD model stay (the
// fandisk's, a cube's twelve edges, a fold from border to border), the short
// pieces of curvature of a coarse organic mesh are no longer creases (the
// elephant loses its ridge vertices and most of its corners), and the
// smoother and mesh_fidelity_ilsa() drop the same edges.
template <class Mesh> void test_open_crease_lines() {
  using vertex_descriptor = typename boost::graph_traits<Mesh>::vertex_descriptor;
  auto open_rule = [](std::size_t minimum) {
    return rules(20., false, [minimum](Rules& r) {
      r.minimum_open_crease_edges = minimum;
      r.fix_unattached_candidates = true;
    });
  };
  auto types = [&](const Mesh& m, std::size_t minimum) {
    std::map<vertex_descriptor, PMP::ILSA_vertex_type> map;
    return classify_with_rules(m, open_rule(minimum), map);
  };
  auto crease_edges = [&](const Mesh& m, std::size_t minimum) { return feature_edge_count(m, open_rule(minimum)); };
  // A cube of twelve triangles: twelve sharp edges, closed; a fold from border to border, six edges.
  const Mesh box = to_mesh<Mesh>(cube(1));
  Soup fold = grid(6);
  for (Point& p : fold.points) p = Point(p.x(), p.y(), 0.4 * std::abs(p.x() - 0.5));
  const Mesh folded = to_mesh<Mesh>(fold);
  for (const Mesh* m : {&box, &folded}) {
    const auto kept = types(*m, 20), paper = types(*m, 0);
    assert(kept.number_of_corner_vertices == paper.number_of_corner_vertices &&
           kept.number_of_ridge_vertices == paper.number_of_ridge_vertices);
    assert(crease_edges(*m, 20) == crease_edges(*m, 0));
  }
  assert(types(box, 20).number_of_corner_vertices == 8 && crease_edges(box, 20) == 12);
  // The fold's five inner vertices: three ridge vertices and, next to the
  // border, two corners (a border vertex is no ridge candidate, so their edge
  // to it is not sharp: the paper's rule).
  assert(types(folded, 20).number_of_ridge_vertices == 3 && types(folded, 20).number_of_corner_vertices == 2 &&
         crease_edges(folded, 20) == 6);

  const Mesh fandisk = read_mesh<Mesh>(data_file("fandisk.off"));
  const Mesh elephant = read_mesh<Mesh>(data_file("elephant.off"));
  const auto cad = types(fandisk, 20), cad_paper = types(fandisk, 0);
  const auto organic = types(elephant, 20), organic_paper = types(elephant, 0);
  std::cout << "open crease lines, 20 edges: fandisk ridge " << cad_paper.number_of_ridge_vertices << " -> "
            << cad.number_of_ridge_vertices << ", crease edges " << crease_edges(fandisk, 0) << " -> "
            << crease_edges(fandisk, 20) << "; elephant ridge " << organic_paper.number_of_ridge_vertices << " -> "
            << organic.number_of_ridge_vertices << ", corner " << organic_paper.number_of_corner_vertices << " -> "
            << organic.number_of_corner_vertices << std::endl;
  assert(cad.number_of_ridge_vertices == cad_paper.number_of_ridge_vertices &&
         cad.number_of_corner_vertices == cad_paper.number_of_corner_vertices);
  assert(crease_edges(fandisk, 20) == crease_edges(fandisk, 0));
  assert(10 * organic.number_of_ridge_vertices < organic_paper.number_of_ridge_vertices);
  assert(2 * organic.number_of_corner_vertices < organic_paper.number_of_corner_vertices);

  // The smoother's feature lines are the classification's: mesh_fidelity_ilsa()
  // counts the default rules' feature edges, and they stay within the tolerance.
  Mesh m = elephant;
  PMP::smooth_surface_mesh_ilsa(m);
  const auto lines = PMP::mesh_fidelity_ilsa(elephant, m, CGAL::parameters::ilsa_compute_hausdorff_distance(false));
  assert(lines.number_of_sharp_edges == feature_edge_count(elephant, rules(20., false, [](Rules&) {})));
  assert(lines.number_of_sharp_edges < crease_edges(elephant, 0));
  assert(lines.max_crease_deviation <= PMP::internal::ILSA::defaults::fidelity_tolerance + 1e-12);
}

} // namespace

int main() {
  test_kinks_stay_and_creases_keep_shape<Surface_mesh>();
  test_kinks_stay_and_creases_keep_shape<Polyhedron>();
  test_vertex_range<Surface_mesh>();
  test_vertex_range<Polyhedron>();
  test_kink_rule_and_crease_bound_alone();
  test_two_sided_measure();
  test_crease_contrast<Surface_mesh>();
  test_crease_contrast<Polyhedron>();
  test_open_line_rule();
  test_open_crease_lines<Surface_mesh>();
  test_open_crease_lines<Polyhedron>();
  std::cout << "test_ilsa_creases: all checks passed\n";
  return 0;
}
