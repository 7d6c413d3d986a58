// Issue 6's benchmark: end-to-end surface meshing time of delpsc next to CGAL Mesh_3 on the
// libcgal-demo models at h = 2%, 1% and 0.5% of the bounding-box diagonal, with both output
// vertex counts, and whether each output meets guarantee G1 (refine::check_skeleton).
//
// delpsc: read -> build_complex (feature angle 60) -> PolygonDomain -> protect::protect(λ = h) ->
// Mesher(facet_size = h) -> output(), as `delpsc mesh --size h` does; with --delpsc-criteria cgal
// also CGAL's two other facet criteria, facet_distance = h/10 and facet_angle = 25.
// CGAL: read -> Polyhedral_mesh_domain_with_features_3 -> detect_features(60) -> make_mesh_3
// with the criteria of cgal_surface_mesher.h -> the facets and feature edges in the complex.
// Each run is a forked child with a wall-clock cap (capped_run.h); times are medians over the
// repetitions, CPU time measured inside the child, G1 checked (outside the timing) on the first one.
// CGAL's output is put into our patch and curve ids first (relabel_to_domain.h).
//
// With --match-vertices yes, delpsc's h is fitted (two untimed runs after CGAL's first) so that
// its output has CGAL's vertex count: the time ratio is then the speed-up at equal output vertex
// count itself, with no assumption that either mesher scales linearly.
//
// Usage: cgal_bench_mesh_vs_cgal [--data DIR] [--models a,b,...] [--sizes 2,1,0.5]
//                                [--repetitions N] [--cap SECONDS] [--delpsc-criteria size|cgal]
//                                [--match-vertices yes|no]
// Prints a Markdown table on stdout (one row per model and size), progress on stderr.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <delpsc/io/read_model.h>
#include <delpsc/protect/complex.h>
#include <delpsc/protect/protect.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/protected_balls.h>
#include <delpsc/refine/skeleton_check.h>

#include "capped_run.h"
#include "cgal_surface_mesher.h"
#include "relabel_to_domain.h"

