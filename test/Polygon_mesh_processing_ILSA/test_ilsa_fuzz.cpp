// Randomised test: the bundled meshes, perturbed along their surface without
// folding, smoothed with random valid parameters; every run must keep the
// invariants (no flipped or collapsed face, fixed vertices bit-identical,
// vertices on the input surface, no NaN, no face below the input's minimum
// aspect ratio or the quality floor, whichever is lower, the input's sharp
// edges and the same edges of the result within the fidelity tolerance of
// each other, both ways; the parallel run, with TBB, gives the same points).
//
// ILSA_FUZZ_CASES (environment) sets the number of cases (the default is the
// short CI run), ILSA_FUZZ_FIRST the first case: case N is the same in every run.
#include "ilsa_test_utils.h"

#include <cstdlib>

using namespace ilsa_test;

int main() {
  const char* env = std::getenv("ILSA_FUZZ_CASES");
  const int cases = env ? std::atoi(env) : 24;
  const char* first_env = std::getenv("ILSA_FUZZ_FIRST"); // to replay one case
  const int first = first_env ? std::atoi(first_env) : 0;
  const std::vector<std::string> names{"sphere_low.off", "hemisphere.off", "fandisk.off", "elephant.off",
                                       "mech-holes-shark.off"};
  std::vector<Surface_mesh> meshes;
  for (const auto& n : names) meshes.push_back(read_mesh<Surface_mesh>(data_file(n)));

  std::uniform_real_distribution<double> unit(0., 1.);
  int failures = 0;
  for (int c = first; c < first + cases; ++c) {
    std::mt19937 rng(2026u + unsigned(c));
    const std::size_t which = std::size_t(c) % meshes.size();
    Surface_mesh original = meshes[which];
    perturb_on_surface(original, 0.2 + 0.6 * unit(rng), unsigned(rng()));
    const unsigned iterations = 1 + unsigned(unit(rng) * 8);
    const unsigned steps = 1 + unsigned(unit(rng) * 5);
    const double relax1 = 0.05 + 0.95 * unit(rng), relax2 = 0.05 + 0.95 * unit(rng);
    const double mu = std::pow(10., -3 + 5 * unit(rng));
    const double wl = 2 * unit(rng), wa = 2 * unit(rng);
    const double angle = 100 + 75 * unit(rng);
    const bool fix = unit(rng) < 0.5, monotone = unit(rng) < 0.2;
    const double floor = 0.5 * unit(rng);
    const bool default_floor = unit(rng) < 0.3;    // the library's: max(0.5, input minimum)
    const bool reject_worsening = unit(rng) < 0.7; // the default, or the paper's acceptance
    const double draw = unit(rng);                 // kink angle: the default (180 - angle), off, or any
    const double kink = draw < 0.3 ? 180. - angle : draw < 0.5 ? 180. : 180. * unit(rng);

    Surface_mesh m = original;
    const auto np = CGAL::parameters::number_of_iterations(iterations)
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
                        .ilsa_crease_kink_angle(kink);
    // Sequential, and in parallel (with TBB), which must give the same points.
    Surface_mesh parallel = original;
    if (default_floor) {
      PMP::smooth_surface_mesh_ilsa(m, np);
      PMP::smooth_surface_mesh_ilsa<CGAL::Parallel_if_available_tag>(parallel, np);
    } else {
      PMP::smooth_surface_mesh_ilsa(m, np.ilsa_quality_floor(floor));
      PMP::smooth_surface_mesh_ilsa<CGAL::Parallel_if_available_tag>(parallel, np.ilsa_quality_floor(floor));
    }
    const bool same_in_parallel = points_of(parallel) == points_of(m);
    // Ridge vertices are checked by the smoothing test; here: surface, flips, fixed vertices, NaN, minimum q.
    std::map<Surface_mesh::Vertex_index, PMP::ILSA_vertex_type> types;
    PMP::classify_vertices_ilsa(
        original, boost::make_assoc_property_map(types),
        CGAL::parameters::ilsa_feature_angle(angle).ilsa_fix_unattached_candidates(fix).ilsa_crease_kink_angle(kink));
    std::size_t fixed_moved = 0, non_finite = 0, collapsed = 0;
    for (auto v : vertices(m)) {
      const Point& p = m.point(v);
      non_finite += !(std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()));
      const bool fixed = types[v] == PMP::ILSA_vertex_type::Corner || types[v] == PMP::ILSA_vertex_type::Boundary;
      fixed_moved += fixed && !(p == original.point(v));
    }
    const auto before = PMP::mesh_quality_ilsa(original), after = PMP::mesh_quality_ilsa(m);
    collapsed = after.number_of_degenerate_faces > before.number_of_degenerate_faces;
    const auto f = PMP::mesh_fidelity_ilsa(original, m, CGAL::parameters::ilsa_feature_angle(angle));
    // No face ends below the input's minimum or the floor, whichever is lower
    // (up to the rounding of writing back the package's normalised coordinates).
    const double effective_floor = monotone ? 1. : default_floor ? (std::max)(0.5, before.min_aspect_ratio) : floor;
    const bool kept_minimum = after.min_aspect_ratio >= (std::min)(before.min_aspect_ratio, effective_floor) - 1e-12;
    const bool ok = f.number_of_flipped_faces == 0 && f.max_vertex_distance <= 1e-9 && fixed_moved == 0 &&
                    non_finite == 0 && !collapsed && kept_minimum && f.max_crease_deviation <= 3e-4 && same_in_parallel;
    if (!ok) {
      ++failures;
      std::cout << "case " << c << " (" << names[which] << ", iterations " << iterations << ", steps " << steps
                << ", relax1 " << relax1 << ", relax2 " << relax2 << ", mu " << mu << ", wl " << wl << ", wa " << wa
                << ", angle " << angle << ", fix " << fix << ", floor " << (default_floor ? -1. : floor)
                << ", monotone " << monotone << ", reject worsening " << reject_worsening << ", kink " << kink
                << "): flipped " << f.number_of_flipped_faces << ", distance " << f.max_vertex_distance
                << ", fixed moved " << fixed_moved << ", non-finite " << non_finite << ", new degenerate " << collapsed
                << ", min q " << before.min_aspect_ratio << " -> " << after.min_aspect_ratio << ", crease deviation "
                << f.max_crease_deviation << ", parallel run identical " << same_in_parallel << std::endl;
      const auto n0 = face_normals_of(original), n1 = face_normals_of(m);
      for (auto fd : faces(m))
        if (n0[std::size_t(fd)] * n1[std::size_t(fd)] < 0) {
          std::cout << "  flipped face " << std::size_t(fd) << ":";
          for (auto v : vertices_around_face(halfedge(fd, m), m))
            std::cout << " " << PMP::to_string(types[v]) << (m.point(v) == original.point(v) ? "" : "(moved)");
          std::cout << std::endl;
        }
    }
  }
  std::cout << "test_ilsa_fuzz: " << cases << " cases, " << failures << " failures" << std::endl;
  ILSA_CHECK(failures == 0);
  return 0;
}
