// ilsa_smooth: smooths a triangle mesh file with ILSA and reports the quality
// before and after.
//
//   ilsa_smooth [INPUT [OUTPUT]] [options]
//
// With no INPUT, the bundled horse is smoothed. Every format that
// CGAL::IO::read_polygon_mesh reads is accepted; OUTPUT keeps the vertex and
// face order and is written only on success, with 17 significant digits
// (binary doubles in PLY; STL stores 32-bit floats, the format's limit).
// `ilsa_smooth --help` lists the options.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Polygon_mesh_processing/classify_vertices_ilsa.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/ilsa_version.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include "ilsa_example_data.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

namespace PMP = CGAL::Polygon_mesh_processing;
#ifdef CGAL_LINKED_WITH_TBB
constexpr bool tbb_available = true;
#else
constexpr bool tbb_available = false; // --threads then has no effect
#endif
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;
namespace defaults = CGAL::Polygon_mesh_processing::internal::ILSA::defaults;

namespace {

struct Options {
  std::string input = ilsa_data_file("horse.ply");
  std::string output;
  // The library's defaults (the usage text below states them; test_ilsa_smoothing checks that it does).
  unsigned int iterations = defaults::number_of_iterations, relaxation_steps = defaults::number_of_relaxation_steps;
  unsigned int penalty_steps = defaults::penalty_steps;
  bool penalty_gauss_seidel = defaults::penalty_gauss_seidel;
  bool tangential = defaults::tangential_displacement;
  bool tangential_sweeps = defaults::tangential_sweeps;
  double relax1 = defaults::relaxation, relax2 = defaults::penalty_relaxation, mu = defaults::penalty_mu;
  double wl = defaults::length_weight, wa = defaults::area_weight, feature_angle = defaults::feature_angle;
  double fidelity_tolerance = defaults::fidelity_tolerance;
  double minimum_gain = defaults::minimum_quality_gain;
  double minimum_remaining_gain = defaults::minimum_remaining_gain;
  double retry_distance = defaults::retry_distance;
  double crease_contrast = defaults::crease_contrast;
  unsigned int minimum_open_crease_edges = defaults::minimum_open_crease_edges;
  std::optional<double> kink_angle;    // the library's default (the feature angle) when not given
  std::optional<double> quality_floor; // the library's default when not given
  bool fix_unattached = defaults::fix_unattached_candidates, project = defaults::do_project;
  bool safety = defaults::use_safety_constraints, monotone = defaults::quality_monotone;
  bool reject_worsening = defaults::reject_worsening_moves, verbose = false;
  unsigned int worst = 0;                                                   // faces listed by --worst
  unsigned int threads = std::max(1u, std::thread::hardware_concurrency()); // 1: sequential
  bool triangulate = false, color_by_quality = false, color_by_type = false;
  std::string report = "auto";                            // auto, summary or full
  std::optional<bool> progress;                           // default: on when stderr is a terminal
  static constexpr std::size_t full_report_faces = 20000; // --report auto: full up to this many faces
};

const char* usage =
    "usage: ilsa_smooth [INPUT [OUTPUT]] [options]\n"
    "Smooths the triangle mesh INPUT with ILSA (default: the bundled horse) and prints its quality\n"
    "before and after; OUTPUT, when given, receives the result. Options take their value as\n"
    "'--option value' or '--option=value'.\n"
    "Formats (by extension): .off .obj .ply .stl .ts (GOCAD) and .vtp (when CGAL has VTK), in and out.\n"
    "OUTPUT keeps the vertex and face order, with 17 significant digits (.ply: binary doubles);\n"
    ".stl holds 32-bit floats only (about 7 digits): the format's limit.\n"
    "  --help, -h              this text\n"
    "  --version               the package's version\n"
    "  --iterations N          largest number of global iterations (default 8)\n"
    "  --min-gain X            stop once an iteration raises the mean q by less, >= 0,\n"
    "                          0 disables this stop (default 1e-4)\n"
    "  --min-remaining-gain X  stop once an iteration's gain of mean q times the iterations\n"
    "                          left is below X, >= 0, 0 disables this stop (default 2e-3);\n"
    "                          with both stops disabled every iteration runs\n"
    "  --relaxation-steps N    sweeps of the ILSA step per iteration (default 2)\n"
    "  --penalty-steps N       sweeps of the penalty step per iteration (default 8)\n"
    "  --gauss-seidel 0|1      1: multicolour Gauss-Seidel sweeps of the penalty step,\n"
    "                          0: Jacobi sweeps (the paper) (default 0)\n"
    "  --relax1 X              ILSA relaxation, (0,1] (default 0.5)\n"
    "  --relax2 X              penalty relaxation, (0,1] (default 0.8)\n"
    "  --tangential 0|1        drop the normal component of the displacements,\n"
    "                          0: keep it (the paper) (default 1)\n"
    "  --tangential-sweeps 0|1 1: every penalty sweep drops the normal component,\n"
    "                          0: dropped once after the sweeps (default 1)\n"
    "  --mu X                  penalty parameter, > 0 (default 1)\n"
    "  --wl X                  length weight, >= 0 (default 1)\n"
    "  --wa X                  area weight, >= 0 (default 0.1)\n"
    "  --feature-angle DEG     an edge is sharp when its face normals differ by more, [0,180) (default 20)\n"
    "  --fix-unattached 0|1    fix ridge candidates without sharp edge, 1: the paper (default 0)\n"
    "  --crease-contrast X     a sharp edge must bend X times more than the flatter other edge\n"
    "                          of each of its faces, >= 0, 0: every one (the paper) (default 5)\n"
    "  --min-open-crease-edges N\n"
    "                          connected sharp edges with an end and fewer edges are curvature,\n"
    "                          not a crease line, 0: none (the paper) (default 20)\n"
    "  --kink-angle DEG        fix a crease vertex where the crease turns by more, [0,180],\n"
    "                          180 disables (default: the feature angle)\n"
    "  --no-project            do not project back onto the input surface\n"
    "  --no-safety             no inversion check after projection\n"
    "  --quality-floor X       safety check: no triangle pushed below this q, [0,1)\n"
    "                          (default: 0.5, or the input's minimum q if higher)\n"
    "  --quality-monotone      reject moves that lower the star's minimum quality\n"
    "  --reject-worsening 0|1  safety check: drop moves that lower the star's mean quality (default 1)\n"
    "  --fidelity-tolerance X  largest distance between the result and the input surface, both ways,\n"
    "                          certified (and along the feature lines), relative to the bounding-box\n"
    "                          diagonal, > 0, inf disables (default 5e-4)\n"
    "  --retry-distance X      a move the safety check dropped (but for the quality floor in a star\n"
    "                          at or above it) is tried again once the neighbours have moved this\n"
    "                          far in all, relative to the mean edge length, >= 0, 0: in the next\n"
    "                          iteration (default 0.03)\n"
    "  --threads N             threads (default: all cores; 1: sequential; the result is the same)\n"
    "  --triangulate           split non-triangle faces first (CGAL triangulate_faces);\n"
    "                          without it a non-triangle face is an error\n"
    "  --color-by-quality      OUTPUT (.ply) gets face colours by aspect ratio q:\n"
    "                          red 0, orange 0.25, yellow 0.5, light green 0.75, green 1\n"
    "  --color-by-type         OUTPUT (.ply) gets vertex colours by ILSA vertex type:\n"
    "                          smooth grey, ridge blue, corner red, boundary green\n"
    "  --report auto|summary|full\n"
    "                          fidelity report: full adds CGAL's bounded-error Hausdorff distance\n"
    "                          (certified to 1e-5, costly on large meshes: 17 s on the horse);\n"
    "                          auto: full up to 20000 faces (default auto)\n"
    "  --progress, --no-progress\n"
    "                          a progress line per iteration on stderr (default: on a terminal)\n"
    "  --verbose               print the set-up's time and what each iteration does (and its time)\n"
    "  --worst N               list the N worst faces after smoothing: aspect ratio before and after,\n"
    "                          type of each vertex and whether it moved, smallest dihedral angle of\n"
    "                          the face's edges in the input\n";

double parse_number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size()) throw std::invalid_argument(flag + " expects a number, got '" + text + "'");
  return value;
}

