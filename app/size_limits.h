// How much work a size λ means for a model, known before any work is done, so that a size far
// too small for the model is refused at once with a message instead of ending at a cap minutes
// (or gigabytes) later.
//  - Protection (§2): a ball of radius at most λ covers at most 2λ of a curve, so the curves need
//    at least (total curve length) / 2λ balls; more than protect's max_balls cannot succeed.
//  - Refinement (§3): with facet_size λ alone the output has 0.66 A / λ² vertices for surface
//    area A on every libcgal-demo model (fandisk, part, anchor, joint, elephant at 0.5%); 1.1 to
//    1.4 KB of memory per vertex at the peak of `delpsc mesh`, since the mesher is freed before
//    the checks and the distances to the input (session 25: the cube at 0.1%, 1,101,956 vertices,
//    1.20 GB; hand at 0.5%, 237,157 vertices, 314 MB; BENCHMARKS.md, "Session 25").
#pragma once

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <delpsc/protect/complex.h>

#include "command.h"

namespace delpsc::app {

/// Output vertices per unit area at facet_size 1, measured (see above): expected vertices are
/// kVertexDensity A / λ².
inline constexpr double kVertexDensity = 0.66;
/// Protecting balls per unit of curve length at edge size 1: Protect's balls at radius λ number
/// about 1.3 length / λ (the unit cube: 450 at λ = 0.0346, 1,745 at 0.00866).
inline constexpr double kBallsPerLength = 1.3;

/// Expected output vertices for facet_size λ (see above), plus the extra protecting balls of an
/// edge size (the largest ball radius) below λ. O(triangles + curves).
inline double expected_vertices(const protect::Complex& complex, double lambda, double edge_size) {
  double area = 0;
  for (const auto& t : complex.triangles) {
    const Vec3& a = complex.vertices[t[0]];
    area += 0.5 * (complex.vertices[t[1]] - a).cross(complex.vertices[t[2]] - a).norm();
  }
  double extra_balls = 0;  // an --edge-size below λ: the balls beyond those λ itself makes
  if (edge_size < lambda) {
    double length = 0;
    for (const protect::Curve& c : complex.curves) length += c.length;
    extra_balls = kBallsPerLength * length * (1 / edge_size - 1 / lambda);
  }
  return kVertexDensity * area / (lambda * lambda) + extra_balls;
}

/// The sample spacing of the report's distances to the input (refine/approximation_error.h),
/// from λ and expected_vertices(): λ/2, but no finer than about 8 samples a vertex of the output
/// (at least 1,000 vertices' worth). A run at λ/2 takes ~A / (λ/2)² = 4 / kVertexDensity ≈ 6
/// samples an expected vertex, so every run that reaches 3/4 of its expected count keeps λ/2
/// (the libcgal-demo models reach 0.87 to 60 times it at 2%). A run that --max-vertices stopped
/// far short of its size would otherwise sample the input at a spacing it never reached:
/// sphere.off at --size 0.01% with --max-vertices 50 ran ~10^9 samples, at 1e-10 it ran out of
/// memory; and each sample is slow against the long slivers of such a mesh (~50 µs a sample,
/// against ~1 µs on a finished one). hausdorff_spacing reports the spacing used. A run
/// --max-seconds stopped passes 1 sample a vertex: the limit was about time.
inline double approximation_spacing(double lambda, double expected, std::size_t output_vertices,
                                    double samples_per_vertex = 8) {
  const double samples_at_half = 4 / kVertexDensity * expected;
  const double most_samples = samples_per_vertex * std::max(static_cast<double>(output_vertices), 1000.0);
  return lambda / 2 * std::max(1.0, std::sqrt(samples_at_half / most_samples));
}

/// Peak memory of `delpsc mesh` per output vertex, rounded up (measured 1.1-1.4 KB, see above).
inline constexpr double kMeshBytesPerVertex = 1.4e3;

/// The memory this process may use, in bytes: the machine's physical memory (POSIX sysconf; 16 GB
/// if it cannot tell), or less where a limit says so - the address-space limit (`ulimit -v`) and
/// a cgroup's memory.max (a container, a CI job). A size the machine held but the limit did not
/// ran until the allocator failed (fandisk at 0.03% under `ulimit -v 8000000`: 4.5 GB, then out
/// of memory) instead of being refused up front.
inline double usable_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  double bytes = pages > 0 && page > 0 ? double(pages) * double(page) : 16e9;
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    bytes = std::min(bytes, static_cast<double>(limit.rlim_cur));
  if (std::FILE* f = std::fopen("/sys/fs/cgroup/memory.max", "r")) {  // "max" when unlimited
    double cgroup = 0;
    if (std::fscanf(f, "%lf", &cgroup) == 1 && cgroup > 0) bytes = std::min(bytes, cgroup);
    std::fclose(f);
  }
  return bytes;
}

