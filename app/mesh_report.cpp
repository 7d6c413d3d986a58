#include "mesh_report.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "json_writer.h"

namespace delpsc::app {

void report_phases(const PhaseTimes& phases) {
  JsonWriter json;
  json.begin_object();
  for (const auto& [name, seconds] : phases) json.key(name).value(seconds);
  final_report().add_json("phases", json.end_object().str());
}

void report_quality(const refine::QualitySummary& q) {
  report("max_angle", q.max_angle_degrees);
  report("radius_edge_ratio", q.max_radius_edge_ratio);
  JsonWriter json;
  json.begin_object()
      .key("triangles").value(q.triangles)
      .key("min_angle_degrees").value(q.min_angle_degrees)
      .key("max_angle_degrees").value(q.max_angle_degrees)
      .key("max_radius_edge_ratio").value(q.max_radius_edge_ratio)
      .key("mean_radius_edge_ratio").value(q.mean_radius_edge_ratio)
      .key("min_angle_histogram_degrees").begin_array();
  for (std::size_t k = 0; k < q.min_angle_histogram.size(); ++k)
    json.begin_object()
        .key("from").value(10 * k)
        .key("to").value(10 * (k + 1))
        .key("triangles").value(q.min_angle_histogram[k])
        .end_object();
  final_report().add_json("quality", json.end_array().end_object().str());
}

void report_disk_failures(const std::vector<refine::DiskFailure>& failures) {
  constexpr std::array kinds{refine::DiskFailure::d1, refine::DiskFailure::d2, refine::DiskFailure::d3,
                             refine::DiskFailure::d4};
  JsonWriter json;
  json.begin_object().key("vertices").value(failures.size());
  for (const auto kind : kinds)
    json.key(refine::to_string(kind)).value(static_cast<std::size_t>(std::count(failures.begin(), failures.end(), kind)));
  final_report().add_json("disk_condition_failures", json.end_object().str());
}

std::vector<PatchTopology> compare_topology(const refine::SkeletonReport& output, const protect::Complex& input) {
  std::vector<PatchTopology> patches;
  for (const refine::PatchSkeleton& s : output.patches) {
    if (s.patch >= input.patches.size()) continue;  // cannot happen: the same domain
    PatchTopology t;
    t.patch = s.patch;
    t.triangles = s.triangles;
    t.manifold = s.manifold && s.triangles > 0;
    // Cut open along slits: counted as the input's patches are (protect::Patch).
    t.euler = s.cut_euler;
    t.boundary_loops = s.cut_boundary_loops;
    t.input_euler = input.patches[s.patch].euler_characteristic;
    t.input_boundary_loops = input.patches[s.patch].boundary_loops;
    patches.push_back(t);
  }
  return patches;
}

void report_topology(const std::vector<PatchTopology>& patches, const GlobalOptions& g) {
  const auto all = [&](auto pred) { return std::all_of(patches.begin(), patches.end(), pred); };
  report("patches_manifold", all([](const PatchTopology& p) { return p.manifold; }));
  report("patches_topology_ok", all([](const PatchTopology& p) { return p.matches_input(); }));
  JsonWriter json;
  json.begin_array();
  for (const PatchTopology& p : patches) {
    json.begin_object()
        .key("patch").value(p.patch)
        .key("triangles").value(p.triangles)
        .key("manifold").value(p.manifold)
        .key("euler").value(p.euler)
        .key("input_euler").value(p.input_euler)
        .key("boundary_loops").value(p.boundary_loops)
        .key("input_boundary_loops").value(p.input_boundary_loops)
        .key("matches_input").value(p.matches_input())
        .end_object();
    if (g.verbosity > 0)
      std::fprintf(stderr, "delpsc: patch %u: %zu triangles, %s, euler %d (input %d), boundary loops %zu (input %zu)%s\n",
                   p.patch, p.triangles, p.manifold ? "manifold" : "NOT a manifold", p.euler, p.input_euler,
                   p.boundary_loops, p.input_boundary_loops, p.matches_input() ? "" : ": differs from the input");
  }
  final_report().add_json("patch_topology", json.end_array().str());
}

namespace {

void write_figures(JsonWriter& json, const refine::ComplexTopology& t) {
  json.begin_object()
      .key("vertices").value(t.vertices)
      .key("edges").value(t.edges)
      .key("triangles").value(t.triangles)
      .key("components").value(t.components)
      .key("euler").value(t.euler)
      .key("boundary_loops").value(t.boundary_loops)
      .key("singular_curves").value(t.singular_curves)
      .key("sheets").value(t.sheets)
      .key("non_orientable_sheets").value(t.non_orientable_sheets)
      .end_object();
}

}  // namespace

void report_complex_topology(const refine::ComplexTopology& output, const refine::ComplexTopology& input,
                             const GlobalOptions& g) {
  const std::vector<std::string> differences = refine::topology_differences(output, input);
  report("topology_ok", differences.empty());
  JsonWriter json;
  json.begin_object().key("output");
  write_figures(json, output);
  json.key("input");
  write_figures(json, input);
  json.key("differences").begin_array();
  for (const std::string& d : differences) json.value(d);
  json.end_array().key("matches_input").value(differences.empty());
  final_report().add_json("topology", json.end_object().str());
  if (g.quiet || differences.empty()) return;
  for (const std::string& d : differences) std::fprintf(stderr, "delpsc: topology: %s\n", d.c_str());
  // What to do about it: G2 (Theorem 4.3) holds once refinement ends at a size below the
  // model's local feature size; a tube or gap thinner than the size is merged or lost.
  std::fprintf(stderr,
               "delpsc: topology: DelPSC guarantees the input's topology only when refinement ends at a size "
               "below the model's thinnest parts and narrowest gaps (Dey & Levine, Theorem 4.3); a smaller --size "
               "resolves them\n");
}

}  // namespace delpsc::app
