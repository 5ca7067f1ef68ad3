// Helpers shared by the tests: known meshes built from polygon soups, tangential
// perturbations, and the invariants every smoothing run must keep.
#ifndef ILSA_TEST_UTILS_H
#define ILSA_TEST_UTILS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/classify_vertices_ilsa.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/aabb_tree.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/bounding_box.h>

#include <array>
#include <cassert>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <random>
#include <string>
#include <vector>

// A check that stays active when NDEBUG is defined (the bad-input test is
// also built with NDEBUG to show the package does not rely on assertions).
#define ILSA_CHECK(condition)                                                                                          \
  do {                                                                                                                 \
    if (!(condition)) {                                                                                                \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #condition << std::endl;                          \
      std::abort();                                                                                                    \
    }                                                                                                                  \
  } while (false)

namespace ilsa_test {

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Surface_mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<K>;
// The AABB tree types under the names of the CGAL in use (see aabb_tree.h).
using CGAL::Polygon_mesh_processing::internal::ILSA::AABB_segment_primitive_3;
using CGAL::Polygon_mesh_processing::internal::ILSA::AABB_tree_3;
using CGAL::Polygon_mesh_processing::internal::ILSA::AABB_triangle_primitive_3;

struct Soup {
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

// The classification rules the package fixes, varied for the tests: the
// package's for `feature_angle`, changed by `change`.
using Rules = PMP::internal::ILSA::Classification_options;
template <class Change> Rules rules(double feature_angle, bool paper, const Change& change) {
  Rules r = Rules::rules(feature_angle, paper);
  change(r);
  return r;
}

// Classifies `m` under `rules` into `types` (as classify_vertices_ilsa());
// `np` gives the constraint maps.
template <class Mesh, class TypeMap, class NamedParameters = CGAL::parameters::Default_named_parameters>
PMP::ILSA_statistics classify_with_rules(const Mesh& m, const Rules& rules, TypeMap& types,
                                         const NamedParameters& np = CGAL::parameters::default_values()) {
  PMP::internal::ILSA::Set_up_incidences incidences;
  const auto input = PMP::internal::ILSA::classified_flat_copy(m, get(CGAL::vertex_point, m), np, incidences, &rules);
  for (std::size_t i = 0; i < input.vertices.size(); ++i) types[input.vertices[i]] = input.classification.type[i];
  PMP::ILSA_statistics s;
  PMP::internal::ILSA::count_types(input.classification, s);
  return s;
}

// Smooths `m` with the named parameters `np`, the smoothing parameters they
// select then changed by `change` (the constants the package fixes, varied
// for the tests), and the classification `rules` when given.
template <class Tag = CGAL::Sequential_tag, class Mesh, class Change,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
PMP::ILSA_statistics smooth_with_changes(Mesh& m, const Change& change,
                                         const NamedParameters& np = CGAL::parameters::default_values(),
                                         const Rules* rules = nullptr) {
  PMP::internal::ILSA::Smoothing_parameters p = PMP::internal::ILSA::read_smoothing_parameters(np);
  change(p);
  return PMP::internal::ILSA::smooth<Tag>(vertices(m), m, np, &p, rules);
}

// The number of feature edges of `m` under `rules`: the edges the crease bound
// holds and mesh_fidelity_ilsa() measures.
template <class Mesh> std::size_t feature_edge_count(const Mesh& m, const Rules& rules) {
  PMP::internal::ILSA::Set_up_incidences incidences;
  const auto input = PMP::internal::ILSA::classified_flat_copy(m, get(CGAL::vertex_point, m),
                                                               CGAL::parameters::default_values(), incidences, &rules);
  std::size_t n = 0;
  for (unsigned char f : input.classification.feature_edge) n += f;
  return n;
}

template <class Mesh> Mesh to_mesh(const Soup& soup) {
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, m);
  ILSA_CHECK(CGAL::is_valid_polygon_mesh(m));
  return m;
}

/// A planar n x n grid of unit squares, each split into two triangles, in z = 0.
inline Soup grid(int n, double size = 1.) {
  Soup s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.points.emplace_back(size * i / n, size * j / n, 0.);
  auto id = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

/// The surface of the cube [-1,1]^3, each face an n x n grid of triangle pairs.
inline Soup cube(int n) {
  Soup s;
  std::map<std::array<long, 3>, std::size_t> index; // integer lattice coordinates -> vertex
  auto vertex = [&](std::array<long, 3> c) {
    auto it = index.find(c);
    if (it != index.end()) return it->second;
    s.points.emplace_back(2. * c[0] / n - 1., 2. * c[1] / n - 1., 2. * c[2] / n - 1.);
    return index[c] = s.points.size() - 1;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          auto at = [&](int a, int b) {
            std::array<long, 3> c{};
            c[axis] = side * n;
            c[u] = a;
            c[w] = b;
            return vertex(c);
          };
          std::size_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
          if (side == 0) std::swap(b, d); // outward orientation
          s.triangles.push_back({a, b, c});
          s.triangles.push_back({a, c, d});
        }
    }
  return s;
}

/// Number of cube coordinates at +-1: 3 at a corner, 2 on an edge, 1 inside a face.
inline int cube_extremal_coordinates(const Point& p, double tolerance = 1e-12) {
  int count = 0;
  for (int k = 0; k < 3; ++k) count += std::abs(std::abs(p[k]) - 1.) <= tolerance;
  return count;
}

/// Moves cube vertices tangentially: inside a face within the face plane, on an
/// edge along the edge, by up to `amount` grid steps; corners stay. No folding
/// for amount < 0.5.
inline void perturb_cube(Soup& s, int n, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-amount * 2. / n, amount * 2. / n);
  for (Point& p : s.points) {
    std::array<double, 3> c{p.x(), p.y(), p.z()};
    for (int k = 0; k < 3; ++k)
      if (std::abs(std::abs(c[k]) - 1.) > 1e-12) c[k] += uniform(rng);
    p = Point(c[0], c[1], c[2]);
  }
}

