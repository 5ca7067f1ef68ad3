// Randomised test: the bundled meshes (and, when present, those of
// ../shared/data), perturbed along their surface without folding, smoothed
// with parameters drawn from their whole valid range, through both overloads
// and with random constraint maps. Every run must keep what the reference
// documentation of smooth_surface_mesh_ilsa promises for its parameters:
// - always: no NaN, fixed vertices (corners, boundary, constrained, outside
//   the vertex range) bit-identical, the parallel run (with TBB) gives the
//   same points;
// - with the safety check: no flipped or newly collapsed face, no face below
//   the input's minimum aspect ratio or the quality floor, whichever is lower;
//   with a finite fidelity tolerance, the input's sharp (or constrained) edges
//   and the same edges of the result within it of each other, both ways (the
//   distance of input vertices to the result is bounded per move, not
//   globally: user manual, "Known Limitations");
// - with projection: every vertex on the input surface.
// A quarter of the cases leave the flip check as the only guard (quality floor
// 0, worsening moves accepted, no fidelity bound).
// Also always: the connectivity is unchanged; in a fifth of the cases a
// `callback` stops the run, which must end in time, the callback having seen
// each iteration run.
// A third of the cases also smooth a transformed copy of the mesh:
// - scaled by a power of two (2^-20 to 2^20): every operation of the package
//   on its normalised coordinates is then the same, so the result mapped back
//   must be the untransformed one, bit for bit;
// - or scaled by 1e-6 to 1e6, moved by up to 1e7 times its size and, without a
//   fidelity bound, rotated (with one, a rotation changes the bounding box the
//   tolerance is relative to): its input carries new rounding, and a move whose
//   acceptance test sits within that rounding of its threshold may go the other
//   way, so the points are not compared; the result must keep the promises
//   that do not depend on the rounding (no NaN, fixed vertices bit-identical, no
//   flipped face with the safety check, on the input surface up to the
//   rounding of the transformed coordinates), and the test reports how far the
//   result mapped back is from the untransformed one (user manual, "Bad Input").
//
// ILSA_FUZZ_CASES (environment) sets the number of cases (the default is the
// short CI run), ILSA_FUZZ_FIRST the first case: case N is the same in every
// run; ILSA_FUZZ_MAX_FACES leaves out meshes with more faces.
#include "ilsa_test_utils.h"

#include <CGAL/Polygon_mesh_processing/detect_features.h>

#include <cstdlib>
#include <filesystem>

using namespace ilsa_test;

namespace {

std::vector<std::string> mesh_files() {
  std::vector<std::string> files;
  for (const std::string& dir : {std::string(ILSA_DATA_DIR), std::string(ILSA_SHARED_DATA_DIR)}) {
    if (!std::filesystem::is_directory(dir)) continue;
    std::vector<std::string> here;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      const std::string ext = e.path().extension().string();
      if (ext == ".off" || ext == ".ply" || ext == ".stl") here.push_back(e.path().string());
    }
    std::sort(here.begin(), here.end());
    for (const auto& f : here) {
      const auto name = std::filesystem::path(f).filename();
      if (std::none_of(files.begin(), files.end(),
                       [&](const std::string& g) { return std::filesystem::path(g).filename() == name; }))
        files.push_back(f);
    }
  }
  return files;
}

} // namespace