/// The most vertices a run may reach: what fits in 80% of the memory it may use. Past
/// that the system would kill the process (or swap for hours) instead of our cap ending it
/// with a message and the mesh reached.
inline double vertices_fitting_in_memory() { return 0.8 * usable_memory_bytes() / kMeshBytesPerVertex; }

/// Refused without an explicit --max-vertices: ten million (about 15 GB while meshing), fewer on
/// a machine whose memory holds fewer.
inline double most_expected_vertices() { return std::min(1e7, vertices_fitting_in_memory()); }

/// The cap on vertices when --max-vertices is not given: 50 times the expected count, at least
/// two million (the 1° wedge at 0.5% needs 438,000), at most twenty million and what fits in
/// memory (a 24 GB machine: 10.7 million).
inline std::size_t automatic_vertex_cap(double expected) {
  const double most = std::min(2e7, vertices_fitting_in_memory());
  return static_cast<std::size_t>(std::clamp(50 * expected, std::min(2e6, most), most));
}

/// Bad-input exit when the curves alone need more than `max_balls` balls at λ.
inline void reject_size_for_balls(const protect::Complex& complex, double lambda, std::size_t max_balls,
                                  const std::string& size_text, const char* option = "--size") {
  double length = 0;
  for (const protect::Curve& c : complex.curves) length += c.length;
  const double least = length / (2 * lambda);
  if (least <= static_cast<double>(max_balls)) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "%s %s is too small for this model: its feature curves (%.6g long in all) need at least %.3g "
                "protecting balls, more than the cap of %zu; choose a larger size",
                option, size_text.c_str(), length, least, max_balls);
  throw Failure{kBadInput, message};
}

/// Bad-input exit when meshing at λ would need more than most_expected_vertices() and the user
/// did not ask for a vertex cap.
inline void reject_size_for_vertices(double expected, const std::string& size_text) {
  if (expected <= most_expected_vertices()) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "--size %s is too small for this model: about %.3g vertices (%.3g GB of memory while meshing); "
                "choose a larger size, or give --max-vertices to try anyway",
                size_text.c_str(), expected, expected * kMeshBytesPerVertex * 1e-9);
  throw Failure{kBadInput, message};
}

/// The smallest --edge-size, as a fraction of --size. Balls that much finer than the sample
/// between them make the triangulation of a straight curve's ball centres against the sparse
/// surface sample nearly quadratic in size: fandisk at --size 4% with edge sizes of 1/32, 1/64,
/// 1/160 and 1/400 of it took 0.46, 1.35, 6.75 and 55 s (9,826 to 98,885 vertices; 1.8 GB at
/// 1/400), the cube and joint at 1/64 0.30 and 0.59 s.
inline constexpr double kSmallestEdgeSizeRatio = 1.0 / 64;

/// Bad-input exit for an --edge-size below kSmallestEdgeSizeRatio times λ.
inline void reject_edge_size(double edge_size, double lambda, const std::string& edge_text, const std::string& size_text) {
  if (edge_size >= kSmallestEdgeSizeRatio * lambda) return;
  throw Failure{kBadInput, "--edge-size " + edge_text + " is below 1/64 of --size " + size_text +
                               ": curves that much finer than the surface around them make the triangulation "
                               "nearly quadratic in size (minutes and gigabytes); choose a --size at most 64 times "
                               "the edge size"};
}

/// Bad-input exit when facet_distance is below λ / 10^4 and the user did not ask for a vertex
/// cap: on a surface of curvature radius R a triangle of circumradius r stands about r² / 2R off
/// it, so the distance d asks for r ≈ sqrt(2 R d); at d = λ / 10^4 and R = 20 λ that is λ / 16,
/// some 250 times the vertices λ alone gives - past the automatic cap, after minutes.
inline void reject_facet_distance(double distance, double lambda, const std::string& text, bool capped) {
  if (capped || distance >= 1e-4 * lambda) return;
  throw Failure{kBadInput, "--facet-distance " + text +
                               " is below 1/10000 of --size: on any curved part that asks for hundreds of times "
                               "the vertices the size alone needs; choose a larger distance, or give "
                               "--max-vertices to try anyway"};
}

/// Peak memory of `delpsc triangulate` per point, rounded up (uniform:1000000: 297 MB RSS).
inline constexpr double kTriangulationBytesPerPoint = 320;

/// Bad-input exit when triangulating n points would not fit in 80% of the memory this process may use.
inline void reject_points_beyond_memory(std::size_t n) {
  const double need = double(n) * kTriangulationBytesPerPoint;
  if (need <= 0.8 * usable_memory_bytes()) return;
  char message[320];
  std::snprintf(message, sizeof message,
                "%zu points need about %.3g GB to triangulate, more than the memory this process may use (%.3g GB) allows; "
                "use fewer points",
                n, need * 1e-9, usable_memory_bytes() * 1e-9);
  throw Failure{kBadInput, message};
}

}  // namespace delpsc::app
