// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Stage 4 of ILSA (user manual, "Projection Guard"): projection of the moved vertices back onto the
// frozen original mesh. Smooth vertices go to the closest point of the
// original surface (AABB tree over its faces), ridge vertices to the closest
// point of their own crease polyline (AABB tree over the sharp edges).
//
// Sheet guard: every vertex remembers the original face (or sharp edge) it lies
// on, its "home". A closest point is accepted only if it lies on a face sharing
// a vertex with the home face and on the same side of every crease (the same
// patch: faces connected without crossing a sharp edge), or for a ridge vertex
// on a sharp edge of the same crease sharing an endpoint with the home edge.
// Otherwise the AABB answer belongs to another sheet (thin plate, parallel
// sheets, the other side of a slot or of a crease) or another crease, and the
// vertex is projected onto that neighbourhood instead, so it can only travel
// across its own patch of the surface, never through space.
//
// Local answer (user manual, "Projection Guard"): the guard makes the answer
// the closest point of the faces near the home face in every case, so a
// smooth vertex is projected onto those faces alone (skipping the faces whose
// bounding ball is out of reach). The AABB tree only tells whether the guard
// kept the answer local (`Result::guarded`): whether a face outside them is
// closer. Each vertex's clearance, its distance to the nearest face not
// incident to it, computed once with the tree, mostly rules that out without
// a query; otherwise a traversal of the tree within the reach of the closest
// distance, stopping at the first face found, decides.

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PROJECTION_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PROJECTION_H

#include <CGAL/Polygon_mesh_processing/internal/ILSA/aabb_tree.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parallel_loops.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/union_find.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

#include <CGAL/AABB_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

class Projector {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = K::Point_3;
  using Triangle = K::Triangle_3;
  using Segment = K::Segment_3;
  using Segment_iterator = std::vector<Segment>::const_iterator;

  // The face tree's primitives are face indices; their triangles are made
  // from the flat mesh when the tree needs them (a stored copy would cost 72
  // bytes per face). The reference point is the first vertex, as for CGAL's
  // AABB_triangle_primitive.
  template <class Value> struct Face_map {
    using key_type = Index;
    using value_type = Value;
    using reference = Value;
    using category = boost::readable_property_map_tag;
    const Flat_mesh* m;
    Value operator[](Index f) const {
      const auto& t = m->faces[f];
      if constexpr (std::is_same_v<Value, Triangle>)
        return Triangle(point(m->points[t[0]]), point(m->points[t[1]]), point(m->points[t[2]]));
      else
        return point(m->points[t[0]]);
    }
    friend Value get(const Face_map& map, Index f) { return map[f]; }
  };
  using Face_triangle_map = Face_map<Triangle>;
  using Face_point_map = Face_map<Point>;
  using Face_primitive =
      CGAL::AABB_primitive<Index, Face_triangle_map, Face_point_map, CGAL::Tag_true, CGAL::Tag_false>;
  using Face_tree = AABB_tree_3<K, Face_primitive>;
  using Crease_tree = AABB_tree_3<K, AABB_segment_primitive_3<K, Segment_iterator>>;

public:
  struct Result {
    Vec3 point;
    std::size_t home; // face (smooth vertex) or sharp edge (ridge vertex) the point lies on
    bool guarded;     // the AABB answer was rejected by the sheet guard
  };

  /// `original` and `classification` must outlive the projector: it keeps
  /// references. `incidences` (those of `original`) is read here only.
  /// `ConcurrencyTag`: how the clearances are computed (the result is the same).
  template <class ConcurrencyTag>
  Projector(const Flat_mesh& original, const Vertex_classification& classification, const Set_up_incidences& incidences,
            ConcurrencyTag)
      : m_(original), c_(classification) {
    // Built here, not lazily at the first query, which may come from several
    // threads: rebuild() inserts the primitives and builds the tree (once; a
    // further build() would build it again).
    if (m_.number_of_faces() > 0)
      face_tree_.rebuild(boost::counting_iterator<Index>(0),
                         boost::counting_iterator<Index>(Index(m_.number_of_faces())), Face_triangle_map{&m_},
                         Face_point_map{&m_});

    // Patches: faces connected across non-sharp edges (union-find).
    Index_union_find<Index> patches(m_.number_of_faces());
    for (std::size_t e = 0; e < m_.edges.size(); ++e) {
      const auto& fs = incidences.edge_faces[e];
      if (fs[0] != npos && fs[1] != npos && !c_.is_sharp(e)) patches.unite(fs[0], fs[1]);
    }
    patch_ = std::move(patches).representatives();

    for (std::size_t e = 0; e < m_.edges.size(); ++e) {
      if (!c_.is_sharp(e)) continue;
      segment_edge_.push_back(Index(e));
      segments_.emplace_back(point(m_.points[m_.edges[e][0]]), point(m_.points[m_.edges[e][1]]));
    }
    if (!segments_.empty()) crease_tree_.rebuild(segments_.cbegin(), segments_.cend());
    compute_clearances<ConcurrencyTag>();
    compute_balls();
  }

