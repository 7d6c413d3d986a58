// Mesher::output: ∪ Skl^i S|_D (DelPSC step 3) as an io::SurfaceMesh.
#include <algorithm>
#include <map>
#include <vector>

#include <delpsc/kernel/large_array.h>

#include "mesher.h"
#include "triangle_orientation.h"

namespace delpsc::refine {

io::SurfaceMesh Mesher::output() const {
  io::SurfaceMesh mesh;
  // Stopped before the first examination ended (MesherOptions::stop): the facets examined so
  // far are a scattered part of the surface, by cell id, and no mesh of anything.
  if (!stats_.initialised) return mesh;
  constexpr std::uint32_t kUnset = 0xffffffffu;
  kernel::LargeVector<std::uint32_t> index(dt_.number_of_points(), kUnset);  // by PointId
  auto vertex = [&](PointId p) {
    if (index[p] == kUnset) {
      index[p] = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back(dt_.point(p).point());
    }
    return index[p];
  };
  // Skl² per patch: every restricted (t, σ), grouped by patch by a counting sort that keeps the
  // records' order within a patch (the run is deterministic, so is that order; a full sort of
  // the triangles was 1.8% of meshing the cube).
  std::vector<std::uint32_t> start(domain_->patch_count() + 1, 0);
  facets_.for_each([&](std::uint32_t, const RestrictedFacet& r) { ++start[r.patch + 1]; });
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  kernel::LargeVector<std::uint32_t> slots(start.back());
  facets_.for_each([&](std::uint32_t slot, const RestrictedFacet& r) { slots[start[r.patch]++] = slot; });
  mesh.vertices.reserve(domain_vertex_count());  // an upper bound: no regrowth copies
  mesh.triangles.reserve(slots.size());
  mesh.triangle_patch.reserve(slots.size());
  for (const std::uint32_t slot : slots) {
    const RestrictedFacet& r = facets_[slot];
    mesh.triangles.push_back({vertex(r.vertices[0]), vertex(r.vertices[1]), vertex(r.vertices[2])});
    mesh.triangle_patch.push_back(static_cast<std::int32_t>(r.patch));
  }
  // Where a component has no inside of its own (an open sheet, or closed shells meeting along a
  // non-manifold edge), the input's orientation decides: a triangle votes by the normal of the
  // input triangle nearest its centroid, when that lies on the triangle's own patch.
  const auto follows_input = [&](std::uint32_t t) {
    const auto& v = mesh.triangles[t];
    const Vec3 &a = mesh.vertices[v[0]], &b = mesh.vertices[v[1]], &c = mesh.vertices[v[2]];
    const auto near = domain_->closest_point((a + b + c) / 3);
    if (!near || near->patch != static_cast<std::uint32_t>(mesh.triangle_patch[t])) return 0;
    const double agreement = (b - a).cross(c - a).dot(near->normal);
    return agreement > 0 ? 1 : agreement < 0 ? -1 : 0;
  };
  orient_triangles(mesh.vertices, mesh.triangles, follows_input);
  // Skl¹: consecutive ball centres along each curve; Skl⁰: the corner balls.
  for (std::uint32_t c = 0; c < domain_->curve_count(); ++c) {
    const std::vector<BallKey> chain = balls_->curve_chain(c);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const auto a = ball_point_.find(chain[i]), b = ball_point_.find(chain[i + 1]);
      if (a == ball_point_.end() || b == ball_point_.end()) continue;
      mesh.edges.push_back({vertex(a->second), vertex(b->second)});
      mesh.edge_curve.push_back(static_cast<std::int32_t>(c));
    }
  }
  std::map<std::uint32_t, PointId> corners;
  for (const auto& [key, p] : ball_point_)
    if (places_[p].corner != kNoElement) corners[places_[p].corner] = p;
  for (const auto& [corner, p] : corners) mesh.corners.push_back(vertex(p));
  return mesh;
}

}  // namespace delpsc::refine