/// Moves the interior vertices of a planar grid within the plane.
inline void perturb_grid(Soup& s, int n, double amount, unsigned seed, double size = 1.) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-amount * size / n, amount * size / n);
  for (Point& p : s.points) {
    const bool border = p.x() == 0 || p.y() == 0 || p.x() == size || p.y() == size;
    if (!border) p = Point(p.x() + uniform(rng), p.y() + uniform(rng), p.z());
  }
}

/// Moves every vertex a random fraction of the way toward a random point of a
/// random incident triangle: it stays on the input surface, and a fraction
/// below 1/3 of the way to that point cannot fold the star.
template <class Mesh> void perturb_on_surface(Mesh& m, double amount, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0., 1.);
  std::vector<std::pair<typename boost::graph_traits<Mesh>::vertex_descriptor, Point>> moves;
  for (auto v : vertices(m)) {
    std::vector<typename boost::graph_traits<Mesh>::face_descriptor> fs;
    for (auto f : faces_around_target(halfedge(v, m), m))
      if (f != boost::graph_traits<Mesh>::null_face()) fs.push_back(f);
    if (fs.empty() || is_border(v, m)) continue;
    const auto f = fs[std::size_t(unit(rng) * fs.size()) % fs.size()];
    double a = unit(rng), b = unit(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const auto h = halfedge(f, m);
    const Point& p0 = get(CGAL::vertex_point, m, source(h, m));
    const Point& p1 = get(CGAL::vertex_point, m, target(h, m));
    const Point& p2 = get(CGAL::vertex_point, m, target(next(h, m), m));
    const Point q = p0 + a * (p1 - p0) + b * (p2 - p0);
    const Point& p = get(CGAL::vertex_point, m, v);
    moves.emplace_back(v, p + amount * unit(rng) * (q - p));
  }
  // Apply only moves that keep every incident face oriented as before.
  for (const auto& mv : moves) {
    const Point old = get(CGAL::vertex_point, m, mv.first);
    std::vector<K::Vector_3> before;
    for (auto f : faces_around_target(halfedge(mv.first, m), m))
      if (f != boost::graph_traits<Mesh>::null_face()) before.push_back(PMP::compute_face_normal(f, m));
    put(CGAL::vertex_point, m, mv.first, mv.second);
    std::size_t k = 0;
    bool ok = true;
    for (auto f : faces_around_target(halfedge(mv.first, m), m))
      if (f != boost::graph_traits<Mesh>::null_face()) {
        const auto h = halfedge(f, m);
        const double q = PMP::triangle_quality_ilsa(get(CGAL::vertex_point, m, source(h, m)),
                                                    get(CGAL::vertex_point, m, target(h, m)),
                                                    get(CGAL::vertex_point, m, target(next(h, m), m)));
        ok = ok && q > 0.01 && PMP::compute_face_normal(f, m) * before[k++] > 0;
      }
    if (!ok) put(CGAL::vertex_point, m, mv.first, old);
  }
}

template <class Mesh> std::vector<Point> points_of(const Mesh& m) {
  std::vector<Point> p;
  for (auto v : vertices(m)) p.push_back(get(CGAL::vertex_point, m, v));
  return p;
}

/// The points and triangles of a Surface_mesh without removed elements, in index order.
inline Soup soup_of(const Surface_mesh& m) {
  Soup soup;
  soup.points = points_of(m);
  for (auto f : faces(m)) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for (auto v : vertices_around_face(halfedge(f, m), m)) t[k++] = std::size_t(v);
    soup.triangles.push_back(t);
  }
  return soup;
}

/// Largest distance between corresponding points of two equally long lists.
inline double max_difference(const std::vector<Point>& a, const std::vector<Point>& b) {
  ILSA_CHECK(a.size() == b.size());
  double d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d = (std::max)(d, std::sqrt(CGAL::squared_distance(a[i], b[i])));
  return d;
}