  /// Home of vertex `v` of the original mesh: an incident face, or for a ridge
  /// vertex one of its two sharp edges.
  std::size_t initial_home(std::size_t v) const {
    if (c_.type[v] == ILSA_vertex_type::Ridge) return c_.attached_edges[v][0];
    return m_.vertex_faces.size(v) > 0 ? *m_.vertex_faces.first(v) : npos;
  }

  /// Closest point to `q` for vertex `v` whose current position `current` lies on `home`
  /// (`current` itself when `q` is `current`). Without `guard`, `Result::guarded` is not
  /// computed (false), which spares tree queries.
  Result project(std::size_t v, const Vec3& q, const Vec3& current, std::size_t home, bool guard = true) const {
    if (q == current) return {current, home, false};
    if (c_.type[v] == ILSA_vertex_type::Ridge)
      return guard ? project_on_crease(q, current, home) : project_on_crease_near(q, current, home);
    Result local;
    if (project_near(q, home, local, guard)) return local;
    return project_on_surface_by_tree(q, current, home);
  }

private:
  static Point point(const Vec3& p) { return Point(p.x(), p.y(), p.z()); }
  static Vec3 vec(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

  // The segment of crease edge `e` (a binary search: a table per edge would
  // cost 4 bytes per edge, and few vertices are ridge vertices).
  std::size_t segment_of(std::size_t e) const {
    return std::size_t(std::lower_bound(segment_edge_.begin(), segment_edge_.end(), Index(e)) - segment_edge_.begin());
  }

  // Faces sharing a vertex with face `home`, in its patch.
  template <class F> void for_each_face_near(std::size_t home, F f) const {
    for (std::size_t w : m_.faces[home])
      for (const Index* g = m_.vertex_faces.first(w); g != m_.vertex_faces.last(w); ++g)
        if (patch_[*g] == patch_[home]) f(*g);
  }

  // Sharp edges of the same crease sharing an endpoint with edge `home`.
  template <class F> void for_each_crease_edge_near(std::size_t home, F f) const {
    for (std::size_t w : m_.edges[home])
      for (const Index* e = m_.vertex_edges.first(w); e != m_.vertex_edges.last(w); ++e)
        if (c_.crease_of_edge[*e] == c_.crease_of_edge[home]) f(*e);
  }

public:
  /// What project() gives a smooth vertex without the local answer (tests compare the two).
  Result project_on_surface_by_tree(const Vec3& q, const Vec3& current, std::size_t home) const {
    const Point query = point(q);
    const auto hint = std::make_pair(point(current), Index(home));
    const auto found = face_tree_.closest_point_and_primitive(query, hint);
    K::Construct_projected_point_3 closest;
    return tree_answer_near(
        q, current, home, vec(found.first), found.second, [this](std::size_t h, auto f) { for_each_face_near(h, f); },
        [&](std::size_t g) { return vec(closest(Face_triangle_map{&m_}[Index(g)], query)); });
  }

private:
  // The sheet guard (user manual, "Projection Guard"): the tree's answer
  // `found` on element `element` when that element is near `home` (one of
  // `for_each_near(home, f)`); otherwise the closest of the points
  // `closest(g)` of the elements near `home`, or `current` if none is closer
  // to `q`, flagged as guarded.
  template <class ForEachNear, class Closest>
  static Result tree_answer_near(const Vec3& q, const Vec3& current, std::size_t home, const Vec3& found,
                                 std::size_t element, const ForEachNear& for_each_near, const Closest& closest) {
    bool near = false;
    for_each_near(home, [&](std::size_t g) { near = near || g == element; });
    if (near) return {found, element, false};

    Result best{current, home, true};
    double best_distance = (q - current).squaredNorm();
    for_each_near(home, [&](std::size_t g) {
      const Vec3 p = closest(g);
      const double distance = (q - p).squaredNorm();
      if (distance < best_distance) best = {p, g, true}, best_distance = distance;
    });
    return best;
  }

  Result project_on_crease(const Vec3& q, const Vec3& current, std::size_t home) const {
    const Point query = point(q);
    const auto hint = std::make_pair(point(current), segments_.cbegin() + std::ptrdiff_t(segment_of(home)));
    const auto found = crease_tree_.closest_point_and_primitive(query, hint);
    K::Construct_projected_point_3 closest;
    return tree_answer_near(
        q, current, home, vec(found.first), segment_edge_[std::size_t(found.second - segments_.cbegin())],
        [this](std::size_t h, auto f) { for_each_crease_edge_near(h, f); },
        [&](std::size_t g) { return vec(closest(segments_[segment_of(g)], query)); });
  }

  // The closest point to `q` of the crease edges near `home` (see
  // for_each_crease_edge_near()): the answer of project_on_crease() but for
  // ties (at the same distance, the first edge in the order of the flat mesh
  // wins, the home edge before the others), without its tree query.
  Result project_on_crease_near(const Vec3& q, const Vec3& current, std::size_t home) const {
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_edge = npos;
    auto measure = [&](std::size_t e) {
      const double d = squared_distance_to_segment(q, m_.points[m_.edges[e][0]], m_.points[m_.edges[e][1]]);
      if (d < best) best = d, best_edge = e;
    };
    measure(home);
    for_each_crease_edge_near(home, measure);
    if (best_edge == npos) return project_on_crease(q, current, home);
    K::Construct_projected_point_3 closest;
    return {vec(closest(segments_[segment_of(best_edge)], point(q))), best_edge, false};
  }

  // The faces around the vertices of face `home`, each once: f(g, near), `near`
  // when g is in the patch of `home` (see for_each_face_near()).
  template <class F> void for_each_face_around(std::size_t home, F f) const {
    const auto& h = m_.faces[home];
    for (std::size_t k = 0; k < 3; ++k)
      for (const Index* g = m_.vertex_faces.first(h[k]); g != m_.vertex_faces.last(h[k]); ++g) {
        const auto& t = m_.faces[*g];
        bool seen = false;
        for (std::size_t j = 0; j < k; ++j) seen = seen || t[0] == h[j] || t[1] == h[j] || t[2] == h[j];
        if (!seen) f(std::size_t(*g), patch_[*g] == patch_[home]);
      }
  }

  bool incident(std::size_t f, std::size_t w) const {
    const auto& t = m_.faces[f];
    return t[0] == w || t[1] == w || t[2] == w;
  }

  // A lower bound of the squared distance from `x` to face `f`: the distance
  // itself for a face that is not thin, else the distance to its edges less
  // its height (the closest-point formula loses its accuracy on slivers).
  double squared_distance_at_least(const Vec3& x, std::size_t f) const {
    const auto& t = m_.faces[f];
    const Vec3 &a = m_.points[t[0]], &b = m_.points[t[1]], &c = m_.points[t[2]];
    if (!thin_[f]) return squared_distance_to_triangle(x, a, b, c);
    const double edges =
        std::sqrt((std::min)({squared_distance_to_segment(x, a, b), squared_distance_to_segment(x, b, c),
                              squared_distance_to_segment(x, c, a)}));
    const double longest = std::sqrt((std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()}));
    const double height = longest > 0 ? area_vector(m_.points, t).norm() / longest : 0.;
    const double bound = (std::max)(0., edges - height);
    return bound * bound;
  }

