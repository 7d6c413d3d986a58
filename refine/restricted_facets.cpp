#include "restricted_facets.h"

#include <algorithm>
#include <cmath>

#include <delpsc/kernel/constructions.h>

namespace delpsc::refine {

using delaunay::CellId;
using delaunay::Facet;
using delaunay::kInfiniteVertex;

RestrictedFacets::RestrictedFacets(const delaunay::RegularTriangulation& dt, const Domain& domain)
    : dt_(&dt), domain_(&domain) {}

RestrictedFacets::Key RestrictedFacets::key_of(std::array<PointId, 3> v) {
  std::sort(v.begin(), v.end());
  return {v[0], v[1], v[2]};
}

std::uint32_t RestrictedFacets::new_record() {
  std::uint32_t s;
  if (!free_.empty()) {
    s = free_.back();
    free_.pop_back();
  } else {
    s = static_cast<std::uint32_t>(records_.size());
    records_.emplace_back();
  }
  ++records_[s].stamp;
  records_[s].alive = true;
  records_[s].next = kNoFacet;
  records_[s].discarded = false;
  ++live_;
  return s;
}

void RestrictedFacets::mirror(CellId c) {
  if (cells_.size() < dt_->cell_capacity()) cells_.resize(dt_->cell_capacity());
  cells_[c] = {dt_->vertex(c, 0), dt_->vertex(c, 1), dt_->vertex(c, 2), dt_->vertex(c, 3)};
}

void RestrictedFacets::forget(const Key& k, std::vector<PointId>& touched) {
  const auto it = head_.find(k);
  if (it == head_.end()) return;
  for (std::uint32_t s = it->second; s != kNoFacet;) {
    RestrictedFacet& r = records_[s];
    for (const PointId v : r.vertices) {
      auto& list = by_vertex_[v];
      const auto pos = std::find(list.begin(), list.end(), s);
      *pos = list.back();
      list.pop_back();
      touched.push_back(v);
    }
    r.alive = false;
    ++r.stamp;  // invalidates heap entries
    free_.push_back(s);
    --live_;
    s = r.next;
  }
  head_.erase(it);
}

// V_t lies on the line of points power-equidistant from t's three vertices: through t's own
// orthocentre, perpendicular to t. A nearly flat cell (four almost coplanar vertices, common on
// planar patches whose coordinates are rounded) has an orthocentre that double arithmetic puts
// visibly off that line; projecting the ends back onto the line (computed from t alone, well
// conditioned) keeps every hit power-equidistant from t's vertices, as size(t, σ) assumes.
void RestrictedFacets::project_on_facet_line(const Key& k, delaunay::VoronoiEdge& e) const {
  const WeightedPoint &a = dt_->point(k.a), &b = dt_->point(k.b), &c = dt_->point(k.c);
  const auto centre = kernel::orthocentre(a, b, c);
  if (!centre) return;
  const Vec3 o = centre->point();
  const Vec3 n = (b.point() - a.point()).cross(c.point() - a.point()).normalized();
  if (!n.allFinite()) return;
  e.source = o + (e.source - o).dot(n) * n;
  if (e.is_ray)
    e.direction = e.direction.dot(n) >= 0 ? n : Vec3(-n);
  else
    e.target = o + (e.target - o).dot(n) * n;
}

void RestrictedFacets::examine(Facet f, const Key& k, std::vector<PointId>& touched) {
  delaunay::VoronoiEdge e = dt_->dual(f);
  project_on_facet_line(k, e);
  if (e.is_ray)
    domain_->intersect_ray(e.source, e.direction, hits_);
  else
    domain_->intersect_segment(e.source, e.target, hits_);
  if (hits_.empty()) return;
  const std::array<PointId, 3> v{k.a, k.b, k.c};
  std::array<WeightedPoint, 3> p{dt_->point(k.a), dt_->point(k.b), dt_->point(k.c)};
  // Hits come sorted by t then patch; group them per patch (few hits: quadratic is fine).
  std::uint32_t first = kNoFacet, last = kNoFacet;
  for (std::size_t i = 0; i < hits_.size(); ++i) {
    const std::uint32_t patch = hits_[i].patch;
    bool seen = false;
    for (std::size_t j = 0; j < i && !seen; ++j) seen = hits_[j].patch == patch;
    if (seen) continue;
    double best = -HUGE_VAL;
    Vec3 best_point = hits_[i].point;
    for (std::size_t j = i; j < hits_.size(); ++j) {
      if (hits_[j].patch != patch) continue;
      // On V_t the three power distances agree up to rounding; take the largest.
      for (const auto& w : p) {
        const double d = (hits_[j].point - w.point()).squaredNorm() - w.w;
        if (d > best) {
          best = d;
          best_point = hits_[j].point;
        }
      }
    }
    const std::uint32_t s = new_record();
    RestrictedFacet& r = records_[s];
    r.vertices = v;
    r.patch = patch;
    r.point = best_point;
    r.power = best;
    r.size = std::sqrt(std::max(0.0, best));
    if (last == kNoFacet)
      first = s;
    else
      records_[last].next = s;
    last = s;
    for (const PointId u : v) {
      if (by_vertex_.size() <= u) by_vertex_.resize(std::max<std::size_t>(u + 1, 2 * by_vertex_.size()));
      by_vertex_[u].push_back(s);
      touched.push_back(u);
    }
    heap_.emplace(r.power, s, r.stamp);
    if (badness_) {
      const double b = badness_(r);
      if (b > 1) bad_heap_.emplace(b, s, r.stamp);
    }
  }
  if (first != kNoFacet) head_[k] = first;
}

void RestrictedFacets::rebuild(std::vector<PointId>& touched) {
  std::vector<Key> keys;
  for (const auto& entry : head_) keys.push_back(entry.first);
  for (const Key& k : keys) forget(k, touched);
  cells_.assign(dt_->cell_capacity(), {});
  for (CellId c = 0; c < dt_->cell_capacity(); ++c) {
    if (!dt_->is_cell_alive(c)) continue;
    mirror(c);
    // Each finite facet once: from its finite cell of smaller id (a hull facet from its only
    // finite cell); facets through the infinite vertex have no dual edge.
    if (dt_->is_infinite(c)) continue;
    for (int i = 0; i < 4; ++i) {
      const Facet f{c, i};
      const CellId other = dt_->neighbour(c, i);
      if (!dt_->is_infinite(other) && other < c) continue;
      examine(f, key_of(dt_->facet_vertices(f)), touched);
    }
  }
}

void RestrictedFacets::update(const delaunay::ChangeSet& changes, std::vector<PointId>& touched) {
  // Destroyed first: their slots may have been recycled by created cells.
  for (const CellId c : changes.destroyed) {
    if (c >= cells_.size()) continue;
    const auto& v = cells_[c];
    for (int i = 0; i < 4; ++i) {
      std::array<PointId, 3> t{};
      int n = 0;
      bool infinite = false;
      for (int j = 0; j < 4; ++j) {
        if (j == i) continue;
        infinite |= v[j] == kInfiniteVertex;
        t[n++] = v[j];
      }
      if (!infinite) forget(key_of(t), touched);
    }
  }
  std::vector<std::pair<Key, Facet>> todo;
  for (const CellId c : changes.created) {
    mirror(c);
    const int inf = dt_->infinite_index(c);
    for (int i = 0; i < 4; ++i) {
      const PointId v = dt_->vertex(c, i);
      if (v != kInfiniteVertex) touched.push_back(v);
      if (inf >= 0 && inf != i) continue;
      Facet f{c, i};
      if (inf == i) f = dt_->mirror_facet(f);  // examine the hull facet from its finite cell
      todo.emplace_back(key_of(dt_->facet_vertices(f)), f);
    }
  }
  std::sort(todo.begin(), todo.end(), [](const auto& x, const auto& y) {
    return std::tie(x.first.a, x.first.b, x.first.c) < std::tie(y.first.a, y.first.b, y.first.c);
  });
  for (std::size_t i = 0; i < todo.size(); ++i) {
    if (i > 0 && todo[i].first == todo[i - 1].first) continue;
    forget(todo[i].first, touched);  // a hull facet's finite cell may be old: drop any stale record
    examine(todo[i].second, todo[i].first, touched);
  }
}

namespace {

// Lazy deletion: pops entries whose record died, was reused (stamp) or was discarded.
template <class Heap>
std::uint32_t top_live(Heap& heap, const std::vector<RestrictedFacet>& records) {
  while (!heap.empty()) {
    const auto [key, s, stamp] = heap.top();
    if (records[s].alive && records[s].stamp == stamp && !records[s].discarded) return s;
    heap.pop();
  }
  return kNoFacet;
}

}  // namespace

std::uint32_t RestrictedFacets::largest() { return top_live(heap_, records_); }
std::uint32_t RestrictedFacets::worst() { return top_live(bad_heap_, records_); }

}  // namespace delpsc::refine
