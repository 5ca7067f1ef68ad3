// Side-by-side benchmark: ILSA (default parameters) against CGAL's own
// smoothers on identical input, in the same process.
//
//   ilsa_benchmark [--runs N] [--peer-iterations N] [MESH ...]
//   ilsa_benchmark --scaling N
//   ilsa_benchmark --write-scaling-mesh N FILE
//   ilsa_benchmark --pareto [--peer-iterations N] [MESH ...]
//   ilsa_benchmark --phases [--runs N] [--peer-iterations N] [MESH ...]
//   ilsa_benchmark --crease-sets [MESH ...]
//   ilsa_benchmark --decisions [MESH ...]
//   ilsa_benchmark --processes [--runs N] [MESH ...]
//
// Without meshes: every bundled mesh, plus ../shared/data when it exists.
// Prints one Markdown table row per (mesh, method): quality (aspect ratio q
// min / mean / share below 0.3, minimum angle), fidelity (flipped faces, max
// vertex distance to the input, Hausdorff distance, two-sided distance between
// the input's sharp edges and the same edges of the result, max and mean;
// distances relative to the bounding-box diagonal),
// the median wall time of N runs (the methods take turns, run by run), and
// ILSA's time over the peer's; then the times of ILSA, tangential relaxation
// (TR) and TR + projection (each of its iterations followed by moving every
// vertex to its closest point on the input) as ratios, with their sums.
// --processes prints instead that time table with each method run in a child
// process of its own (the time of the smoothing call), the methods taking
// turns, median of N runs.
// --scaling N prints instead the scaling table: the horse Loop-subdivided 0
// to N times and perturbed, time per face and peak memory of ILSA and CGAL
// tangential relaxation, each run once in a child process of its own; then
// the horse again with its vertices and faces in a random order.
// --write-scaling-mesh N FILE writes the mesh of the scaling table's row N
// (the horse Loop-subdivided N times and perturbed), e.g. to profile ILSA on it
// with ilsa_smooth.
// --pareto prints instead the comparison at the same distance (user manual,
// "Safety Check"): CGAL tangential relaxation (unconstrained,
// N iterations) and its Hausdorff distance H to the input; then ILSA with its
// defaults but the fidelity tolerance set to H, and the same with the paper's
// classification (no crease contrast, no open-crease rule, candidates without
// a sharp edge fixed); mean q, Hausdorff distance and its ratio to H, flipped
// faces. The Hausdorff distances are CGAL's bounded-error symmetric distance
// (error 1e-5 of the diagonal), certified: the true distance lies within the
// error above the value. Also ILSA with every default: mean q, the distance
// ILSA certified (ILSA_statistics::certified_distance) and CGAL's, over the
// default fidelity tolerance. One run each (no time measured).
// --crease-sets prints instead the connected sets of feature edges of each
// mesh and what the open-crease rule drops (see run_crease_sets()).
// --decisions prints instead what each decision that differs from the paper
// brings (user manual, "Decisions That Differ from the Paper"): ILSA with its
// defaults, then with one decision at a time reverted to the paper's choice
// (or without one of the package's rules), then the paper's variant; mean and
// minimum q, the distance ILSA certified, the largest crease deviation
// (mesh_fidelity_ilsa(), sampled), the fixed vertices, the iterations run and
// the time, one thread, one run each.
// --phases prints instead where ILSA's time goes, one thread, median of N
// runs: the time to the end of the first iteration (the callback's first
// call), the median time between two later calls (one iteration with its
// convergence test), the set-up as the first less one iteration, and the
// iterations run; beside it tangential relaxation's total and time per
// iteration (it has no set-up of its own to separate).
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/internal/ILSA/aabb_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/centroid.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <iostream>
#include <string>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CGAL::Polygon_mesh_processing::internal::ILSA::AABB_tree_3;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
using edge_descriptor = boost::graph_traits<Mesh>::edge_descriptor;

// Reads the triangle mesh `file` into `input` (defined below main's helpers).
bool read_input(const std::string& file, Mesh& input);

