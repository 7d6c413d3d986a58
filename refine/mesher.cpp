#include "mesher.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <delpsc/kernel/predicates.h>

#include "cell_surface_point.h"
#include "extra_pieces.h"
#include "initial_sample.h"

namespace delpsc::refine {

using delaunay::CellId;
using delaunay::PointStatus;

namespace {

VertexPlace on_patch(std::uint32_t patch) {
  VertexPlace v;
  v.kind = VertexPlace::Kind::surface;
  v.patch = patch;
  return v;
}

// A protecting ball's vertex: its key, and the curve or corner it protects.
VertexPlace of_ball(BallKey key, const ProtectingBall& b) {
  VertexPlace v;
  v.kind = VertexPlace::Kind::ball;
  v.ball = key;
  v.curve = b.curve;
  v.corner = b.corner;
  return v;
}

}  // namespace

Mesher::Mesher(const Domain& domain, BallSource& balls, const MesherOptions& options)
    : domain_(&domain),
      balls_(&balls),
      options_(options),
      criteria_(FacetCriteriaOptions{options.facet_size, options.sizing, options.facet_distance, options.facet_angle}),
      facets_(dt_, domain),
      disk_(domain, balls, places_) {
  facets_.set_badness([this](const RestrictedFacet& r) { return criteria_.badness(r, dt_); });
  // Outside (0, 1] select_sample would choose nothing, and the run would quietly start as the
  // paper's instead.
  if (!(options.sample_ball_clearance > 0 && options.sample_ball_clearance <= 1))
    throw std::invalid_argument("sample_ball_clearance must be in (0, 1] (got " +
                                std::to_string(options.sample_ball_clearance) + ")");
}

void Mesher::seed_points(std::vector<Vec3>& seeds, std::vector<std::uint32_t>& seed_patch) const {
  const kernel::Box3 box = domain_->bounding_box();
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  const double diag = (box.hi - box.lo).norm();
  const Vec3 dirs[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
  std::vector<SurfaceHit> hits;
  for (std::uint32_t patch = 0; patch < domain_->patch_count(); ++patch) {
    if (!domain_->patch_curves(patch).empty()) continue;
    // Candidates: where lines through the patch's interior point and through the box centre
    // meet the patch. Then farthest-point sampling from the interior point.
    std::vector<Vec3> candidates{domain_->patch_interior_point(patch)};
    for (const Vec3& through : {candidates[0], centre})
      for (const Vec3& d : dirs) {
        const Vec3 u = d.normalized() * 2 * diag;
        domain_->intersect_segment(through - u, through + u, hits);
        for (const SurfaceHit& h : hits)
          if (h.patch == patch) candidates.push_back(h.point);
      }
    std::vector<Vec3> chosen{candidates[0]};
    std::vector<double> dist(candidates.size());
    for (std::size_t i = 0; i < candidates.size(); ++i) dist[i] = (candidates[i] - chosen[0]).squaredNorm();
    while (static_cast<int>(chosen.size()) < options_.seeds_per_patch) {
      const auto far = std::max_element(dist.begin(), dist.end()) - dist.begin();
      if (dist[far] <= 1e-18 * diag * diag) break;
      chosen.push_back(candidates[far]);
      for (std::size_t i = 0; i < candidates.size(); ++i)
        dist[i] = std::min(dist[i], (candidates[i] - chosen.back()).squaredNorm());
    }
    for (const Vec3& p : chosen) {
      seeds.push_back(p);
      seed_patch.push_back(patch);
    }
  }
}

namespace {
// MesherOptions::stop answered true inside initialise(): thrown only between two insertions or
// two examined cells, where the triangulation and the restricted facets are whole.
struct StopRequested {};
}  // namespace

void Mesher::stop_if_asked() const {
  if (options_.stop && options_.stop()) throw StopRequested{};
}

void Mesher::initialise() {
  const kernel::Box3 box = domain_->bounding_box();
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  const double diag = std::max((box.hi - box.lo).norm(), 1e-300);
  kernel::LargeVector<WeightedPoint> points;
  kernel::LargeVector<VertexPlace> places;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner = centre + 3 * diag * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
    points.push_back(WeightedPoint::from(corner));
    places.emplace_back();
  }
  frame_points_ = 8;
  const std::vector<BallKey> keys = balls_->live_balls();
  for (const BallKey k : keys) {
    const ProtectingBall b = balls_->ball(k);
    points.push_back(WeightedPoint::from(b.centre, b.radius * b.radius));
    places.push_back(of_ball(k, b));
  }
  std::vector<Vec3> seeds;
  std::vector<std::uint32_t> seed_patch;
  seed_points(seeds, seed_patch);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const double x[3] = {seeds[i].x(), seeds[i].y(), seeds[i].z()};
    // Admissibility: no seed inside a ball (balls of other components may reach this patch).
    const bool inside = std::any_of(keys.begin(), keys.end(), [&](BallKey k) {
      const ProtectingBall b = balls_->ball(k);
      const WeightedPoint w = WeightedPoint::from(b.centre, b.radius * b.radius);
      return kernel::power_distance_sign(x, w.data()) <= 0;
    });
    if (inside) continue;
    points.push_back(WeightedPoint::from(seeds[i]));
    places.push_back(on_patch(seed_patch[i]));
    ++stats_.seeds;
  }
  stop_if_asked();
  add_initial_sample(keys, points, places);
  stop_if_asked();
  // The sample makes this phase long on big models: the progress line keeps moving.
  const auto tick = [this] {
    if (options_.progress) options_.progress(domain_vertex_count());
    stop_if_asked();
  };
  std::vector<PointId> ids;
  // Room for step 2's points too (1-27% more on the CGAL demo models): the per-point arrays of
  // the triangulation and places_ then grow in place instead of being copied to new blocks
  // (reserved memory that is never written costs no page fault).
  const std::size_t room = points.size() + points.size() / RestrictedFacets::kGrowthRoom + 64;
  dt_.reserve(room);
  places_.reserve(room);
  // The frame first (see insert()): on the cube at 0.456% its corners, left to the spatial
  // order, made eight cavities of 2,700-14,600 cells; 6.5% of the run's instructions.
  dt_.insert(points, &ids, [&](std::size_t) { tick(); }, frame_points_);
  places_.assign(dt_.number_of_points(), {});
  for (std::size_t i = 0; i < ids.size(); ++i) {
    places_[ids[i]] = places[i];
    if (places[i].kind == VertexPlace::Kind::ball) ball_point_[places[i].ball] = ids[i];
  }
  // The frame points' power cells miss the domain (mesher.h): their facets need no query.
  facets_.exclude_vertices(std::span<const PointId>(ids).first(frame_points_));
  touched_.clear();
  // The sample's proven cover spares most of the first examination's queries (rebuild).
  facets_.rebuild(touched_, tick, sample_cover_power_);
  stats_.cover_skipped = facets_.skipped();
  stats_.first_queries = facets_.queries();
  for (PointId p = 0; p < places_.size(); ++p) recheck(p);
  refinements_at_full_check_ = stats_.ball_refinements;
  stats_.initialised = true;
}

