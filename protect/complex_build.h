// Internal to protect/: the steps of build_complex (complex.h), one file each, run in this order
// on a Complex being filled. Each step documents what it reads and what it writes.
#pragma once

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

/// Reads triangles and the edge table; splits each triangle whose boundary edge has other
/// boundary edges running along it through vertices exactly on it (a T-junction) into a fan at
/// those vertices, appending to triangles and triangle_source and rebuilding the edge table.
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