namespace {

// Feature angle shared by every method, between face normals: ILSA's default
// (the paper's dihedral 160 degrees), passed to detect_sharp_edges() for the peers.
const double feature_angle = 20.; // between face normals, as detect_sharp_edges() takes it

struct Method {
  std::string name;
  std::function<std::size_t(Mesh&)> run; // returns the number of iterations run
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

// Peak resident memory of this process so far, in MB (Linux: VmHWM).
double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.;
  return 0;
}

// CGAL tangential relaxation kept on the input surface, as a CGAL user writes
// it (the smoothing step of isotropic_remeshing() with projection): each of
// the `iterations` iterations of tangential_relaxation() is followed by moving
// every vertex to its closest point on the input, found with an AABB tree of
// a copy of the input built once (its time included).
void tangential_relaxation_projected(Mesh& m, unsigned iterations) {
  using Tree = AABB_tree_3<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>;
  const Mesh input = m;
  Tree tree(faces(input).first, faces(input).second, input);
  tree.accelerate_distance_queries();
  for (unsigned i = 0; i < iterations; ++i) {
    PMP::tangential_relaxation(m, CGAL::parameters::number_of_iterations(1));
    for (auto v : vertices(m)) m.point(v) = tree.closest_point(m.point(v));
  }
}

// One measurement of the scaling table, in a process of its own so that its
// peak memory is its own: "load" reads the mesh and builds one AABB tree over
// its faces; the others read it and smooth it. Prints seconds, peak MB and
// iterations run.
int run_child(const std::string& mode, const std::string& file) {
  Mesh m;
  if (!CGAL::IO::read_polygon_mesh(file, m)) return 1;
  const auto start = std::chrono::steady_clock::now();
  std::size_t iterations = 0;
  if (mode == "load") {
    using Tree = AABB_tree_3<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>;
    Tree tree(faces(m).first, faces(m).second, m);
    tree.build();
    iterations = tree.size() > 0;
  } else if (mode == "ilsa")
    iterations = PMP::smooth_surface_mesh_ilsa(m).number_of_iterations;
#ifdef CGAL_LINKED_WITH_TBB
  else if (mode == "ilsa-parallel")
    iterations = PMP::smooth_surface_mesh_ilsa<CGAL::Parallel_tag>(m).number_of_iterations;
#endif
  else if (mode == "tangential")
    PMP::tangential_relaxation(m, CGAL::parameters::number_of_iterations(10)), iterations = 10;
  else if (mode == "tangential-projected")
    tangential_relaxation_projected(m, 10), iterations = 10;
  else
    return 1;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%.6f %.1f %zu\n", seconds, peak_memory_mb(), iterations);
  return 0;
}

// The bundled horse Loop-subdivided `levels` times, its vertices then moved a
// random fraction (below 0.3) of the way to the centroid of a random incident
// face, so that there is work to do.
Mesh subdivided_horse(unsigned levels) {
  Mesh m;
  CGAL::IO::read_polygon_mesh(std::string(ILSA_DATA_DIR) + "/horse.ply", m);
  if (levels > 0) CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(levels));
  std::mt19937 rng(levels);
  std::uniform_real_distribution<double> unit(0., 1.);
  std::vector<K::Point_3> moved(m.points().begin(), m.points().end());
  for (auto v : vertices(m)) {
    if (is_border(v, m)) continue;
    std::vector<Mesh::Face_index> around;
    for (auto f : faces_around_target(halfedge(v, m), m)) around.push_back(f);
    const auto f = around[std::size_t(unit(rng) * double(around.size())) % around.size()];
    std::vector<K::Point_3> corners;
    for (auto w : vertices_around_face(halfedge(f, m), m)) corners.push_back(m.point(w));
    const K::Point_3 c = CGAL::centroid(corners[0], corners[1], corners[2]);
    moved[std::size_t(v)] = m.point(v) + 0.3 * unit(rng) * (c - m.point(v));
  }
  for (auto v : vertices(m)) m.point(v) = moved[std::size_t(v)];
  return m;
}

// `m` with its vertices and faces in a random order (same points, same faces).
Mesh shuffled(const Mesh& m) {
  std::mt19937 rng(1);
  std::vector<Mesh::Vertex_index> order(m.vertices().begin(), m.vertices().end());
  std::shuffle(order.begin(), order.end(), rng);
  Mesh s;
  std::map<Mesh::Vertex_index, Mesh::Vertex_index> added;
  for (auto v : order) added[v] = s.add_vertex(m.point(v));
  std::vector<Mesh::Face_index> fs(m.faces().begin(), m.faces().end());
  std::shuffle(fs.begin(), fs.end(), rng);
  for (auto f : fs) {
    std::vector<Mesh::Vertex_index> corners;
    for (auto w : vertices_around_face(halfedge(f, m), m)) corners.push_back(added[w]);
    s.add_face(corners);
  }
  return s;
}