namespace {

using namespace delpsc;
using bench::RunEnd;

// CPU time of this process: both meshers are single-threaded, and on a shared machine the CPU
// time is what a busy neighbour inflates least.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// What one run sends back to the parent (trivially copyable: it crosses a pipe).
struct Measured {
  std::size_t vertices = 0, triangles = 0;
  double seconds = 0;         ///< end to end, reading the file included; CPU time
  double seconds_refine = 0;  ///< delpsc: Mesh2Complex and output(); CGAL: 0
  int g1 = -1;                ///< 1 holds, 0 fails, -1 not checked
  char note[200] = "";        ///< the first G1 problem, or why the run failed
};

void set_note(Measured& m, const std::string& s) {
  std::snprintf(m.note, sizeof m.note, "%s", s.c_str());
}

// How far a vertex may be from the model, for both meshers: 1e-6 of the diagonal. CGAL puts a few
// curve vertices up to ~3e-8 diagonals off the model (rounding in its polyline parametrisation,
// not a topological defect) where `delpsc mesh --check` accepts 1e-9 for its own vertices.
double g1_tolerance(const refine::PolygonDomain& domain) {
  const kernel::Box3 box = domain.bounding_box();
  return 1e-6 * (box.hi - box.lo).norm();
}

Measured measure_delpsc(const std::string& path, double h, bool cgal_criteria, bool check) {
  Measured m;
  try {
    const double t0 = cpu_seconds();
    const io::ReadResult model = io::read_model(path);
    const refine::PolygonDomain domain(protect::build_complex(model.soup));
    protect::BallSet ball_set = protect::protect(domain.complex(), h);
    const double t_refine = cpu_seconds();
    refine::ProtectedBalls balls(ball_set);
    refine::MesherOptions options;
    options.facet_size = h;
    if (cgal_criteria) options.facet_distance = h / 10, options.facet_angle = 25;
    refine::Mesher mesher(domain, balls, options);
    mesher.run();
    const io::SurfaceMesh mesh = mesher.output();
    m.seconds = cpu_seconds() - t0;
    m.seconds_refine = cpu_seconds() - t_refine;
    m.vertices = mesh.vertices.size();
    m.triangles = mesh.triangles.size();
    if (check) {
      const std::size_t failing = mesher.failing_vertices().size();
      const refine::SkeletonReport report = refine::check_skeleton(mesh, domain, g1_tolerance(domain));
      m.g1 = report.ok() && failing == 0 && !mesher.stats().stuck ? 1 : 0;
      if (!report.ok()) set_note(m, report.problems.front());
      else if (failing != 0) set_note(m, "disk condition fails at " + std::to_string(failing) + " vertices");
      else if (mesher.stats().stuck) set_note(m, mesher.stats().message);
    }
  } catch (const std::exception& e) {
    set_note(m, e.what());
    m.g1 = 0;
  }
  return m;
}

// How far the mesh's farthest vertex is from the domain, relative to the diagonal: tells a
// vertex off the surface from a rounding error when G1 reports one.
std::string farthest_vertex(const io::SurfaceMesh& mesh, const refine::PolygonDomain& domain) {
  double worst = 0;
  for (const Vec3& v : mesh.vertices)
    if (const auto c = domain.closest_point(v)) worst = std::max(worst, c->squared_distance);
  char buf[96];
  std::snprintf(buf, sizeof buf, "farthest vertex %.2g diagonals off", std::sqrt(worst) / (g1_tolerance(domain) * 1e6));
  return buf;
}

Measured measure_cgal(const std::string& path, double h, bool check, const io::TriangleSoup& soup,
                      const refine::PolygonDomain& domain) {
  Measured m;
  try {
    const double t0 = cpu_seconds();
    // Stopped before the input faces are copied: only the G1 check below needs them.
    bench::CgalSurfaceMesh out = bench::cgal_mesh_surface(path, h, [&] { m.seconds = cpu_seconds() - t0; });
    m.vertices = out.mesh.vertices.size();
    m.triangles = out.mesh.triangles.size();
    if (check) {
      if (const auto why = bench::relabel_to_domain(out.mesh, out.input_faces, soup, domain)) {
        set_note(m, "not checked: " + *why);
      } else {
        const refine::SkeletonReport report = refine::check_skeleton(out.mesh, domain, g1_tolerance(domain));
        m.g1 = report.ok() ? 1 : 0;
        if (!report.ok())
          set_note(m, report.problems.front() + " (" + std::to_string(report.problems.size()) + " problems; " +
                          farthest_vertex(out.mesh, domain) + ")");
      }
    }
  } catch (const std::exception& e) {
    set_note(m, e.what());
    m.g1 = 0;
  }
  return m;
}

struct Options {
  std::filesystem::path data = std::filesystem::path(__FILE__).parent_path() / "../../data/cgal-demo";
  std::vector<std::string> models = {"fandisk", "part", "anchor", "joint", "cube", "elephant", "sphere"};
  std::vector<double> sizes = {2, 1, 0.5};  // percent of the diagonal
  int repetitions = 3;
  double cap = 60;  // seconds per run
  bool cgal_criteria = false;  // delpsc also with facet_distance and facet_angle
  bool match_vertices = false;  // delpsc at the size that gives CGAL's vertex count
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return false;
    const std::string v = argv[++i];
    try {
      if (a == "--data") o.data = v;
      else if (a == "--models") o.models = split(v);
      else if (a == "--sizes") {
        o.sizes.clear();
        for (const auto& s : split(v)) o.sizes.push_back(std::stod(s));
      } else if (a == "--repetitions") o.repetitions = std::max(1, std::stoi(v));
      else if (a == "--cap") o.cap = std::stod(v);
      else if (a == "--delpsc-criteria" && (v == "size" || v == "cgal")) o.cgal_criteria = v == "cgal";
      else if (a == "--match-vertices" && (v == "yes" || v == "no")) o.match_vertices = v == "yes";
      else return false;
    } catch (const std::exception&) {
      return false;
    }
  }
  return !o.models.empty() && !o.sizes.empty() && o.cap > 0 &&
         std::all_of(o.sizes.begin(), o.sizes.end(), [](double s) { return s > 0; });
}

