// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flat, index-based copy of the input mesh on which every ILSA stage runs.
// It is built once per call, in one place, so the sweeps never traverse the
// graph or allocate. Coordinates are translated to the bounding-box centre and
// divided by the bounding-box diagonal: every tolerance below is relative, and
// a mesh moved by +1e7 or scaled by 1e-6 is smoothed the same way.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FLAT_MESH_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FLAT_MESH_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vec3.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

/// Index of a vertex, face or edge in the flat mesh: 32 bits, half the memory of
/// `std::size_t` (build_flat_mesh() rejects a mesh with more elements).
using Index = std::uint32_t;
/// No element (a border edge's missing face, no home yet). Compares equal to
/// itself also after conversion to `std::size_t`.
constexpr Index npos = (std::numeric_limits<Index>::max)();

/// Compressed adjacency: the items of element `i` are `items[begin[i]] .. items[begin[i+1]-1]`.
struct Adjacency {
  std::vector<Index> begin{0};
  std::vector<Index> items;

  std::size_t size(std::size_t i) const { return begin[i + 1] - begin[i]; }
  const Index* first(std::size_t i) const { return items.data() + begin[i]; }
  const Index* last(std::size_t i) const { return items.data() + begin[i + 1]; }

  // Builds the adjacency of `n` elements from the (element, item) pairs that
  // `pairs(emit)` passes to `emit(element, item)`, keeping their order; `pairs`
  // is called twice (a count, then the fill), so no list of pairs is stored.
  template <class Pairs> void assign(std::size_t n, const Pairs& pairs) {
    begin.assign(n + 1, 0);
    pairs([&](std::size_t element, std::size_t) { ++begin[element + 1]; });
    for (std::size_t i = 0; i < n; ++i) begin[i + 1] += begin[i];
    items.resize(begin[n]);
    pairs([&](std::size_t element, std::size_t item) { items[begin[element]++] = Index(item); });
    for (std::size_t i = n; i > 0; --i) begin[i] = begin[i - 1]; // the fill advanced each begin to the next
    begin[0] = 0;
  }

  // The faces around each of `n` vertices, in face order (a face whose vertex
  // repeats is listed once per corner).
  void assign_faces(std::size_t n, const std::vector<std::array<Index, 3>>& faces) {
    assign(n, [&](auto emit) {
      for (std::size_t f = 0; f < faces.size(); ++f)
        for (Index v : faces[f]) emit(v, f);
    });
  }
};

/// The flat copy: what every stage reads, for the whole call.
struct Flat_mesh {
  std::vector<Vec3> points;                // normalised coordinates
  std::vector<std::array<Index, 3>> faces; // vertex indices, mesh orientation
  std::vector<std::array<Index, 2>> edges; // endpoints
  Adjacency vertex_faces;                  // faces around each vertex
  Adjacency vertex_neighbors;              // one-ring vertices
  Adjacency vertex_edges;                  // edges around each vertex, same order as vertex_neighbors
  Vec3 center = Vec3::Zero();
  double scale = 1.;

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_faces() const { return faces.size(); }

  Vec3 to_input(const Vec3& p) const { return center + scale * p; }
};

/// The incidences of the flat copy that only the set-up reads (the
/// classification, and the constructors of Projector and Move_safety, which
/// take them as an argument and keep no reference): apart from Flat_mesh so
/// that their owner frees them before the iterations.
struct Set_up_incidences {
  std::vector<std::array<Index, 2>> edge_faces; // incident faces of each edge, npos on a border
  std::vector<unsigned char> on_border;         // per vertex: endpoint of a border edge
  std::vector<unsigned char> non_manifold;      // per vertex: shared by several umbrellas
};

/// Twice the area vector of triangle `f` for the positions `pos`.
inline Vec3 area_vector(const std::vector<Vec3>& pos, const std::array<Index, 3>& f) {
  return (pos[f[1]] - pos[f[0]]).cross(pos[f[2]] - pos[f[0]]);
}

/// Squared distance from `p` to the segment `ab`.
inline double squared_distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double l = ab.squaredNorm();
  const double t = l > 0 ? (std::min)(1., (std::max)(0., (p - a).dot(ab) / l)) : 0.;
  return (p - a - t * ab).squaredNorm();
}