// Scaling table: time per face and peak memory of ILSA (sequential and
// parallel) and CGAL tangential relaxation (10 iterations) on the horse and
// its subdivisions, each measurement in a child process.
void run_scaling(const std::string& self, unsigned max_level) {
  std::cout << "\n| mesh | faces | method | time s | iterations run | time per face µs | time per face / horse's | "
               "peak memory MB | peak / (load + AABB tree) |\n|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, double> horse_per_face;
  // One group of rows; the first group (the horse) is the reference of "time per face / horse's".
  auto measure = [&](const Mesh& m, const std::string& name, const std::string& tag) {
    const std::string file = (std::filesystem::temp_directory_path() / ("ilsa_scaling_" + tag + ".ply")).string();
    CGAL::IO::write_polygon_mesh(file, m, CGAL::parameters::use_binary_mode(true));
    std::vector<std::string> modes{"load", "ilsa"};
#ifdef CGAL_LINKED_WITH_TBB
    modes.push_back("ilsa-parallel");
#endif
    modes.push_back("tangential");
    double load_peak = 0;
    for (const std::string& mode : modes) {
      FILE* child = popen(("\"" + self + "\" --child " + mode + " \"" + file + "\"").c_str(), "r");
      double seconds = 0, peak = 0;
      std::size_t iterations = 0;
      const bool ok = child && std::fscanf(child, "%lf %lf %zu", &seconds, &peak, &iterations) == 3;
      if (child) pclose(child);
      if (!ok) {
        std::cerr << "scaling: " << mode << " on " << file << " failed\n";
        continue;
      }
      if (mode == "load") {
        load_peak = peak;
        std::printf("| %s | %zu | load + AABB tree | %.3f | | | | %.0f | 1 |\n", name.c_str(),
                    std::size_t(num_faces(m)), seconds, peak);
        continue;
      }
      const double per_face = 1e6 * seconds / double(num_faces(m));
      if (!horse_per_face.count(mode)) horse_per_face[mode] = per_face;
      const std::string label = mode == "ilsa"            ? "ILSA (defaults)"
                                : mode == "ilsa-parallel" ? "ILSA (defaults), Parallel_tag"
                                                          : "CGAL tangential relaxation";
      std::printf("| %s | %zu | %s | %.3f | %zu | %.2f | %.2f | %.0f | %.2f |\n", name.c_str(),
                  std::size_t(num_faces(m)), label.c_str(), seconds, iterations, per_face,
                  per_face / horse_per_face[mode], peak, peak / load_peak);
      std::fflush(stdout);
    }
    std::remove(file.c_str());
  };
  for (unsigned level = 0; level <= max_level; ++level)
    measure(subdivided_horse(level),
            level == 0 ? "horse, perturbed" : "horse, Loop " + std::to_string(level) + "x, perturbed",
            std::to_string(level));
  // The same horse with its vertices and faces listed in a random order: the
  // cost of an input whose order has no locality.
  measure(shuffled(subdivided_horse(0)), "horse, perturbed, shuffled order", "shuffled");
}

// One row of the time tables: the median times of ILSA, tangential
// relaxation and tangential relaxation with projection on one mesh.
struct Time_row {
  std::string mesh;
  std::size_t faces = 0;
  double ilsa = 0, tangential = 0, projected = 0;
};

// The time table: the rows, their ratios, and the sums over the rows.
void print_time_table(const std::vector<Time_row>& rows) {
  std::cout << "\n| mesh | faces | ILSA s | TR s | TR + projection s | ILSA / TR | ILSA / (TR + projection) |\n"
               "|---|---|---|---|---|---|---|\n";
  Time_row sum{"**sum**"};
  for (const Time_row& r : rows) {
    std::printf("| %s | %zu | %.3f | %.3f | %.3f | %.2f | %.2f |\n", r.mesh.c_str(), r.faces, r.ilsa, r.tangential,
                r.projected, r.ilsa / r.tangential, r.ilsa / r.projected);
    sum.faces += r.faces, sum.ilsa += r.ilsa, sum.tangential += r.tangential, sum.projected += r.projected;
  }
  if (rows.size() > 1)
    std::printf("| %s | %zu | %.3f | %.3f | %.3f | %.2f | %.2f |\n", sum.mesh.c_str(), sum.faces, sum.ilsa,
                sum.tangential, sum.projected, sum.ilsa / sum.tangential, sum.ilsa / sum.projected);
  std::fflush(stdout);
}

