// Internal to protect/: the steps of build_complex (complex.h), one file each, run in this order
// on a Complex being filled. Each step documents what it reads and what it writes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "complex.h"

namespace delpsc::protect::detail {

/// Reads the soup; writes vertices, triangles, triangle_source, cleanup. Returns the canonical
/// (welded) index of every soup vertex. (triangle_cleanup.cpp)
kernel::LargeVector<std::uint32_t> clean_triangles(const io::TriangleSoup& soup, Complex& complex);

/// Reads triangles; writes edges, triangle_edges, edge_triangle_offsets, edge_triangles.
/// (edge_table.cpp)
void build_edge_table(Complex& complex);

/// A triangle whose largest angle is within this many radians (0.0057°) of 180° is a "flat cap":
/// a numerical accident, not a shape (triangle_cleanup.cpp says where the value comes from).
inline constexpr double kFlatCapRadians = 1e-4;

/// The vertex (0, 1, 2) opposite the longest edge when p is a flat cap (its two angles at the
/// ends of the longest edge, height / distance to each end, summing below kFlatCapRadians), else
/// -1. That vertex projects strictly inside the longest edge (the other two angles are acute).
/// (triangle_cleanup.cpp)
int flat_cap_middle(const std::array<Vec3, 3>& p);

/// A vertex of one side of a crack counts as on an edge of the other when their flatness is
/// below this (0.057°): ten times the flat caps' tolerance, since a crack's evidence is a whole
/// walk - both sides leave one vertex and meet again, each side's vertices on the other's edges
/// in order. Six significant digits move a vertex by up to 5e-6 of its coordinates' decade,
/// which over a piece of edge 1% of that long is an angle of 5e-4 (t_junctions.cpp).
inline constexpr double kCrackRadians = 1e-3;

/// A vertex also counts as on an edge of the other side when its distance from the edge is
/// below this times the largest coordinate of the three (as the file wrote them), at a flatness
/// below kCrackMostRadians: the error of six significant digits (5e-6 of the coordinates'
/// decade) on each of the three points, whatever the edge's length. A model of a few mm at
/// 100 mm from the origin, written with six digits, has its vertices 1e-4 off; only a file that
/// lost that much precision has cracks this wide (t_junctions.cpp).
inline constexpr double kCrackOfCoordinates = 2e-5;
inline constexpr double kCrackMostRadians = 0.1;

/// How far m is from lying on the segment from a to b, as the sum of the triangle's two angles
/// at a and b (small-angle approximation: m's distance from the line over its distance from
/// each end). 0 on the line; below kFlatCapRadians a flat cap when m projects inside. a != b and
/// m distinct from both. (triangle_cleanup.cpp)
double flatness(const Vec3& a, const Vec3& m, const Vec3& b);

/// Reads triangles and the edge table; splits each triangle whose boundary edge has other
/// boundary edges running along it through vertices on it (a T-junction) into a fan at those
/// vertices, appending to triangles and triangle_source, counting in cleanup and rebuilding the
/// edge table. A vertex counts as on the edge when exactly on it, or near enough (flatness below
/// kCrackRadians: a crack left by rounding, cleanup.near_t_junctions).
/// Returns how many edges were healed. (t_junctions.cpp)
std::size_t heal_t_junctions(Complex& complex);

/// Reads triangles, triangle_source and the edge table; writes cleanup.duplicate_triangles and
/// cleanup.first_duplicate. (duplicate_triangles.cpp)
void find_duplicate_triangles(Complex& complex);

/// Index of the undirected edge {u, v}, or kNoIndex. O(log d) for d edges at min(u, v).
std::uint32_t find_edge(const Complex& complex, std::uint32_t u, std::uint32_t v);

/// Reads triangles, edges, options (polylines mapped through `canonical`); writes edge_feature.
/// (feature_edges.cpp)
void classify_feature_edges(Complex& complex, const kernel::LargeVector<std::uint32_t>& canonical);

/// Triangles around each vertex grouped two ways: into fans connected through non-feature edges
/// ("wedges", the vertices of the patches cut open along their features) and into fans
/// connected through any edge ("sheets"; more than one means separate sheets touch only at
/// the vertex). (patches.cpp)
struct VertexFans {
  kernel::LargeVector<std::uint32_t> corner_wedge;   ///< wedge of corner (t, k), index 3 t + k
  std::uint32_t wedge_count = 0;
  kernel::LargeVector<std::uint32_t> vertex_sheets;  ///< number of sheets at each vertex
};

/// Reads triangles, edges, edge_feature; writes triangle_patch and the patch list's triangles
/// (patches, patch_triangle_offsets, patch_triangles); returns the fans.
VertexFans find_patches(Complex& complex);

/// Reads everything above; writes corners and curves with their arc lengths, edge_curve.
/// (curves.cpp)
void find_corners_and_curves(Complex& complex, const VertexFans& fans);

/// Reads everything above; writes the incidence lists (curve_patches, patch_curves,
/// patch_corners, corner_curves, corner_patches) and each patch's Euler characteristic and
/// boundary loop count. (patches.cpp)
void link_incidences(Complex& complex, const VertexFans& fans);

/// Reads triangles, triangle_patch, the edge table, edge_curve, vertex_corner and pinches;
/// writes pinch_fan_offsets, pinch_fans and unsupported_pinches. O(T) when there are pinches,
/// nothing otherwise. (pinch_fans.cpp)
void describe_pinch_fans(Complex& complex);

/// Tiny union-find with path halving, for the grouping steps.
class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  /// Returns true if x and y were in different sets.
  bool unite(std::uint32_t x, std::uint32_t y) {
    x = find(x);
    y = find(y);
    if (x == y) return false;
    if (x < y) parent_[y] = x;
    else parent_[x] = y;
    return true;
  }

 private:
  kernel::LargeVector<std::uint32_t> parent_;
};

/// Builds CSR offsets from per-item counts (offsets[i+1] - offsets[i] = counts[i]).
kernel::LargeVector<std::uint32_t> offsets_from_counts(std::span<const std::uint32_t> counts);

}  // namespace delpsc::protect::detail