/// Squared distance from `p` to the triangle `abc` (closest-point regions as in
/// Ericson, Real-Time Collision Detection, 5.1.5). The closest point it takes
/// is always a point of the triangle, so that the distance is never below the
/// true one by more than rounding (the fidelity certificate bounds distances
/// from above with it); a triangle with coincident or collinear corners is
/// taken as its edges.
inline double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return ap.squaredNorm();
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return bp.squaredNorm();
  // The edge regions need the edge's squared length (d1 - d3, d2 - d6, and
  // (d4 - d3) + (d5 - d6)) positive: a zero-length edge would give 0 / 0.
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0 && d1 > d3) return (ap - (d1 / (d1 - d3)) * ab).squaredNorm();
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return cp.squaredNorm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0 && d2 > d6) return (ap - (d2 / (d2 - d6)) * ac).squaredNorm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0 && (d4 - d3) + (d5 - d6) > 0)
    return (bp - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b)).squaredNorm();
  const double sum = va + vb + vc;
  const double v = vb / sum, w = vc / sum;
  // Inside unless the triangle is degenerate (or rounding of a needle put
  // the point outside): then the closest of its edges.
  if (!(sum > 0 && v >= 0 && w >= 0 && v + w <= 1))
    return (std::min)({squared_distance_to_segment(p, a, b), squared_distance_to_segment(p, b, c),
                       squared_distance_to_segment(p, c, a)});
  return (ap - v * ab - w * ac).squaredNorm();
}

/// `x` as a float no smaller than `x` (rounded up), or no larger (rounded
/// down): for bounds stored in floats that must stay bounds.
inline float float_rounded_up(double x) {
  const float f = float(x);
  return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}
inline float float_rounded_down(double x) {
  const float f = float(x);
  return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

/// Unit normal of triangle `f`, or zero for a degenerate triangle.
inline Vec3 unit_normal(const std::vector<Vec3>& pos, const std::array<Index, 3>& f) {
  const Vec3 n = area_vector(pos, f);
  const double l = n.norm();
  return l > 0 ? Vec3(n / l) : Vec3::Zero();
}

/// Flat index of each vertex (or face) descriptor, through an index map (the
/// user's `vertex_index_map`, or the dynamic map of `vertex_index_map_of()`).
/// Flat indices follow the order of `vertices(tm)` whatever the map's order, so
/// the result does not depend on it.
template <class VertexIndexMap> struct Flat_indices {
  VertexIndexMap map;
  std::vector<std::size_t> flat; // flat index of each map index

  template <class Descriptor> std::size_t operator()(const Descriptor& v) const {
    return flat[std::size_t(get(map, v))];
  }
};

/// The user's index map for `Tag` (`vertex_index_map` or `face_index_map`;
/// `number_in_order()` rejects a map that is not one to one with `ILSA_error`),
/// or `make_default()`.
template <class Tag, class NamedParameters, class MakeDefault>
auto index_map_of(const NamedParameters& np, MakeDefault make_default) {
  if constexpr (parameters::is_default_parameter<NamedParameters, Tag>::value)
    return make_default();
  else
    return parameters::get_parameter(np, Tag{});
}
/// Without a user map: a dynamic property map numbering the elements in
/// iteration order, valid also for a `Surface_mesh` with removed elements
/// (whose internal indices have gaps until `collect_garbage()`).
template <class Map, class Range> Map number_elements(Map map, const Range& range) {
  std::size_t i = 0;
  for (const auto& x : range) put(map, x, i++);
  return map;
}
template <class TriangleMesh, class NamedParameters>
auto vertex_index_map_of(const TriangleMesh& tm, const NamedParameters& np) {
  return index_map_of<internal_np::vertex_index_t>(
      np, [&] { return number_elements(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm), vertices(tm)); });
}
template <class TriangleMesh, class NamedParameters>
auto face_index_map_of(const TriangleMesh& tm, const NamedParameters& np) {
  return index_map_of<internal_np::face_index_t>(
      np, [&] { return number_elements(get(CGAL::dynamic_face_property_t<std::size_t>(), tm), faces(tm)); });
}

/// Fills `indices.flat` for the descriptors of `list` (in flat order); throws `ILSA_error`
/// unless `indices.map` maps them one to one onto [0, list.size()).
template <class Indices, class Descriptor>
void number_in_order(Indices& indices, const std::vector<Descriptor>& list, const char* what) {
  indices.flat.assign(list.size(), npos);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto i = get(indices.map, list[k]);
    if (!(std::size_t(i) < list.size()) || indices.flat[std::size_t(i)] != npos)
      throw ILSA_error(std::string(what) + " does not number the " + std::to_string(list.size()) +
                       " elements one to one from 0");
    indices.flat[std::size_t(i)] = k;
  }
}