unsigned int parse_count(const std::string& flag, const std::string& text) {
  const double value = parse_number(flag, text);
  if (value < 0 || value > 1e6 || value != double((unsigned int)value))
    throw std::invalid_argument(flag + " expects a non-negative whole number, got '" + text + "'");
  return (unsigned int)value;
}

Options parse(int argc, char** argv) {
  Options o;
  std::vector<std::string> positional;
  std::map<std::string, std::function<void(const std::string&)>> valued{
      {"--iterations", [&](const std::string& s) { o.iterations = parse_count("--iterations", s); }},
      {"--relaxation-steps", [&](const std::string& s) { o.relaxation_steps = parse_count("--relaxation-steps", s); }},
      {"--penalty-steps", [&](const std::string& s) { o.penalty_steps = parse_count("--penalty-steps", s); }},
      {"--gauss-seidel", [&](const std::string& s) { o.penalty_gauss_seidel = parse_count("--gauss-seidel", s) != 0; }},
      {"--tangential", [&](const std::string& s) { o.tangential = parse_count("--tangential", s) != 0; }},
      {"--tangential-sweeps",
       [&](const std::string& s) { o.tangential_sweeps = parse_count("--tangential-sweeps", s) != 0; }},
      {"--relax1", [&](const std::string& s) { o.relax1 = parse_number("--relax1", s); }},
      {"--relax2", [&](const std::string& s) { o.relax2 = parse_number("--relax2", s); }},
      {"--mu", [&](const std::string& s) { o.mu = parse_number("--mu", s); }},
      {"--wl", [&](const std::string& s) { o.wl = parse_number("--wl", s); }},
      {"--wa", [&](const std::string& s) { o.wa = parse_number("--wa", s); }},
      {"--feature-angle", [&](const std::string& s) { o.feature_angle = parse_number("--feature-angle", s); }},
      {"--min-gain", [&](const std::string& s) { o.minimum_gain = parse_number("--min-gain", s); }},
      {"--min-remaining-gain",
       [&](const std::string& s) { o.minimum_remaining_gain = parse_number("--min-remaining-gain", s); }},
      {"--retry-distance", [&](const std::string& s) { o.retry_distance = parse_number("--retry-distance", s); }},
      {"--kink-angle", [&](const std::string& s) { o.kink_angle = parse_number("--kink-angle", s); }},
      {"--crease-contrast", [&](const std::string& s) { o.crease_contrast = parse_number("--crease-contrast", s); }},
      {"--min-open-crease-edges",
       [&](const std::string& s) { o.minimum_open_crease_edges = parse_count("--min-open-crease-edges", s); }},
      {"--quality-floor", [&](const std::string& s) { o.quality_floor = parse_number("--quality-floor", s); }},
      {"--fidelity-tolerance",
       [&](const std::string& s) { o.fidelity_tolerance = parse_number("--fidelity-tolerance", s); }},
      {"--fix-unattached", [&](const std::string& s) { o.fix_unattached = parse_count("--fix-unattached", s) != 0; }},
      {"--reject-worsening",
       [&](const std::string& s) { o.reject_worsening = parse_count("--reject-worsening", s) != 0; }},
      {"--worst", [&](const std::string& s) { o.worst = parse_count("--worst", s); }},
      {"--threads",
       [&](const std::string& s) {
         o.threads = parse_count("--threads", s);
         if (o.threads == 0) throw std::invalid_argument("--threads expects at least 1, got '" + s + "'");
       }},
  };
  valued["--report"] = [&](const std::string& s) {
    if (s != "auto" && s != "summary" && s != "full")
      throw std::invalid_argument("--report expects auto, summary or full, got '" + s + "'");
    o.report = s;
  };
  std::map<std::string, std::function<void()>> switches{
      {"--no-project", [&] { o.project = false; }},
      {"--no-safety", [&] { o.safety = false; }},
      {"--quality-monotone", [&] { o.monotone = true; }},
      {"--verbose", [&] { o.verbose = true; }},
      {"--triangulate", [&] { o.triangulate = true; }},
      {"--color-by-quality", [&] { o.color_by_quality = true; }},
      {"--color-by-type", [&] { o.color_by_type = true; }},
      {"--progress", [&] { o.progress = true; }},
      {"--no-progress", [&] { o.progress = false; }},
      {"--help", [] { std::cout << usage, std::exit(0); }},
      {"-h", [] { std::cout << usage, std::exit(0); }},
      {"--version",
       [] {
         std::cout << "ilsa_smooth " << CGAL_PMP_ILSA_VERSION << " (CGAL " << CGAL_VERSION_STR << ")\n", std::exit(0);
       }},
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    // --option=value is --option value.
    const std::size_t equals = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
    const std::string name = arg.substr(0, equals);
    if (valued.count(name)) {
      if (equals != std::string::npos)
        valued[name](arg.substr(equals + 1));
      else if (i + 1 < argc)
        valued[name](argv[++i]);
      else
        throw std::invalid_argument(name + " expects a value");
    } else if (switches.count(name)) {
      if (equals != std::string::npos) throw std::invalid_argument(name + " takes no value, got '" + arg + "'");
      switches[name]();
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw std::invalid_argument("unknown option '" + name + "' (see --help)");
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() > 2) throw std::invalid_argument("too many file arguments (see --help)");
  if (positional.size() > 0) o.input = positional[0];
  if (positional.size() > 1) o.output = positional[1];
  // Checked before anything is read or smoothed.
  for (const auto& [flag, on] : {std::pair<const char*, bool>{"--color-by-quality", o.color_by_quality},
                                 std::pair<const char*, bool>{"--color-by-type", o.color_by_type}})
    if (on && (o.output.size() < 4 || o.output.substr(o.output.size() - 4) != ".ply"))
      throw std::invalid_argument(std::string(flag) + " writes colours to a PLY file: give an OUTPUT ending in .ply");
  return o;
}

// The library's messages name its parameters; the tool's name the flags.
std::string in_flag_terms(std::string message) {
  static const std::pair<const char*, const char*> names[] = {
      {"ilsa_penalty_relaxation", "--relax2"},
      {"ilsa_relaxation", "--relax1"},
      {"ilsa_penalty_mu", "--mu"},
      {"ilsa_length_weight", "--wl"},
      {"ilsa_area_weight", "--wa"},
      {"ilsa_feature_angle", "--feature-angle"},
      {"ilsa_crease_kink_angle", "--kink-angle"},
      {"ilsa_crease_contrast", "--crease-contrast"},
      {"ilsa_minimum_open_crease_edges", "--min-open-crease-edges"},
      {"ilsa_minimum_quality_gain", "--min-gain"},
      {"ilsa_minimum_remaining_gain", "--min-remaining-gain"},
      {"ilsa_retry_distance", "--retry-distance"},
      {"ilsa_quality_floor", "--quality-floor"},
      {"ilsa_fidelity_tolerance", "--fidelity-tolerance"},
      {"number_of_relaxation_steps", "--relaxation-steps"},
      {"ilsa_penalty_steps", "--penalty-steps"},
      {"number_of_iterations", "--iterations"},
  };
  for (const auto& [library, flag] : names)
    for (std::size_t at = message.find(library); at != std::string::npos; at = message.find(library, at))
      message.replace(at, std::string(library).size(), flag);
  return message;
}

// Red (q = 0) through orange, yellow and light green to green (q = 1).
CGAL::IO::Color quality_color(double q) {
  static const double stops[5][3] = {{165, 0, 38}, {244, 109, 67}, {254, 224, 139}, {166, 217, 106}, {26, 152, 80}};
  const double x = (std::min)(1., (std::max)(0., q)) * 4.;
  const int i = (std::min)(3, int(x));
  const double t = x - i;
  auto channel = [&](int c) { return (unsigned char)std::lround(stops[i][c] + t * (stops[i + 1][c] - stops[i][c])); };
  return CGAL::IO::Color(channel(0), channel(1), channel(2));
}

void print_quality(const char* label, const PMP::ILSA_quality_summary& q) {
  std::cout << std::fixed << std::setprecision(4) << label << ": aspect ratio q min " << q.min_aspect_ratio << " mean "
            << q.mean_aspect_ratio << ", q<0.3 " << std::setprecision(2) << 100. * q.share_below_threshold
            << " %, min angle " << q.min_angle << " deg, degenerate faces " << q.number_of_degenerate_faces << "\n";
}

// The `count` worst faces of `smoothed` (same connectivity as `original`), with
// what holds each back: fixed vertices, vertices that did not move, folds of the
// input (a small dihedral angle).
void print_worst_faces(const Mesh& original, const Mesh& smoothed, unsigned int count, const Options& o) {
  std::map<Mesh::Vertex_index, PMP::ILSA_vertex_type> types;
  PMP::classify_vertices_ilsa(original, boost::make_assoc_property_map(types),
                              CGAL::parameters::ilsa_feature_angle(o.feature_angle)
                                  .ilsa_fix_unattached_candidates(o.fix_unattached)
                                  .ilsa_crease_kink_angle(o.kink_angle.value_or(o.feature_angle))
                                  .ilsa_crease_contrast(o.crease_contrast)
                                  .ilsa_minimum_open_crease_edges(o.minimum_open_crease_edges));
  auto aspect_ratio = [](const Mesh& m, Mesh::Face_index f) {
    const auto h = halfedge(f, m);
    return PMP::triangle_quality_ilsa(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
  };
  std::vector<std::pair<double, Mesh::Face_index>> ranked;
  for (auto f : faces(smoothed)) ranked.emplace_back(aspect_ratio(smoothed, f), f);
  count = (std::min)(count, (unsigned int)ranked.size());
  std::partial_sort(ranked.begin(), ranked.begin() + count, ranked.end());
  for (unsigned int i = 0; i < count; ++i) {
    const auto f = ranked[i].second;
    std::cout << std::fixed << std::setprecision(4) << "worst face " << std::size_t(f) << ": q "
              << aspect_ratio(original, f) << " -> " << ranked[i].first << ", vertices";
    double smallest_dihedral = 180;
    for (auto h : halfedges_around_face(halfedge(f, original), original)) {
      const auto v = target(h, original);
      std::cout << " " << PMP::to_string(types[v]) << (original.point(v) == smoothed.point(v) ? " (not moved)" : "");
      const auto o = opposite(h, original);
      if (is_border(o, original)) continue;
      const auto& p = original.point(source(h, original));
      const auto& r = original.point(target(next(h, original), original));
      const auto& t = original.point(target(next(o, original), original));
      smallest_dihedral =
          (std::min)(smallest_dihedral, std::abs(CGAL::approximate_dihedral_angle(p, original.point(v), r, t)));
    }
    std::cout << std::setprecision(1) << ", smallest input dihedral angle " << smallest_dihedral << " deg\n";
  }
}

// The named parameters of the flags.
auto smoothing_parameters(const Options& o, const std::function<bool(double)>& callback) {
  return CGAL::parameters::number_of_iterations(o.iterations)
      .number_of_relaxation_steps(o.relaxation_steps)
      .ilsa_penalty_steps(o.penalty_steps)
      .ilsa_penalty_gauss_seidel(o.penalty_gauss_seidel)
      .ilsa_tangential_displacement(o.tangential)
      .ilsa_tangential_sweeps(o.tangential_sweeps)
      .ilsa_relaxation(o.relax1)
      .ilsa_penalty_relaxation(o.relax2)
      .ilsa_penalty_mu(o.mu)
      .ilsa_length_weight(o.wl)
      .ilsa_area_weight(o.wa)
      .ilsa_feature_angle(o.feature_angle)
      .ilsa_fix_unattached_candidates(o.fix_unattached)
      .ilsa_crease_kink_angle(o.kink_angle.value_or(o.feature_angle))
      .ilsa_crease_contrast(o.crease_contrast)
      .ilsa_minimum_open_crease_edges(o.minimum_open_crease_edges)
      .ilsa_minimum_quality_gain(o.minimum_gain)
      .ilsa_minimum_remaining_gain(o.minimum_remaining_gain)
      .ilsa_retry_distance(o.retry_distance)
      .do_project(o.project)
      .use_safety_constraints(o.safety)
      .ilsa_quality_monotone(o.monotone)
      .ilsa_reject_worsening_moves(o.reject_worsening)
      .ilsa_fidelity_tolerance(o.fidelity_tolerance)
      .callback(callback)
      .verbose(o.verbose);
}

// The library checks its parameters before it reads the mesh: an empty mesh
// tests the flags' values before the input is read and anything printed
// (without --verbose, which would print the empty mesh's vertex types).
void check_parameters(Options o) {
  Mesh empty;
  o.verbose = false;
  const auto np = smoothing_parameters(o, std::function<bool(double)>());
  try {
    if (o.quality_floor)
      PMP::smooth_surface_mesh_ilsa(empty, np.ilsa_quality_floor(*o.quality_floor));
    else
      PMP::smooth_surface_mesh_ilsa(empty, np);
  } catch (const PMP::ILSA_error& e) {
    throw std::runtime_error(in_flag_terms(e.what()));
  }
}

int run(const Options& o) {
  Mesh mesh;
  check_parameters(o);
  if (!CGAL::IO::read_polygon_mesh(o.input, mesh))
    throw std::runtime_error("cannot read a polygon mesh from '" + o.input + "'");
  if (num_faces(mesh) == 0) throw std::runtime_error("'" + o.input + "' has no faces");
  // Input the smoother rejects is reported before any figure is printed.
  for (const auto& p : mesh.points())
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw std::runtime_error("'" + o.input + "' has a non-finite coordinate (NaN or infinity)");
  std::size_t polygons = 0;
  for (auto f : faces(mesh)) polygons += degree(f, mesh) != 3;
  std::cout << o.input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  if (polygons > 0) {
    if (!o.triangulate)
      throw std::runtime_error("'" + o.input + "' has " + std::to_string(polygons) +
                               " faces that are not triangles: ILSA smooths triangle meshes (--triangulate splits "
                               "them first)");
    if (!PMP::triangulate_faces(mesh)) throw std::runtime_error("--triangulate could not split every face");
    std::cout << "triangulated: " << polygons << " faces split, " << num_faces(mesh) << " triangles\n";
  }
  print_quality("before", PMP::mesh_quality_ilsa(mesh));

  const Mesh original = mesh;
  const unsigned int total = o.iterations;
  const bool progress = o.progress.value_or(isatty(fileno(stderr)) != 0) && !o.verbose;
  const std::function<bool(double)> show_progress = [&](double advancement) {
    std::cerr << "\rILSA iteration " << std::lround(advancement * total) << " of at most " << total << std::flush;
    return true;
  };
  const auto start = std::chrono::steady_clock::now();
  const auto np = smoothing_parameters(o, progress ? show_progress : std::function<bool(double)>());
  // Sequential with one thread, TBB otherwise (when the package was built with it).
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, o.threads);
#endif
  auto smooth = [&](const auto& parameters) {
    return o.threads == 1 ? PMP::smooth_surface_mesh_ilsa<CGAL::Sequential_tag>(mesh, parameters)
                          : PMP::smooth_surface_mesh_ilsa<CGAL::Parallel_if_available_tag>(mesh, parameters);
  };
  PMP::ILSA_statistics s;
  try {
    s = o.quality_floor ? smooth(np.ilsa_quality_floor(*o.quality_floor)) : smooth(np);
  } catch (const PMP::ILSA_error& e) {
    throw std::runtime_error(in_flag_terms(e.what()));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (progress && s.number_of_iterations > 0) std::cerr << "\n";

  print_quality("after ", PMP::mesh_quality_ilsa(mesh));
  std::cout << "vertices: " << s.number_of_smooth_vertices << " smooth, " << s.number_of_ridge_vertices << " ridge, "
            << s.number_of_corner_vertices << " corner (" << s.number_of_kink_vertices << " crease kinks), "
            << s.number_of_boundary_vertices << " boundary\n"
            << "moves: " << s.number_of_moves << " accepted, " << s.number_of_shortened_moves << " shortened, "
            << s.number_of_rejected_moves << " rejected by the safety check ("
            << s.number_of_moves_dropped_before_projection << " of them before projection), "
            << s.number_of_settled_skips << " skipped as settled\n";
  auto limits = [](const PMP::ILSA_move_limits& l) {
    return std::to_string(l.flip_or_collapse) + " flip or collapse, " + std::to_string(l.quality_floor) +
           " quality floor, " + std::to_string(l.worsening) + " worsening, " + std::to_string(l.fidelity) +
           " fidelity, " + std::to_string(l.crease) + " crease";
  };
  std::cout << "limited by: dropped " << limits(s.moves_dropped_by) << "; shortened " << limits(s.moves_shortened_by)
            << "\n"
            << std::setprecision(3) << "time: " << seconds << " s for " << s.number_of_iterations << " iterations ("
            << (o.threads == 1 || !tbb_available ? std::string("sequential") : std::to_string(o.threads) + " threads")
            << ")\n";
  if (s.number_of_iterations > 0)
    std::cout << std::scientific << std::setprecision(2) << "certified: Hausdorff distance to the input at most "
              << s.certified_distance << ", feature lines at most " << s.certified_crease_distance
              << " [both ways, relative to the bounding-box diagonal; inf: no bound enforced]\n";
  const bool full = o.report == "full" || (o.report == "auto" && num_faces(mesh) <= Options::full_report_faces);
  const PMP::ILSA_fidelity_summary f =
      PMP::mesh_fidelity_ilsa(original, mesh,
                              CGAL::parameters::ilsa_feature_angle(o.feature_angle)
                                  .ilsa_crease_contrast(o.crease_contrast)
                                  .ilsa_minimum_open_crease_edges(o.minimum_open_crease_edges)
                                  .ilsa_compute_hausdorff_distance(full));
  std::cout << std::scientific << std::setprecision(2) << "fidelity: " << f.number_of_flipped_faces
            << " flipped faces, vertex distance to input max " << f.max_vertex_distance << " mean "
            << f.mean_vertex_distance << ", ";
  if (full)
    std::cout << "Hausdorff " << f.hausdorff_distance << " (CGAL, certified to +" << f.hausdorff_error << ")";
  else
    std::cout << "Hausdorff not computed (--report full)";
  std::cout << ", crease deviation (" << f.number_of_sharp_edges << " sharp edges, both ways) max "
            << f.max_crease_deviation << " mean " << f.mean_crease_deviation;
  if (f.closed) std::cout << ", volume change " << f.volume_change;
  std::cout << " [distances relative to the bounding-box diagonal]\n";
  if (o.report == "full" && (o.crease_contrast > 0 || o.minimum_open_crease_edges > 1)) {
    // The same along every edge beyond the feature angle, the curvature that
    // the contrast and the open-crease rule do not take for creases included
    // (user manual, "Crease contrast" and "Open Crease Lines").
    const auto all = PMP::mesh_fidelity_ilsa(original, mesh,
                                             CGAL::parameters::ilsa_feature_angle(o.feature_angle)
                                                 .ilsa_crease_contrast(0.)
                                                 .ilsa_minimum_open_crease_edges(0)
                                                 .ilsa_compute_hausdorff_distance(false));
    std::cout << "feature lines without the contrast: deviation (" << all.number_of_sharp_edges
              << " edges beyond the feature angle, both ways) max " << all.max_crease_deviation << " mean "
              << all.mean_crease_deviation << "\n";
  }

  if (o.worst > 0) print_worst_faces(original, mesh, o.worst, o);

  if (o.output.empty()) {
    std::cout << "nothing written: no OUTPUT file given\n";
    return 0;
  }
  if (o.color_by_quality) {
    auto colors = mesh.add_property_map<Mesh::Face_index, CGAL::IO::Color>("f:color").first;
    for (auto face : faces(mesh)) {
      const auto h = halfedge(face, mesh);
      colors[face] = quality_color(PMP::triangle_quality_ilsa(mesh.point(source(h, mesh)), mesh.point(target(h, mesh)),
                                                              mesh.point(target(next(h, mesh), mesh))));
    }
  }
  if (o.color_by_type) {
    // The types of the input, which the smoothing used.
    std::map<Mesh::Vertex_index, PMP::ILSA_vertex_type> types;
    PMP::classify_vertices_ilsa(original, boost::make_assoc_property_map(types),
                                CGAL::parameters::ilsa_feature_angle(o.feature_angle)
                                    .ilsa_fix_unattached_candidates(o.fix_unattached)
                                    .ilsa_crease_kink_angle(o.kink_angle.value_or(o.feature_angle))
                                    .ilsa_crease_contrast(o.crease_contrast)
                                    .ilsa_minimum_open_crease_edges(o.minimum_open_crease_edges));
    auto colors = mesh.add_property_map<Mesh::Vertex_index, CGAL::IO::Color>("v:color").first;
    for (auto v : vertices(mesh)) {
      const PMP::ILSA_vertex_type t = types[v];
      colors[v] = t == PMP::ILSA_vertex_type::Smooth   ? CGAL::IO::Color(190, 190, 190)
                  : t == PMP::ILSA_vertex_type::Ridge  ? CGAL::IO::Color(30, 90, 220)
                  : t == PMP::ILSA_vertex_type::Corner ? CGAL::IO::Color(220, 30, 30)
                                                       : CGAL::IO::Color(30, 170, 60);
    }
  }
  // Write next to the target, then rename: a failed write leaves no partial file.
  // The temporary keeps the extension, which selects the format.
  const std::size_t dot = o.output.find_last_of('.');
  const std::size_t slash = o.output.find_last_of('/');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string extension = has_extension ? o.output.substr(dot) : std::string();
  const std::string temporary =
      has_extension ? o.output.substr(0, dot) + ".ilsa-partial" + extension : o.output + ".ilsa-partial";
  if (!std::ofstream(temporary)) throw std::runtime_error("cannot write '" + o.output + "'");
  if (!CGAL::IO::write_polygon_mesh(temporary, mesh, CGAL::parameters::stream_precision(17))) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + o.output + "' (formats: see --help)");
  }
  if (std::rename(temporary.c_str(), o.output.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + o.output + "'");
  }
  std::cout << "written: " << o.output;
  if (extension == ".stl" || extension == ".STL")
    std::cout << " (STL stores 32-bit floats: coordinates rounded to about 7 significant digits)";
  if (o.color_by_quality) std::cout << " (faces coloured by q)";
  if (o.color_by_type) std::cout << " (vertices coloured by type)";
  std::cout << "\n";
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    // The library's errors start with "ILSA: "; the tool's prefix says it once.
    std::string what = in_flag_terms(e.what());
    if (what.rfind("ILSA: ", 0) == 0) what.erase(0, 6);
    std::cerr << "ilsa_smooth: error: " << what << "\n";
    return 1;
  }
}
