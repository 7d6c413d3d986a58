#include "polygon_domain.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <delpsc/kernel/bits.h>
#include <delpsc/kernel/predicates.h>

#include "surface_lattice.h"
#include "thinning_grid.h"
#include "triangle_clusters.h"
#include "triangle_samples.h"

namespace delpsc::refine {

namespace {

// The merge key of a hit: which mesh element the point lies on. Triangles around a mesh vertex
// or along a mesh edge all report that vertex or edge (exact classification), so equal keys
// within a patch are one crossing.
struct KeyedHit {
  std::uint32_t patch;
  std::uint8_t kind;  // kernel::FeatureKind: vertex, edge, face
  std::uint32_t element;
  double t;
  Vec3 point;
};

struct CoplanarSpan {
  double t0, t1;
  Vec3 p0, p1;
};

// The plane of one of the fan's triangles (the largest, or one of four spread over the fan)
// when all its triangles but at most protect::detail::kMostLeftOut lie in it (exact), those few
// then taken out of the fan's sectors, which stay disjoint (a cap fanned from a rim point,
// certified with the side's triangles there); else none, and the fan as it was.
std::optional<std::array<Vec3, 3>> flat_part(const protect::Complex& complex, protect::detail::Fan& fan) {
  const auto corners = [&](const protect::detail::Fan::Sector& s) {
    const auto& t = complex.triangles[s.triangle];
    return std::array<Vec3, 3>{complex.vertices[t[0]], complex.vertices[t[1]], complex.vertices[t[2]]};
  };
  const auto& sectors = fan.sectors;
  if (sectors.empty()) return std::nullopt;
  for (const std::size_t reference : protect::detail::reference_candidates(complex, fan.centre, sectors)) {
    const std::array<Vec3, 3> plane = corners(sectors[reference]);
    const auto in_plane = [&](const protect::detail::Fan::Sector& s) {
      return kernel::orient3d(plane[0], plane[1], plane[2], complex.vertices[s.start]) == 0 &&
             kernel::orient3d(plane[0], plane[1], plane[2], complex.vertices[s.end]) == 0;
    };
    const auto off = static_cast<std::size_t>(std::count_if(sectors.begin(), sectors.end(), [&](const auto& s) { return !in_plane(s); }));
    if (off > protect::detail::kMostLeftOut || off == sectors.size()) continue;
    std::erase_if(fan.sectors, [&](const auto& s) { return !in_plane(s); });
    return plane;
  }
  return std::nullopt;
}

}  // namespace

PolygonDomain::PolygonDomain(protect::Complex complex, bool search_fans)
    : complex_(std::move(complex)),
      tree_(complex_.vertices, complex_.triangles),
      closest_(complex_.vertices, complex_.triangles, tree_) {
  if (search_fans) {
    std::vector<std::uint32_t> fan_at;
    std::vector<protect::detail::Fan> fans =
        protect::detail::certify_fans(complex_, ClosestPointIndex::kMinFanDegree, fan_at);
    if (!fans.empty()) {
      fan_owner_.assign(complex_.triangles.size(), protect::detail::kNoFan);
      for (protect::detail::Fan& fan : fans) {
        SegmentFan& f = segment_fans_.emplace_back();
        f.plane = flat_part(complex_, fan);
        for (const auto& sector : fan.sectors) {
          std::uint32_t& owner = fan_owner_[sector.triangle];
          if (owner == protect::detail::kNoFan) owner = static_cast<std::uint32_t>(segment_fans_.size() - 1);
          for (const std::uint32_t v : complex_.triangles[sector.triangle]) f.box.extend(complex_.vertices[v]);
        }
        f.fan = std::move(fan);
      }
      for (std::uint32_t t = 0; t < complex_.triangles.size(); ++t)
        if (fan_owner_[t] == protect::detail::kNoFan) {
          rest_triangles_.push_back(complex_.triangles[t]);
          rest_ids_.push_back(t);
        }
      rest_tree_ = kernel::AabbTree(complex_.vertices, rest_triangles_);
    }
  }
  patch_points_.assign(complex_.patch_count(), Vec3::Zero());
  std::vector<double> best(complex_.patch_count(), -1);
  for (std::uint32_t t = 0; t < complex_.triangles.size(); ++t) {
    const auto& tri = complex_.triangles[t];
    const Vec3 &p = complex_.vertices[tri[0]], &q = complex_.vertices[tri[1]], &r = complex_.vertices[tri[2]];
    const double area2 = (q - p).cross(r - p).squaredNorm();
    const std::uint32_t patch = complex_.triangle_patch[t];
    if (area2 > best[patch]) {
      best[patch] = area2;
      patch_points_[patch] = (p + q + r) / 3;
    }
  }
}

PolygonDomain::PolygonDomain(const io::TriangleSoup& soup, const protect::ComplexOptions& options)
    : PolygonDomain(protect::build_complex(soup, options)) {}

CurveSegment PolygonDomain::curve_segment_in_ball(std::uint32_t c, double s, double r) const {
  const protect::CurveInterval i = complex_.segment_in_ball(c, s, r);
  return {i.s0, i.s1, i.whole};
}

void PolygonDomain::merge_hits(std::vector<kernel::TriangleIntersection>& hits, const Vec3& a, const Vec3& b,
                               std::vector<SurfaceHit>& out) const {
  out.clear();
  // With fans, in triangle order: what follows then depends on the set of hits alone, not on
  // the order the rest's tree and the fans' searches found them in (ties below keep the first).
  // Without, the tree's order, as before fans were searched (the same meshes, bit for bit).
  if (!segment_fans_.empty())
    std::sort(hits.begin(), hits.end(),
              [](const kernel::TriangleIntersection& x, const kernel::TriangleIntersection& y) {
                return x.triangle < y.triangle;
              });
  thread_local std::vector<KeyedHit> crossings;
  crossings.clear();
  std::map<std::uint32_t, CoplanarSpan> spans;
  const Vec3 d = b - a;
  for (const auto& h : hits) {
    const std::uint32_t patch = complex_.triangle_patch[h.triangle];
    if (h.hit.contact == kernel::Contact::coplanar) {
      const Vec3 exit = h.hit.t_exit == 0 ? a : h.hit.t_exit == 1 ? b : Vec3(a + h.hit.t_exit * d);
      auto [it, fresh] = spans.try_emplace(patch, CoplanarSpan{h.hit.t, h.hit.t_exit, h.hit.point, exit});
      if (fresh) continue;
      CoplanarSpan& span = it->second;
      if (h.hit.t < span.t0) {
        span.t0 = h.hit.t;
        span.p0 = h.hit.point;
      }
      if (h.hit.t_exit > span.t1) {
        span.t1 = h.hit.t_exit;
        span.p1 = exit;
      }
      continue;
    }
    const auto& tri = complex_.triangles[h.triangle];
    const auto kind = h.hit.feature.kind;
    const int index = h.hit.feature.index;
    std::uint32_t element = h.triangle;
    if (kind == kernel::FeatureKind::vertex) element = tri[index];
    else if (kind == kernel::FeatureKind::edge) element = complex_.triangle_edges[h.triangle][index];
    crossings.push_back({patch, static_cast<std::uint8_t>(kind), element, h.hit.t, h.hit.point});
  }
  std::sort(crossings.begin(), crossings.end(), [](const KeyedHit& x, const KeyedHit& y) {
    return std::tie(x.patch, x.kind, x.element, x.t) < std::tie(y.patch, y.kind, y.element, y.t);
  });
  for (std::size_t i = 0; i < crossings.size(); ++i) {
    const KeyedHit& h = crossings[i];
    if (i > 0 && h.patch == crossings[i - 1].patch && h.kind == crossings[i - 1].kind &&
        h.element == crossings[i - 1].element)
      continue;
    // A crossing at the end of a coplanar overlap of the same patch is that overlap's end (the
    // segment leaves the plane through a neighbouring triangle); parameters computed by the two
    // different formulas may differ by rounding, hence the small relative slack.
    const auto span = spans.find(h.patch);
    if (span != spans.end()) {
      const double slack = 1e-12 * (1 + std::abs(span->second.t0) + std::abs(span->second.t1));
      if (h.t >= span->second.t0 - slack && h.t <= span->second.t1 + slack) continue;
    }
    out.push_back({h.point, h.t, h.patch, false});
  }
  for (const auto& [patch, span] : spans) {
    out.push_back({span.p0, span.t0, patch, true});
    if (span.t1 > span.t0) out.push_back({span.p1, span.t1, patch, true});
  }
  std::sort(out.begin(), out.end(), [](const SurfaceHit& x, const SurfaceHit& y) {
    return std::tie(x.t, x.patch) < std::tie(y.t, y.patch);
  });
}

void PolygonDomain::intersect_segment(const Vec3& a, const Vec3& b, std::vector<SurfaceHit>& out) const {
  thread_local std::vector<kernel::TriangleIntersection> hits;
  collect_hits(a, b, hits);
  merge_hits(hits, a, b, out);
}

// A fan triangle the segment meets lies in a sector near the segment's shadow (sectors_near,
// exact), and each listed triangle gets the tree's own exact test with its corners in the same
// order, so the hits are the tree's, bit for bit; only their order differs, which merge_hits
// does not see.
void PolygonDomain::intersect_segment_with_fans(const Vec3& a, const Vec3& b,
                                                std::vector<kernel::TriangleIntersection>& hits) const {
  rest_tree_.intersect_segment(a, b, hits);
  for (auto& h : hits) h.triangle = rest_ids_[h.triangle];
  kernel::Box3 span;
  span.extend(a);
  span.extend(b);
  thread_local std::vector<std::uint32_t> sectors;
  const std::array<const double*, 2> ends{a.data(), b.data()};
  for (std::uint32_t f = 0; f < segment_fans_.size(); ++f) {
    const SegmentFan& fan = segment_fans_[f];
    if (!fan.box.overlaps(span)) continue;
    if (fan.plane) {  // a flat cap: most dual edges near it do not cross its plane (exact)
      const auto& [p, q, r] = *fan.plane;
      const int side_a = kernel::orient3d(p, q, r, a);
      if (side_a != 0 && side_a == kernel::orient3d(p, q, r, b)) continue;
    }
    sectors.clear();
    protect::detail::sectors_near(complex_, fan.fan, ends, sectors);
    std::sort(sectors.begin(), sectors.end());
    sectors.erase(std::unique(sectors.begin(), sectors.end()), sectors.end());
    for (const std::uint32_t k : sectors) {
      const std::uint32_t t = fan.fan.sectors[k].triangle;
      if (fan_owner_[t] != f) continue;
      const auto& tri = complex_.triangles[t];
      const kernel::TriangleHit hit = kernel::intersect_segment_triangle(
          a, b, complex_.vertices[tri[0]], complex_.vertices[tri[1]], complex_.vertices[tri[2]]);
      if (hit) hits.push_back({t, hit});
    }
  }
}

void PolygonDomain::collect_hits(const Vec3& a, const Vec3& b, std::vector<kernel::TriangleIntersection>& out) const {
  out.clear();
  // The angular search's predicates are exact only within their range; elsewhere the tree.
  if (segment_fans_.empty() || !kernel::in_exact_range(a) || !kernel::in_exact_range(b))
    tree_.intersect_segment(a, b, out);
  else
    intersect_segment_with_fans(a, b, out);
}

void PolygonDomain::triangle_hits(const Vec3& a, const Vec3& b, std::vector<kernel::TriangleIntersection>& out) const {
  collect_hits(a, b, out);
  std::sort(out.begin(), out.end(), [](const kernel::TriangleIntersection& x, const kernel::TriangleIntersection& y) {
    return x.triangle < y.triangle;
  });
}

void PolygonDomain::intersect_ray(const Vec3& origin, const Vec3& direction, std::vector<SurfaceHit>& out) const {
  thread_local std::vector<kernel::TriangleIntersection> hits;
  hits.clear();
  tree_.intersect_ray(origin, direction, hits);
  merge_hits(hits, origin, origin + direction, out);
}

std::optional<ClosestSurfacePoint> PolygonDomain::closest_point(const Vec3& x, double below_squared) const {
  const auto c = closest_.closest_point(x, below_squared);
  if (!c) return std::nullopt;
  const auto& t = complex_.triangles[c->triangle];
  const Vec3 &a = complex_.vertices[t[0]], &b = complex_.vertices[t[1]], &d = complex_.vertices[t[2]];
  return ClosestSurfacePoint{c->point, complex_.triangle_patch[c->triangle], c->squared_distance, (b - a).cross(d - a)};
}

void PolygonDomain::triangles_in_box(const kernel::Box3& box, std::vector<PatchTriangle>& out) const {
  std::vector<std::uint32_t> ids;
  tree_.triangles_in_box(box, ids);
  out.clear();
  for (const std::uint32_t t : ids) {
    const auto& v = complex_.triangles[t];
    out.push_back({{complex_.vertices[v[0]], complex_.vertices[v[1]], complex_.vertices[v[2]]}, complex_.triangle_patch[t]});
  }
}

CandidateParts PolygonDomain::surface_candidates(double spacing, std::size_t budget, kernel::LargeVector<Vec3>& points,
                                                 kernel::LargeVector<std::uint32_t>& patches) const {
  if (!(spacing > 0) || !std::isfinite(spacing)) return {};
  const double per_area = 4.0 / (spacing * spacing);
  const double step = kLatticeStep * spacing, jitter = kLatticeJitter * spacing;
  kernel::LargeVector<double> expected_in(complex_.triangles.size());
  double total = 0;
  for (std::uint32_t t = 0; t < complex_.triangles.size(); ++t) {
    const auto& tri = complex_.triangles[t];
    const Vec3 &a = complex_.vertices[tri[0]], &b = complex_.vertices[tri[1]], &c = complex_.vertices[tri[2]];
    total += expected_in[t] = 0.5 * (b - a).cross(c - a).norm() * per_area;
  }
  if (!(total <= static_cast<double>(budget))) return {};  // also when not finite
  const std::size_t start = points.size();
  // The net (made last, below): triangle_samples at kNetRadius spacings and every vertex of a
  // triangle. Counted first, so that the budget bounds it too; left out when it does not fit.
  const double net_radius = kNetRadius * spacing;
  double samples_expected = 0;  // the triangles' samples, without their corners
  for (const auto& tri : complex_.triangles)
    samples_expected += triangle_sample_count(complex_.vertices[tri[0]], complex_.vertices[tri[1]], complex_.vertices[tri[2]], net_radius);
  const double net_expected = static_cast<double>(complex_.vertices.size()) + samples_expected;
  if (total + net_expected <= static_cast<double>(budget)) total += net_expected;  // the lattice leaves it room

  // The lattice on clusters of at least half a spacing² (smaller ones would get less than one
  // lattice point each: random candidates serve them as well), first: the mesher chooses from it
  // first. Its work (rows and sites tried) is capped by what the budget leaves after the random
  // candidates; a lattice that would need more (needles many steps long) is dropped, and the
  // random candidates go everywhere, as without it.
  const double band = 2.5 * spacing;
  const TriangleClusters clusters = cluster_triangles(complex_, kClusterAngle, band);
  kernel::LargeVector<double> cluster_area(clusters.seed.size(), 0);
  for (std::uint32_t t = 0; t < complex_.triangles.size(); ++t) cluster_area[clusters.cluster_of[t]] += expected_in[t];
  bool lattice_laid = true;
  const auto has_lattice = [&](std::uint32_t t) { return lattice_laid && cluster_area[clusters.cluster_of[t]] >= 2; };
  std::vector<LatticeFrame> frames(clusters.seed.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto& tri = complex_.triangles[clusters.seed[k]];
    const Vec3 &a = complex_.vertices[tri[0]], &b = complex_.vertices[tri[1]], &c = complex_.vertices[tri[2]];
    frames[k] = lattice_frame((b - a).cross(c - a), a, step);
  }
  const auto random_expected = static_cast<std::size_t>(std::ceil(total));  // total <= budget < 2^64
  std::size_t work = budget > random_expected ? budget - random_expected : 0;
  for (std::uint32_t t = 0; t < complex_.triangles.size() && lattice_laid; ++t) {
    if (!has_lattice(t)) continue;
    const auto& tri = complex_.triangles[t];
    lattice_laid = jittered_lattice(frames[clusters.cluster_of[t]], complex_.vertices[tri[0]], complex_.vertices[tri[1]],
                                    complex_.vertices[tri[2]], step, jitter, points, &work);
    patches.resize(points.size(), complex_.triangle_patch[t]);
  }
  if (!lattice_laid) {
    points.resize(start);
    patches.resize(start);
  }
  const std::size_t lattice = points.size() - start;

  for (std::uint32_t t = 0; t < complex_.triangles.size(); ++t) {
    // splitmix64 seeded by the mixed triangle index: the same points on every call and machine,
    // and no overlap between the streams of triangles t and t + 1 (neighbours, often).
    std::uint64_t state = kernel::mix64(t + 0x632be59bd9b4e019ull);
    const auto uniform = [&state] {
      return static_cast<double>(kernel::mix64(state += 0x9e3779b97f4a7c15ull) >> 11) * 0x1.0p-53;
    };
    const auto& tri = complex_.triangles[t];
    const Vec3 &a = complex_.vertices[tri[0]], &b = complex_.vertices[tri[1]], &c = complex_.vertices[tri[2]];
    const double expected = expected_in[t];
    // Where the cluster has a lattice, random candidates only within ~2.5 spacings of its
    // boundary (below): the lattice covers the rest.
    const bool lattice_here = has_lattice(t);
    if (lattice_here && clusters.distance[t] > band) continue;
    const auto emit = [&](double u, double v) {  // lattice coordinates, u + v <= 1
      points.push_back(a + u * (b - a) + v * (c - a));
      patches.push_back(complex_.triangle_patch[t]);
    };
    // Uniform in the triangle (u0, v0) + s (1 - r) (du1) + s r (du2): the square root spreads
    // points evenly in area.
    const auto uniform_in = [&](double u0, double v0, double u1, double v1, double u2, double v2) {
      const double s = std::sqrt(uniform()), r = uniform();
      emit(u0 + s * (1 - r) * (u1 - u0) + s * r * (u2 - u0), v0 + s * (1 - r) * (v1 - v0) + s * r * (v2 - v0));
    };
    if (expected < 1) {  // a triangle much smaller than spacing: one point or none, as expected
      if (uniform() < expected) uniform_in(0, 0, 1, 0, 0, 1);
      continue;
    }
    // In a cluster with a lattice, random candidates only near the cluster's boundary edges: the
    // lattice covers the rest, so every candidate there would be refused. A candidate can be
    // chosen only where the lattice left a gap: at a seam with another cluster, or where a ball
    // refused lattice points (within sqrt(spacing² + r²) <= 1.42 spacing of its centre, on a
    // boundary edge since curves are features), plus the cover radius ~1 spacing: 2.5 spacings.
    // The distance to edge k is the barycentric coordinate of the opposite corner times that
    // corner's height, linear over a stratum, so a stratum's corners bound it.
    const double twice_area = (b - a).cross(c - a).norm();
    const std::uint8_t edges = clusters.boundary_edges[t];
    const double h0 = edges & 1 ? twice_area / (c - b).norm() : HUGE_VAL;
    const double h1 = edges & 2 ? twice_area / (c - a).norm() : HUGE_VAL;
    const double h2 = edges & 4 ? twice_area / (b - a).norm() : HUGE_VAL;
    const auto inside_band = [&](double u, double v) { return std::min({(1 - u - v) * h0, u * h1, v * h2}) > band; };
    // Only a triangle on the boundary can tell its strata apart (one inside the cluster but
    // within the band of its boundary keeps them all).
    const auto interior = [&](double u0, double v0, double u1, double v1, double u2, double v2) {
      return lattice_here && edges != 0 && inside_band(u0, v0) && inside_band(u1, v1) && inside_band(u2, v2);
    };
    // Stratified: the triangle cut into m² equal triangles by a barycentric grid, one point in
    // each with probability expected / m². Even cover for the count, where independent points
    // would leave holes that refinement then fills one insertion at a time.
    const int m = static_cast<int>(std::ceil(std::sqrt(expected)));
    const double keep = expected / (static_cast<double>(m) * m), step_uv = 1.0 / m;
    for (int i = 0; i < m; ++i)
      for (int j = 0; i + j < m; ++j) {
        const double u = i * step_uv, v = j * step_uv;
        if (uniform() < keep && !interior(u, v, u + step_uv, v, u, v + step_uv))
          uniform_in(u, v, u + step_uv, v, u, v + step_uv);
        if (i + j + 1 < m && uniform() < keep && !interior(u + step_uv, v, u, v + step_uv, u + step_uv, v + step_uv))
          uniform_in(u + step_uv, v, u, v + step_uv, u + step_uv, v + step_uv);
      }
  }
  // The stratified counts may pass their expectation: the promise is none at all then.
  if (points.size() - start > budget) {
    points.resize(start);
    patches.resize(start);
    return {};
  }
  CandidateParts parts;
  parts.lattice = lattice;
  // The net when it fits in what the lattice and the random points left (counted, not made).
  if (static_cast<double>(points.size() - start) + net_expected <= static_cast<double>(budget)) {
    const std::size_t net_start = points.size();
    // A net whose triangle samples are out of all proportion to the rest (fans of needles,
    // kNetExcess; the corners are bounded by the input's size and not counted, so that a dense
    // model at a coarse size is not thinned) is thinned: each point left out lies within
    // kNetThinning net radii of one kept, so the kept ones reach every point of the patches
    // within (1 + kNetThinning) net radii.
    const bool thinned = samples_expected > kNetExcess * std::max(1.0, static_cast<double>(net_start - start));
    ThinningGrid grid(thinned ? kNetThinning * net_radius : 0);
    kernel::LargeVector<Vec3> row;  // one triangle's samples, before thinning
    std::vector<std::uint8_t> corner_done(complex_.vertices.size(), 0);
    for (std::uint32_t t = 0; t < complex_.triangles.size(); ++t) {
      const auto& tri = complex_.triangles[t];
      row.clear();
      for (const std::uint32_t v : tri)
        if (!corner_done[v]) {
          corner_done[v] = 1;
          row.push_back(complex_.vertices[v]);
        }
      triangle_samples(complex_.vertices[tri[0]], complex_.vertices[tri[1]], complex_.vertices[tri[2]], net_radius, row);
      for (const Vec3& p : row)
        if (!thinned || grid.admit(p)) points.push_back(p);
      patches.resize(points.size(), complex_.triangle_patch[t]);
    }
    parts.net = points.size() - net_start;
    parts.net_radius = thinned ? (1 + kNetThinning) * net_radius : net_radius;
  }
  return parts;
}

}  // namespace delpsc::refine