void Mesher::add_initial_sample(std::span<const BallKey> keys, kernel::LargeVector<WeightedPoint>& points,
                                kernel::LargeVector<VertexPlace>& places) {
  // Candidates come at λ's density; with a sizing function each is tested against its own
  // spacing min(λ, sizing(x)) (scaled by kGapFillSpacing for the gap fillers; where sizing asks
  // for less than λ the sample is only as dense as λ's, and refinement does the rest). A sizing
  // function alone (no λ): the paper's start.
  if (!options_.initial_sample || !(options_.facet_size > 0)) return;
  kernel::LargeVector<Vec3> candidates;
  kernel::LargeVector<std::uint32_t> patches;
  // About 1 candidate in 6 or 7 is chosen, and the lattice tries more sites than it keeps. A
  // size far too small for the cap would exhaust memory here (~50 bytes a candidate), so the
  // candidates are bounded by the cap - but generously: with 8 per allowed vertex, a cap just
  // above what the size needs left the lattice out or the sample altogether, and a cap never
  // reached changed the mesh (fandisk at 0.3%: 66,008 vertices without a cap, 78,111 under
  // a cap of 80,000, none of the sample under 66,100). A sample that does not fit under the cap
  // is still left out below.
  constexpr std::size_t kCandidatesPerAllowedVertex = 64;
  const std::size_t cap = options_.max_vertices;
  const std::size_t budget =
      cap > 0 && cap < 0xffffffffu / kCandidatesPerAllowedVertex ? kCandidatesPerAllowedVertex * cap : 0xffffffffu;
  const CandidateParts parts = domain_->surface_candidates(options_.facet_size, budget, candidates, patches);
  std::vector<WeightedPoint> balls;
  double largest_radius = 0;
  for (const BallKey k : keys) {
    const ProtectingBall b = balls_->ball(k);
    balls.push_back(WeightedPoint::from(b.centre, b.radius * b.radius));
    largest_radius = std::max(largest_radius, b.radius);
  }
  std::vector<Vec3> fixed;  // the seeds chosen above
  for (std::size_t i = 0; i < points.size(); ++i)
    if (places[i].kind == VertexPlace::Kind::surface) fixed.push_back(points[i].point());
  std::vector<double> local;
  if (options_.sizing) {
    local.resize(candidates.size());
    for (std::size_t i = 0; i < candidates.size(); ++i)
      if (const double s = options_.sizing(candidates[i]); s > 0) local[i] = std::min(options_.facet_size, s);
      // else 0 (also for NaN): the candidate is skipped; FacetCriteria reports a bad sizing
  }
  bool net_decided = false;
  const std::vector<std::uint32_t> chosen =
      select_sample(candidates, parts, balls, fixed, options_.facet_size, local, &net_decided,
                    options_.sample_ball_clearance, options_.stop);
  // --max-vertices bounds the whole run: a sample that would pass it is left out, and the
  // paper's start then refines coarse to fine up to the cap, a coarse mesh of all the model
  // rather than a part of a fine one.
  if (options_.max_vertices > 0 && keys.size() + fixed.size() + chosen.size() > options_.max_vertices) return;
  points.reserve(points.size() + chosen.size());
  places.reserve(places.size() + chosen.size());
  for (const std::uint32_t i : chosen) {
    points.push_back(WeightedPoint::from(candidates[i]));
    places.push_back(on_patch(patches[i]));
    ++stats_.sampled;
  }
  // Every ball, seed and chosen point goes into the triangulation (a hidden one is dominated
  // by the vertices there), which is what the bound assumes; the net was chosen from at the
  // gap fillers' spacing.
  if (net_decided && parts.net_radius > 0)
    sample_cover_power_ = sample_cover_power(kGapFillSpacing * options_.facet_size, parts.net_radius, largest_radius,
                                             options_.sample_ball_clearance);
}

