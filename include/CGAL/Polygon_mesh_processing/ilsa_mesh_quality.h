// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The header's name in version 1.0.0, kept for one version (user manual,
// "Names"): it includes <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>, with CGAL's
// deprecation warning (an error under CGAL_NO_DEPRECATED_CODE).

#ifndef CGAL_POLYGON_MESH_PROCESSING_ILSA_MESH_QUALITY_H
#define CGAL_POLYGON_MESH_PROCESSING_ILSA_MESH_QUALITY_H

#define CGAL_DEPRECATED_HEADER "<CGAL/Polygon_mesh_processing/ilsa_mesh_quality.h>"
#define CGAL_REPLACEMENT_HEADER "<CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>"
#include <CGAL/Installation/internal/deprecation_warning.h>

#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>

#endif // CGAL_POLYGON_MESH_PROCESSING_ILSA_MESH_QUALITY_H
