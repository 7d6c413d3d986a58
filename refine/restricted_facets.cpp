#include "restricted_facets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <delpsc/kernel/bits.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/kernel/predicates.h>

namespace delpsc::refine {

using delaunay::CellId;
using delaunay::Facet;
using delaunay::kInfiniteVertex;

RestrictedFacets::RestrictedFacets(const delaunay::RegularTriangulation& dt, const Domain& domain)
    : dt_(&dt), domain_(&domain), box_(domain.bounding_box()) {}

void RestrictedFacets::exclude_vertices(std::span<const PointId> points) {
  // Validated first: a stray id (kNoPoint, say) would otherwise size the table to 4 GB.
  for (const PointId p : points)
    if (p >= dt_->number_of_points())
      throw std::invalid_argument("RestrictedFacets::exclude_vertices: " + std::to_string(p) +
                                  " is no point of the triangulation (" +
                                  std::to_string(dt_->number_of_points()) + " points)");
  for (const PointId p : points) {
    if (excluded_.size() <= p) excluded_.resize(p + 1, 0);
    excluded_[p] = 1;
  }
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
  records_[s].kept = 0;
  ++live_;
  return s;
}

void RestrictedFacets::forget(FacetRef& ref) {
  const FacetRef first = ref;
  ref = kNoFacet;
  // A dead record: the facet's other side was forgotten first (no slot is reused meanwhile).
  if (names_record(first) && records_[first].alive) forget_chain(first);
}

void RestrictedFacets::forget_chain(std::uint32_t first) {
  for (std::uint32_t s = first; s != kNoFacet;) {
    const std::uint32_t next = records_[s].next;
    forget_record(s);
    s = next;
  }
}

void RestrictedFacets::forget_record(std::uint32_t s) {
  RestrictedFacet& r = records_[s];
  gone_.push_back({r.vertices[0], r.vertices[1], r.vertices[2], r.patch});
  for (const PointId v : r.vertices) {
    by_vertex_.erase_first(v, [s](const Incidence& x) { return x.slot == s; });
  }
  r.alive = false;
  ++r.stamp;  // invalidates heap entries
  (updating_ ? free_later_ : free_).push_back(s);
  --live_;
}

// A nearly flat cell (four almost coplanar vertices, common on planar patches whose coordinates
// are rounded) has an orthocentre that double arithmetic puts visibly off t's line; projecting
// the ends of dual(f) back onto the line (computed from t alone, well conditioned) keeps every
// hit power-equidistant from t's vertices, as size(t, σ) assumes. Neither this nor
// dual_on_facet_line is accurate for such a cell; this one is what the flat cells of the test
// models were first met with, and it ends their refinement (on the prism with a short curve
// refined by the paper's global step 2(a), dual_on_facet_line for every facet ran to the test's
// cap of 30,000 vertices where this ends after 1,900 insertions), so flat cells keep it.
delaunay::VoronoiEdge RestrictedFacets::dual_projected(delaunay::Facet f, const std::optional<FacetLine>& line) const {
  delaunay::VoronoiEdge e = dt_->dual(f);
  if (!line) return e;
  const Vec3 &o = line->orthocentre, &n = line->normal;
  e.source = o + (e.source - o).dot(n) * n;
  if (e.is_ray)
    e.direction = e.direction.dot(n) >= 0 ? n : Vec3(-n);
  else
    e.target = o + (e.target - o).dot(n) * n;
  return e;
}

std::optional<RestrictedFacets::FacetLine> RestrictedFacets::facet_line(const std::array<PointId, 3>& t) const {
  const WeightedPoint &a = dt_->point(t[0]), &b = dt_->point(t[1]), &c = dt_->point(t[2]);
  const auto centre = kernel::orthocentre(a, b, c);
  const Vec3 ab = b.point() - a.point(), ac = c.point() - a.point();
  const Vec3 cross = ab.cross(ac);
  const Vec3 n = cross.normalized();
  if (!centre || !n.allFinite()) return std::nullopt;
  return FacetLine{centre->point(), n, (centre->point() - a.point()).squaredNorm() - a.w,
                   cross.squaredNorm() / (ab.squaredNorm() * ac.squaredNorm())};
}

// V_t lies on the line of points power-equidistant from t's three vertices: through t's own
// orthocentre o, perpendicular to t (§1.2's power diagram). Along it, x = o + s n has power
// distance P + s² to each vertex of t (P = π(o, a); o and a lie in t's plane, so (o - a).n = 0),
// and π(o, d) + 2 s n.(o - d) + s² to the fourth vertex d of a cell on either side, so the
// cell's orthocentre, where the two agree, sits at s_d = (P - π(o, d)) / (2 n.(o - d)). That is
// one dot product and one power distance per side instead of a 4-point orthocentre solve each
// (~5% of meshing), and the ends lie on t's line by construction, so every hit is power-
// equidistant from t's vertices, as size(t, σ) assumes. For a well-conditioned facet (both
// cells finite and far from flat, see well_conditioned) it agrees with the orthocentres to
// rounding; examine() uses it only then.
delaunay::VoronoiEdge RestrictedFacets::dual_on_facet_line(delaunay::Facet f, const std::optional<FacetLine>& line) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!line) return {Vec3::Constant(kNaN), Vec3::Constant(kNaN), Vec3::Zero(), false};
  const Vec3 &o = line->orthocentre, &n = line->normal;
  const double p = line->power;
  const auto end = [&](delaunay::Facet side) {
    const WeightedPoint& d = dt_->point(dt_->vertex(side.cell, side.index));
    const Vec3 od = o - d.point();
    return o + ((p - (od.squaredNorm() - d.w)) / (2 * n.dot(od))) * n;
  };
  return {end(f), end(dt_->mirror_facet(f)), Vec3::Zero(), false};
}

