// Step 5 of build_complex: corners, and curves as the feature polylines between them.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "complex_build.h"

namespace delpsc::protect::detail {

namespace {

std::uint32_t other_end(const Complex& complex, std::uint32_t e, std::uint32_t v) {
  return complex.edges[e][0] == v ? complex.edges[e][1] : complex.edges[e][0];
}

kernel::LargeVector<std::uint32_t> patches_along(const Complex& complex, std::uint32_t e) {
  kernel::LargeVector<std::uint32_t> p;
  for (const auto t : complex.edge_triangle_ids(e)) p.push_back(complex.triangle_patch[t]);
  std::sort(p.begin(), p.end());
  return p;
}

}  // namespace

void find_corners_and_curves(Complex& complex, const VertexFans& fans) {
  const auto n_vertices = static_cast<std::uint32_t>(complex.vertices.size());
  const auto n_edges = static_cast<std::uint32_t>(complex.edges.size());

  // Feature edges around each vertex (CSR, increasing edge order).
  kernel::LargeVector<std::uint32_t> degree(n_vertices, 0);
  for (std::uint32_t e = 0; e < n_edges; ++e)
    if (complex.edge_feature[e] != 0) {
      ++degree[complex.edges[e][0]];
      ++degree[complex.edges[e][1]];
    }
  const kernel::LargeVector<std::uint32_t> start = offsets_from_counts(degree);
  kernel::LargeVector<std::uint32_t> around(start.back());
  {
    kernel::LargeVector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t e = 0; e < n_edges; ++e)
      if (complex.edge_feature[e] != 0) {
        around[fill[complex.edges[e][0]]++] = e;
        around[fill[complex.edges[e][1]]++] = e;
      }
  }

  // Corners by the four local rules (complex.h), in vertex order.
  const double corner_angle = complex.options.corner_angle_degrees;
  const bool turn_rule = corner_angle < 180;
  const double cos_turn = std::cos(corner_angle * std::numbers::pi / 180);
  complex.vertex_corner.assign(n_vertices, kNoIndex);
  complex.corner_vertex.clear();
  complex.corner_flags.clear();
  auto add_corner = [&](std::uint32_t v, std::uint8_t flags) {
    complex.vertex_corner[v] = static_cast<std::uint32_t>(complex.corner_vertex.size());
    complex.corner_vertex.push_back(v);
    complex.corner_flags.push_back(flags);
  };
  // The triangles' angles at each vertex, summed (kCornerApex). First a lower bound without
  // square roots or arc tangents - sin² θ <= θ, and π/2 for an obtuse angle - which rules out
  // nearly every vertex (a smooth one sums to ~2π); then the exact sums for the few left. With
  // atan2 for every corner this pass was 0.8 of build_complex's 2.5 ms on fandisk.
  const double apex_sum = kApexAngleDegrees * std::numbers::pi / 180;
  const auto corner_vectors = [&](const std::array<std::uint32_t, 3>& t, int k) {
    const Vec3& p = complex.vertices[t[k]];
    return std::pair{Vec3(complex.vertices[t[(k + 1) % 3]] - p), Vec3(complex.vertices[t[(k + 2) % 3]] - p)};
  };
  kernel::LargeVector<double> angle_sum(n_vertices, 0.0);
  for (const auto& t : complex.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto [a, b] = corner_vectors(t, k);
      const double dot = a.dot(b), lengths = a.squaredNorm() * b.squaredNorm();
      angle_sum[t[k]] += dot < 0 ? std::numbers::pi / 2 : lengths > 0 ? a.cross(b).squaredNorm() / lengths : 0;
    }
  bool any_candidate = false;
  for (std::uint32_t v = 0; v < n_vertices; ++v) {
    const bool candidate = degree[v] == 0 && fans.vertex_sheets[v] == 1 && angle_sum[v] < apex_sum;
    angle_sum[v] = candidate ? 0 : HUGE_VAL;  // from here: the exact sum, or HUGE_VAL for no tip
    any_candidate |= candidate;
  }
  if (any_candidate)
    for (const auto& t : complex.triangles)
      for (int k = 0; k < 3; ++k)
        if (angle_sum[t[k]] < HUGE_VAL) {
          const auto [a, b] = corner_vectors(t, k);
          angle_sum[t[k]] += std::atan2(a.cross(b).norm(), a.dot(b));
        }
  for (std::uint32_t v = 0; v < n_vertices; ++v) {
    std::uint8_t flags = 0;
    if (angle_sum[v] > 0 && angle_sum[v] < apex_sum) flags |= kCornerApex;  // candidates only: HUGE_VAL else
    if (degree[v] != 0 && degree[v] != 2) flags |= kCornerDegree;
    if (degree[v] == 2) {
      const std::uint32_t e1 = around[start[v]], e2 = around[start[v] + 1];
      const Vec3& p = complex.vertices[v];
      const Vec3 in = p - complex.vertices[other_end(complex, e1, v)];
      const Vec3 out = complex.vertices[other_end(complex, e2, v)] - p;
      // Turning angle > threshold  <=>  cos(turn) < cos(threshold).
      if (turn_rule && in.dot(out) < cos_turn * in.norm() * out.norm()) flags |= kCornerTurn;
      if (patches_along(complex, e1) != patches_along(complex, e2)) flags |= kCornerIncidence;
    }
    if (fans.vertex_sheets[v] > 1) flags |= kCornerSheets;
    if (flags != 0) add_corner(v, flags);
  }