/// The repetitions of one mesher on one model and size.
struct Series {
  std::vector<Measured> runs;
  RunEnd first_end = RunEnd::kDone;  // how the first run ended
  bool skipped = false;               // not run: a larger size already hit the cap
  double median_seconds() const {
    std::vector<double> t;
    for (const Measured& m : runs) t.push_back(m.seconds);
    std::sort(t.begin(), t.end());
    return t.empty() ? 0 : t[t.size() / 2];
  }
};
std::string g1_cell(const Series& s) {
  if (s.runs.empty()) return "—";
  const Measured& m = s.runs.front();
  return m.g1 == 1 ? "yes" : m.g1 == 0 ? std::string("**no**: ") + m.note : std::string("? ") + m.note;
}

std::string time_cell(const Series& s, double cap) {
  char buf[64];
  if (s.skipped) return "skipped";
  if (s.runs.empty()) {
    if (s.first_end == RunEnd::kTimedOut) std::snprintf(buf, sizeof buf, "> %g s (cap)", cap);
    else std::snprintf(buf, sizeof buf, "crashed");
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.3g s%s", s.median_seconds(), s.runs.size() == 1 ? " (1 run)" : "");
  return buf;
}

std::string count(std::size_t n) {
  std::string s = std::to_string(n);
  for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(static_cast<std::size_t>(i), ",");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr,
                 "usage: %s [--data DIR] [--models a,b,...] [--sizes 2,1,0.5] [--repetitions N] [--cap SECONDS] "
                 "[--delpsc-criteria size|cgal] [--match-vertices yes|no]\n",
                 argv[0]);
    return 2;
  }
  std::printf("delpsc criteria: facet_size = h%s%s\n\n", o.cgal_criteria ? ", facet_distance = h/10, facet_angle = 25" : "",
              o.match_vertices ? "; delpsc's h chosen to give CGAL's vertex count (in brackets)" : "");
  std::printf("| model | h | delpsc vertices | delpsc time | of which refine | delpsc G1 | CGAL vertices | CGAL time "
              "| CGAL G1 | CGAL time / delpsc time | vertices/s, delpsc / CGAL |\n");
  std::printf("|---|---|---:|---:|---:|---|---:|---:|---|---:|---:|\n");
  std::vector<double> ratios;               // CGAL time / delpsc time, per row with both
  double total_ours = 0, total_cgal = 0;    // their medians summed over those rows
  for (const std::string& name : o.models) {
    const std::string path = (o.data / (name + ".off")).string();
    if (!std::filesystem::exists(path)) {
      std::fprintf(stderr, "%s: absent (scripts/get-cgal-data.sh %s fetches it)\n", path.c_str(), name.c_str());
      continue;
    }
    // Loaded once here for h and for checking CGAL's output; the timed runs read the file again.
    const io::ReadResult model = io::read_model(path);
    const refine::PolygonDomain domain(protect::build_complex(model.soup));
    // CGAL's output is judged against CGAL's own corners: detect_features ends a polyline at a
    // vertex of two feature edges only where they meet at an acute angle (Mesh_3's Angle_tester:
    // a turn of more than 90 degrees), where our complex puts a corner from a 60-degree turn.
    // Against our complex, a CGAL edge across a turn of 60-90 degrees joins two of our curves and
    // fails G1 at a corner CGAL never promised (the elephant's, BENCHMARKS.md session 29). The
    // patches are the same either way.
    protect::ComplexOptions cgal_corners;
    cgal_corners.corner_angle_degrees = 90;
    const refine::PolygonDomain cgal_domain(protect::build_complex(model.soup, cgal_corners));
    const kernel::Box3 box = domain.bounding_box();
    const double diagonal = (box.hi - box.lo).norm();
    bool ours_capped = false, cgal_capped = false;
    std::vector<double> sizes = o.sizes;
    std::sort(sizes.begin(), sizes.end(), std::greater<>());  // coarse first: a capped size skips the finer ones
    for (const double percent : sizes) {
      const double h = percent / 100 * diagonal;
      Series ours, cgal;
      ours.skipped = ours_capped, cgal.skipped = cgal_capped;
      double h_ours = h;  // --match-vertices: set after CGAL's first run
      for (int rep = 0; rep < o.repetitions; ++rep) {
        const bool check = rep == 0;
        // One run of each mesher in turn, so that a change of machine load hits both alike.
        auto one = [&](Series& s, bool& capped, auto&& measure) {
          if (s.skipped || capped || (rep > 0 && s.runs.size() < static_cast<std::size_t>(rep))) return;
          // A run longer than a third of the cap is not repeated: the whole table stays affordable.
          if (rep > 0 && s.runs.front().seconds > o.cap / 3) return;
          const auto run = bench::run_capped<Measured>(measure, o.cap);
          if (run.end == RunEnd::kDone) s.runs.push_back(run.result);
          else if (rep == 0) s.first_end = run.end, capped = run.end == RunEnd::kTimedOut;
        };
        const auto run_ours = [&] { one(ours, ours_capped, [&] { return measure_delpsc(path, h_ours, o.cgal_criteria, check); }); };
        if (o.match_vertices && rep == 0) {
          // CGAL first, then two untimed runs of ours to fit h to its vertex count (vertices go
          // as 1/h² away from the features; the second run corrects for them).
          one(cgal, cgal_capped, [&] { return measure_cgal(path, h, check, model.soup, cgal_domain); });
          for (int fit = 0; fit < 2 && !cgal.runs.empty() && !ours.skipped && !ours_capped; ++fit) {
            const auto trial = bench::run_capped<Measured>([&] { return measure_delpsc(path, h_ours, o.cgal_criteria, false); }, o.cap);
            if (trial.end != RunEnd::kDone || trial.result.vertices == 0) break;
            const double ratio = double(trial.result.vertices) / double(cgal.runs.front().vertices);
            h_ours *= std::clamp(std::sqrt(ratio), 0.5, 2.0);
          }
          run_ours();
        } else {
          run_ours();
          one(cgal, cgal_capped, [&] { return measure_cgal(path, h, check, model.soup, cgal_domain); });
        }
        std::fprintf(stderr, "%s %g%% repetition %d: delpsc %s, CGAL %s\n", name.c_str(), percent, rep + 1,
                     time_cell(ours, o.cap).c_str(), time_cell(cgal, o.cap).c_str());
      }
      char ratio[32] = "—", throughput[32] = "—", refine_share[32] = "—";
      if (!ours.runs.empty() && !cgal.runs.empty()) {
        const double to = ours.median_seconds(), tc = cgal.median_seconds();
        std::snprintf(ratio, sizeof ratio, "%.2f", tc / to);
        ratios.push_back(tc / to);
        total_ours += to, total_cgal += tc;
        std::snprintf(throughput, sizeof throughput, "%.2f",
                      (double(ours.runs.front().vertices) / to) / (double(cgal.runs.front().vertices) / tc));
      }
      if (!ours.runs.empty()) {
        std::vector<double> r;
        for (const Measured& m : ours.runs) r.push_back(m.seconds_refine);
        std::sort(r.begin(), r.end());
        std::snprintf(refine_share, sizeof refine_share, "%.3g s", r[r.size() / 2]);
      }
      char size_cell[48];
      if (o.match_vertices) std::snprintf(size_cell, sizeof size_cell, "%g%% (%.3g%%)", percent, 100 * h_ours / diagonal);
      else std::snprintf(size_cell, sizeof size_cell, "%g%%", percent);
      std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", name.c_str(), size_cell,
                  ours.runs.empty() ? "—" : count(ours.runs.front().vertices).c_str(), time_cell(ours, o.cap).c_str(),
                  refine_share, g1_cell(ours).c_str(),
                  cgal.runs.empty() ? "—" : count(cgal.runs.front().vertices).c_str(), time_cell(cgal, o.cap).c_str(),
                  g1_cell(cgal).c_str(), ratio, throughput);
      std::fflush(stdout);
    }
  }
  // The table's summary: the spread of the per-row ratios, and the whole suite's time.
  if (!ratios.empty()) {
    std::sort(ratios.begin(), ratios.end());
    const std::size_t n = ratios.size();
    const double median = n % 2 ? ratios[n / 2] : (ratios[n / 2 - 1] + ratios[n / 2]) / 2;
    const auto at_least_10 = std::count_if(ratios.begin(), ratios.end(), [](double r) { return r >= 10; });
    std::printf("\nCGAL time / delpsc time over %zu rows: %.2f to %.2f, median %.2f; %td rows at 10 or more; "
                "all rows' times summed: %.3g s against %.3g s, %.2f\n",
                n, ratios.front(), ratios.back(), median, at_least_10, total_cgal, total_ours, total_cgal / total_ours);
  }
  return 0;
}