DiskVerdict Mesher::recheck(PointId p) {
  failing_d12_.erase(p);
  failing_d34_.erase(p);
  if (p >= places_.size() || places_[p].kind == VertexPlace::Kind::outside) return {};
  if (dt_.status(p) != PointStatus::vertex) {
    // A hidden ball still protects its curve but has no umbrella: D1 fails at it.
    if (dt_.status(p) != PointStatus::hidden || places_[p].kind != VertexPlace::Kind::ball) return {};
    failing_d12_.insert(p);
    return {DiskFailure::d1};
  }
  const DiskVerdict v = disk_.check(p, facets_);
  if (v.failure == DiskFailure::d1 || v.failure == DiskFailure::d2) failing_d12_.insert(p);
  if (v.failure == DiskFailure::d3 || v.failure == DiskFailure::d4) failing_d34_.insert(p);
  return v;
}

void Mesher::apply(const delaunay::ChangeSet& changes, PointId inserted) {
  touched_.clear();
  facets_.update(changes, touched_, inserted);
  for (const PointId p : changes.hidden) touched_.push_back(p);
  for (const PointId p : changes.revealed) touched_.push_back(p);
  std::sort(touched_.begin(), touched_.end());
  touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
  for (const PointId p : touched_) recheck(p);
}

