// Copyright (c) 2026 The Polygon_mesh_processing_ILSA authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fidelity certificate (user manual, "Fidelity Certificate"):
// - the certified distances of a triangle and of a segment to a union of
//   triangles or segments are upper bounds of the distances of densely
//   sampled points, on random configurations, and so are those of the
//   height route (height_bound()) over random height fields, some folded,
//   some reaching past the triangle; triangles with coincident corners (the
//   zero-area faces of collapsed edges) are at the distance of their edges,
//   and both routes stay upper bounds over patches with a collapsed edge;
// - the smoothed meshes stay within the fidelity tolerance of their input,
//   both ways, as judged by CGAL's own bounded-error symmetric Hausdorff
//   distance (is_Hausdorff_distance_larger(), error 1e-5 of the diagonal,
//   counted against the package), on the bundled meshes, the shared ones when
//   present, at the default tolerance and at 1e-4 and 1e-3, on Surface_mesh and
//   Polyhedron_3, sequential and parallel; and the bound ILSA_statistics
//   reports is at most the tolerance;
// - without the bound the same judge finds the result beyond it, so the test
//   can fail.
// ILSA_FIDELITY_MAX_FACES (environment) leaves out the larger meshes;
// ILSA_FIDELITY_TOLERANCES (environment, e.g. "1e-4 5e-4 1e-3") judges every
// mesh at each of these tolerances instead of the default only.

#include "ilsa_test_utils.h"

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/distance_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/fidelity_certificate.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/defaults.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace ilsa_test;
namespace ilsa = CGAL::Polygon_mesh_processing::internal::ILSA;

// Random triangles against a few random triangles nearby (and segments
// against segments): the certified bound is never below the distance of a
// sampled point, and it is found for configurations well within the limit.
void test_bounds_against_samples() {
  std::mt19937 rng(20261206u);
  std::uniform_real_distribution<double> unit(-1., 1.);
  auto point = [&](double s) { return ilsa::Vec3(s * unit(rng), s * unit(rng), 0.1 * s * unit(rng)); };
  std::size_t certified = 0, segments_certified = 0;
  for (int c = 0; c < 2000; ++c) {
    const ilsa::Vec3 a = point(1), b = point(1), d = point(1);
    std::vector<std::array<ilsa::Vec3, 3>> candidates(1 + c % 6);
    for (auto& t : candidates) t = {point(1.5), point(1.5), point(1.5)};
    const double limit = 0.05 + 2 * std::abs(unit(rng));
    auto candidate = [&](std::size_t k) { return candidates[k]; };
    const double bound = ilsa::triangle_bound(a, b, d, candidates.size(), candidate, limit);
    double sampled = 0;
    const int n = 40;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const ilsa::Vec3 x = a + (double(i) / n) * (b - a) + (double(j) / n) * (d - a);
        double best = std::numeric_limits<double>::infinity();
        for (const auto& t : candidates)
          best = (std::min)(best, ilsa::squared_distance_to_triangle(x, t[0], t[1], t[2]));
        sampled = (std::max)(sampled, std::sqrt(best));
      }
    if (bound <= limit) {
      ++certified;
      ILSA_CHECK(bound >= sampled - 1e-12);
    } else {
      ILSA_CHECK(bound == std::numeric_limits<double>::infinity());
    }
    // The segment version, on the first edges.
    std::vector<std::array<ilsa::Vec3, 2>> edges;
    for (const auto& t : candidates) edges.push_back({t[0], t[1]});
    const double segment = ilsa::segment_bound(
        a, b, edges.size(), [&](std::size_t k) { return edges[k]; }, limit);
    double segment_sampled = 0;
    for (int i = 0; i <= 200; ++i) {
      const ilsa::Vec3 x = a + (i / 200.) * (b - a);
      double best = std::numeric_limits<double>::infinity();
      for (const auto& e : edges) best = (std::min)(best, ilsa::squared_distance_to_segment(x, e[0], e[1]));
      segment_sampled = (std::max)(segment_sampled, std::sqrt(best));
    }
    if (segment <= limit) {
      ++segments_certified;
      ILSA_CHECK(segment >= segment_sampled - 1e-12);
    }
  }
  // A triangle on a flat mesh of eight triangles around it, lifted a little:
  // certified close to the lift.
  const std::vector<std::array<ilsa::Vec3, 3>> flat{{ilsa::Vec3(-2, -2, 0), ilsa::Vec3(2, -2, 0), ilsa::Vec3(2, 2, 0)},
                                                    {ilsa::Vec3(-2, -2, 0), ilsa::Vec3(2, 2, 0), ilsa::Vec3(-2, 2, 0)}};
  const double lifted = ilsa::triangle_bound(
      ilsa::Vec3(-1, -1, 1e-3), ilsa::Vec3(1, -0.5, 2e-3), ilsa::Vec3(0, 1, 1e-3), flat.size(),
      [&](std::size_t k) { return flat[k]; }, 1e-2);
  ILSA_CHECK(lifted >= 2e-3 && lifted <= 2e-3 + 1e-12);
  std::cout << "certified bounds against samples: " << certified << " triangles and " << segments_certified
            << " segments certified of 2000, none below a sample; lifted triangle " << lifted << std::endl;
  ILSA_CHECK(certified > 200 && segments_certified > 200);
}