  static double squared_distance_to_box(const Vec3& x, const CGAL::Bbox_3& b) {
    double d = 0;
    for (int i = 0; i < 3; ++i) {
      const double gap = (std::max)({b.min(i) - x[i], x[i] - b.max(i), 0.});
      d += gap * gap;
    }
    return d;
  }

  // Traversal of the face tree for a face that touches no vertex of `home`
  // and may lie within `reach` (squared) of `x`: it stops at the first one.
  struct Reach_traits {
    const Projector* self;
    const Vec3& x;
    std::size_t home;
    double reach; // squared
    bool found = false;
    bool go_further() const { return !found; }
    void intersection(const Point&, const Face_primitive& primitive) {
      for (Index w : self->m_.faces[home])
        if (self->incident(primitive.id(), w)) return;
      if (self->squared_distance_at_least(x, primitive.id()) <= reach) found = true;
    }
    template <class Node> bool do_intersect(const Point&, const Node& node) const {
      return squared_distance_to_box(x, node.bbox()) <= reach;
    }
  };

  // Traversal of the face tree for the smallest squared distance from vertex
  // `w` to the faces not incident to it, nearest boxes first.
  struct Clearance_traits {
    using Priority = double;
    const Projector* self;
    Index w;
    double best; // squared
    bool go_further() const { return true; }
    void intersection(const Point&, const Face_primitive& primitive) {
      if (!self->incident(primitive.id(), w))
        best = (std::min)(best, self->squared_distance_at_least(self->m_.points[w], primitive.id()));
    }
    double box_distance(const CGAL::Bbox_3& b) const { return squared_distance_to_box(self->m_.points[w], b); }
    template <class Node> bool do_intersect(const Point&, const Node& node) const {
      return box_distance(node.bbox()) < best;
    }
    template <class Node> std::pair<bool, double> do_intersect_with_priority(const Point&, const Node& node) const {
      const double d = box_distance(node.bbox());
      return {d < best, -d};
    }
  };