bool Mesher::insert_surface_point(std::uint32_t slot) {
  const RestrictedFacet r = facets_[slot];
  const double x[3] = {r.point.x(), r.point.y(), r.point.z()};
  // x lies on V_t: t's vertices are its power-nearest, so positive power distance to them means
  // positive power distance to every vertex, i.e. x lies in no ball (admissibility, §2.1).
  for (const PointId v : r.vertices) {
    if (kernel::power_distance_sign(x, dt_.point(v).data()) > 0) continue;
    ++stats_.refused_inside_ball;
    if (places_[v].kind == VertexPlace::Kind::ball) {
      refine_ball(places_[v].ball);
      return true;
    }
    // x on an unweighted vertex of t: impossible for a point of V_t (it would be power-
    // equidistant at distance size > 0); the dual edge was computed too inaccurately (a nearly
    // flat cell). Stop offering this record, as for a point found off V_t below.
    ++stats_.rejected_inaccurate;
    facets_.discard(slot);
    return true;
  }
  // After the check, `where` is the cell containing the point: the insertion starts there
  // instead of walking the same way again.
  CellId where = dt_.incident_cell(r.vertices[0]);
  if (far_off_dual_edge(r, where)) {
    ++stats_.rejected_inaccurate;
    facets_.discard(slot);
    return true;
  }
  if (!insert_unweighted(r.point, r.patch, where)) {
    // The point is not on V_t after all: the dual edge's ends, orthocentres of nearly flat cells,
    // were computed too inaccurately in doubles. Stop offering this record.
    ++stats_.rejected_inaccurate;
    facets_.discard(slot);
  }
  return true;
}

bool Mesher::insert_unweighted(const Vec3& x, std::uint32_t patch, CellId where) {
  const PointId id = static_cast<PointId>(dt_.number_of_points());
  places_.push_back(on_patch(patch));
  dt_.insert(WeightedPoint::from(x), &changes_, where);
  if (dt_.status(id) != PointStatus::vertex) {  // hidden: forget it
    dt_.remove(id, &changes_);
    places_[id] = {};
    return false;
  }
  apply(changes_, id);
  recheck(id);  // the facets' update names only vertices whose umbrellas changed
  return true;
}

bool Mesher::far_off_dual_edge(const RestrictedFacet& r, CellId& where) const {
  // A point of V_t has t's vertices as its power-nearest. One computed through a nearly flat
  // cell can be grossly wrong: on the crossed ridges at 4% a facet of four co-circular balls
  // got the point of another face 1.09 away, inserted, then re-offered the same point by the
  // next facet of that circle, a cluster of points 1e-16 apart whose tiny facets failed D2
  // forever (400,000 vertices). Any vertex much nearer to the point proves it off V_t; the
  // vertices of the cell containing it are where such a one sits. The factor 1/2 ignores the
  // rounding of a point genuinely near an end of V_t (a fourth vertex as near as t's).
  const auto power = [&](PointId q) {
    const WeightedPoint& w = dt_.point(q);
    return (w.point() - r.point).squaredNorm() - w.w;
  };
  const double on_edge = power(r.vertices[0]);
  const CellId c = where = dt_.locate(r.point, where);
  for (int i = 0; i < 4; ++i) {
    const PointId v = dt_.vertex(c, i);
    if (v != delaunay::kInfiniteVertex && power(v) < 0.5 * on_edge) return true;
  }
  return false;
}

PointId Mesher::insert_ball(BallKey key) {
  const ProtectingBall b = balls_->ball(key);
  const PointId id = static_cast<PointId>(dt_.number_of_points());
  places_.push_back(of_ball(key, b));
  dt_.insert(WeightedPoint::from(b.centre, b.radius * b.radius), &changes_);
  ball_point_[key] = id;
  // Unweighted points the new ball hides are forgotten (they would break admissibility).
  std::vector<PointId> swallowed;
  for (const PointId h : changes_.hidden)
    if (places_[h].kind == VertexPlace::Kind::surface) swallowed.push_back(h);
  apply(changes_, id);
  recheck(id);  // the facets' update names only vertices whose umbrellas changed
  for (const PointId h : swallowed) remove_point(h);
  return id;
}

void Mesher::remove_point(PointId p) {
  if (dt_.status(p) == PointStatus::removed) return;
  std::string error;
  if (!dt_.remove(p, &changes_, &error)) throw std::logic_error("Mesher: removal failed: " + error);
  apply(changes_, delaunay::kNoPoint);
  recheck(p);
}