// The --processes table: ILSA with every default, tangential relaxation (10
// iterations) and tangential relaxation with projection (10 iterations),
// each run in a child process of its own (the time of the smoothing call,
// reading left out), the three taking turns, `runs` runs each; medians.
void run_processes(const std::string& self, const std::vector<std::string>& files, int runs) {
  std::vector<Time_row> rows;
  const std::vector<std::string> modes{"ilsa", "tangential", "tangential-projected"};
  for (const std::string& file : files) {
    Mesh input;
    if (!read_input(file, input)) continue;
    std::vector<std::vector<double>> samples(modes.size());
    for (int r = 0; r < runs; ++r)
      for (std::size_t k = 0; k < modes.size(); ++k) {
        FILE* child = popen(("\"" + self + "\" --child " + modes[k] + " \"" + file + "\"").c_str(), "r");
        double seconds = 0, peak = 0;
        std::size_t iterations = 0;
        const bool ok = child && std::fscanf(child, "%lf %lf %zu", &seconds, &peak, &iterations) == 3;
        if (child) pclose(child);
        if (!ok) {
          std::cerr << "processes: " << modes[k] << " on " << file << " failed\n";
          return;
        }
        samples[k].push_back(seconds);
      }
    rows.push_back({std::filesystem::path(file).filename().string(), std::size_t(num_faces(input)), median(samples[0]),
                    median(samples[1]), median(samples[2])});
  }
  std::cout << "Each method in a process of its own, one thread, the methods taking turns; median of " << runs
            << " runs; TR: CGAL tangential_relaxation, 10 iterations; TR + projection: the same, each iteration "
               "followed by the closest point on the input (AABB tree)\n";
  print_time_table(rows);
}

} // namespace

// Reads the triangle mesh `file` into `input`; says so and returns false if it cannot.
bool read_input(const std::string& file, Mesh& input) {
  if (CGAL::IO::read_polygon_mesh(file, input) && !is_empty(input) && CGAL::is_triangle_mesh(input)) return true;
  std::cerr << "skipping " << file << ": not a readable triangle mesh\n";
  return false;
}

// The --pareto table (see the top of the file).
void run_pareto(const std::vector<std::string>& files, unsigned peer_iterations) {
  const double default_tolerance = PMP::internal::ILSA::defaults::fidelity_tolerance;
  std::cout << "| mesh | tangential relaxation: q / H / flipped | ILSA, tolerance H: q / H (/ peer's H) / flipped | "
               "ILSA, tolerance H, paper's classification: q / H (/ peer's H) / flipped | ILSA q - peer q "
               "(paper's classification) | ILSA defaults: q / certified by ILSA / tolerance | ILSA defaults: CGAL's H "
               "/ tolerance |\n|---|---|---|---|---|---|---|\n";
  for (const std::string& file : files) {
    Mesh input;
    if (!read_input(file, input)) continue;
    struct Result {
      double q, h;
      std::size_t flipped;
    };
    const CGAL::Bbox_3 box = PMP::bbox(input);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    auto measure = [&](const Mesh& m) {
      const auto f = PMP::mesh_fidelity_ilsa(
          input, m, CGAL::parameters::ilsa_feature_angle(feature_angle).ilsa_compute_hausdorff_distance(false));
      const double h =
          PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(input, m, 1e-5 * diagonal) / diagonal;
      return Result{PMP::mesh_quality_ilsa(m).mean_aspect_ratio, h, f.number_of_flipped_faces};
    };
    Mesh peer = input;
    PMP::tangential_relaxation(peer, CGAL::parameters::number_of_iterations(peer_iterations));
    const Result p = measure(peer);
    // The defaults, or the paper's classification: every feature edge between
    // candidates sharp (no crease contrast, no open-crease rule), candidates
    // without a sharp edge fixed.
    auto ilsa = [&](bool paper) {
      namespace ilsa = PMP::internal::ILSA;
      Mesh m = input;
      ilsa::Classification_options rules = ilsa::Classification_options::rules(feature_angle, false);
      if (paper) rules.crease_contrast = 0, rules.minimum_open_crease_edges = 0, rules.fix_unattached_candidates = true;
      ilsa::smooth<CGAL::Parallel_if_available_tag>(vertices(m), m, CGAL::parameters::ilsa_fidelity_tolerance(p.h),
                                                    nullptr, &rules);
      return measure(m);
    };
    const Result a = ilsa(false), b = ilsa(true);
    Mesh defaults = input;
    const double certified =
        PMP::smooth_surface_mesh_ilsa<CGAL::Parallel_if_available_tag>(defaults).certified_distance;
    const Result d = measure(defaults);
    std::printf("| %s | %.4f / %.2e / %zu | %.4f / %.2e (%.2f) / %zu | %.4f / %.2e (%.2f) / %zu | %+.4f (%+.4f) | "
                "%.4f / %.2e / %.3f | %.2e / %.3f |\n",
                std::filesystem::path(file).filename().string().c_str(), p.q, p.h, p.flipped, a.q, a.h, a.h / p.h,
                a.flipped, b.q, b.h, b.h / p.h, b.flipped, a.q - p.q, b.q - p.q, d.q, certified,
                certified / default_tolerance, d.h, d.h / default_tolerance);
    std::fflush(stdout);
  }
}