int main() {
  const char* env = std::getenv("ILSA_FUZZ_CASES");
  const int cases = env ? std::atoi(env) : 24;
  const char* first_env = std::getenv("ILSA_FUZZ_FIRST"); // to replay one case
  const int first = first_env ? std::atoi(first_env) : 0;
  const char* max_faces_env = std::getenv("ILSA_FUZZ_MAX_FACES"); // the sanitizer run leaves out the large meshes
  const std::size_t max_faces = max_faces_env ? std::size_t(std::atol(max_faces_env)) : std::size_t(-1);
  std::vector<std::string> files;
  std::vector<Surface_mesh> meshes;
  for (const auto& f : mesh_files()) {
    Surface_mesh m;
    if (CGAL::IO::read_polygon_mesh(f, m) && !is_empty(m) && CGAL::is_triangle_mesh(m) && num_faces(m) <= max_faces)
      meshes.push_back(m), files.push_back(f);
  }
  ILSA_CHECK(meshes.size() >= (max_faces_env ? 4u : 6u));
  std::cout << "test_ilsa_fuzz: " << meshes.size() << " meshes" << std::endl;

  std::uniform_real_distribution<double> unit(0., 1.);
  const double unbounded = std::numeric_limits<double>::infinity();
  int failures = 0, flip_only = 0, transformed = 0, transformed_elsewhere = 0;
  double worst_transformed_difference = 0; // of the copies not scaled by a power of two
  for (int c = first; c < first + cases; ++c) {
    std::mt19937 rng(2026u + unsigned(c));
    const std::size_t which = std::size_t(c) % meshes.size();
    Surface_mesh original = meshes[which];
    perturb_on_surface(original, 0.2 + 0.6 * unit(rng), unsigned(rng()));
    auto draw = [&](double p) { return unit(rng) < p; };
    unsigned iterations = draw(0.1) ? 30 : 1 + unsigned(unit(rng) * 8);
    const unsigned steps = 1 + unsigned(unit(rng) * 5);
    double relax1 = 0.05 + 0.95 * unit(rng), relax2 = 0.05 + 0.95 * unit(rng);
    double mu = std::pow(10., -3 + 5 * unit(rng));
    double wl = 2 * unit(rng), wa = 2 * unit(rng);
    const double angle = 5 + 75 * unit(rng); // between face normals
    const bool fix = draw(0.5), monotone = draw(0.1);
    const double kink_draw = unit(rng); // the default (the feature angle), off, or any
    const double kink = kink_draw < 0.3 ? angle : kink_draw < 0.5 ? 180. : 180. * unit(rng);
    const double floor_draw = unit(rng); // the library's default: max(0.5, input minimum)
    bool default_floor = floor_draw < 0.3;
    double floor = floor_draw < 0.4 ? 0. : floor_draw < 0.5 ? 0.99 : 0.9 * unit(rng);
    bool reject_worsening = draw(0.7);
    const double tolerance_draw = unit(rng);
    double tolerance = tolerance_draw < 0.3   ? 3e-4
                       : tolerance_draw < 0.5 ? unbounded
                       : tolerance_draw < 0.6 ? 1e-7
                                              : std::pow(10., -5 + 3 * unit(rng));
    const double gain = draw(0.5) ? 1e-4 : 0.;
    const bool project = !draw(0.1), safety = !draw(0.1);
    const bool use_range = draw(0.3), use_vertex_map = draw(0.2), use_edge_map = draw(0.25);
    const double edge_angle = 10 + 50 * unit(rng);
    const bool relax = draw(0.5); // constrained edges slide (or stay fixed, CGAL's default)
    // The flip check alone.
    const bool only_flip_check = safety && draw(0.25);
    if (only_flip_check) {
      // Nothing else holds the moves back, and the paper's soap film (area
      // term) is off: the moves most likely to fold a star.
      floor = 0., default_floor = false, reject_worsening = false, tolerance = unbounded, ++flip_only;
      wa = 0., relax1 = relax2 = 1., mu = 100., iterations = (std::max)(iterations, 8u);
    }

    using vd = Surface_mesh::Vertex_index;
    using ed = Surface_mesh::Edge_index;
    std::vector<vd> range;
    std::map<vd, bool> constrained_vertices;
    std::map<ed, bool> constrained_edges;
    for (auto v : vertices(original)) {
      if (!use_range || draw(0.7)) range.push_back(v);
      constrained_vertices[v] = use_vertex_map && draw(0.1);
    }
    if (use_edge_map) PMP::detect_sharp_edges(original, edge_angle, boost::make_assoc_property_map(constrained_edges));
    std::set<vd> in_range(range.begin(), range.end());

    // A fifth of the cases stop through the callback, after the iteration that
    // reaches `stop_after` (drawn from a generator of its own, so that the
    // other draws of each case stay as they were).
    std::mt19937 callback_rng(7919u + unsigned(c));
    const double stop_after = unit(callback_rng) < 0.2 ? unit(callback_rng) : 2.;
    std::size_t callback_calls = 0; // of the sequential run
    const std::function<bool(double)> stop_at = [stop_after](double advancement) { return advancement < stop_after; };
    // The iterations the stop allows: the first k with k / iterations >= stop_after.
    std::size_t allowed = iterations;
    for (std::size_t k = 1; k <= iterations; ++k)
      if (double(k) / double(iterations) >= stop_after) {
        allowed = k;
        break;
      }

    auto np = CGAL::parameters::number_of_iterations(iterations)
                  .number_of_relaxation_steps(steps)
                  .ilsa_relaxation(relax1)
                  .ilsa_penalty_relaxation(relax2)
                  .ilsa_penalty_mu(mu)
                  .ilsa_length_weight(wl)
                  .ilsa_area_weight(wa)
                  .ilsa_feature_angle(angle)
                  .ilsa_fix_unattached_candidates(fix)
                  .ilsa_quality_monotone(monotone)
                  .ilsa_reject_worsening_moves(reject_worsening)
                  .ilsa_crease_kink_angle(kink)
                  .ilsa_fidelity_tolerance(tolerance)
                  .ilsa_minimum_quality_gain(gain)
                  .do_project(project)
                  .use_safety_constraints(safety)
                  .relax_constraints(relax)
                  .vertex_is_constrained_map(boost::make_assoc_property_map(constrained_vertices))
                  .callback(stop_at);
    // Sequential, and in parallel (with TBB), which must give the same points.
    Surface_mesh m = original, parallel = original;
    auto run = [&](Surface_mesh& x, auto tag, const auto& parameters) {
      using Tag = decltype(tag);
      // `range` and the maps hold descriptors of `original`: a Surface_mesh copy has the same ones.
      if (use_edge_map)
        return PMP::smooth_surface_mesh_ilsa<Tag>(
            range, x, parameters.edge_is_constrained_map(boost::make_assoc_property_map(constrained_edges)));
      return PMP::smooth_surface_mesh_ilsa<Tag>(range, x, parameters);
    };
    PMP::ILSA_statistics statistics;
    auto run_both = [&](const auto& parameters) {
      const std::function<bool(double)> counted = [&](double a) { return ++callback_calls, stop_at(a); };
      statistics = run(m, CGAL::Sequential_tag(), parameters.callback(counted));
      run(parallel, CGAL::Parallel_if_available_tag(), parameters);
    };
    if (default_floor)
      run_both(np);
    else
      run_both(np.ilsa_quality_floor(floor));
    const bool same_in_parallel = points_of(parallel) == points_of(m);

    // The vertex types the run used.
    auto classify = [&](const Surface_mesh& input, std::map<vd, PMP::ILSA_vertex_type>& types) {
      const auto classification = CGAL::parameters::ilsa_feature_angle(angle)
                                      .ilsa_fix_unattached_candidates(fix)
                                      .ilsa_crease_kink_angle(kink)
                                      .relax_constraints(relax)
                                      .vertex_is_constrained_map(boost::make_assoc_property_map(constrained_vertices));
      if (use_edge_map)
        PMP::classify_vertices_ilsa(
            input, boost::make_assoc_property_map(types),
            classification.edge_is_constrained_map(boost::make_assoc_property_map(constrained_edges)));
      else
        PMP::classify_vertices_ilsa(input, boost::make_assoc_property_map(types), classification);
    };

    // The same smoothing of a transformed copy (see the top of this file).
    bool transformed_ok = true;
    double transformed_difference = 0, rounding_of_copy = 0;
    if (draw(1. / 3.)) {
      const bool exact = draw(0.5);
      const double diagonal = bbox_diagonal(original);
      const double scale = exact ? std::ldexp(1., -20 + int(41 * unit(rng))) : std::pow(10., -6 + 12 * unit(rng));
      const double offset_size = exact ? 0. : std::pow(10., 7 * unit(rng)) * scale * diagonal;
      const K::Vector_3 offset(offset_size * (2 * unit(rng) - 1), offset_size * (2 * unit(rng) - 1),
                               offset_size * (2 * unit(rng) - 1));
      // A uniformly random rotation (unit quaternion), only without the fidelity bound.
      double a = 1, b = 0, cq = 0, d = 0;
      if (!exact && (!std::isfinite(tolerance) || !safety)) {
        std::normal_distribution<double> normal;
        a = normal(rng), b = normal(rng), cq = normal(rng), d = normal(rng);
        const double n = std::sqrt(a * a + b * b + cq * cq + d * d);
        a /= n, b /= n, cq /= n, d /= n;
      }
      const double R[3][3] = {{a * a + b * b - cq * cq - d * d, 2 * (b * cq - a * d), 2 * (b * d + a * cq)},
                              {2 * (b * cq + a * d), a * a - b * b + cq * cq - d * d, 2 * (cq * d - a * b)},
                              {2 * (b * d - a * cq), 2 * (cq * d + a * b), a * a - b * b - cq * cq + d * d}};
      Surface_mesh moved_input = original;
      for (auto v : vertices(moved_input)) {
        const Point& p = original.point(v);
        const double x[3] = {p.x(), p.y(), p.z()};
        double y[3];
        for (int i = 0; i < 3; ++i) y[i] = scale * (R[i][0] * x[0] + R[i][1] * x[1] + R[i][2] * x[2]) + offset[i];
        moved_input.point(v) = Point(y[0], y[1], y[2]);
      }
      Surface_mesh moved = moved_input;
      if (default_floor)
        run(moved, CGAL::Sequential_tag(), np);
      else
        run(moved, CGAL::Sequential_tag(), np.ilsa_quality_floor(floor));
      for (auto v : vertices(moved)) {
        const Point& p = moved.point(v);
        const double y[3] = {(p.x() - offset.x()) / scale, (p.y() - offset.y()) / scale, (p.z() - offset.z()) / scale};
        const Point back(R[0][0] * y[0] + R[1][0] * y[1] + R[2][0] * y[2],
                         R[0][1] * y[0] + R[1][1] * y[1] + R[2][1] * y[2],
                         R[0][2] * y[0] + R[1][2] * y[1] + R[2][2] * y[2]);
        transformed_difference =
            (std::max)(transformed_difference, std::sqrt(CGAL::squared_distance(back, m.point(v))) / diagonal);
      }
      ++transformed;
      if (exact) {
        transformed_ok = transformed_difference == 0;
      } else {
        // Rounding of the transformed coordinates, relative to the diagonal.
        rounding_of_copy = std::ldexp(1., -53) * (offset_size / (scale * diagonal) + 1);
        std::map<vd, PMP::ILSA_vertex_type> moved_types;
        classify(moved_input, moved_types);
        for (auto v : vertices(moved)) {
          const Point& p = moved.point(v);
          transformed_ok = transformed_ok && std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
          const bool fixed = moved_types[v] == PMP::ILSA_vertex_type::Corner ||
                             moved_types[v] == PMP::ILSA_vertex_type::Boundary || !in_range.count(v);
          transformed_ok = transformed_ok && !(fixed && !(p == moved_input.point(v)));
        }
        const auto g =
            PMP::mesh_fidelity_ilsa(moved_input, moved, CGAL::parameters::ilsa_compute_hausdorff_distance(false));
        if (safety) transformed_ok = transformed_ok && g.number_of_flipped_faces == 0;
        if (project) transformed_ok = transformed_ok && g.max_vertex_distance <= 1e-9 + 8 * rounding_of_copy;
        // How far the result is from the untransformed one: rounding, or a decision that went the other way.
        if (transformed_difference > 1e3 * rounding_of_copy * (iterations + 1) + 1e-13) ++transformed_elsewhere;
        worst_transformed_difference = (std::max)(worst_transformed_difference, transformed_difference);
      }
    }
    // Fixed vertices: corners and boundary of the same classification, and
    // the vertices outside the range.
    std::map<vd, PMP::ILSA_vertex_type> types;
    classify(original, types);
    std::size_t fixed_moved = 0, non_finite = 0;
    for (auto v : vertices(m)) {
      const Point& p = m.point(v);
      non_finite += !(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
      const bool fixed = types[v] == PMP::ILSA_vertex_type::Corner || types[v] == PMP::ILSA_vertex_type::Boundary ||
                         !in_range.count(v);
      fixed_moved += fixed && !(p == original.point(v));
    }
    const auto before = PMP::mesh_quality_ilsa(original), after = PMP::mesh_quality_ilsa(m);
    const bool collapsed = after.number_of_degenerate_faces > before.number_of_degenerate_faces;
    const auto f = use_edge_map
                       ? PMP::mesh_fidelity_ilsa(original, m,
                                                 CGAL::parameters::ilsa_feature_angle(angle).edge_is_constrained_map(
                                                     boost::make_assoc_property_map(constrained_edges)))
                       : PMP::mesh_fidelity_ilsa(original, m, CGAL::parameters::ilsa_feature_angle(angle));
    // No face ends below the input's minimum or the floor, whichever is lower
    // (up to the rounding of writing back the package's normalised coordinates).
    const double effective_floor = monotone ? 1. : default_floor ? (std::max)(0.5, before.min_aspect_ratio) : floor;
    const bool kept_minimum = after.min_aspect_ratio >= (std::min)(before.min_aspect_ratio, effective_floor) - 1e-12;
    const double rounding = 1e-12; // of the diagonal: the write-back of normalised coordinates
    // The connectivity is the input's; the callback saw every iteration run and stopped the run in time.
    bool same_faces = true;
    for (auto fa = faces(original).begin(), fb = faces(m).begin(); fa != faces(original).end(); ++fa, ++fb) {
      auto ha = halfedge(*fa, original), hb = halfedge(*fb, m);
      for (int k = 0; k < 3; ++k, ha = next(ha, original), hb = next(hb, m))
        same_faces = same_faces && target(ha, original) == target(hb, m);
    }
    const bool callback_ok =
        callback_calls == statistics.number_of_iterations && statistics.number_of_iterations <= allowed;
    bool ok = same_in_parallel && non_finite == 0 && fixed_moved == 0 && transformed_ok && same_faces && callback_ok;
    if (safety) {
      ok = ok && f.number_of_flipped_faces == 0 && !collapsed && kept_minimum;
      if (std::isfinite(tolerance)) ok = ok && f.max_crease_deviation <= tolerance + rounding;
    }
    if (project) ok = ok && f.max_vertex_distance <= 1e-9;
    if (!ok) {
      ++failures;
      std::cout << "case " << c << " (" << files[which] << ", iterations " << iterations << ", steps " << steps
                << ", relax1 " << relax1 << ", relax2 " << relax2 << ", mu " << mu << ", wl " << wl << ", wa " << wa
                << ", angle " << angle << ", fix " << fix << ", floor " << (default_floor ? -1. : floor)
                << ", monotone " << monotone << ", reject worsening " << reject_worsening << ", kink " << kink
                << ", tolerance " << tolerance << ", gain " << gain << ", project " << project << ", safety " << safety
                << ", range " << use_range << ", vertex map " << use_vertex_map << ", edge map " << use_edge_map
                << ", relax " << relax << "): flipped " << f.number_of_flipped_faces << ", distance "
                << f.max_vertex_distance << ", fixed moved " << fixed_moved << ", non-finite " << non_finite
                << ", new degenerate " << collapsed << ", min q " << before.min_aspect_ratio << " -> "
                << after.min_aspect_ratio << ", crease deviation " << f.max_crease_deviation
                << ", parallel run identical " << same_in_parallel << ", same faces " << same_faces
                << ", callback: stop after " << stop_after << ", " << callback_calls << " calls, "
                << statistics.number_of_iterations << " iterations run, " << allowed << " allowed"
                << ", transformed copy: promises kept " << transformed_ok << ", off by " << transformed_difference
                << " (input rounding " << rounding_of_copy << ")" << std::endl;
    }
  }
  std::cout << "test_ilsa_fuzz: " << cases << " cases (" << flip_only << " with the flip check as the only guard, "
            << transformed << " also transformed, " << transformed_elsewhere
            << " of them with vertices beyond rounding of the untransformed result, by at most "
            << worst_transformed_difference << " of the diagonal), " << failures << " failures" << std::endl;
  ILSA_CHECK(failures == 0);
  return 0;
}