void Mesher::refine_ball(BallKey key) {
  ++stats_.ball_refinements;
  const BallUpdate update = balls_->refine(key);
  for (const BallKey k : update.removed) {
    const auto it = ball_point_.find(k);
    if (it == ball_point_.end()) continue;
    const PointId p = it->second;
    ball_point_.erase(it);
    remove_point(p);
  }
  std::vector<PointId> added;
  for (const BallKey k : update.added) added.push_back(insert_ball(k));
  // Unweighted vertices inside a new ball: among its neighbours (a point inside the ball that
  // is not hidden has a power cell touching the ball's).
  std::vector<CellId> star;
  std::vector<PointId> inside;
  for (const PointId b : added) {
    if (dt_.status(b) != PointStatus::vertex) continue;
    star.clear();
    dt_.incident_cells(b, star);
    for (const CellId c : star)
      for (int i = 0; i < 4; ++i) {
        const PointId v = dt_.vertex(c, i);
        if (v == delaunay::kInfiniteVertex || places_[v].kind != VertexPlace::Kind::surface) continue;
        if (kernel::power_distance_sign(dt_.point(v).data(), dt_.point(b).data()) <= 0) inside.push_back(v);
      }
  }
  std::sort(inside.begin(), inside.end());
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  for (const PointId v : inside) {
    ++stats_.swallowed;
    remove_point(v);
  }
}

bool Mesher::refine_around(PointId p, std::uint32_t failing_patch) {
  std::uint32_t best = kNoFacet;
  double d1 = -1;
  BallKey big = kNoBallKey;
  double d2 = -1;
  auto consider_ball = [&](PointId q) {
    if (places_[q].kind != VertexPlace::Kind::ball) return;
    const double r = balls_->ball(places_[q].ball).radius;
    if (r > d2) {
      d2 = r;
      big = places_[q].ball;
    }
  };
  // d2 for a ball p is its own radius. Taking the largest ball of p's umbrella instead made the
  // D2 failures of the curve balls next to a corner refine the corner ball each time: on
  // triceratops.off, at a needle triangle whose ends are 5° wide, the corner ball shrank five
  // times while the failure followed it inward, to the floor. A ball larger than its facets is
  // still refined at its own failure, and the unweighted points joined to it still weigh it.
  consider_ball(p);
  const bool own_ball_only = places_[p].kind == VertexPlace::Kind::ball;
  for (const Incidence& x : facets_.incident(p)) {
    const std::uint32_t slot = x.slot;
    const RestrictedFacet& r = facets_[slot];
    if (!own_ball_only)
      for (const PointId v : r.vertices) consider_ball(v);
    if (r.discarded || r.size <= d1) continue;
    d1 = r.size;
    best = slot;
  }
  // A ball whose umbrella misses the failing patch σ altogether (it has facets on other patches,
  // or none): its largest facets elsewhere do not touch σ. At the tip of a narrow cone meeting a
  // plane there, each RefineBall was preceded by ~1,200 insertions of plane facets around the
  // tip, and the cone's umbrella stayed empty one scale down, to the balls' floor or the vertex
  // cap. σ's own facets one ring out (at p's neighbours) sample σ near p's sphere instead.
  std::uint32_t empty_patch = kNoElement;
  if (own_ball_only && failing_patch != kNoElement) {
    const auto incident = facets_.incident(p);
    if (std::none_of(incident.begin(), incident.end(),
                     [&](const Incidence& x) { return facets_[x.slot].patch == failing_patch; })) {
      empty_patch = failing_patch;
      best = largest_facet_next_to(p, failing_patch, d1);
    }
  }
  const bool corner = big != kNoBallKey && balls_->ball(big).corner != kNoElement;
  if (best != kNoFacet && d1 >= (corner ? kLocalCornerBallRatio : kLocalBallRatio) * d2) {  // a ball only far above its facets
    ++stats_.insertions_disk;
    return insert_surface_point(best);
  }
  if (big == kNoBallKey) return places_[p].kind == VertexPlace::Kind::surface && facets_.incident(p).empty() &&
                                insert_in_own_cell(p);
  // A ball with an empty umbrella: a surface point of its cell instead of a smaller ball, which
  // would have the same empty cell one scale down (cell_surface_point.h). At least 1.5 radii out
  // (power 1.25 r²), so the insertions stay bounded below by the ball's radius.
  if (own_ball_only && empty_patch != kNoElement) {
    const double r = balls_->ball(big).radius;
    const bool none = facets_.incident(p).empty();
    const auto x = surface_point_in_cell(dt_, *domain_, p, 1.25 * r * r, [&](std::uint32_t patch) {
      return none ? disk_.on_patch(p, patch) : patch == empty_patch;
    });
    if (x && insert_unweighted(x->point, x->patch, dt_.incident_cell(p))) {
      ++stats_.insertions_empty_cell;
      return true;
    }
  }
  // C3 (§2.1) broken at p: its centre, a point of its curve segment, inside a larger ball that
  // is not adjacent to it. Lemma 2.3 gives C3 from C3.a and C3.b only once the balls are small
  // next to the curve's shape; a curve folding back within a ball radius of itself (a sheet bent
  // into a hairpin, its boundary coming back 1/400 of the diagonal away) breaks it at coarse
  // sizes. The larger ball is the one too large there: refining p instead left it under that
  // ball at every scale, down to the balls' floor.
  if (own_ball_only)
    if (const BallKey over = larger_ball_over(p); over != kNoBallKey) big = over;
  refine_ball(big);
  return true;
}