// The --phases table (see the top of the file).
void run_phases(const std::vector<std::string>& files, int runs, unsigned peer_iterations) {
  std::cout << "| mesh | ILSA total s | to the end of iteration 1 s | per iteration s | set-up s (estimate) | "
               "set-up / total | iterations | tangential relaxation total s | per iteration s | ILSA set-up / peer "
               "total |\n|---|---|---|---|---|---|---|---|---|---|\n";
  using Clock = std::chrono::steady_clock;
  for (const std::string& file : files) {
    Mesh input;
    if (!read_input(file, input)) continue;
    std::vector<double> totals, firsts, steps, peers;
    std::size_t iterations = 0;
    for (int r = 0; r < runs; ++r) {
      Mesh m = input;
      std::vector<Clock::time_point> calls;
      const std::function<bool(double)> stamp = [&calls](double) {
        calls.push_back(Clock::now());
        return true;
      };
      const auto start = Clock::now();
      iterations = PMP::smooth_surface_mesh_ilsa(m, CGAL::parameters::callback(stamp)).number_of_iterations;
      totals.push_back(std::chrono::duration<double>(Clock::now() - start).count());
      if (calls.empty()) continue;
      firsts.push_back(std::chrono::duration<double>(calls.front() - start).count());
      std::vector<double> between;
      for (std::size_t k = 1; k < calls.size(); ++k)
        between.push_back(std::chrono::duration<double>(calls[k] - calls[k - 1]).count());
      if (!between.empty()) steps.push_back(median(between));
      Mesh p = input;
      const auto peer_start = Clock::now();
      PMP::tangential_relaxation(p, CGAL::parameters::number_of_iterations(peer_iterations));
      peers.push_back(std::chrono::duration<double>(Clock::now() - peer_start).count());
    }
    if (firsts.empty() || steps.empty() || peers.empty()) continue;
    const double total = median(totals), first = median(firsts), step = median(steps), peer = median(peers);
    const double setup = first - step;
    std::printf("| %s | %.3f | %.3f | %.4f | %.3f | %.2f | %zu | %.3f | %.4f | %.2f |\n",
                std::filesystem::path(file).filename().string().c_str(), total, first, step, setup, setup / total,
                iterations, peer, peer / double(peer_iterations), setup / peer);
    std::fflush(stdout);
  }
}

// The --crease-sets table (user manual, "Open Crease Lines"): the connected
// sets of feature edges (beyond the feature angle, kept by the default crease
// contrast) of each mesh before the open-crease rule, by the package's
// classification code: how many, their sizes, how many have a loose end (a
// vertex with one of their edges, not on the border), and how many sets and
// edges the default rule drops; then the vertex types with the paper's rule
// (0) and with the default (20), candidates without sharp edge fixed in both.
void run_crease_sets(const std::vector<std::string>& files) {
  namespace ilsa = PMP::internal::ILSA;
  std::cout << "| mesh | feature edges | sets | edges in the largest sets | sets with a loose end | "
               "sets (edges) dropped, fewer than "
            << ilsa::defaults::minimum_open_crease_edges
            << " edges and a loose end | ridge / corner vertices, rule off | ridge / corner vertices, default "
               "|\n|---|---|---|---|---|---|---|---|\n";
  for (const std::string& file : files) {
    Mesh input;
    if (!read_input(file, input)) continue;
    ilsa::Set_up_incidences incidences;
    // The package's rules, candidates without sharp edge fixed, without and with the open-crease rule.
    ilsa::Classification_options off = ilsa::Classification_options::rules(feature_angle, false), on = off;
    off.fix_unattached_candidates = on.fix_unattached_candidates = true;
    off.minimum_open_crease_edges = 0;
    const auto flat = ilsa::classified_flat_copy(input, get(CGAL::vertex_point, input),
                                                 CGAL::parameters::default_values(), incidences, &off);
    const ilsa::Flat_mesh& m = flat.mesh;
    const std::vector<unsigned char>& feature = flat.classification.feature_edge;
    // The sets as the rule forms them (drop_short_open_lines()).
    const ilsa::Line_sets sets = ilsa::line_sets(
        m.number_of_vertices(), [&m](std::size_t e) { return m.edges[e]; },
        [&incidences](std::size_t v) { return incidences.on_border[v] != 0; }, feature);
    const std::size_t minimum = ilsa::defaults::minimum_open_crease_edges;
    const std::size_t features = std::size_t(std::count(feature.begin(), feature.end(), 1));
    std::vector<std::size_t> sizes;
    std::size_t open = 0, dropped = 0, dropped_edges = 0;
    for (std::size_t set = 0; set < sets.size.size(); ++set) {
      if (sets.size[set] == 0) continue;
      sizes.push_back(sets.size[set]);
      open += sets.loose[set];
      if (ilsa::is_short_open_line(sets, set, minimum)) ++dropped, dropped_edges += sets.size[set];
    }
    std::sort(sizes.rbegin(), sizes.rend());
    std::string largest;
    for (std::size_t i = 0; i < sizes.size() && i < 5; ++i) largest += (i ? ", " : "") + std::to_string(sizes[i]);
    PMP::ILSA_statistics off_types; // the classification made above, the rule off
    ilsa::count_types(flat.classification, off_types);
    ilsa::Set_up_incidences on_incidences;
    PMP::ILSA_statistics with_rule;
    ilsa::count_types(ilsa::classified_flat_copy(input, get(CGAL::vertex_point, input),
                                                 CGAL::parameters::default_values(), on_incidences, &on)
                          .classification,
                      with_rule);
    std::printf("| %s | %zu | %zu | %s | %zu | %zu (%zu) | %zu / %zu | %zu / %zu |\n",
                std::filesystem::path(file).filename().string().c_str(), features, sizes.size(),
                largest.empty() ? "-" : largest.c_str(), open, dropped, dropped_edges,
                off_types.number_of_ridge_vertices, off_types.number_of_corner_vertices,
                with_rule.number_of_ridge_vertices, with_rule.number_of_corner_vertices);
    std::fflush(stdout);
  }
}