using Grid_face = std::array<ilsa::Index, 3>;

// The faces of a grid of `grid` by `grid` points, numbered row by row: two
// triangles per cell.
std::vector<Grid_face> grid_faces(int grid) {
  std::vector<Grid_face> faces;
  for (int j = 0; j + 1 < grid; ++j)
    for (int i = 0; i + 1 < grid; ++i) {
      const ilsa::Index v = ilsa::Index(j * grid + i);
      faces.push_back({v, v + 1, v + ilsa::Index(grid) + 1});
      faces.push_back({v, v + ilsa::Index(grid) + 1, v + ilsa::Index(grid)});
    }
  return faces;
}

// Whether the edge from corner i to corner i + 1 of face k is cancelled by
// the reverse edges of the other faces (height_bound()'s `cancelled`).
bool is_cancelled(const std::vector<Grid_face>& faces, std::size_t k, std::size_t i) {
  const ilsa::Index u = faces[k][i], v = faces[k][(i + 1) % 3];
  int net = 0;
  for (const Grid_face& f : faces)
    for (std::size_t j = 0; j < 3; ++j)
      net += int(f[j] == u && f[(j + 1) % 3] == v) - int(f[j] == v && f[(j + 1) % 3] == u);
  return net == 0;
}

// The quicker bound over a height field: random grid patches (some folded,
// some steep) under random triangles, some reaching past the patch: every
// bound it finds is at least the distance of every sampled point, and every
// point it reports as far is farther than the limit from the whole patch.
void test_height_bound_against_samples() {
  std::mt19937 rng(20261207u);
  std::uniform_real_distribution<double> unit(-1., 1.);
  std::size_t certified = 0, far_points = 0;
  const int grid = 6;
  for (int c = 0; c < 3000; ++c) {
    const double jitter = c % 5 == 0 ? 0.9 : 0.2, height = c % 3 == 0 ? 0.6 : 0.05;
    std::vector<ilsa::Vec3> points;
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i)
        points.push_back(ilsa::Vec3((i + jitter * unit(rng) / 2) * 3. / (grid - 1) - 1.5,
                                    (j + jitter * unit(rng) / 2) * 3. / (grid - 1) - 1.5, height * unit(rng)));
    const std::vector<Grid_face> faces = grid_faces(grid);
    auto candidate = [&](std::size_t k) {
      return std::array<ilsa::Vec3, 3>{points[faces[k][0]], points[faces[k][1]], points[faces[k][2]]};
    };
    auto cancelled = [&](std::size_t k, std::size_t i) { return is_cancelled(faces, k, i); };
    const double reach = c % 4 == 0 ? 2. : 1.;
    auto corner = [&] { return ilsa::Vec3(reach * unit(rng), reach * unit(rng), 0.1 * unit(rng)); };
    const ilsa::Vec3 a = corner(), b = corner(), d = corner();
    const double limit = 0.05 + std::abs(unit(rng));
    ilsa::Vec3 far;
    bool has_far = false;
    const double bound = ilsa::height_bound(a, b, d, faces.size(), candidate, cancelled, limit, &far, &has_far);
    auto distance = [&](const ilsa::Vec3& x) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < faces.size(); ++k) {
        const auto t = candidate(k);
        best = (std::min)(best, ilsa::squared_distance_to_triangle(x, t[0], t[1], t[2]));
      }
      return std::sqrt(best);
    };
    if (bound <= limit) {
      ++certified;
      double sampled = 0;
      const int n = 30;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
          sampled = (std::max)(sampled, distance(a + (double(i) / n) * (b - a) + (double(j) / n) * (d - a)));
      ILSA_CHECK(bound >= sampled - 1e-12);
    } else if (has_far) {
      ++far_points;
      ILSA_CHECK(distance(far) > limit - 1e-12);
    }
  }
  std::cout << "height bounds against samples: " << certified << " triangles certified of 3000, none below a sample; "
            << far_points << " far points, all beyond the limit" << std::endl;
  ILSA_CHECK(certified > 300 && far_points > 30);
}