bool Mesher::insert_in_own_cell(PointId p) {
  std::vector<CellId> star;
  dt_.incident_cells(p, star);
  double nearest = HUGE_VAL;  // squared distance to p's nearest neighbour
  for (const CellId c : star)
    for (int i = 0; i < 4; ++i)
      if (const PointId q = dt_.vertex(c, i); q != delaunay::kInfiniteVertex && q != p)
        nearest = std::min(nearest, (dt_.point(q).point() - dt_.point(p).point()).squaredNorm());
  const std::uint32_t patch = places_[p].patch;
  const double least = kLocalBallRatio * kLocalBallRatio * nearest;
  const auto x = surface_point_in_cell(dt_, *domain_, p, least, [&](std::uint32_t s) { return s == patch; });
  if (!x || !insert_unweighted(x->point, x->patch, dt_.incident_cell(p))) return false;
  ++stats_.insertions_empty_cell;
  return true;
}

std::uint32_t Mesher::largest_facet_next_to(PointId p, std::uint32_t patch, double& size) const {
  std::uint32_t best = kNoFacet;
  size = -1;
  std::vector<CellId> star;
  dt_.incident_cells(p, star);
  for (const CellId c : star)
    for (int i = 0; i < 4; ++i) {
      const PointId q = dt_.vertex(c, i);
      if (q == delaunay::kInfiniteVertex || q == p) continue;
      for (const Incidence& x : facets_.incident(q)) {
        const RestrictedFacet& r = facets_[x.slot];
        if (r.patch != patch || r.discarded || r.size <= size) continue;
        size = r.size;
        best = x.slot;
      }
    }
  return best;
}

BallKey Mesher::larger_ball_over(PointId p) const {
  const BallKey own = places_[p].ball;
  const ProtectingBall mine = balls_->ball(own);
  BallKey over = kNoBallKey;
  double largest = mine.radius;
  std::vector<CellId> star;
  dt_.incident_cells(p, star);
  for (const CellId c : star)
    for (int i = 0; i < 4; ++i) {
      const PointId q = dt_.vertex(c, i);
      if (q == delaunay::kInfiniteVertex || q == p || places_[q].kind != VertexPlace::Kind::ball) continue;
      const ProtectingBall other = balls_->ball(places_[q].ball);
      if (other.radius <= largest || (other.centre - mine.centre).squaredNorm() >= other.radius * other.radius ||
          balls_->adjacent(own, places_[q].ball))
        continue;
      largest = other.radius;
      over = places_[q].ball;
    }
  return over;
}

// Step 2(a) inserts x for a D3/D4 failure, and the termination proof (Theorem 3.1) bounds x's
// weighted distance to the offending vertex q below by "no two balls from two different 2-faces
// intersect": a ball on a curve off σ keeps away from σ. Protect does not ensure that (C1-C3
// are about curves), and a ball that reaches near σ defeats the bound: each x, power-equidistant
// from q and two points of σ, comes with a new facet of half its size, a bisection toward the
// ball's sphere. On libcgal-demo's boeing.off (a ball on a curve 0.19 off a wing tip's plane)
// 40,000 such insertions piled points 1e-7 apart; boeing and cheese at 1% ran past 90 s (cheese
// to 1.8 GB and the balls' floor), and a cube under a sheet hovering within λ never ended
// (test_mesher_features). They now mesh in 1.5, 3 and 0.1 s. So when x's power distance
// to such a ball q is below q's radius squared (x within √2 radii of its centre), q is the one
// too large here: refine it, as D1/D2 would with d2 > d1. Balls only shrink, so this happens
// finitely often (Lemma 3.1's tree), and once q is small next to its distance from σ the
// insertions of the paper resume.
BallKey Mesher::ball_reaching_patch(const RestrictedFacet& r) const {
  BallKey reaching = kNoBallKey;
  double largest = r.size;
  for (const PointId v : r.vertices) {
    if (places_[v].kind != VertexPlace::Kind::ball || disk_.on_patch(v, r.patch)) continue;
    const double radius = balls_->ball(places_[v].ball).radius;
    if (radius > largest) {
      largest = radius;
      reaching = places_[v].ball;
    }
  }
  return reaching;
}