/// A renumbering of the vertices and faces of a mesh: `vertices[i]` is the
/// old number of new vertex `i`, `vertex_number` its inverse; the same for faces.
struct Locality_order {
  std::vector<Index> vertices, vertex_number, faces, face_number;
};

/// Breadth-first order over the faces of `faces` (`n` vertices): each component
/// from its lowest vertex, the new vertices of a face in increasing old number
/// (whatever corner the face starts at), the faces of a vertex in their order;
/// a face is numbered when its first vertex is reached. Isolated vertices keep
/// their place among the seeds.
inline Locality_order locality_order(std::size_t n, const std::vector<std::array<Index, 3>>& faces) {
  Adjacency around; // faces of each vertex, in face order
  around.assign_faces(n, faces);
  Locality_order o;
  o.vertex_number.assign(n, npos);
  o.face_number.assign(faces.size(), npos);
  o.vertices.reserve(n);
  o.faces.reserve(faces.size());
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (o.vertex_number[seed] != npos) continue;
    o.vertex_number[seed] = Index(o.vertices.size());
    o.vertices.push_back(Index(seed));
    for (std::size_t head = o.vertices.size() - 1; head < o.vertices.size(); ++head) {
      const Index v = o.vertices[head];
      for (const Index* f = around.first(v); f != around.last(v); ++f) {
        if (o.face_number[*f] != npos) continue;
        o.face_number[*f] = Index(o.faces.size());
        o.faces.push_back(*f);
        std::array<Index, 3> t = faces[*f];
        std::sort(t.begin(), t.end());
        for (Index w : t)
          if (o.vertex_number[w] == npos) {
            o.vertex_number[w] = Index(o.vertices.size());
            o.vertices.push_back(w);
          }
      }
    }
  }
  return o;
}

/// Every index, and every item count of an adjacency, must fit an `Index`.
inline void require_indexable(std::size_t n, const char* what) {
  if (n >= std::size_t(npos))
    throw ILSA_error(std::string("the mesh has too many ") + what + " (" + std::to_string(n) + "; at most 2^32 - 2)");
}

/// The coordinates of the vertices of `vertex_list`, checked finite; sets the
/// bounding-box centre and diagonal of `m` (the points are normalised once
/// renumbered).
template <class VertexPointMap, class VertexDescriptor>
std::vector<Vec3> read_points(const VertexPointMap& vpm, const std::vector<VertexDescriptor>& vertex_list,
                              Flat_mesh& m) {
  const std::size_t nv = vertex_list.size();
  std::vector<Vec3> raw(nv);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (std::size_t i = 0; i < nv; ++i) {
    const auto& p = get(vpm, vertex_list[i]);
    raw[i] = Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if (!raw[i].allFinite())
      throw ILSA_error("vertex " + std::to_string(i) + " has a non-finite coordinate (NaN or infinity)");
    lo = lo.cwiseMin(raw[i]);
    hi = hi.cwiseMax(raw[i]);
  }
  if (nv > 0) {
    m.center = 0.5 * (lo + hi);
    const double diagonal = (hi - lo).norm();
    m.scale = diagonal > 0 ? diagonal : 1.;
  }
  return raw;
}

/// The faces of `tm` (`face_list`), with the vertices numbered in the order of
/// `vertices(tm)`; throws for a face that is not a triangle.
template <class TriangleMesh, class VertexIndices>
std::vector<std::array<Index, 3>>
read_faces(const TriangleMesh& tm,
           const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_list,
           const VertexIndices& vertex_index) {
  std::vector<std::array<Index, 3>> input_faces;
  input_faces.reserve(face_list.size());
  for (auto f : face_list) {
    std::array<Index, 3> t{};
    std::size_t k = 0;
    for (auto v : vertices_around_face(halfedge(f, tm), tm)) {
      if (k < 3) t[k] = Index(vertex_index(v));
      ++k;
    }
    if (k != 3)
      throw ILSA_error("face " + std::to_string(input_faces.size()) + " has " + std::to_string(k) +
                       " vertices; only triangle meshes are supported (triangulate first)");
    input_faces.push_back(t);
  }
  return input_faces;
}

