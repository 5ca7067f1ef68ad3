// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Version of the package. CMakeLists.txt reads it from here: this is the one
// place where it is written.

#ifndef CGAL_POLYGON_MESH_PROCESSING_ILSA_VERSION_H
#define CGAL_POLYGON_MESH_PROCESSING_ILSA_VERSION_H

/// \ingroup PkgPMPILSARef
/// Version of the package, "major.minor.patch".
#define CGAL_PMP_ILSA_VERSION "2.0.0"

#endif // CGAL_POLYGON_MESH_PROCESSING_ILSA_VERSION_H