std::size_t Mesher::domain_vertex_count() const {
  // While a batch is still below dimension 3 its points wait as pending, frame points included.
  const std::size_t n = dt_.number_of_vertices();
  return n > frame_points_ ? n - frame_points_ : 0;
}

void Mesher::run() {
  // max_vertices bounds the whole run, and every protecting ball enters the triangulation
  // first: more balls than the cap cannot end under it. Inserting them anyway was the slowest
  // case there is (curve points without the sample between them: fandisk at --size 0.01% has
  // 97,536 balls, and under --max-vertices 50 took over a minute and 4 GB before refining).
  if (options_.max_vertices > 0) {
    const std::size_t balls = balls_->live_balls().size();
    if (balls > options_.max_vertices) {
      stats_.stopped_at_max_vertices = true;
      stats_.message = "stopped at --max-vertices " + std::to_string(options_.max_vertices) +
                       " before refining: the protecting balls alone number " + std::to_string(balls);
      return;
    }
  }
  try {
    initialise();
  } catch (const StopRequested&) {
    stats_.stopped_on_request = true;
    stats_.message = "stopped on request while initialising";
    return;
  }
  if (dt_.dimension() < 3) {
    stats_.stuck = true;
    stats_.message = "the triangulation did not reach dimension 3";
    return;
  }
  for (std::size_t step = 1;; ++step) {
    if (options_.progress && step % std::max<std::size_t>(options_.progress_every, 1) == 0)
      options_.progress(domain_vertex_count());
    if (step % 64 == 0 && options_.stop && options_.stop()) {
      stats_.stopped_on_request = true;
      stats_.message = "stopped on request";
      return;
    }
    if (options_.max_vertices > 0 && domain_vertex_count() >= options_.max_vertices) {
      stats_.stopped_at_max_vertices = true;
      stats_.message = "stopped at --max-vertices " + std::to_string(options_.max_vertices);
      return;
    }
    if (!failing_d12_.empty()) {
      // Re-verify before acting: an entry goes stale if its vertex's verdict changed without
      // its (triangle, patch) pairs changing (ball adjacency after a RefineBall elsewhere).
      const PointId p = *failing_d12_.begin();
      const DiskVerdict verdict = recheck(p);
      if (failing_d12_.count(p) == 0) continue;
      if (options_.local_disk_refinement && refine_around(p, verdict.patch)) continue;
      ++stats_.global_choices;
      const std::uint32_t top = facets_.largest();
      const double d1 = top == kNoFacet ? -1 : facets_[top].size;
      const BallKey big = balls_->largest();
      const double d2 = big == kNoBallKey ? -1 : balls_->ball(big).radius;
      if (top != kNoFacet && d1 >= d2) {
        ++stats_.insertions_disk;
        if (insert_surface_point(top)) continue;
      } else if (big != kNoBallKey) {
        refine_ball(big);
        continue;
      }
      stats_.stuck = true;
      stats_.message = "D1/D2 fails with nothing left to refine";
      return;
    }
    if (!failing_d34_.empty()) {
      const PointId p = *failing_d34_.begin();
      const DiskVerdict v = disk_.check(p, facets_);
      if (v.facet == kNoFacet) {  // stale entry
        recheck(p);
        if (failing_d34_.count(p) != 0) failing_d34_.erase(p);
        continue;
      }
      // A record whose point proved off V_t (discarded) would be offered again forever: refine
      // around p instead.
      if (facets_[v.facet].discarded) {
        if (refine_around(p, v.patch)) continue;
      } else if (const BallKey near = ball_reaching_patch(facets_[v.facet]); near != kNoBallKey) {
        refine_ball(near);
        continue;
      } else {
        ++stats_.insertions_d34;
        if (insert_surface_point(v.facet)) continue;
      }
      stats_.stuck = true;
      stats_.message = "D3/D4 fails at a point that cannot be inserted";
      return;
    }
    if (const std::uint32_t bad = facets_.worst(); bad != kNoFacet) {  // step 2(b)
      FacetCriterion which = FacetCriterion::none;
      criteria_.badness(facets_[bad], dt_, &which);
      ++(which == FacetCriterion::distance ? stats_.insertions_distance
         : which == FacetCriterion::angle  ? stats_.insertions_angle
                                           : stats_.insertions_size);
      if (insert_surface_point(bad)) continue;
      stats_.stuck = true;
      stats_.message = std::string(to_string(which)) + " criterion: point cannot be inserted";
      return;
    }
    // Nothing flagged. A vertex's verdict depends on its restricted facets, which apply()
    // re-checks whenever they change, and on the balls' adjacency (D3), which only RefineBall
    // changes. With no RefineBall since the last full pass the incremental re-checks saw every
    // change and the disk condition holds everywhere; otherwise confirm with a full pass. (The
    // pass found nothing on any model without ball refinements, and cost 3-4% of the cube.)
    if (stats_.ball_refinements != refinements_at_full_check_ && sweep_failures()) continue;
    if (!options_.refine_extra_pieces || !refine_extra_pieces()) return;
  }
}

