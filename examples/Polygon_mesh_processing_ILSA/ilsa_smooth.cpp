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
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/mesh_quality_ilsa.h>
#include <CGAL/Polygon_mesh_processing/ilsa_version.h>
#include <CGAL/Polygon_mesh_processing/smooth_surface_mesh_ilsa.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include "ilsa_example_data.h"

#include <boost/property_map/function_property_map.hpp>

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
#include <sstream>
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
  unsigned int iterations = defaults::number_of_iterations;
  double minimum_gain = defaults::minimum_quality_gain;
  std::optional<double> quality_floor; // the library's default when not given
  double fidelity_tolerance = defaults::fidelity_tolerance;
  bool paper = defaults::paper_variant, project = defaults::do_project, safety = defaults::use_safety_constraints;
  double feature_angle = defaults::feature_angle;
  std::string sharp_edges_file;                                             // --sharp-edges
  std::optional<double> detect_sharp_edges;                                 // --detect-sharp-edges
  std::optional<std::vector<unsigned char>> crease_edges;                   // per edge, from one of the two above
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
    "\n"
    "Input and output:\n"
    "  --help, -h              this text\n"
    "  --version               the package's version\n"
    "  --triangulate           split non-triangle faces first (CGAL triangulate_faces);\n"
    "                          without it a non-triangle face is an error\n"
    "  --color-by-quality      OUTPUT (.ply) gets face colours by aspect ratio q:\n"
    "                          red 0, orange 0.25, yellow 0.5, light green 0.75, green 1\n"
    "  --color-by-type         OUTPUT (.ply) gets vertex colours by ILSA vertex type:\n"
    "                          smooth grey, ridge blue, corner red, boundary green\n"
    "\n"
    "Quality and fidelity:\n"
    "  --iterations N          largest number of global iterations (default 8)\n"
    "  --min-gain X            stop once an iteration raises the mean q by less, >= 0,\n"
    "                          0: every iteration runs (default 1e-4)\n"
    "  --quality-floor X       no triangle pushed below this q, [0,1)\n"
    "                          (default: 0.5, or the input's minimum q if higher)\n"
    "  --fidelity-tolerance X  largest distance between the result and the input surface, both ways,\n"
    "                          certified for every point (and between the feature lines), relative\n"
    "                          to the bounding-box diagonal, > 0, inf disables (default 5e-4)\n"
    "  --paper                 the paper's variant: its classification, displacement, sweeps and\n"
    "                          acceptance of moves (the guarantees stay)\n"
    "  --no-safety             no safety check: no flip test, quality floor or fidelity bound\n"
    "  --no-project            do not project back onto the input surface\n"
    "\n"
    "Creases:\n"
    "  --feature-angle DEG     an edge is sharp when its face normals differ by more, [0,180) (default 20)\n"
    "  --sharp-edges FILE      keep these crease edges instead of detecting them: one edge a line,\n"
    "                          two vertex indices of INPUT (from 0); '#' starts a comment\n"
    "  --detect-sharp-edges DEG\n"
    "                          keep the crease edges of CGAL's detect_sharp_edges() at this angle\n"
    "                          instead; with either, crease vertices slide along the given edges\n"
    "\n"
    "Report and threads:\n"
    "  --report auto|summary|full\n"
    "                          fidelity report: full adds CGAL's bounded-error Hausdorff distance\n"
    "                          (certified to 1e-5, costly on large meshes: 17 s on the horse);\n"
    "                          auto: full up to 20000 faces (default auto)\n"
    "  --progress, --no-progress\n"
    "                          a progress line per iteration on stderr (default: on a terminal)\n"
    "  --worst N               list the N worst faces after smoothing: aspect ratio before and after,\n"
    "                          type of each vertex and whether it moved, smallest dihedral angle of\n"
    "                          the face's edges in the input\n"
    "  --threads N             threads (default: all cores; 1: sequential; the result is the same)\n";

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
      {"--min-gain", [&](const std::string& s) { o.minimum_gain = parse_number("--min-gain", s); }},
      {"--quality-floor", [&](const std::string& s) { o.quality_floor = parse_number("--quality-floor", s); }},
      {"--fidelity-tolerance",
       [&](const std::string& s) { o.fidelity_tolerance = parse_number("--fidelity-tolerance", s); }},
      {"--feature-angle", [&](const std::string& s) { o.feature_angle = parse_number("--feature-angle", s); }},
      {"--sharp-edges", [&](const std::string& s) { o.sharp_edges_file = s; }},
      {"--detect-sharp-edges",
       [&](const std::string& s) {
         o.detect_sharp_edges = parse_number("--detect-sharp-edges", s);
         if (!(*o.detect_sharp_edges >= 0 && *o.detect_sharp_edges <= 180))
           throw std::invalid_argument("--detect-sharp-edges expects an angle in [0, 180], got '" + s + "'");
       }},
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
      {"--paper", [&] { o.paper = true; }},
      {"--no-project", [&] { o.project = false; }},
      {"--no-safety", [&] { o.safety = false; }},
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
  if (!o.sharp_edges_file.empty() && o.detect_sharp_edges)
    throw std::invalid_argument("--sharp-edges and --detect-sharp-edges both give the crease edges: choose one");
  return o;
}