// Triangles with coincident corners, as the collapsed edges of a mesh give
// (zero-area faces): the distance to one is the distance to its edges, and
// the certified bounds stay upper bounds when such triangles are among the
// candidates (a NaN distance would pass the bounds' comparisons as small).
void test_degenerate_candidates() {
  std::mt19937 rng(20261208u);
  std::uniform_real_distribution<double> unit(-1., 1.);
  using Triangle = std::array<ilsa::Vec3, 3>;
  auto point = [&](double s) { return ilsa::Vec3(s * unit(rng), s * unit(rng), s * unit(rng)); };
  auto edges_distance = [](const ilsa::Vec3& x, const Triangle& t) {
    return (std::min)({ilsa::squared_distance_to_segment(x, t[0], t[1]),
                       ilsa::squared_distance_to_segment(x, t[1], t[2]),
                       ilsa::squared_distance_to_segment(x, t[2], t[0])});
  };
  // The distance function: a corner moved onto the next one, all three
  // corners at one point, or one on the segment between the others.
  for (int c = 0; c < 5000; ++c) {
    Triangle t{point(1), point(1), point(1)};
    const int k = c % 5;
    if (k < 3)
      t[std::size_t(k)] = t[std::size_t(k + 1) % 3];
    else if (k == 3)
      t[1] = t[2] = t[0];
    else
      t[2] = 0.5 * (t[0] + t[1]);
    const ilsa::Vec3 x = point(2);
    const double d = ilsa::squared_distance_to_triangle(x, t[0], t[1], t[2]), e = edges_distance(x, t);
    ILSA_CHECK(std::abs(d - e) <= 1e-12 * (1 + e));
  }
  // The reference distance of the samples below.
  auto reference = [&](const ilsa::Vec3& x, const Triangle& t) {
    const bool coincident = t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
    return coincident ? edges_distance(x, t) : ilsa::squared_distance_to_triangle(x, t[0], t[1], t[2]);
  };
  auto sampled = [&](const ilsa::Vec3& a, const ilsa::Vec3& b, const ilsa::Vec3& d, const std::vector<Triangle>& ts) {
    double worst = 0;
    const int n = 30;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const ilsa::Vec3 x = a + (double(i) / n) * (b - a) + (double(j) / n) * (d - a);
        double best = std::numeric_limits<double>::infinity();
        for (const Triangle& t : ts) best = (std::min)(best, reference(x, t));
        worst = (std::max)(worst, std::sqrt(best));
      }
    return worst;
  };
  // A flat grid patch with one edge collapsed (its end moved onto its
  // start), under a triangle lifted a little: both routes.
  std::size_t certified = 0, height_certified = 0;
  const int grid = 6;
  for (int c = 0; c < 1000; ++c) {
    std::vector<ilsa::Vec3> points;
    for (int j = 0; j < grid; ++j)
      for (int i = 0; i < grid; ++i)
        points.push_back(ilsa::Vec3((i + 0.2 * unit(rng)) * 3. / (grid - 1) - 1.5,
                                    (j + 0.2 * unit(rng)) * 3. / (grid - 1) - 1.5, 0.05 * unit(rng)));
    const std::vector<Grid_face> faces = grid_faces(grid);
    const Grid_face& collapsed = faces[std::size_t(double(faces.size()) * (unit(rng) + 1) / 2)];
    const std::size_t corner = std::size_t(c % 3);
    points[collapsed[(corner + 1) % 3]] = points[collapsed[corner]];
    std::vector<Triangle> ts;
    for (const auto& f : faces) ts.push_back({points[f[0]], points[f[1]], points[f[2]]});
    auto candidate = [&](std::size_t k) { return ts[k]; };
    auto cancelled = [&](std::size_t k, std::size_t i) { return is_cancelled(faces, k, i); };
    // The triangle has a corner at the collapsed point half the time.
    auto near_patch = [&] { return ilsa::Vec3(1.2 * unit(rng), 1.2 * unit(rng), 0.05 * unit(rng)); };
    const ilsa::Vec3 a = c % 2 == 0 ? points[collapsed[corner]] + ilsa::Vec3(0, 0, 0.02 * unit(rng)) : near_patch(),
                     b = near_patch(), d = near_patch();
    const double limit = 0.05 + 0.5 * std::abs(unit(rng));
    const double bound = ilsa::triangle_bound(a, b, d, ts.size(), candidate, limit);
    const double height = ilsa::height_bound(a, b, d, ts.size(), candidate, cancelled, limit);
    if (!(bound <= limit) && !(height <= limit)) continue;
    const double s = sampled(a, b, d, ts);
    if (bound <= limit) {
      ++certified;
      ILSA_CHECK(bound >= s - 1e-12);
    }
    if (height <= limit) {
      ++height_certified;
      ILSA_CHECK(height >= s - 1e-12);
    }
  }
  std::cout << "degenerate candidates: distances to 5000 degenerate triangles are those to their edges; " << certified
            << " and " << height_certified
            << " triangles certified of 1000 (pieces, heights) over patches with a collapsed edge, none below a sample"
            << std::endl;
  ILSA_CHECK(certified > 100 && height_certified > 100);
}