// G2 (Theorem 4.3) holds once λ is small enough, but the disk condition that step 2 checks is
// local and passes on a closed piece of a patch's restricted triangles away from the rest
// (extra_pieces.h). Each such piece has its largest facets refined - those within an octave of
// its largest, as step 2(b) takes a band of badness -: each point lies on the patch,
// power-farther than its facet's size from every vertex, so the piece is sampled finer until its
// dual edges no longer cross the patch where they did. The octave keeps the rounds (each a pass
// over every record) to a few per halving of the piece's facets, not one per insertion. Facets
// below kLocalCornerBallRatio times λ there are left as they are (the check reports a piece that
// remains): that floor bounds the insertions by the packing argument of step 2(a)'s local
// choice. (At kLocalBallRatio a cone of 1° on a sheet kept a piece of 24 facets at its tip at
// 1%, the largest 0.38 of that floor; at 1/256 it goes.)
bool Mesher::refine_extra_pieces() {
  // Stamped first: an insertion for one facet may forget another and reuse its slot.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> chosen;  // slot, stamp
  for (const ExtraPiece& piece : extra_pieces(facets_, dt_.number_of_points())) {
    double largest = 0;
    for (const std::uint32_t s : piece.facets)
      if (!facets_[s].discarded) largest = std::max(largest, facets_[s].size);
    for (const std::uint32_t s : piece.facets) {
      const RestrictedFacet& r = facets_[s];
      if (!r.discarded && r.size >= 0.5 * largest && r.size >= kLocalCornerBallRatio * criteria_.size_bound(r.point))
        chosen.emplace_back(s, r.stamp);
    }
  }
  for (const auto& [slot, stamp] : chosen) {
    // The loop asks the cap once a step; a batch would overshoot it.
    if (options_.max_vertices > 0 && domain_vertex_count() >= options_.max_vertices) break;
    if (!facets_[slot].alive || facets_[slot].stamp != stamp || facets_[slot].discarded) continue;
    ++stats_.insertions_pieces;
    insert_surface_point(slot);
  }
  return !chosen.empty();
}

bool Mesher::sweep_failures() {
  ++stats_.full_sweeps;
  refinements_at_full_check_ = stats_.ball_refinements;
  std::size_t found = 0;
  for (PointId p = 0; p < places_.size(); ++p) {
    recheck(p);
    found += failing_d12_.count(p) + failing_d34_.count(p);
  }
  return found > 0;
}

std::vector<std::pair<PointId, DiskVerdict>> Mesher::failing_vertices() const {
  std::vector<std::pair<PointId, DiskVerdict>> out;
  if (!stats_.initialised) return out;  // the restricted facets are not all known
  for (PointId p = 0; p < places_.size(); ++p) {
    if (places_[p].kind == VertexPlace::Kind::outside) continue;
    const PointStatus s = dt_.status(p);
    if (s == PointStatus::vertex) {
      const DiskVerdict v = disk_.check(p, facets_);
      if (v.failure != DiskFailure::none) out.emplace_back(p, v);
    } else if (s == PointStatus::hidden && places_[p].kind == VertexPlace::Kind::ball) {
      out.emplace_back(p, DiskVerdict{DiskFailure::d1, kNoElement, kNoFacet});
    }
  }
  return out;
}

}  // namespace delpsc::refine
