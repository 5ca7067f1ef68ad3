// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_POLYGON_MESH_PROCESSING_ILSA_TYPES_H
#define CGAL_POLYGON_MESH_PROCESSING_ILSA_TYPES_H

#include <CGAL/Named_function_parameters.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {
// Tells the overloads `f(tm, np)` and `f(range, tm, np)` apart, also when `np` is a non-const lvalue.
template <class T> struct is_named_parameters : std::false_type {};
template <class T, class Tag, class Base>
struct is_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>> : std::true_type {};
} // namespace ILSA
} // namespace internal

/// \ingroup PkgPMPILSARef
/// The four vertex types of ILSA (Chen et al. 2007, Section 3).
/// Boundary and corner vertices are fixed; ridge and smooth vertices are adjustable.
enum class ILSA_vertex_type : unsigned char {
  Smooth = 0,  ///< interior vertex of a flat-enough star: moves on the surface
  Ridge = 1,   ///< vertex on a crease line with exactly two sharp edges: moves along the crease
  Corner = 2,  ///< crease junction, cone tip, non-manifold, isolated or user-constrained vertex: fixed
  Boundary = 3 ///< endpoint of a border edge: fixed
};

/// Name of a vertex type ("smooth", "ridge", "corner", "boundary").
inline const char* to_string(ILSA_vertex_type t) {
  switch (t) {
  case ILSA_vertex_type::Smooth:
    return "smooth";
  case ILSA_vertex_type::Ridge:
    return "ridge";
  case ILSA_vertex_type::Corner:
    return "corner";
  case ILSA_vertex_type::Boundary:
    return "boundary";
  }
  return "unknown";
}

/// \ingroup PkgPMPILSARef
/// Thrown by `smooth_surface_mesh_ilsa()` and `classify_vertices_ilsa()` when the
/// input mesh cannot be processed (non-triangle face, non-finite coordinate,
/// vertex that does not belong to the mesh) or a parameter is out of range.
/// When it is thrown, the mesh has not been modified.
class ILSA_error : public std::invalid_argument {
public:
  explicit ILSA_error(const std::string& what) : std::invalid_argument("ILSA: " + what) {}
};

/// \ingroup PkgPMPILSARef
/// Moves of a call of `smooth_surface_mesh_ilsa()` counted by the test of the
/// safety check that limited them: the last test a move failed in its
/// iteration (user manual, "Safety Check").
struct ILSA_move_limits {
  std::size_t flip_or_collapse = 0; ///< a triangle around the vertex would invert or collapse
  std::size_t quality_floor = 0;    ///< the worst triangle of the star would get worse below the quality floor
  std::size_t worsening = 0;        ///< the mean aspect ratio of the star would drop (user manual, "Worsening Moves")
  std::size_t fidelity = 0;         ///< the surface would move farther than the fidelity tolerance from the input
  std::size_t crease = 0;           ///< a feature line would move farther than the fidelity tolerance from the input's

  std::size_t total() const { return flip_or_collapse + quality_floor + worsening + fidelity + crease; }
  ILSA_move_limits& operator+=(const ILSA_move_limits& x) {
    flip_or_collapse += x.flip_or_collapse, quality_floor += x.quality_floor, worsening += x.worsening;
    fidelity += x.fidelity, crease += x.crease;
    return *this;
  }
  friend bool operator==(const ILSA_move_limits& a, const ILSA_move_limits& b) {
    return a.flip_or_collapse == b.flip_or_collapse && a.quality_floor == b.quality_floor &&
           a.worsening == b.worsening && a.fidelity == b.fidelity && a.crease == b.crease;
  }
};

/// \ingroup PkgPMPILSARef
/// What a call of `smooth_surface_mesh_ilsa()` did.
struct ILSA_statistics {
  std::size_t number_of_smooth_vertices = 0;
  std::size_t number_of_ridge_vertices = 0;
  std::size_t number_of_corner_vertices = 0;
  std::size_t number_of_boundary_vertices = 0;
  std::size_t number_of_kink_vertices = 0;   ///< corners among them that are crease kinks (two sharp edges)
  std::size_t number_of_iterations = 0;      ///< global iterations run
  std::size_t number_of_moves = 0;           ///< accepted vertex moves, summed over the iterations
  std::size_t number_of_shortened_moves = 0; ///< moves accepted only after being shortened by the safety check
  std::size_t number_of_rejected_moves = 0;  ///< moves dropped by the safety check
  /// those of them dropped by its worsening pre-test, before projection (user manual, "Worsening Moves")
  std::size_t number_of_moves_dropped_before_projection = 0;
  std::size_t number_of_guarded_projections = 0; ///< projections the sheet guard kept local
  /// iterations in which a vertex whose move the safety check dropped (but for the quality floor in a star at or above
  /// it) was left where it was, untested, its neighbours having moved too little since (user manual, "Retrying Dropped
  /// Moves"); neither moves nor rejected moves
  std::size_t number_of_settled_skips = 0;
  /// the moves the safety check dropped after projection (`number_of_rejected_moves` less those dropped before
  /// projection), by the test that dropped them
  ILSA_move_limits moves_dropped_by;
  ILSA_move_limits moves_shortened_by; ///< the shortened moves, by the test that shortened them last
  /// an upper bound of the Hausdorff distance (both ways) between the smoothed and the input surface, certified by
  /// the safety check (user manual, "Fidelity Certificate"), relative to the bounding-box diagonal like
  /// `ilsa_fidelity_tolerance`: at most the tolerance; infinity when no bound is enforced (an infinite tolerance,
  /// `use_safety_constraints(false)` or `do_project(false)`)
  double certified_distance = 0;
  /// the same between the feature lines of the smoothed surface and of the input (the crease bound)
  double certified_crease_distance = 0;
};

} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_ILSA_TYPES_H