  // clearance_[w]: the distance from vertex w to the nearest face not incident
  // to it, less the rounding margin; thin_[f]: whether face f is a sliver.
  template <class ConcurrencyTag> void compute_clearances() {
    const std::size_t n = m_.number_of_faces();
    thin_.assign(n, 0);
    for (std::size_t f = 0; f < n; ++f) {
      const auto& t = m_.faces[f];
      const double longest = (std::max)({(m_.points[t[1]] - m_.points[t[0]]).squaredNorm(),
                                         (m_.points[t[2]] - m_.points[t[1]]).squaredNorm(),
                                         (m_.points[t[0]] - m_.points[t[2]]).squaredNorm()});
      thin_[f] = longest == 0 || !(area_vector(m_.points, m_.faces[f]).norm() >= thin_ratio * longest);
    }
    clearance_.assign(m_.number_of_vertices(), -1.f);
    if (n == 0) return;
    parallel_for<ConcurrencyTag>(m_.number_of_vertices(), [&](std::size_t w) {
      if (m_.vertex_faces.size(w) == 0) return;
      Clearance_traits traits{this, Index(w), std::numeric_limits<double>::infinity()};
      // A first bound, so that the traversal prunes from the start: the
      // distance to a neighbour that lies on a face not incident to `w`, no
      // less than that face's value (the traversal finds the smallest value).
      for (const Index* u = m_.vertex_neighbors.first(w); u != m_.vertex_neighbors.last(w); ++u)
        for (const Index* g = m_.vertex_faces.first(*u); g != m_.vertex_faces.last(*u); ++g)
          if (!incident(*g, w)) {
            traits.best = (std::min)(traits.best, (m_.points[*u] - m_.points[w]).squaredNorm());
            break;
          }
      face_tree_.traversal_with_priority(point(m_.points[w]), traits);
      // Stored as a float rounded down: a smaller clearance only sends more
      // queries to the tree, whose answer is the same.
      clearance_[w] = float_rounded_down(std::sqrt(traits.best) - margin);
    });
  }

public:
  /// The closest point to `q` of the faces near `home` (sharing a vertex with
  /// it, in its patch), which the sheet guard makes the answer (see the top of
  /// this file); `guarded` tells whether a face outside them is closer (the
  /// AABB tree's closest point would lie on another sheet or patch; not
  /// computed without `guard`). Among faces at the same distance the first in
  /// the order of the flat mesh wins, the home face before the others. False
  /// only if no near face has a finite distance to `q`.
  bool project_near(const Vec3& q, std::size_t home, Result& out, bool guard = true) const {
    double best = std::numeric_limits<double>::infinity(), other = best;
    std::size_t best_face = npos;
    // A face whose bounding ball is farther from `q` than the reach of the
    // best distance so far can neither lower `best` nor `other` below it: its
    // distance is not computed. The home face comes first, so that the reach
    // is short from the start.
    double within = std::numeric_limits<double>::infinity();
    auto measure = [&](std::size_t g, bool near) {
      const auto& t = m_.faces[g];
      if (!near) {
        other = (std::min)(other, squared_distance_at_least(q, g));
        return;
      }
      const double d = squared_distance_to_triangle(q, m_.points[t[0]], m_.points[t[1]], m_.points[t[2]]);
      if (d < best) best = d, best_face = g, within = std::sqrt(best) + ball_slack;
    };
    measure(home, true);
    for_each_face_around(home, [&](std::size_t g, bool near) {
      if (g != home && ball_within(q, g, within)) measure(g, near);
    });
    if (best_face == npos) return false;
    // Guarded: a face of another patch around `home`, or a face that touches
    // no vertex of `home` (the clearances of the vertices of `home` rule it
    // out, or else a traversal of the tree that looks no farther than the
    // best distance), is closer. Slivers are compared by a lower bound of
    // their distance (see squared_distance_at_least()).
    bool guarded = guard && other < best;
    if (guard && !guarded) {
      const double reach = std::sqrt(best);
      double clear = -1.;
      for (Index w : m_.faces[home]) clear = (std::max)(clear, double(clearance_[w]) - (q - m_.points[w]).norm());
      if (!(clear > reach)) {
        Reach_traits traits{this, q, home, best};
        face_tree_.traversal(point(q), traits);
        guarded = traits.found;
      }
    }
    K::Construct_projected_point_3 closest;
    out = {vec(closest(Face_triangle_map{&m_}[Index(best_face)], point(q))), best_face, guarded};
    return true;
  }