template <class Mesh>
std::vector<PMP::ILSA_vertex_type> types_of(const Mesh& m, std::map<std::string, std::size_t>* counts = nullptr) {
  using vd = typename boost::graph_traits<Mesh>::vertex_descriptor;
  std::map<vd, PMP::ILSA_vertex_type> map;
  PMP::classify_vertices_ilsa(m, boost::make_assoc_property_map(map));
  std::vector<PMP::ILSA_vertex_type> t;
  for (auto v : vertices(m)) t.push_back(map.at(v));
  if (counts)
    for (auto x : t) ++(*counts)[PMP::to_string(x)];
  return t;
}

template <class Mesh> double bbox_diagonal(const Mesh& m) {
  const auto pts = points_of(m);
  const auto box = CGAL::bounding_box(pts.begin(), pts.end());
  return std::sqrt(CGAL::squared_distance(box.min(), box.max()));
}

template <class Mesh> std::vector<K::Vector_3> face_normals_of(const Mesh& m) {
  std::vector<K::Vector_3> n;
  for (auto f : faces(m)) {
    const auto h = halfedge(f, m);
    const Point& a = get(CGAL::vertex_point, m, source(h, m));
    const Point& b = get(CGAL::vertex_point, m, target(h, m));
    const Point& c = get(CGAL::vertex_point, m, target(next(h, m), m));
    n.push_back(CGAL::cross_product(b - a, c - a));
  }
  return n;
}

/// What a smoothing run must keep. `on_crease(i, p)` tells whether point `p`
/// of ridge vertex `i` is on its original crease line.
struct Invariant_report {
  double max_distance = 0; // relative to the bounding-box diagonal
  std::size_t flipped = 0;
  std::size_t fixed_moved = 0; // boundary or corner vertices whose point changed
  std::size_t ridge_off_crease = 0;
  double mean_q_before = 0, mean_q_after = 0;
};

template <class Mesh, class OnCrease>
Invariant_report check_invariants(const Mesh& original, const Mesh& smoothed, OnCrease on_crease) {
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
  using Tree = AABB_tree_3<K, Primitive>;
  Tree tree(faces(original).first, faces(original).second, original);
  const double diagonal = bbox_diagonal(original);
  const auto types = types_of(original);
  const auto before = points_of(original), after = points_of(smoothed);
  Invariant_report r;
  for (std::size_t i = 0; i < after.size(); ++i) {
    r.max_distance = (std::max)(r.max_distance, std::sqrt(tree.squared_distance(after[i])) / diagonal);
    if ((types[i] == PMP::ILSA_vertex_type::Boundary || types[i] == PMP::ILSA_vertex_type::Corner) &&
        !(after[i] == before[i]))
      ++r.fixed_moved;
    if (types[i] == PMP::ILSA_vertex_type::Ridge && !on_crease(i, after[i])) ++r.ridge_off_crease;
  }
  const auto n0 = face_normals_of(original), n1 = face_normals_of(smoothed);
  for (std::size_t f = 0; f < n0.size(); ++f)
    if (n0[f] * n1[f] <= 0) ++r.flipped;
  r.mean_q_before = PMP::mesh_quality_ilsa(original).mean_aspect_ratio;
  r.mean_q_after = PMP::mesh_quality_ilsa(smoothed).mean_aspect_ratio;
  return r;
}

inline std::string data_file(const std::string& name) {
  return std::string(ILSA_DATA_DIR) + "/" + name;
}

template <class Mesh> Mesh read_mesh(const std::string& path) {
  Mesh m;
  const bool ok = CGAL::IO::read_polygon_mesh(path, m);
  ILSA_CHECK(ok && !is_empty(m));
  CGAL_USE(ok);
  return m;
}

// The package's flat copy of `tm` with its default index maps (`vertex_list`,
// `edge_list`: the descriptors in flat order; `incidences`: what only the
// set-up reads).
template <class Mesh>
CGAL::Polygon_mesh_processing::internal::ILSA::Flat_mesh
flat_copy(const Mesh& tm, std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>& vertex_list,
          std::vector<typename boost::graph_traits<Mesh>::edge_descriptor>& edge_list,
          CGAL::Polygon_mesh_processing::internal::ILSA::Set_up_incidences& incidences) {
  namespace ilsa = CGAL::Polygon_mesh_processing::internal::ILSA;
  const auto np = CGAL::parameters::default_values();
  ilsa::Flat_indices<decltype(ilsa::vertex_index_map_of(tm, np))> vertex_index{ilsa::vertex_index_map_of(tm, np), {}};
  return ilsa::build_flat_mesh(tm, get(CGAL::vertex_point, tm), vertex_list, vertex_index,
                               ilsa::face_index_map_of(tm, np), edge_list, incidences);
}

} // namespace ilsa_test

#endif