  // Curves: walk from each corner along each of its unvisited feature edges until a corner.
  // Every vertex met in between has feature degree 2, so the walk has one way to go on.
  complex.edge_curve.assign(n_edges, kNoIndex);
  complex.curves.clear();
  complex.curve_vertices.clear();
  complex.curve_arclength.clear();
  auto trace = [&](std::uint32_t corner, std::uint32_t e) {
    Curve curve;
    const auto id = static_cast<std::uint32_t>(complex.curves.size());
    curve.first = static_cast<std::uint32_t>(complex.curve_vertices.size());
    curve.start_corner = corner;
    std::uint32_t v = complex.corner_vertex[corner];
    double s = 0;
    complex.curve_vertices.push_back(v);
    complex.curve_arclength.push_back(0);
    while (true) {
      complex.edge_curve[e] = id;
      const std::uint32_t w = other_end(complex, e, v);
      s += (complex.vertices[w] - complex.vertices[v]).norm();
      complex.curve_vertices.push_back(w);
      complex.curve_arclength.push_back(s);
      v = w;
      if (complex.vertex_corner[v] != kNoIndex) break;
      e = around[start[v]] == e ? around[start[v] + 1] : around[start[v]];
    }
    curve.end_corner = complex.vertex_corner[v];
    curve.closed = curve.end_corner == curve.start_corner;
    curve.count = static_cast<std::uint32_t>(complex.curve_vertices.size()) - curve.first;
    curve.length = s;
    complex.curves.push_back(curve);
  };
  auto trace_all_from = [&](std::uint32_t corner) {
    const std::uint32_t v = complex.corner_vertex[corner];
    for (std::uint32_t i = start[v]; i < start[v + 1]; ++i)
      if (complex.edge_curve[around[i]] == kNoIndex) trace(corner, around[i]);
  };
  const auto rule_corners = static_cast<std::uint32_t>(complex.corner_vertex.size());
  for (std::uint32_t k = 0; k < rule_corners; ++k) trace_all_from(k);

  // What is left are loops of degree-2 vertices with no corner: put one at the loop's smallest
  // vertex index (deterministic, independent of the edge order) and trace the closed curve.
  for (std::uint32_t e = 0; e < n_edges; ++e) {
    if (complex.edge_feature[e] == 0 || complex.edge_curve[e] != kNoIndex) continue;
    std::uint32_t v = complex.edges[e][0], lowest = v, edge = e;
    do {
      v = other_end(complex, edge, v);
      lowest = std::min(lowest, v);
      edge = around[start[v]] == edge ? around[start[v] + 1] : around[start[v]];
    } while (v != complex.edges[e][0]);
    add_corner(lowest, kCornerLoop);
    trace_all_from(static_cast<std::uint32_t>(complex.corner_vertex.size() - 1));
  }
}

}  // namespace delpsc::protect::detail
