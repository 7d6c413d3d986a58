// The parts of `delpsc mesh`'s final report that are more than one number: phase times, the
// shape of the triangles, where the disk condition fails, and each patch's topology against the
// input's - the 2-manifold of G1 and the Euler characteristic and boundary loops that G2 (§4,
// Theorem 4.4: the mesh is homeomorphic to the complex for a small enough λ) makes equal. Each
// adds summary key=value lines (report.h) and a structured member of the JSON report.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <delpsc/protect/complex.h>
#include <delpsc/refine/complex_topology.h>
#include <delpsc/refine/disk_condition.h>
#include <delpsc/refine/quality_summary.h>
#include <delpsc/refine/skeleton_check.h>

#include "command.h"

namespace delpsc::app {

/// Seconds spent in each phase, in the order they ran (JSON "phases", an object).
using PhaseTimes = std::vector<std::pair<std::string, double>>;
void report_phases(const PhaseTimes& phases);

/// Lines max_angle and radius_edge_ratio (the largest); JSON "quality": every figure of
/// QualitySummary and the histogram of smallest angles.
void report_quality(const refine::QualitySummary& quality);

/// JSON "disk_condition_failures": how many vertices fail it, by kind (D1..D4). No line: the
/// line disk_condition already says "ok" or the count.
void report_disk_failures(const std::vector<refine::DiskFailure>& failures);

struct PatchTopology {
  std::uint32_t patch = 0;
  std::size_t triangles = 0;
  bool manifold = false;
  int euler = 0, input_euler = 0;
  std::size_t boundary_loops = 0, input_boundary_loops = 0;
  bool matches_input() const {
    return manifold && euler == input_euler && boundary_loops == input_boundary_loops;
  }
};

/// One entry per patch of `input`, from the skeleton check of the output (same patch ids); the
/// output's figures are those of the patch cut open along its slits, as the input's are.
std::vector<PatchTopology> compare_topology(const refine::SkeletonReport& output, const protect::Complex& input);

/// Lines patches_manifold and patches_topology_ok (true when every patch is a manifold /
/// matches the input); JSON "patch_topology", one object per patch; with -v one line per patch
/// on stderr.
void report_topology(const std::vector<PatchTopology>& patches, const GlobalOptions& g);

/// G2 for the whole output (Theorem 4.3: |∪ Skl^i| homeomorphic to |D| at a fine enough λ),
/// which the per-patch figures cannot see (a fin detached from its box, sheets of a book glued
/// to the wrong page): line topology_ok (true when every figure of refine::ComplexTopology
/// agrees; a necessary condition only), JSON "topology" with both sides' figures and the
/// differences, which are also printed on stderr unless -q.
void report_complex_topology(const refine::ComplexTopology& output, const refine::ComplexTopology& input,
                             const GlobalOptions& g);

}  // namespace delpsc::app