// Whether update() may carry the outcome of f's examination over to the next triangulation
// (a boundary facet of a later cavity is then not queried again): both cells and f itself far
// from flat, so their orthocentres and f's normal carry a relative error of order
// 1e-16 / kRatio, ~1e-11 of the cell's size - the size of the rounding any fresh query makes.
// A nearly flat cell (almost co-spherical points on a planar patch) can put its orthocentre
// visibly off (see dual_projected): such a facet is examined afresh each time.
bool RestrictedFacets::well_conditioned(Facet f) const {
  constexpr double kRatio = 1e-5;
  // Each cell's answer is kept until its slot is reused (update() clears it for created cells):
  // a cell is asked once for each of its facets, the test is the same each time.
  const auto flat = [&](CellId c) {
    if (c >= flat_.size()) flat_.resize(dt_->cell_capacity(), kFlatUnknown);
    if (flat_[c] != kFlatUnknown) return flat_[c] == kFlatYes;
    const Vec3 a = dt_->point(dt_->vertex(c, 0)).point();
    const Vec3 ab = dt_->point(dt_->vertex(c, 1)).point() - a;
    const Vec3 ac = dt_->point(dt_->vertex(c, 2)).point() - a;
    const Vec3 ad = dt_->point(dt_->vertex(c, 3)).point() - a;
    const double volume = ab.dot(ac.cross(ad));  // squared below: no square roots
    const bool is_flat = volume * volume <= kRatio * kRatio * ab.squaredNorm() * ac.squaredNorm() * ad.squaredNorm();
    flat_[c] = is_flat ? kFlatYes : kFlatNo;
    return is_flat;
  };
  const Facet m = dt_->mirror_facet(f);
  if (dt_->is_infinite(f.cell) || dt_->is_infinite(m.cell) || flat(f.cell) || flat(m.cell)) return false;
  const auto t = dt_->facet_vertices(f);
  const Vec3 a = dt_->point(t[0]).point();
  const Vec3 ab = dt_->point(t[1]).point() - a, ac = dt_->point(t[2]).point() - a;
  return ab.cross(ac).squaredNorm() > kRatio * kRatio * ab.squaredNorm() * ac.squaredNorm();
}