std::size_t max_faces() {
  const char* text = std::getenv("ILSA_FIDELITY_MAX_FACES");
  return text ? std::size_t(std::strtoull(text, nullptr, 10)) : std::numeric_limits<std::size_t>::max();
}

// Smooths `input` with the tolerance `tolerance` and judges the result with
// CGAL's bounded-error distance; returns the result.
template <class Mesh, class ConcurrencyTag = CGAL::Sequential_tag>
Mesh smooth_and_judge(const Mesh& input, double tolerance, const std::string& name) {
  Mesh result = input;
  const auto stats =
      PMP::smooth_surface_mesh_ilsa<ConcurrencyTag>(result, CGAL::parameters::ilsa_fidelity_tolerance(tolerance));
  const double diagonal = bbox_diagonal(input), error = 1e-5 * diagonal;
  const bool larger = PMP::is_Hausdorff_distance_larger<CGAL::Sequential_tag>(
      input, result, tolerance * diagonal, error, CGAL::parameters::use_one_sided_hausdorff(false),
      CGAL::parameters::default_values());
  std::cout << name << " (" << num_faces(input) << " faces), tolerance " << tolerance << ": certified "
            << stats.certified_distance << ", crease " << stats.certified_crease_distance
            << ", CGAL: larger than the tolerance: " << (larger ? "yes" : "no") << ", mean q "
            << PMP::mesh_quality_ilsa(input).mean_aspect_ratio << " -> "
            << PMP::mesh_quality_ilsa(result).mean_aspect_ratio << std::endl;
  ILSA_CHECK(!larger);
  ILSA_CHECK(stats.certified_distance <= tolerance);
  ILSA_CHECK(stats.certified_crease_distance <= tolerance);
  ILSA_CHECK(PMP::mesh_quality_ilsa(result).mean_aspect_ratio > PMP::mesh_quality_ilsa(input).mean_aspect_ratio);
  return result;
}

// The tolerances every mesh is judged at.
std::vector<double> tolerances() {
  const char* text = std::getenv("ILSA_FIDELITY_TOLERANCES");
  if (!text) return {ilsa::defaults::fidelity_tolerance};
  std::vector<double> list;
  std::istringstream in(text);
  for (double t; in >> t;) list.push_back(t);
  ILSA_CHECK(!list.empty());
  return list;
}