/// Renumbering for memory locality (user manual, "Performance"): every stage
/// visits the vertices in index order and reads their faces and neighbours,
/// so neighbours should have close indices. Vertices in breadth-first order
/// over the faces (each component from its first vertex in the order of
/// `vertices(tm)`), faces in the order they are first reached. The order
/// depends only on the order of the vertices and faces, not on which corner
/// the graph starts a face at. Sets the points (normalised) and faces of `m`,
/// and renumbers `vertex_list` and the flat indices.
template <class VertexDescriptor, class VertexIndices, class FaceIndices>
void renumber_for_locality(const std::vector<Vec3>& raw, const std::vector<std::array<Index, 3>>& input_faces,
                           std::vector<VertexDescriptor>& vertex_list, VertexIndices& vertex_index,
                           FaceIndices& face_index, Flat_mesh& m) {
  const std::size_t nv = vertex_list.size();
  const Locality_order order = locality_order(nv, input_faces);
  {
    std::vector<VertexDescriptor> renumbered(nv);
    m.points.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) {
      renumbered[i] = vertex_list[order.vertices[i]];
      m.points[i] = (raw[order.vertices[i]] - m.center) / m.scale;
    }
    vertex_list.swap(renumbered);
  }
  for (auto& i : vertex_index.flat) i = order.vertex_number[i];
  for (auto& i : face_index.flat) i = order.face_number[i];
  m.faces.resize(input_faces.size());
  for (std::size_t f = 0; f < input_faces.size(); ++f) {
    const auto& t = input_faces[order.faces[f]];
    m.faces[f] = {order.vertex_number[t[0]], order.vertex_number[t[1]], order.vertex_number[t[2]]};
  }
}

/// The edges of `tm` in a canonical order (by endpoint indices, lower index
/// first, the face on the lower-to-higher halfedge first), whatever order the
/// graph lists them in: meshes of different types with the same vertices and
/// faces give bit-identical results (but where two edges join the same two
/// vertices, which keep the graph's order). Sets the edges of `m`, the faces of each
/// edge and the border vertices in `incidences`, the descriptors in `edge_list`.
template <class TriangleMesh, class VertexIndices, class FaceIndices>
void read_edges(const TriangleMesh& tm, const VertexIndices& vertex_index, const FaceIndices& face_index, Flat_mesh& m,
                Set_up_incidences& incidences,
                std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& edge_list) {
  using GT = boost::graph_traits<TriangleMesh>;
  struct Edge_record {
    Index a, b, f0, f1;
  };
  const std::vector<typename GT::edge_descriptor> graph_edges(edges(tm).begin(), edges(tm).end());
  std::vector<Edge_record> records; // in the graph's order
  require_indexable(2 * graph_edges.size(), "edge ends");
  records.reserve(graph_edges.size());
  for (const auto& e : graph_edges) {
    auto h = halfedge(e, tm);
    if (vertex_index(source(h, tm)) > vertex_index(target(h, tm))) h = opposite(h, tm);
    const auto f0 = face(h, tm), f1 = face(opposite(h, tm), tm);
    records.push_back({Index(vertex_index(source(h, tm))), Index(vertex_index(target(h, tm))),
                       f0 == GT::null_face() ? npos : Index(face_index(f0)),
                       f1 == GT::null_face() ? npos : Index(face_index(f1))});
  }
  // Sorted by (a, b), then by the graph's order where two edges join the same
  // two vertices, in linear time as in build_vertex_adjacency(): bucketed by
  // `a` (in the graph's order), then each vertex's few sorted by `b`.
  Adjacency by_lower_end;
  by_lower_end.assign(m.number_of_vertices(), [&](auto emit) {
    for (std::size_t k = 0; k < records.size(); ++k) emit(records[k].a, k);
  });
  for (std::size_t v = 0; v < m.number_of_vertices(); ++v)
    std::sort(by_lower_end.items.begin() + std::ptrdiff_t(by_lower_end.begin[v]),
              by_lower_end.items.begin() + std::ptrdiff_t(by_lower_end.begin[v + 1]),
              [&](Index x, Index y) { return std::make_pair(records[x].b, x) < std::make_pair(records[y].b, y); });

  incidences.on_border.assign(m.number_of_vertices(), 0);
  edge_list.clear();
  m.edges.reserve(records.size());
  incidences.edge_faces.clear();
  incidences.edge_faces.reserve(records.size());
  edge_list.reserve(records.size());
  for (Index k : by_lower_end.items) {
    const Edge_record& r = records[k];
    if (r.f0 == npos || r.f1 == npos) incidences.on_border[r.a] = incidences.on_border[r.b] = 1;
    m.edges.push_back({r.a, r.b});
    incidences.edge_faces.push_back({r.f0, r.f1});
    edge_list.push_back(graph_edges[k]);
  }
}

