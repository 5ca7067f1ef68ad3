// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The core of ILSA compiled once (user manual, "Compiling the Core Once"):
// the classification and the iterations on the flat copy, which do not depend
// on the user's mesh type. Programs that define CGAL_ILSA_COMPILED_CORE
// include only their declarations (internal/ILSA/core.h) and link this file's
// object; the CMake target CGAL::Polygon_mesh_processing_ILSA_core does both.

#ifndef CGAL_ILSA_COMPILED_CORE
#error "src/ilsa_core.cpp is compiled with CGAL_ILSA_COMPILED_CORE defined, as the programs that link it"
#endif

#include <CGAL/Polygon_mesh_processing/internal/ILSA/global_loop.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/vertex_classification.h>

namespace CGAL {
namespace Polygon_mesh_processing {
namespace internal {
namespace ILSA {

template std::vector<Vec3> smooth_flat_copy<CGAL::Sequential_tag>(const Flat_mesh&, const Vertex_classification&,
                                                                  const ILSA_neighborhoods&,
                                                                  const Smoothing_parameters&, Set_up_incidences&,
                                                                  ILSA_statistics&);
#ifdef CGAL_LINKED_WITH_TBB
template std::vector<Vec3> smooth_flat_copy<CGAL::Parallel_tag>(const Flat_mesh&, const Vertex_classification&,
                                                                const ILSA_neighborhoods&, const Smoothing_parameters&,
                                                                Set_up_incidences&, ILSA_statistics&);
#endif

} // namespace ILSA
} // namespace internal
} // namespace Polygon_mesh_processing
} // namespace CGAL