void test_meshes() {
  const double tolerance = ilsa::defaults::fidelity_tolerance;
  std::vector<std::string> files;
  for (const char* name :
       {"sphere_low.off", "elephant.off", "hemisphere.off", "fandisk.off", "mech-holes-shark.off", "horse.ply"})
    files.push_back(data_file(name));
  const std::string shared = ILSA_SHARED_DATA_DIR;
  for (const char* name : {"beetle.off", "camelhead.off", "cow.off", "abc4.stl"})
    if (std::filesystem::exists(shared + "/" + name)) files.push_back(shared + "/" + name);
  for (const std::string& file : files) {
    const Surface_mesh input = read_mesh<Surface_mesh>(file);
    if (num_faces(input) > max_faces()) {
      std::cout << file << ": left out (ILSA_FIDELITY_MAX_FACES)" << std::endl;
      continue;
    }
    for (double t : tolerances()) smooth_and_judge(input, t, std::filesystem::path(file).filename().string());
  }
  // Other tolerances, Polyhedron_3, and Parallel_tag with the same bits.
  const Surface_mesh elephant = read_mesh<Surface_mesh>(data_file("elephant.off"));
  for (double t : {1e-4, 1e-3}) smooth_and_judge(elephant, t, "elephant");
  const Polyhedron polyhedron = read_mesh<Polyhedron>(data_file("fandisk.off"));
  if (num_faces(polyhedron) <= max_faces()) smooth_and_judge(polyhedron, tolerance, "fandisk (Polyhedron_3)");
#ifdef CGAL_LINKED_WITH_TBB
  const Surface_mesh sequential = smooth_and_judge(elephant, 1e-4, "elephant");
  const Surface_mesh parallel =
      smooth_and_judge<Surface_mesh, CGAL::Parallel_tag>(elephant, 1e-4, "elephant (parallel)");
  ILSA_CHECK(points_of(sequential) == points_of(parallel));
#endif
  // Without the bound, the judge finds the elephant beyond the tolerance.
  Surface_mesh unbounded = elephant;
  const auto stats = PMP::smooth_surface_mesh_ilsa(
      unbounded, CGAL::parameters::ilsa_fidelity_tolerance(std::numeric_limits<double>::infinity()));
  const double diagonal = bbox_diagonal(elephant);
  const bool larger = PMP::is_Hausdorff_distance_larger<CGAL::Sequential_tag>(
      elephant, unbounded, tolerance * diagonal, 1e-5 * diagonal, CGAL::parameters::use_one_sided_hausdorff(false),
      CGAL::parameters::default_values());
  std::cout << "elephant without the bound: CGAL: larger than " << tolerance << ": " << (larger ? "yes" : "no")
            << ", certified " << stats.certified_distance << std::endl;
  ILSA_CHECK(larger && stats.certified_distance == std::numeric_limits<double>::infinity());
}

// The edges the certificate counts as cancelled (cancelled_edges(), which
// height_bound() then leaves out of its nearness test): each must be cancelled
// by the reverse edges of the other candidates, for every face of an open and
// of a closed mesh, with the first ring and with the second. Counting an edge
// that is not (at the rim of the candidates, or on the mesh's boundary) would
// let the height route certify a triangle the candidates do not cover.
void test_cancelled_edges() {
  for (const std::string name : {"hemisphere.off", "mech-holes-shark.off", "fandisk.off"}) {
    const Surface_mesh tm = read_mesh<Surface_mesh>(data_file(name));
    std::vector<Surface_mesh::Vertex_index> vertex_list;
    std::vector<Surface_mesh::Edge_index> edge_list;
    ilsa::Set_up_incidences incidences;
    const ilsa::Flat_mesh m = flat_copy(tm, vertex_list, edge_list, incidences);
    const std::vector<unsigned char> balanced = ilsa::balanced_edges(m);
    std::size_t cancelled_count = 0, kept_count = 0;
    for (std::size_t f = 0; f < m.number_of_faces(); ++f)
      for (const bool second_ring : {false, true}) {
        ilsa::Face_candidates candidates(m, f);
        if (second_ring) candidates.add_second_ring(m);
        std::array<unsigned char, ilsa::Face_candidates::capacity> cancelled{};
        ilsa::cancelled_edges(m, balanced, candidates, cancelled);
        for (std::size_t k = 0; k < candidates.n; ++k)
          for (std::size_t i = 0; i < 3; ++i) {
            if (!(cancelled[k] >> i & 1)) {
              ++kept_count;
              continue;
            }
            const auto& s = m.faces[candidates.face[k]];
            const ilsa::Index u = s[i], v = s[(i + 1) % 3];
            int net = 0; // uses u -> v less uses v -> u among the candidates
            for (std::size_t j = 0; j < candidates.n; ++j)
              for (std::size_t l = 0; l < 3; ++l) {
                const auto& r = m.faces[candidates.face[j]];
                net += int(r[l] == u && r[(l + 1) % 3] == v) - int(r[l] == v && r[(l + 1) % 3] == u);
              }
            assert(net == 0);
            ++cancelled_count;
          }
      }
    std::cout << "cancelled edges, " << name << ": " << cancelled_count << " cancelled, " << kept_count
              << " kept, each cancelled one by the other candidates" << std::endl;
    assert(cancelled_count > 0 && kept_count > 0);
  }
}

int main() {
  test_cancelled_edges();
  test_bounds_against_samples();
  test_height_bound_against_samples();
  test_degenerate_candidates();
  test_meshes();
  std::cout << "test_ilsa_fidelity: OK" << std::endl;
  return 0;
}
