#include "restricted_facets_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include <delpsc/kernel/constructions.h>

namespace delpsc::refine {

namespace {

using Pair = std::array<std::uint32_t, 4>;  // sorted triangle vertices, patch

std::vector<Pair> pairs_of(const RestrictedFacets& facets) {
  std::vector<Pair> out;
  facets.for_each([&](std::uint32_t, const RestrictedFacet& r) {
    out.push_back({r.vertices[0], r.vertices[1], r.vertices[2], r.patch});
  });
  std::sort(out.begin(), out.end());
  return out;
}

// Whether (t, patch) is not restricted after all: t's exact dual edge, found on t's line from
// every vertex rather than from t's two cells (each vertex v keeps the part where t's vertices
// are not power-farther than v: one linear condition in the offset s, since both powers grow
// as s²), misses the patch. A fresh scan computes the edge from the cells, and from nearly flat
// cells it can run where the true one does not. Doubtful cases (no orthocentre, an edge that the
// rounding of its ends could reach the patch with) count as restricted. O(V).
bool truly_misses(const delaunay::RegularTriangulation& dt, const Domain& domain, const RestrictedFacet& r,
                  double scale) {
  const WeightedPoint &a = dt.point(r.vertices[0]), &b = dt.point(r.vertices[1]), &c = dt.point(r.vertices[2]);
  const auto centre = kernel::orthocentre(a, b, c);
  const Vec3 n = (b.point() - a.point()).cross(c.point() - a.point()).normalized();
  if (!centre || !n.allFinite()) return false;
  const Vec3 o = centre->point();
  const double power = (o - a.point()).squaredNorm() - a.w;
  double lo = -HUGE_VAL, hi = HUGE_VAL;
  for (PointId v = 0; v < dt.number_of_points(); ++v) {
    if (dt.status(v) != delaunay::PointStatus::vertex || v == r.vertices[0] || v == r.vertices[1] ||
        v == r.vertices[2])
      continue;
    // π(o + s n, v) - π(o + s n, t) = (π(o, v) - P) + 2 s n.(o - v) must not be negative.
    const WeightedPoint& w = dt.point(v);
    const double c0 = (o - w.point()).squaredNorm() - w.w - power, c1 = 2 * n.dot(o - w.point());
    if (c1 > 0)
      lo = std::max(lo, -c0 / c1);
    else if (c1 < 0)
      hi = std::min(hi, -c0 / c1);
    else if (c0 < 0)
      return true;
  }
  const double slack = 1e-9 * scale;
  lo -= slack;
  hi += slack;
  if (!(lo <= hi)) return true;
  std::vector<SurfaceHit> hits;
  if (std::isfinite(lo) && std::isfinite(hi)) {
    domain.intersect_segment(o + lo * n, o + hi * n, hits);
  } else if (std::isfinite(lo) || std::isfinite(hi)) {
    const double end = std::isfinite(lo) ? lo : hi;
    domain.intersect_ray(o + end * n, std::isfinite(lo) ? n : Vec3(-n), hits);
  } else {
    std::vector<SurfaceHit> other;
    domain.intersect_ray(o, n, hits);
    domain.intersect_ray(o, -n, other);
    hits.insert(hits.end(), other.begin(), other.end());
  }
  return std::none_of(hits.begin(), hits.end(), [&](const SurfaceHit& h) { return h.patch == r.patch; });
}

// Points and sizes of the same pair may differ by this much relative to the box's diagonal.
constexpr double kRecordTolerance = 1e-9;

std::string text(const Vec3& x) {
  return std::to_string(x.x()) + ", " + std::to_string(x.y()) + ", " + std::to_string(x.z());
}

std::string describe(const Pair& p, const char* where) {
  return "triangle " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
         " restricted to patch " + std::to_string(p[3]) + " " + where;
}

}  // namespace

std::string RestrictedFacets::refs_consistent() const {
  const auto at = [&](delaunay::CellId c, int i) {
    const std::size_t k = 4 * std::size_t{c} + static_cast<std::size_t>(i);
    return k < facet_refs_.size() ? facet_refs_[k] : kNoFacet;
  };
  const auto where = [](delaunay::CellId c, int i) {
    return "the reference of cell " + std::to_string(c) + ", facet " + std::to_string(i);
  };
  for (delaunay::CellId c = 0; c < dt_->cell_capacity(); ++c)
    for (int i = 0; i < 4; ++i) {
      const FacetRef r = at(c, i);
      if (!dt_->is_cell_alive(c)) {
        if (r != kNoFacet) return where(c, i) + " (a dead cell) is not empty";
        continue;
      }
      if (r != at(dt_->neighbour(c, i), dt_->mirror_index(c, i))) return where(c, i) + " differs from its mirror's";
      if (!names_record(r)) continue;
      if (r >= records_.size() || !records_[r].alive) return where(c, i) + " names a dead record";
      std::array<PointId, 3> t = dt_->facet_vertices(delaunay::Facet{c, i});
      std::sort(t.begin(), t.end());
      if (records_[r].vertices != t) return where(c, i) + " names another triangle's record";
    }
  return {};
}

std::vector<std::string> check_restricted_facets(const delaunay::RegularTriangulation& dt, const Domain& domain,
                                                 const RestrictedFacets& kept, std::size_t max_problems) {
  // The references first: a stale one would make a later update() forget another facet's records.
  if (const std::string refs = kept.refs_consistent(); !refs.empty()) return {refs};
  RestrictedFacets fresh(dt, domain);
  kernel::LargeVector<PointId> touched;
  fresh.rebuild(touched);
  const std::vector<Pair> a = pairs_of(kept), b = pairs_of(fresh);
  std::vector<std::string> problems;
  const kernel::Box3 box = domain.bounding_box();
  const double scale = (box.hi - box.lo).norm();
  // Pairs both have: the same point of V_t ∩ σ and the same size, which step 2 reads (a carried
  // record keeps the point found on a longer dual edge; it must still be the one the shrunk edge
  // gives). Up to rounding: the two may come from the facet's two sides.
  std::vector<std::pair<Pair, const RestrictedFacet*>> kept_records;
  kept.for_each([&](std::uint32_t, const RestrictedFacet& r) {
    kept_records.push_back({{r.vertices[0], r.vertices[1], r.vertices[2], r.patch}, &r});
  });
  std::sort(kept_records.begin(), kept_records.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  const double tolerance = kRecordTolerance * scale;
  fresh.for_each([&](std::uint32_t, const RestrictedFacet& r) {
    const Pair p{r.vertices[0], r.vertices[1], r.vertices[2], r.patch};
    const auto at = std::lower_bound(kept_records.begin(), kept_records.end(), p,
                                     [](const auto& x, const Pair& key) { return x.first < key; });
    if (at == kept_records.end() || at->first != p || problems.size() >= max_problems) return;
    const RestrictedFacet& k = *at->second;
    if (!((k.point - r.point).norm() <= tolerance && std::abs(k.size - r.size) <= tolerance))
      problems.push_back(describe(p, ("is kept with point (" + text(k.point) + ") and size " + std::to_string(k.size) +
                                      "; a fresh scan finds (" + text(r.point) + ") and " + std::to_string(r.size))
                                         .c_str()));
  });
  std::vector<Pair> only;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(only));
  for (const Pair& p : only)
    if (problems.size() < max_problems) problems.push_back(describe(p, "is kept but a fresh scan does not find it"));
  only.clear();
  std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(only));
  if (only.empty()) return problems;
  fresh.for_each([&](std::uint32_t, const RestrictedFacet& r) {
    const Pair p{r.vertices[0], r.vertices[1], r.vertices[2], r.patch};
    if (problems.size() < max_problems && std::binary_search(only.begin(), only.end(), p) &&
        !truly_misses(dt, domain, r, scale))
      problems.push_back(describe(p, "is found by a fresh scan but not kept"));
  });
  return problems;
}

}  // namespace delpsc::refine