/// Edges around each vertex (bucketed in edge order), each vertex's few
/// sorted by their other end, then by edge where two edges join the same two
/// vertices: one-ring neighbours in increasing index order, at linear cost.
inline void build_vertex_adjacency(Flat_mesh& m) {
  const std::size_t nv = m.number_of_vertices();
  m.vertex_edges.assign(nv, [&](auto emit) {
    for (std::size_t e = 0; e < m.edges.size(); ++e) emit(m.edges[e][0], e), emit(m.edges[e][1], e);
  });
  m.vertex_neighbors.begin = m.vertex_edges.begin;
  m.vertex_neighbors.items.resize(m.vertex_edges.items.size());
  for (std::size_t i = 0; i < nv; ++i) {
    auto other_end = [&](Index e) { return m.edges[e][0] == i ? m.edges[e][1] : m.edges[e][0]; };
    const std::size_t first = m.vertex_edges.begin[i], last = m.vertex_edges.begin[i + 1];
    auto& items = m.vertex_edges.items;
    std::sort(items.begin() + std::ptrdiff_t(first), items.begin() + std::ptrdiff_t(last),
              [&](Index x, Index y) { return std::make_pair(other_end(x), x) < std::make_pair(other_end(y), y); });
    for (std::size_t j = first; j < last; ++j) m.vertex_neighbors.items[j] = other_end(items[j]);
  }
}

/// A vertex whose faces do not all lie in one umbrella is non-manifold.
template <class TriangleMesh>
void mark_non_manifold(const TriangleMesh& tm,
                       const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_list,
                       const Flat_mesh& m, Set_up_incidences& incidences) {
  using GT = boost::graph_traits<TriangleMesh>;
  incidences.non_manifold.assign(m.number_of_vertices(), 0);
  for (std::size_t i = 0; i < m.number_of_vertices(); ++i) {
    if (m.vertex_faces.size(i) == 0) continue;
    std::size_t umbrella = 0;
    for (auto h : halfedges_around_target(halfedge(vertex_list[i], tm), tm))
      if (face(h, tm) != GT::null_face()) ++umbrella;
    if (umbrella != m.vertex_faces.size(i)) incidences.non_manifold[i] = 1;
  }
}

/// Builds the flat copy of `tm`. `vertex_list` receives the vertex descriptors in
/// index order, `vertex_index` the flat numbering of the vertices (its `map` must
/// be set), `edge_list` the edge descriptors, `incidences` what only the set-up
/// reads. `face_index_map` numbers the faces.
/// Throws `ILSA_error` for a non-triangle face, a non-finite coordinate or an
/// index map that is not one to one; `tm` is only read.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
Flat_mesh build_flat_mesh(const TriangleMesh& tm, const VertexPointMap& vpm,
                          std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertex_list,
                          Flat_indices<VertexIndexMap>& vertex_index, const FaceIndexMap& face_index_map,
                          std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& edge_list,
                          Set_up_incidences& incidences) {
  Flat_mesh m;
  vertex_list.assign(vertices(tm).begin(), vertices(tm).end());
  require_indexable(vertex_list.size(), "vertices");
  number_in_order(vertex_index, vertex_list, "vertex_index_map");
  Flat_indices<FaceIndexMap> face_index{face_index_map, {}};
  {
    const std::vector<Vec3> raw = read_points(vpm, vertex_list, m);
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_list(faces(tm).begin(),
                                                                                             faces(tm).end());
    require_indexable(3 * face_list.size(), "face corners");
    number_in_order(face_index, face_list, "face_index_map");
    renumber_for_locality(raw, read_faces(tm, face_list, vertex_index), vertex_list, vertex_index, face_index, m);
  }
  m.vertex_faces.assign_faces(m.number_of_vertices(), m.faces);
  read_edges(tm, vertex_index, face_index, m, incidences, edge_list);
  build_vertex_adjacency(m);
  mark_non_manifold(tm, vertex_list, m, incidences);
  return m;
}

/// Writes T_new back to `tm`: the adjustable vertices that moved, in the
/// input's coordinates; fixed and unmoved vertices are not touched.
template <class VertexDescriptor, class VertexPointMap>
void write_back(const Flat_mesh& original, const std::vector<Vec3>& pos, const std::vector<Index>& adjustable,
                const std::vector<VertexDescriptor>& vertex_list, VertexPointMap vpm) {
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  for (std::size_t v : adjustable) {
    if (pos[v] == original.points[v]) continue;
    const Vec3 p = original.to_input(pos[v]);
    put(vpm, vertex_list[v], Point(p.x(), p.y(), p.z()));
  }
}

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_FLAT_MESH_H