// The --decisions table (see the top of the file).
void run_decisions(const std::vector<std::string>& files) {
  namespace ilsa = PMP::internal::ILSA;
  using Change = std::function<void(ilsa::Smoothing_parameters&, ilsa::Classification_options&)>;
  const std::vector<std::pair<std::string, Change>> variants = {
      {"defaults", [](auto&, auto&) {}},
      {"displacement with its normal component", [](auto& p, auto&) { p.penalty.tangential = false; }},
      {"2 penalty sweeps", [](auto& p, auto&) { p.penalty.sweeps = p.sweeps; }},
      {"worsening moves accepted", [](auto& p, auto&) { p.reject_worsening = false; }},
      {"dropped moves retried at once", [](auto& p, auto&) { p.retry_distance = 0; }},
      {"no remaining-gain stop", [](auto& p, auto&) { p.minimum_remaining_gain = 0; }},
      {"no crease contrast", [](auto&, auto& r) { r.crease_contrast = 0; }},
      {"no open-crease rule", [](auto&, auto& r) { r.minimum_open_crease_edges = 0; }},
      {"candidates without sharp edge fixed", [](auto&, auto& r) { r.fix_unattached_candidates = true; }},
      {"no crease kinks", [](auto&, auto& r) { r.kink_angle_degrees = 180; }},
      {"no fidelity bound", [](auto& p, auto&) { p.fidelity_tolerance = std::numeric_limits<double>::infinity(); }},
      {"no quality floor", [](auto& p, auto&) { p.quality_floor = 0, p.raise_floor_to_input_minimum = false; }},
      {"the paper's variant", [](auto&, auto&) {}},
  };
  std::cout << "| mesh | variant | mean q | min q | certified distance | crease deviation | fixed vertices | "
               "iterations | time s |\n|---|---|---|---|---|---|---|---|---|\n";
  std::vector<std::string> names;                           // of the meshes read
  std::vector<std::vector<double>> mean_q(variants.size()); // per variant, per mesh
  for (const std::string& file : files) {
    Mesh input;
    if (!read_input(file, input)) continue;
    names.push_back(std::filesystem::path(file).stem().string());
    std::size_t variant = 0;
    for (const auto& [name, change] : variants) {
      const bool paper = name == "the paper's variant";
      const auto np = CGAL::parameters::ilsa_paper_variant(paper);
      ilsa::Smoothing_parameters p = ilsa::read_smoothing_parameters(np);
      ilsa::Classification_options r = ilsa::read_classification_options(np);
      change(p, r);
      Mesh m = input;
      const auto start = std::chrono::steady_clock::now();
      const auto s = ilsa::smooth<CGAL::Sequential_tag>(vertices(m), m, np, &p, &r);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // The crease deviation along the feature lines of this variant's classification.
      PMP::ILSA_fidelity_summary f;
      {
        ilsa::Set_up_incidences incidences;
        const auto flat = ilsa::classified_flat_copy(input, get(CGAL::vertex_point, input), np, incidences, &r);
        std::map<Mesh::Edge_index, bool> lines;
        for (std::size_t e = 0; e < flat.mesh.edges.size(); ++e)
          if (flat.classification.feature_edge[e]) {
            const auto h = halfedge(flat.vertices[flat.mesh.edges[e][0]], flat.vertices[flat.mesh.edges[e][1]], input);
            lines[edge(h.first, input)] = true;
          }
        f = PMP::mesh_fidelity_ilsa(input, m,
                                    CGAL::parameters::edge_is_constrained_map(boost::make_assoc_property_map(lines))
                                        .ilsa_compute_hausdorff_distance(false));
      }
      const auto q = PMP::mesh_quality_ilsa(m);
      mean_q[variant++].push_back(q.mean_aspect_ratio);
      std::printf("| %s | %s | %.4f | %.4f | %.2e | %.2e | %zu | %zu | %.3f |\n",
                  std::filesystem::path(file).filename().string().c_str(), name.c_str(), q.mean_aspect_ratio,
                  q.min_aspect_ratio, s.certified_distance, f.max_crease_deviation,
                  s.number_of_corner_vertices + s.number_of_boundary_vertices, s.number_of_iterations, seconds);
      std::fflush(stdout);
    }
  }
  // The mean q again, a row per variant: the defaults', then each variant's change.
  std::cout << "\n| variant |";
  for (const std::string& name : names) std::cout << " " << name << " |";
  std::cout << "\n|---|";
  for (std::size_t i = 0; i < names.size(); ++i) std::cout << "---|";
  std::cout << "\n";
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::cout << "| " << variants[v].first << " |";
    for (std::size_t i = 0; i < names.size(); ++i)
      std::printf(v == 0 ? " %.4f |" : " %+.4f |", v == 0 ? mean_q[0][i] : mean_q[v][i] - mean_q[0][i]);
    std::cout << "\n";
  }
}

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "--child") return run_child(argv[2], argv[3]);
  int runs = 5;
  unsigned peer_iterations = 10;
  int scaling = -1;     // --scaling N: the scaling table up to N subdivisions, and nothing else
  int write_level = -1; // --write-scaling-mesh N FILE
  std::string write_file;
  bool pareto = false, phases = false, crease_sets = false, decisions = false, processes = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc)
      runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--scaling" && i + 1 < argc)
      scaling = std::max(0, std::atoi(argv[++i]));
    else if (a == "--write-scaling-mesh" && i + 2 < argc) {
      write_level = std::max(0, std::atoi(argv[++i]));
      write_file = argv[++i];
    } else if (a == "--pareto")
      pareto = true;
    else if (a == "--phases")
      phases = true;
    else if (a == "--crease-sets")
      crease_sets = true;
    else if (a == "--decisions")
      decisions = true;
    else if (a == "--processes")
      processes = true;
    else if (a == "--peer-iterations" && i + 1 < argc)
      peer_iterations = unsigned(std::max(1, std::atoi(argv[++i])));
    else
      files.push_back(a);
  }
  if (scaling >= 0) {
    run_scaling(argv[0], unsigned(scaling));
    return 0;
  }
  if (write_level >= 0) {
    const Mesh mesh = subdivided_horse(unsigned(write_level));
    return CGAL::IO::write_polygon_mesh(write_file, mesh, CGAL::parameters::use_binary_mode(true)) ? 0 : 1;
  }
  if (files.empty()) files = default_meshes();
  if (pareto) {
    run_pareto(files, peer_iterations);
    return 0;
  }
  if (processes) {
    run_processes(argv[0], files, runs);
    return 0;
  }
  if (phases) {
    run_phases(files, runs, peer_iterations);
    return 0;
  }
  if (crease_sets) {
    run_crease_sets(files);
    return 0;
  }
  if (decisions) {
    run_decisions(files);
    return 0;
  }