  /// Whether the bounding ball of input face `g` comes within `reach` of `x`
  /// (true for an infinite reach). When it does not, the distance from `x` to
  /// the face exceeds `reach` less `ball_slack`.
  bool ball_within(const Vec3& x, std::size_t g, double reach) const {
    const Ball& b = balls_[g];
    const double gap = reach + double(b.radius);
    const Vec3 c(double(b.center[0]), double(b.center[1]), double(b.center[2]));
    return !((x - c).squaredNorm() > gap * gap);
  }

  /// Allowance for the rounding of the bounding-ball test (normalised units),
  /// far above its errors (about 1e-16) and far below any distance the smoothing depends on.
  static constexpr double ball_slack = 1e-13;

private:
  // Bounding balls of the faces, in floats: the centre rounded, the radius
  // measured from the rounded centre and rounded up, so that the ball holds
  // the face.
  struct Ball {
    std::array<float, 3> center;
    float radius;
  };
  void compute_balls() {
    balls_.resize(m_.number_of_faces());
    for (std::size_t f = 0; f < balls_.size(); ++f) {
      const auto& t = m_.faces[f];
      const Vec3 centroid = (m_.points[t[0]] + m_.points[t[1]] + m_.points[t[2]]) / 3.;
      Ball& b = balls_[f];
      for (int i = 0; i < 3; ++i) b.center[i] = float(centroid[i]);
      const Vec3 c(double(b.center[0]), double(b.center[1]), double(b.center[2]));
      double radius = 0;
      for (Index w : t) radius = (std::max)(radius, (m_.points[w] - c).norm());
      b.radius = float_rounded_up(radius);
    }
  }

  // Rounding margin of the clearances, in normalised units (the bounding-box
  // diagonal is 1): far above the rounding of the distances (about 1e-16),
  // far below any distance the smoothing depends on.
  static constexpr double margin = 1e-10;
  // A face is thin (a sliver) when twice its area is below this fraction of
  // its longest edge squared. It protects the clearances: the distance to a
  // thin face is bounded through its edges (squared_distance_at_least()),
  // where the closest-point formula loses its accuracy.
  static constexpr double thin_ratio = 1e-2;

  const Flat_mesh& m_;
  const Vertex_classification& c_;
  std::vector<float> clearance_;    // per vertex, see compute_clearances()
  std::vector<unsigned char> thin_; // per face
  std::vector<Ball> balls_;         // per face, see compute_balls()
  std::vector<Segment> segments_;
  std::vector<Index> segment_edge_; // segment -> edge, in increasing order
  std::vector<Index> patch_;        // face -> representative face of its patch
  Face_tree face_tree_;
  Crease_tree crease_tree_;
};

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_PROJECTION_H
