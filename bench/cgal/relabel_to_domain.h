// Puts another mesher's surface mesh (CGAL's, labelled with CGAL's patch and curve ids) into
// the ids of our Domain, so that refine::check_skeleton - guarantee G1 - judges both outputs
// with the same code.
//
// Patches: CGAL's detect_features(60) and our build_complex (feature angle 60) both cut the
// input triangles into patches along sharp edges; each CGAL patch is mapped to ours through the
// input faces it holds (matched by their corner coordinates). When the two segmentations are
// not the same partition the comparison is refused with a message rather than guessed.
// Curves: a feature edge of the mesh is given the curve nearest its midpoint (the edge is a
// chord between two points of one curve). Cost O(F log F) for F input faces plus O(E n) for E
// feature edges and n curve polyline vertices.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <delpsc/io/read_model.h>
#include <delpsc/refine/polygon_domain.h>

#include "cgal_surface_mesher.h"

namespace delpsc::bench {

namespace detail {

// Order-free key of a triangle: its corners' coordinates, corners sorted.
inline std::array<double, 9> triangle_key(std::array<Vec3, 3> c) {
  std::sort(c.begin(), c.end(), [](const Vec3& a, const Vec3& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  std::array<double, 9> key{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) key[3 * k + i] = c[k][i];
  return key;
}

}  // namespace detail

/// Rewrites mesh.triangle_patch and mesh.edge_curve into the ids of `domain` (built from
/// `soup`). Returns why it cannot when CGAL's patches and ours are not the same partition.
inline std::optional<std::string> relabel_to_domain(io::SurfaceMesh& mesh, std::span<const CgalInputFace> faces,
                                                    const io::TriangleSoup& soup, const refine::PolygonDomain& domain) {
  const protect::Complex& complex = domain.complex();
  std::map<std::array<double, 9>, std::uint32_t> our_patch;  // by soup triangle
  for (std::size_t t = 0; t < complex.triangles.size(); ++t) {
    const auto& v = soup.triangles[complex.triangle_source[t]];
    our_patch.emplace(detail::triangle_key({soup.vertices[v[0]], soup.vertices[v[1]], soup.vertices[v[2]]}),
                      complex.triangle_patch[t]);
  }
  std::map<int, std::set<std::uint32_t>> ours_of;  // CGAL patch -> our patches among its faces
  for (const CgalInputFace& f : faces) {
    const auto it = our_patch.find(detail::triangle_key(f.corners));
    if (it != our_patch.end()) ours_of[f.patch].insert(it->second);
  }
  std::map<int, std::int32_t> patch_map;
  std::set<std::uint32_t> used;
  for (const auto& [cgal, ours] : ours_of) {
    if (ours.size() != 1 || !used.insert(*ours.begin()).second)
      return "CGAL's patch " + std::to_string(cgal) + " is not one of our patches (the segmentations differ)";
    patch_map[cgal] = static_cast<std::int32_t>(*ours.begin());
  }
  if (used.size() != domain.patch_count())
    return std::to_string(domain.patch_count() - used.size()) + " of our patches have no CGAL patch";
  for (std::int32_t& p : mesh.triangle_patch) {
    const auto it = patch_map.find(p);
    if (it == patch_map.end()) return "a CGAL facet is on patch " + std::to_string(p) + ", which has no input face";
    p = it->second;
  }
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const Vec3 mid = 0.5 * (mesh.vertices[mesh.edges[e][0]] + mesh.vertices[mesh.edges[e][1]]);
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t c = 0; c < domain.curve_count(); ++c) {
      const double d = (domain.curve_point(c, domain.curve_closest_parameter(c, mid)) - mid).squaredNorm();
      if (d < best) best = d, mesh.edge_curve[e] = static_cast<std::int32_t>(c);
    }
  }
  return std::nullopt;
}

}  // namespace delpsc::bench
