// Parallel runs (user manual, "Parallel Runs"): smooth_surface_mesh_ilsa with
// CGAL::Parallel_tag gives the same points, bit for bit, as the sequential
// run, whatever the number of threads; on several meshes, with the
// whole-mesh and the vertex-range overloads, with constraint maps, with the
// Gauss-Seidel sweeps of the penalty step, with the fidelity bound at the
// input edges, on Surface_mesh and Polyhedron_3. Without TBB, Parallel_if_available_tag
// runs sequentially and the same comparison holds.
#include "ilsa_test_utils.h"

#include <CGAL/Polygon_mesh_processing/detect_features.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

using namespace ilsa_test;

namespace {

const std::vector<std::size_t> thread_counts{1, 2, 8};

// Runs `smooth(mesh)` sequentially, then in parallel with each thread count,
// and checks that every run gives the sequential points exactly.
template <class Mesh, class Smooth> void compare(const Mesh& input, const Smooth& smooth, const char* what) {
  Mesh sequential = input;
  const auto s = smooth(sequential, CGAL::Sequential_tag());
  assert(s.number_of_moves > 0);
  const auto expected = points_of(sequential);
  assert(max_difference(expected, points_of(input)) > 0);
  for (std::size_t threads : thread_counts) {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
#endif
    Mesh parallel = input;
    const auto p = smooth(parallel, CGAL::Parallel_if_available_tag());
    const auto got = points_of(parallel);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < got.size(); ++i) differing += !(got[i] == expected[i]);
    std::cout << what << ", " << threads << " threads: " << differing << " vertices differ from the sequential run"
              << std::endl;
    assert(differing == 0);
    assert(p.number_of_moves == s.number_of_moves && p.number_of_rejected_moves == s.number_of_rejected_moves &&
           p.number_of_shortened_moves == s.number_of_shortened_moves &&
           p.number_of_moves_dropped_before_projection == s.number_of_moves_dropped_before_projection &&
           p.number_of_settled_skips == s.number_of_settled_skips);
    assert(p.moves_dropped_by == s.moves_dropped_by && p.moves_shortened_by == s.moves_shortened_by);
  }
}

// `file` perturbed along its surface with `seed`, smoothed with the named
// parameters `np`, compared as compare() does.
template <class Mesh, class NamedParameters>
void compare_perturbed(const char* file, unsigned seed, const NamedParameters& np, const char* what) {
  Mesh input = read_mesh<Mesh>(data_file(file));
  perturb_on_surface(input, 0.5, seed);
  compare(
      input, [&np](Mesh& m, auto tag) { return PMP::smooth_surface_mesh_ilsa<decltype(tag)>(m, np); }, what);
}

template <class Mesh> void test_meshes() {
  for (const char* name : {"fandisk.off", "elephant.off", "mech-holes-shark.off", "hemisphere.off"})
    compare_perturbed<Mesh>(name, 11, CGAL::parameters::number_of_iterations(5), name);
  // The paper's variant: its displacement and classification.
  compare_perturbed<Mesh>("fandisk.off", 13, CGAL::parameters::number_of_iterations(4).ilsa_paper_variant(true),
                          "fandisk, the paper's variant");
  // A tight fidelity tolerance: most moves are shortened or dropped by the
  // certificates (user manual, "Fidelity Certificate"), whose faces are
  // checked in parallel and blamed in face order.
  compare_perturbed<Mesh>("elephant.off", 14, CGAL::parameters::number_of_iterations(4).ilsa_fidelity_tolerance(1e-4),
                          "elephant, fidelity tolerance 1e-4");
}

// The other paths of the loop: the paper's acceptance without fidelity bound,
// no projection, no safety check, and the vertex-range overload with the
// sharp edges of detect_sharp_edges as constraints.
void test_paths() {
  Surface_mesh input = read_mesh<Surface_mesh>(data_file("fandisk.off"));
  perturb_on_surface(input, 0.5, 12);
  compare(
      input,
      [](Surface_mesh& m, auto tag) {
        return PMP::smooth_surface_mesh_ilsa<decltype(tag)>(
            m, CGAL::parameters::number_of_iterations(4)
                   .ilsa_paper_variant(true)
                   .ilsa_fidelity_tolerance(std::numeric_limits<double>::infinity())
                   .ilsa_quality_floor(0.));
      },
      "fandisk, paper's acceptance");
  compare(
      input,
      [](Surface_mesh& m, auto tag) {
        return PMP::smooth_surface_mesh_ilsa<decltype(tag)>(
            m, CGAL::parameters::number_of_iterations(4).do_project(false));
      },
      "fandisk, no projection");
  compare(
      input,
      [](Surface_mesh& m, auto tag) {
        return PMP::smooth_surface_mesh_ilsa<decltype(tag)>(
            m, CGAL::parameters::number_of_iterations(4).use_safety_constraints(false));
      },
      "fandisk, no safety check");
  compare(
      input,
      [](Surface_mesh& m, auto tag) {
        auto sharp = m.add_property_map<Surface_mesh::Edge_index, bool>("e:sharp", false).first;
        PMP::detect_sharp_edges(m, 30., sharp);
        std::vector<Surface_mesh::Vertex_index> half;
        for (auto v : vertices(m))
          if (std::size_t(v) % 2 == 0) half.push_back(v);
        const auto s = PMP::smooth_surface_mesh_ilsa<decltype(tag)>(
            half, m, CGAL::parameters::number_of_iterations(4).edge_is_constrained_map(sharp).relax_constraints(true));
        m.remove_property_map(sharp);
        return s;
      },
      "fandisk, vertex range and edge_is_constrained_map");
}

} // namespace

int main() {
  test_meshes<Surface_mesh>();
  test_meshes<Polyhedron>();
  test_paths();
#ifdef CGAL_LINKED_WITH_TBB
  std::cout << "test_ilsa_parallel: all checks passed (TBB)\n";
#else
  std::cout << "test_ilsa_parallel: all checks passed (no TBB: Parallel_if_available_tag ran sequentially)\n";
#endif
  return 0;
}