#ifdef CGAL_PMP_USE_CERES_SOLVER
  const bool ceres = true;
#else
  const bool ceres = false;
#endif
  std::cout << "Runs per method: " << runs << " (median wall time); CGAL peers: " << peer_iterations
            << " iterations; sharp edges for the peers: detect_sharp_edges at " << feature_angle
            << " degrees; Ceres (area smoothing): " << (ceres ? "yes" : "no") << "\n\n";
  std::cout << "| mesh | method | q min | q mean | q<0.3 % | min angle | flipped | max dist | Hausdorff | "
               "crease dev. max | crease dev. mean | time s (median) | ILSA time / this | "
               "time per iteration s | iterations run |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

  std::vector<Time_row> time_rows;
  for (const std::string& file : files) {
    Mesh input;
    if (!read_input(file, input)) continue;
    const std::string name = std::filesystem::path(file).filename().string();

    // Sharp edges for the peers, computed once on the input (same edge indices in every copy).
    std::vector<edge_descriptor> sharp;
    {
      auto map = input.add_property_map<edge_descriptor, bool>("e:sharp", false).first;
      PMP::detect_sharp_edges(input, feature_angle, map);
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
    methods.push_back(
        {"ILSA (defaults)", [](Mesh& m) { return PMP::smooth_surface_mesh_ilsa(m).number_of_iterations; }});
#ifdef CGAL_LINKED_WITH_TBB
    methods.push_back({"ILSA (defaults), Parallel_tag", [](Mesh& m) {
                         return PMP::smooth_surface_mesh_ilsa<CGAL::Parallel_tag>(m).number_of_iterations;
                       }});
#endif
    methods.push_back({"CGAL angle smoothing + sharp edges", [&](Mesh& m) {
                         auto ecm = with_constraints(m);
                         PMP::angle_and_area_smoothing(m, CGAL::parameters::number_of_iterations(peer_iterations)
                                                              .use_area_smoothing(false)
                                                              .use_Delaunay_flips(false)
                                                              .edge_is_constrained_map(ecm));
                         return std::size_t(peer_iterations);
                       }});
    if (ceres)
      methods.push_back({"CGAL angle+area smoothing + sharp edges", [&](Mesh& m) {
                           auto ecm = with_constraints(m);
                           PMP::angle_and_area_smoothing(m, CGAL::parameters::number_of_iterations(peer_iterations)
                                                                .use_Delaunay_flips(false)
                                                                .edge_is_constrained_map(ecm));
                           return std::size_t(peer_iterations);
                         }});
    methods.push_back({"CGAL tangential relaxation", [&](Mesh& m) {
                         PMP::tangential_relaxation(m, CGAL::parameters::number_of_iterations(peer_iterations));
                         return std::size_t(peer_iterations);
                       }});
    methods.push_back({"CGAL tangential relaxation + projection", [&](Mesh& m) {
                         tangential_relaxation_projected(m, peer_iterations);
                         return std::size_t(peer_iterations);
                       }});
    methods.push_back({"CGAL tangential relaxation + sharp edges", [&](Mesh& m) {
                         auto ecm = with_constraints(m);
                         PMP::tangential_relaxation(m, CGAL::parameters::number_of_iterations(peer_iterations)
                                                           .edge_is_constrained_map(ecm)
                                                           .relax_constraints(true));
                         return std::size_t(peer_iterations);
                       }});

    const auto q0 = PMP::mesh_quality_ilsa(input);
    std::printf("| %s | input | %.4f | %.4f | %.2f | %.2f | | | | | | | | | |\n", name.c_str(), q0.min_aspect_ratio,
                q0.mean_aspect_ratio, 100. * q0.share_below_threshold, q0.min_angle);

    // The methods take turns (run 1 of each, then run 2 of each, ...), so
    // that a drift of the machine's speed during the measurement weighs on
    // every method alike and the ratios stay comparable.
    std::vector<double> times(methods.size());
    std::vector<std::size_t> iterations(methods.size());
    std::vector<Mesh> results(methods.size());
    std::vector<std::vector<double>> samples(methods.size());
    for (int r = 0; r < runs; ++r)
      for (std::size_t k = 0; k < methods.size(); ++k) {
        Mesh m = input;
        const auto start = std::chrono::steady_clock::now();
        iterations[k] = methods[k].run(m);
        samples[k].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (r == 0) results[k] = m;
      }
    for (std::size_t k = 0; k < methods.size(); ++k) times[k] = median(samples[k]);
    auto time_of = [&](const std::string& method) {
      for (std::size_t k = 0; k < methods.size(); ++k)
        if (methods[k].name == method) return times[k];
      return 0.;
    };
    time_rows.push_back({name, std::size_t(num_faces(input)), times[0], time_of("CGAL tangential relaxation"),
                         time_of("CGAL tangential relaxation + projection")});
    for (std::size_t k = 0; k < methods.size(); ++k) {
      Mesh& m = results[k];
      const auto q = PMP::mesh_quality_ilsa(m);
      const auto f = PMP::mesh_fidelity_ilsa(input, m, CGAL::parameters::ilsa_feature_angle(feature_angle));
      std::printf(
          "| %s | %s | %.4f | %.4f | %.2f | %.2f | %zu | %.1e | %.2e | %.1e | %.1e | %.3f | %s | %.4f | %zu |\n",
          name.c_str(), methods[k].name.c_str(), q.min_aspect_ratio, q.mean_aspect_ratio,
          100. * q.share_below_threshold, q.min_angle, f.number_of_flipped_faces, f.max_vertex_distance,
          f.hausdorff_distance, f.max_crease_deviation, f.mean_crease_deviation, times[k],
          k == 0 ? "1" : std::to_string(times[0] / times[k]).substr(0, 5).c_str(), times[k] / double(iterations[k]),
          iterations[k]);
    }
    std::fflush(stdout);
  }
  std::cout << "\nTimes of the table above (medians, one process): ILSA with every default, TR = CGAL tangential "
               "relaxation, TR + projection = CGAL tangential relaxation + projection\n";
  print_time_table(time_rows);
  return 0;
}
