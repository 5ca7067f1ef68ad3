// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The core of ILSA: the classification of the flat copy (stage 1, paper §3)
// and the iterations (Algo. 1 to 3, projection, safety check). The core reads
// the flat copy only, never the user's mesh type, so it can be compiled once (user manual, "Compiling the Core Once").
// This header declares its two functions, classify() and smooth_flat_copy(). Header-only (the default), the public
// headers include their definitions (vertex_classification.h, global_loop.h); with CGAL_ILSA_COMPILED_CORE defined,
// they do not, and src/ilsa_core.cpp defines them (for CGAL::Sequential_tag, and CGAL::Parallel_tag with TBB).

#ifndef CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CORE_H
#define CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CORE_H

#include <CGAL/Polygon_mesh_processing/ilsa_types.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/classification.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/flat_mesh.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/parameters.h>

#include <vector>

// `inline` where the core is header-only; nothing where it is compiled once.
// The two ways give the core's functions different names (an inline
// namespace), so that a program may mix files compiled both ways: each file
// calls its own way's functions, and no function has two definitions.
#ifdef CGAL_ILSA_COMPILED_CORE
#define CGAL_ILSA_CORE_INLINE
#define CGAL_ILSA_CORE_NAMESPACE compiled_core
#else
#define CGAL_ILSA_CORE_INLINE inline
#define CGAL_ILSA_CORE_NAMESPACE header_only_core
#endif

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

inline namespace CGAL_ILSA_CORE_NAMESPACE {

/// Stage 1 (paper §3): the vertex types, sharp edges and crease lines of `m`
/// (vertex_classification.h).
CGAL_ILSA_CORE_INLINE Vertex_classification classify(const Flat_mesh& m, const Set_up_incidences& incidences,
                                                     const Classification_options& options);

/// The iterations of one call (Algo. 1, global_loop.h) on the classified flat
/// copy `original`: builds the projection trees, the clearances and the safety
/// check, frees `incidences`, iterates, and returns T_new in the flat copy's
/// coordinates.
template <class ConcurrencyTag>
std::vector<Vec3> smooth_flat_copy(const Flat_mesh& original, const Vertex_classification& classification,
                                   const ILSA_neighborhoods& neighborhoods, const Smoothing_parameters& parameters,
                                   Set_up_incidences& incidences, ILSA_statistics& stats);

} // namespace CGAL_ILSA_CORE_NAMESPACE

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL

#endif // CGAL_POLYGON_MESH_PROCESSING_INTERNAL_ILSA_CORE_H