// The library's messages name its parameters; the tool's name the flags.
std::string in_flag_terms(std::string message) {
  static const std::pair<const char*, const char*> names[] = {
      {"ilsa_feature_angle", "--feature-angle"}, {"ilsa_minimum_quality_gain", "--min-gain"},
      {"ilsa_quality_floor", "--quality-floor"}, {"ilsa_fidelity_tolerance", "--fidelity-tolerance"},
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

// The named parameters of the flags, handed to `f`: those of the crease
// flags (feature angle, paper's variant, the user's crease edges that
// vertices slide along), and those of the smoothing when `smoothing`.
template <class F>
auto with_parameters(const Options& o, const std::function<bool(double)>& callback, bool smoothing, const F& f) {
  const auto creases = CGAL::parameters::ilsa_feature_angle(o.feature_angle).ilsa_paper_variant(o.paper);
  auto more = [&](const auto& np) {
    if (!smoothing) return f(np);
    const auto all = np.number_of_iterations(o.iterations)
                         .ilsa_minimum_quality_gain(o.minimum_gain)
                         .ilsa_fidelity_tolerance(o.fidelity_tolerance)
                         .do_project(o.project)
                         .use_safety_constraints(o.safety)
                         .callback(callback);
    return o.quality_floor ? f(all.ilsa_quality_floor(*o.quality_floor)) : f(all);
  };
  if (!o.crease_edges) return more(creases);
  const std::vector<unsigned char>* edges = &*o.crease_edges;
  const auto map = boost::make_function_property_map<Mesh::Edge_index, bool>(
      [edges](Mesh::Edge_index e) { return (*edges)[std::size_t(e)] != 0; });
  return more(creases.edge_is_constrained_map(map).relax_constraints(true));
}
template <class F> auto with_crease_parameters(const Options& o, const F& f) {
  return with_parameters(o, std::function<bool(double)>(), false, f);
}

// The `count` worst faces of `smoothed` (same connectivity as `original`), with
// what holds each back: fixed vertices, vertices that did not move, folds of the
// input (a small dihedral angle).
void print_worst_faces(const Mesh& original, const Mesh& smoothed, unsigned int count, const Options& o) {
  std::map<Mesh::Vertex_index, PMP::ILSA_vertex_type> types;
  with_crease_parameters(o, [&](const auto& np) {
    return PMP::classify_vertices_ilsa(original, boost::make_assoc_property_map(types), np);
  });
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

// The crease edges of --sharp-edges (a file of vertex index pairs) or
// --detect-sharp-edges (CGAL's detect_sharp_edges()), one flag per edge of `mesh`.
std::vector<unsigned char> crease_edges(const Options& o, Mesh& mesh) {
  std::vector<unsigned char> crease(num_edges(mesh), 0);
  if (o.detect_sharp_edges) {
    auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:ilsa_detected_sharp", false).first;
    PMP::detect_sharp_edges(mesh, *o.detect_sharp_edges, sharp);
    for (auto e : edges(mesh)) crease[std::size_t(e)] = sharp[e] ? 1 : 0;
    mesh.remove_property_map(sharp);
    return crease;
  }
  std::ifstream in(o.sharp_edges_file);
  if (!in) throw std::runtime_error("--sharp-edges: cannot read '" + o.sharp_edges_file + "'");
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    std::istringstream fields(line);
    double a = 0, b = 0;
    std::string rest;
    if (!(fields >> a)) continue; // a blank or comment line
    const std::string where = "--sharp-edges: '" + o.sharp_edges_file + "' line " + std::to_string(number);
    if (!(fields >> b) || (fields >> rest))
      throw std::runtime_error(where + ": expected two vertex indices, got '" + line + "'");
    const double n = double(num_vertices(mesh));
    for (double i : {a, b})
      if (!(i >= 0 && i < n && i == std::floor(i))) {
        std::ostringstream index;
        index << i;
        throw std::runtime_error(where + ": no vertex " + index.str() + " (the input has " +
                                 std::to_string(num_vertices(mesh)) + ", numbered from 0)");
      }
    const auto h = halfedge(Mesh::Vertex_index(Mesh::size_type(a)), Mesh::Vertex_index(Mesh::size_type(b)), mesh);
    if (!h.second)
      throw std::runtime_error(where + ": vertices " + std::to_string(std::size_t(a)) + " and " +
                               std::to_string(std::size_t(b)) + " share no edge");
    crease[std::size_t(edge(h.first, mesh))] = 1;
  }
  return crease;
}

// The library checks its parameters before it reads the mesh: an empty mesh
// tests the flags' values before the input is read and anything printed.
void check_parameters(const Options& o) {
  Mesh empty;
  try {
    with_parameters(o, std::function<bool(double)>(), true,
                    [&](const auto& np) { return PMP::smooth_surface_mesh_ilsa(empty, np); });
  } catch (const PMP::ILSA_error& e) {
    throw std::runtime_error(in_flag_terms(e.what()));
  }
}

int run(Options o) {
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
  if (!o.sharp_edges_file.empty() || o.detect_sharp_edges) {
    o.crease_edges = crease_edges(o, mesh);
    std::cout << "crease edges: " << std::count(o.crease_edges->begin(), o.crease_edges->end(), 1) << " from "
              << (o.detect_sharp_edges ? "detect_sharp_edges() at " + std::to_string(*o.detect_sharp_edges) + " deg"
                                       : "'" + o.sharp_edges_file + "'")
              << "\n";
  }
  print_quality("before", PMP::mesh_quality_ilsa(mesh));

  const Mesh original = mesh;
  const unsigned int total = o.iterations;
  const bool progress = o.progress.value_or(isatty(fileno(stderr)) != 0);
  const std::function<bool(double)> show_progress = [&](double advancement) {
    std::cerr << "\rILSA iteration " << std::lround(advancement * total) << " of at most " << total << std::flush;
    return true;
  };
  const auto start = std::chrono::steady_clock::now();
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
    s = with_parameters(o, progress ? show_progress : std::function<bool(double)>(), true, smooth);
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
  const PMP::ILSA_fidelity_summary f = with_crease_parameters(o, [&](const auto& np) {
    return PMP::mesh_fidelity_ilsa(original, mesh, np.ilsa_compute_hausdorff_distance(full));
  });
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
    with_crease_parameters(o, [&](const auto& np) {
      return PMP::classify_vertices_ilsa(original, boost::make_assoc_property_map(types), np);
    });
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
