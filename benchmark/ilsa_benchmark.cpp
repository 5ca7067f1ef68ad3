// Side-by-side benchmark: ILSA (default parameters) against CGAL's own
// smoothers on identical input, in the same process.
//
//   ilsa_benchmark [--runs N] [--peer-iterations N] [MESH ...]
//
// Without meshes: every bundled mesh, plus ../shared/data when it exists.
// Prints one Markdown table row per (mesh, method): quality (aspect ratio q
// min / mean / share below 0.3, minimum angle), fidelity (flipped faces, max
// vertex distance to the input, Hausdorff distance, two-sided distance between
// the input's sharp edges and the same edges of the result, max and mean;
// distances relative to the bounding-box diagonal),
// the median wall time of N runs, and ILSA's time over the peer's.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/ilsa_mesh_quality.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using edge_descriptor = boost::graph_traits<Mesh>::edge_descriptor;

namespace {

// Dihedral feature angle shared by every method: ILSA's default (160 degrees),
// i.e. a normal deviation of 20 degrees for detect_sharp_edges.
const double feature_angle = 160.;

struct Method {
  std::string name;
  std::function<void(Mesh&)> run;
  unsigned iterations;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::string> default_meshes() {
  std::vector<std::string> files;
  for (const std::string& dir : {std::string(ILSA_DATA_DIR), std::string(ILSA_SHARED_DATA_DIR)}) {
    if (!std::filesystem::is_directory(dir)) continue;
    std::vector<std::string> here;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      const std::string ext = e.path().extension().string();
      if (ext == ".off" || ext == ".ply" || ext == ".stl" || ext == ".obj") here.push_back(e.path().string());
    }
    std::sort(here.begin(), here.end());
    for (const auto& f : here) {
      const std::string name = std::filesystem::path(f).filename().string();
      const bool seen = std::any_of(files.begin(), files.end(), [&](const std::string& g) {
        return std::filesystem::path(g).filename().string() == name;
      });
      if (!seen) files.push_back(f);
    }
  }
  return files;
}

} // namespace

int main(int argc, char** argv) {
  int runs = 5;
  unsigned peer_iterations = 10;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc)
      runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--peer-iterations" && i + 1 < argc)
      peer_iterations = unsigned(std::max(1, std::atoi(argv[++i])));
    else
      files.push_back(a);
  }
  if (files.empty()) files = default_meshes();

#ifdef CGAL_PMP_USE_CERES_SOLVER
  const bool ceres = true;
#else
  const bool ceres = false;
#endif
  std::cout << "Runs per method: " << runs << " (median wall time); CGAL peers: " << peer_iterations
            << " iterations; sharp edges for the peers: detect_sharp_edges at " << 180. - feature_angle
            << " degrees; Ceres (area smoothing): " << (ceres ? "yes" : "no") << "\n\n";
  std::cout << "| mesh | method | q min | q mean | q<0.3 % | min angle | flipped | max dist | Hausdorff | "
               "crease dev. max | crease dev. mean | time s (median) | ILSA time / this | "
               "time per iteration s |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

  for (const std::string& file : files) {
    Mesh input;
    if (!CGAL::IO::read_polygon_mesh(file, input) || is_empty(input) || !CGAL::is_triangle_mesh(input)) {
      std::cerr << "skipping " << file << ": not a readable triangle mesh\n";
      continue;
    }
    const std::string name = std::filesystem::path(file).filename().string();

    // Sharp edges for the peers, computed once on the input (same edge indices in every copy).
    std::vector<edge_descriptor> sharp;
    {
      auto map = input.add_property_map<edge_descriptor, bool>("e:sharp", false).first;
      PMP::detect_sharp_edges(input, 180. - feature_angle, map);
      for (auto e : edges(input))
        if (map[e]) sharp.push_back(e);
      input.remove_property_map(map);
    }
    auto with_constraints = [&sharp](Mesh& m) {
      auto map = m.add_property_map<edge_descriptor, bool>("e:constrained", false).first;
      for (auto e : sharp) map[e] = true;
      return map;
    };

    std::vector<Method> methods;
    methods.push_back({"ILSA (defaults)", [](Mesh& m) { PMP::smooth_surface_mesh_ilsa(m); }, 20});
    methods.push_back({"CGAL angle smoothing + sharp edges",
                       [&](Mesh& m) {
                         auto ecm = with_constraints(m);
                         PMP::angle_and_area_smoothing(m, CGAL::parameters::number_of_iterations(peer_iterations)
                                                              .use_area_smoothing(false)
                                                              .use_Delaunay_flips(false)
                                                              .edge_is_constrained_map(ecm));
                       },
                       peer_iterations});
    if (ceres)
      methods.push_back({"CGAL angle+area smoothing + sharp edges",
                         [&](Mesh& m) {
                           auto ecm = with_constraints(m);
                           PMP::angle_and_area_smoothing(m, CGAL::parameters::number_of_iterations(peer_iterations)
                                                                .use_Delaunay_flips(false)
                                                                .edge_is_constrained_map(ecm));
                         },
                         peer_iterations});
    methods.push_back(
        {"CGAL tangential relaxation",
         [&](Mesh& m) { PMP::tangential_relaxation(m, CGAL::parameters::number_of_iterations(peer_iterations)); },
         peer_iterations});
    methods.push_back({"CGAL tangential relaxation + sharp edges",
                       [&](Mesh& m) {
                         auto ecm = with_constraints(m);
                         PMP::tangential_relaxation(m, CGAL::parameters::number_of_iterations(peer_iterations)
                                                           .edge_is_constrained_map(ecm)
                                                           .relax_constraints(true));
                       },
                       peer_iterations});

    const auto q0 = PMP::mesh_quality_ilsa(input);
    std::printf("| %s | input | %.4f | %.4f | %.2f | %.2f | | | | | | | | |\n", name.c_str(), q0.min_aspect_ratio,
                q0.mean_aspect_ratio, 100. * q0.share_below_threshold, q0.min_angle);

    std::vector<double> times(methods.size());
    std::vector<Mesh> results(methods.size());
    for (std::size_t k = 0; k < methods.size(); ++k) {
      std::vector<double> t;
      for (int r = 0; r < runs; ++r) {
        Mesh m = input;
        const auto start = std::chrono::steady_clock::now();
        methods[k].run(m);
        t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (r == 0) results[k] = m;
      }
      times[k] = median(t);
    }
    for (std::size_t k = 0; k < methods.size(); ++k) {
      Mesh& m = results[k];
      const auto q = PMP::mesh_quality_ilsa(m);
      const auto f = PMP::mesh_fidelity_ilsa(input, m, CGAL::parameters::ilsa_feature_angle(feature_angle));
      std::printf("| %s | %s | %.4f | %.4f | %.2f | %.2f | %zu | %.1e | %.2e | %.1e | %.1e | %.3f | %s | %.4f |\n",
                  name.c_str(), methods[k].name.c_str(), q.min_aspect_ratio, q.mean_aspect_ratio,
                  100. * q.share_below_threshold, q.min_angle, f.number_of_flipped_faces, f.max_vertex_distance,
                  f.hausdorff_distance, f.max_crease_deviation, f.mean_crease_deviation, times[k],
                  k == 0 ? "1" : std::to_string(times[0] / times[k]).substr(0, 5).c_str(),
                  times[k] / methods[k].iterations);
    }
    std::fflush(stdout);
  }
  return 0;
}