void RestrictedFacets::examine(Facet f, double cover_power) {
  // Vertices in increasing order: t's orthocentre and line (so the dual edge) and the record do
  // not depend on which cell the facet is seen from.
  std::array<PointId, 3> v = dt_->facet_vertices(f);
  kernel::sort3(v);
  // V_t lies in the power cell of an excluded vertex, which misses the domain: no record, and an
  // outcome update() may carry over (it stays true however the cells change).
  if (std::any_of(v.begin(), v.end(), [&](PointId u) { return u < excluded_.size() && excluded_[u]; })) return;
  // Beyond the proven cover (rebuild): V_t misses the domain, whatever the cells (the bound is
  // on t's own line, an exact statement about t alone), so the outcome may be carried over as a
  // queried one's. First without the orthocentre: it lies on the radical plane of every two of
  // t's vertices, so P is at least the least power distance on that plane (most culled facets
  // have an edge that long). Then P itself, where the shape test keeps its rounding far below
  // the margin (t's angle at a above 0.06°).
  constexpr double kCoverMargin = 1.01, kShapeFloor = 1e-6;
  if (cover_power < HUGE_VAL) {
    const WeightedPoint &a = dt_->point(v[0]), &b = dt_->point(v[1]), &c = dt_->point(v[2]);
    // The least power on the radical plane of x and y is m² / (4 d²) - w_x; compared with the
    // bound without dividing (two vertices never coincide: d² > 0).
    const double bound = kCoverMargin * cover_power;
    const auto beyond = [bound](const WeightedPoint& x, const WeightedPoint& y) {
      const double d2 = (x.point() - y.point()).squaredNorm(), m = d2 + x.w - y.w;
      return d2 > 0 && m * m > 4 * d2 * (bound + x.w);
    };
    if (beyond(a, b) || beyond(a, c) || beyond(b, c)) {
      ++skipped_;
      return;
    }
  }
  const std::optional<FacetLine> line = facet_line(v);
  if (line && line->power > kCoverMargin * cover_power && line->shape > kShapeFloor) {
    ++skipped_;
    return;
  }
  // Computed first: it decides how to compute the dual edge and whether update() may carry the
  // outcome over (false for a hull facet, whose dual is a ray).
  const bool conditioned = well_conditioned(f);
  const delaunay::VoronoiEdge e = conditioned ? dual_on_facet_line(f, line) : dual_projected(f, line);
  if (!e.source.allFinite() || !(e.is_ray ? e.direction : e.target).allFinite()) {
    // A cell flat in doubles (four co-circular points of a planar patch, typically) has no
    // orthocentre: its end of the edge is NaN or inf, and a query with such an end reports garbage
    // hits. Where V_t lies is then undecidable in doubles; the facet gets no record and is not
    // trusted, so it is examined again whenever a cavity reaches it (and the flat cell goes).
    const Facet m = dt_->mirror_facet(f);
    ref(f.cell, f.index) = ref(m.cell, m.index) = kUntrusted;
    return;
  }
  // With a proven cover, a point of V_t on the domain is within sqrt(bound - P) of t's
  // orthocentre along the line (its power there is P + s²): only that window of the edge is
  // queried, and nothing when the edge misses it. The dual edges of big cells run deep into the
  // volume: the window is their surface end. Unlike the skips above, this one depends on the
  // computed edge, so an empty window counts as a query without hits: not trusted when the
  // edge came from nearly flat cells (below).
  const bool clip = cover_power < HUGE_VAL && line && line->shape > kShapeFloor;
  if (clip) {
    const double reach = std::sqrt(kCoverMargin * cover_power - line->power);
    const Vec3 &o = line->orthocentre, &n = line->normal;
    const double s0 = (e.source - o).dot(n);
    double lo = s0, hi = s0;
    if (e.is_ray)
      (e.direction.dot(n) >= 0 ? hi : lo) = e.direction.dot(n) >= 0 ? HUGE_VAL : -HUGE_VAL;
    else
      (e.target - o).dot(n) < s0 ? lo = (e.target - o).dot(n) : hi = (e.target - o).dot(n);
    lo = std::max(lo, -reach);
    hi = std::min(hi, reach);
    if (lo <= hi) {
      ++queries_;
      domain_->intersect_segment(o + lo * n, o + hi * n, hits_);
    } else {
      ++skipped_;
      hits_.clear();
    }
  } else {
    ++queries_;
    if (e.is_ray)
      domain_->intersect_ray(e.source, e.direction, hits_);
    else
      domain_->intersect_segment(e.source, e.target, hits_);
  }
  if (hits_.empty()) {
    if (!conditioned) {  // update() must not carry this outcome over
      const Facet m = dt_->mirror_facet(f);
      ref(f.cell, f.index) = ref(m.cell, m.index) = kUntrusted;
    }
    return;
  }
  std::array<WeightedPoint, 3> p{dt_->point(v[0]), dt_->point(v[1]), dt_->point(v[2])};
  const bool trusted = conditioned;
  // Hits come sorted by t then patch; group them per patch (few hits: quadratic is fine).
  std::uint32_t first = kNoFacet, last = kNoFacet;
  for (std::size_t i = 0; i < hits_.size(); ++i) {
    const std::uint32_t patch = hits_[i].patch;
    bool seen = false;
    for (std::size_t j = 0; j < i && !seen; ++j) seen = hits_[j].patch == patch;
    if (seen) continue;
    double best = -HUGE_VAL;
    Vec3 best_point = hits_[i].point;
    int crossings = 0;
    for (std::size_t j = i; j < hits_.size(); ++j) {
      if (hits_[j].patch != patch) continue;
      crossings += hits_[j].coplanar ? 2 : 1;  // a coplanar run's ends move with the segment's
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
    r.carriable = trusted && crossings == 1;
    if (last == kNoFacet)
      first = s;
    else
      records_[last].next = s;
    last = s;
    for (int k = 0; k < 3; ++k) {
      const PointId u = v[k];
      by_vertex_.push(u, {s, patch, {v[k == 0 ? 1 : 0], v[k == 2 ? 1 : 2]}});
    }
    made_.push_back({v[0], v[1], v[2], patch});
    if (heap_active_) heap_.emplace(r.power, s, r.stamp);
    if (badness_) {
      const double b = badness_(r);
      if (b > 1) bad_heap_.emplace(order_key(b, r.point), s, r.stamp);
    }
  }
  if (first == kNoFacet) return;
  ref(f.cell, f.index) = first;
  const Facet m = dt_->mirror_facet(f);
  ref(m.cell, m.index) = first;
}

double RestrictedFacets::order_key(double badness, const Vec3& x) const {
  // Step 2(b) may insert the points of bad facets in any order (§3: each keeps weighted distance
  // above λ from all of S, whatever came before). Largest first grades the mesh; within an
  // eighth of an octave of badness the order is the Morton order of the points instead, so that
  // consecutive insertions touch neighbouring cells: after the initial sample the facets left
  // to refine all lie in one or two such bands (sizes just above λ) and come out in a spatially
  // coherent order (step 2's insertions -4 to -17%, the same angles). The key is the band plus a
  // fraction in [0, 1) decreasing along a 42-bit Morton code (14 bits per axis of the box); the
  // band stays far below 2^11, so the sum is exact in a double.
  const Vec3 extent = (box_.hi - box_.lo).cwiseMax(Vec3::Constant(1e-300));
  std::uint32_t q[3];
  for (int k = 0; k < 3; ++k)
    q[k] = static_cast<std::uint32_t>(std::clamp((x[k] - box_.lo[k]) / extent[k], 0.0, 1.0) * 16383.0);
  std::uint64_t code = 0;
  for (int bit = 13; bit >= 0; --bit)
    for (int k = 0; k < 3; ++k) code = code << 1 | ((q[k] >> bit) & 1u);
  return std::floor(std::log2(badness) * 8) + static_cast<double>((std::uint64_t{1} << 42) - 1 - code) * 0x1.0p-42;
}

void RestrictedFacets::touch_changed(kernel::LargeVector<PointId>& touched) {
  auto touch = [&](const std::array<std::uint32_t, 4>& t) { touched.insert(touched.end(), t.begin(), t.begin() + 3); };
  if (gone_.empty() || made_.empty()) {
    // Nothing to cancel out (rebuild from an empty set: every record new): no sort needed
    // (1.4% of meshing the cube when rebuild sorted its 110,000 records).
    for (const auto& t : gone_) touch(t);
    for (const auto& t : made_) touch(t);
    gone_.clear();
    made_.clear();
    return;
  }
  // The disk condition at v reads only the (triangle, patch) pairs incident to v: a facet
  // re-examined with the same outcome (the common case on the cavity's boundary) changes nothing.
  std::sort(gone_.begin(), gone_.end());
  std::sort(made_.begin(), made_.end());
  std::size_t i = 0, j = 0;
  while (i < gone_.size() || j < made_.size()) {
    if (j == made_.size() || (i < gone_.size() && gone_[i] < made_[j]))
      touch(gone_[i++]);
    else if (i == gone_.size() || made_[j] < gone_[i])
      touch(made_[j++]);
    else
      ++i, ++j;
  }
  gone_.clear();
  made_.clear();
}

void RestrictedFacets::rebuild(kernel::LargeVector<PointId>& touched, const std::function<void()>& tick, double cover_power) {
  for (FacetRef& r : facet_refs_) forget(r);
  cover_power_ = cover_power;
  // Room for what step 2 adds after the first examination (1-27% more vertices on the CGAL demo
  // models), reserved now: growing these past their size later would copy them whole and fault
  // in a new block twice their size (on the cube at 0.456%, 19 MB for facet_refs_ after 14
  // insertions). Reserved and untouched memory costs no page fault.
  const std::size_t cells = dt_->cell_capacity(), points = dt_->number_of_points();
  const std::size_t cell_room = cells + cells / kGrowthRoom + 64, point_room = points + points / kGrowthRoom + 64;
  flat_.reserve(cell_room);
  facet_refs_.reserve(4 * cell_room);
  created_mark_.reserve(cell_room);
  by_vertex_.reserve(point_room);
  // About two restricted facets a vertex on a surface.
  records_.reserve(2 * point_room);
  flat_.assign(cells, kFlatUnknown);
  facet_refs_.assign(4 * cells, kNoFacet);
  // Which cells are live and finite, in one sequential pass: asking the neighbour itself below
  // was a cache miss per facet (cell ids follow the free list, scattered in space), three
  // quarters of this loop's own time on the cube at 1.87%, for facets the cover then skips
  // without reading that cell.
  kernel::LargeVector<std::uint8_t> finite(cells);
  for (CellId c = 0; c < cells; ++c) finite[c] = dt_->is_cell_alive(c) && !dt_->is_infinite(c);
  for (CellId c = 0; c < cells; ++c) {
    // Each finite facet once: from its finite cell of smaller id (a hull facet from its only
    // finite cell); facets through the infinite vertex have no dual edge.
    if (tick && (c & 0xffff) == 0xffff) tick();
    if (!finite[c]) continue;
    // The cell's excluded vertices, by index: every facet but the one opposite such a vertex
    // has it, and examine() would only find that out (on a convex model a third of the facets
    // are the frame's).
    unsigned excluded_at = 0;
    for (int i = 0; i < 4; ++i) {
      const PointId v = dt_->vertex(c, i);
      if (v < excluded_.size() && excluded_[v]) excluded_at |= 1u << i;
    }
    for (int i = 0; i < 4; ++i) {
      if ((excluded_at & ~(1u << i)) != 0) continue;
      const CellId other = dt_->neighbour(c, i);
      if (other < c && finite[other]) continue;
      examine(Facet{c, i}, cover_power);
    }
  }
  touch_changed(touched);
}

std::optional<std::uint32_t> RestrictedFacets::carry_over(std::uint32_t first, PointId inserted) {
  for (std::uint32_t s = first; s != kNoFacet; s = records_[s].next)
    if (!records_[s].carriable || records_[s].discarded) return std::nullopt;
  const double* p = dt_->point(inserted).data();
  std::uint32_t head = kNoFacet, last = kNoFacet;
  for (std::uint32_t s = first; s != kNoFacet;) {
    RestrictedFacet& r = records_[s];
    const std::uint32_t next = r.next;
    const double x[3] = {r.point.x(), r.point.y(), r.point.z()};
    // Exact: x stays on the shrunk V_t iff it is not strictly power-closer to the new point.
    if (kernel::compare_power_distance(x, dt_->point(r.vertices[0]).data(), p) > 0) {
      forget_record(s);
    } else {
      r.kept = update_epoch_;
      r.next = kNoFacet;
      if (last == kNoFacet)
        head = s;
      else
        records_[last].next = s;
      last = s;
    }
    s = next;
  }
  return head;
}

void RestrictedFacets::update(const delaunay::ChangeSet& changes, kernel::LargeVector<PointId>& touched, PointId inserted) {
  const bool insertion = inserted != delaunay::kNoPoint;
  if (!insertion) cover_power_ = std::numeric_limits<double>::infinity();  // see rebuild()
  if (facet_refs_.size() < 4 * dt_->cell_capacity()) facet_refs_.resize(4 * dt_->cell_capacity(), kNoFacet);
  updating_ = true;
  if (created_mark_.size() < dt_->cell_capacity()) created_mark_.resize(dt_->cell_capacity(), 0);
  // A created cell may reuse a destroyed one's slot: forget what well_conditioned() knew of it.
  if (flat_.size() < dt_->cell_capacity()) flat_.resize(dt_->cell_capacity(), kFlatUnknown);
  for (const CellId c : changes.created) flat_[c] = kFlatUnknown;
  ++update_epoch_;
  // What the boundary facets held, read from the destroyed side (ChangeSet::replaced) before the
  // loop below clears it: those lines are about to be read anyway, while the surviving
  // neighbour's would be one more cache miss per boundary facet. Both sides of a facet between
  // live cells always hold the same reference.
  const bool mapped = insertion && changes.replaced.size() == changes.created.size();
  boundary_refs_.clear();
  if (mapped)
    for (const Facet x : changes.replaced) boundary_refs_.push_back(ref(x.cell, x.index));
  // Destroyed first: their slots may have been recycled by created cells, and still hold the old
  // references. After an insertion the records are only set aside here, since a facet on the
  // cavity's boundary may carry its records over (below); the rest are forgotten at the end.
  doomed_.clear();
  for (const CellId c : changes.destroyed)
    for (int i = 0; i < 4; ++i) {
      FacetRef& r = ref(c, i);
      if (insertion) {
        if (names_record(r)) doomed_.push_back(r);
        r = kNoFacet;
      } else {
        forget(r);
      }
    }
  // Which neighbours were created too. After an insertion every created cell has the new point
  // as a vertex and no surviving one has: the facet opposite it lies on the cavity's boundary,
  // the other three between created cells. That reads the cell just made instead of a mark in
  // a side array (a cache miss per facet, ~1.5% of meshing); removals use the marks.
  if (!insertion)
    for (const CellId c : changes.created)
      if (dt_->is_cell_alive(c)) created_mark_[c] = update_epoch_;
  for (std::size_t k = 0; k < changes.created.size(); ++k) {
    const CellId c = changes.created[k];
    if (!dt_->is_cell_alive(c)) continue;
    const int inf = dt_->infinite_index(c);
    for (int i = 0; i < 4; ++i) {
      if (inf >= 0 && inf != i) continue;  // a facet through the infinite vertex: no dual edge
      // Each facet once: a facet between two created cells from the one of smaller id.
      const CellId n = dt_->neighbour(c, i);
      const bool n_created = insertion ? dt_->vertex(c, i) != inserted : created_mark_[n] == update_epoch_;
      if (n_created && n < c) continue;
      const Facet f = inf == i ? dt_->mirror_facet(Facet{c, i}) : Facet{c, i};  // hull facet: from its finite cell
      const Facet m = dt_->mirror_facet(f);
      // A facet on the boundary of an insertion's cavity (its other cell n survives) keeps the
      // part of its old dual edge that stays power-closer to t than to the new point: inserting
      // a point only carves its cell out of the others, V_t(new) = V_t(old) ∩ {x : π(x, t) <=
      // π(x, p)} (§1.2's power diagram; a hidden point's cell was empty already). So the new
      // dual meets exactly the old crossings on that side, and no query is needed: if the old
      // dual met no patch - n's side of the facet holds no record, not even a stale one - the
      // new one meets none either (~40% of a cavity's facets are such boundary facets, most of
      // them off the surface); if it crossed each patch once, each record stays or goes by one
      // exact comparison (carry_over). The old outcome must have been computed well-conditioned
      // (see well_conditioned), and the facet with its new cell must be well-conditioned too, else
      // it is recomputed: a fresh examination of the same cells, which is what a scan of the final
      // triangulation (restricted_facets_check.h) does, then gives the same outcome.
      if (insertion && !n_created) {
        const Facet old = inf == i ? f : m;  // the surviving cell's side
        const FacetRef r = mapped ? boundary_refs_[k] : ref(old.cell, old.index);
        if (r == kNoFacet && well_conditioned(f)) {
          ref(c, i) = kNoFacet;
          continue;
        }
        if (names_record(r) && records_[r].alive && well_conditioned(f)) {
          if (const auto head = carry_over(r, inserted)) {
            ref(old.cell, old.index) = ref(c, i) = *head;
            continue;
          }
        }
      }
      // Any record still reachable from either side is stale (its dual edge changed).
      forget(ref(f.cell, f.index));
      forget(ref(m.cell, m.index));
      examine(f, cover_power_);
    }
  }
  for (FacetRef& r : doomed_)
    if (records_[r].kept != update_epoch_) forget(r);
  free_.insert(free_.end(), free_later_.begin(), free_later_.end());
  free_later_.clear();
  updating_ = false;
  touch_changed(touched);
}

namespace {

// Lazy deletion: pops entries whose record died, was reused (stamp) or was discarded.
template <class Heap>
std::uint32_t top_live(Heap& heap, const kernel::LargeVector<RestrictedFacet>& records) {
  while (!heap.empty()) {
    const auto [key, s, stamp] = heap.top();
    if (records[s].alive && records[s].stamp == stamp && !records[s].discarded) return s;
    heap.pop();
  }
  return kNoFacet;
}

}  // namespace

std::uint32_t RestrictedFacets::largest() {
  if (!heap_active_) {
    // First call: the heap is made from the live records and kept from then on. The mesher asks
    // only when step 2(a) falls back to the global choice, which with its default local choice
    // may be never: pushing every record made (~9 per insertion) and popping them again as
    // stale cost ~3% of meshing for nothing.
    std::vector<HeapEntry> entries;
    for_each([&](std::uint32_t s, const RestrictedFacet& r) { entries.emplace_back(r.power, s, r.stamp); });
    heap_ = std::priority_queue<HeapEntry>(std::less<HeapEntry>(), std::move(entries));
    heap_active_ = true;
  }
  return top_live(heap_, records_);
}
std::uint32_t RestrictedFacets::worst() { return top_live(bad_heap_, records_); }

}  // namespace delpsc::refine
