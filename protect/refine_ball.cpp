// RefineBall, DelPSC §2.2, applied to a set of balls at once (protect.h explains the runs).
//   vertex ball B(v, r): replaced by B(v, r/2); the ball next to it on every curve ending at v
//                        is refined as well (in the same round);
//   interior ball b:     removed with the rest of its run of consecutive marked balls; the gap
//                        between the run's neighbours b_1, b_2 is covered by
//                        Cover(x, y, r_σ/4), x the end of seg(b_1), y the start of seg(b_2),
//                        r_σ the smallest radius among the run, b_1 and b_2 (the paper's rule;
//                        the graded cover of protect.h is the default).
// Every new ball is at most 7/24 of the radius of a ball it replaces (Lemma 2.5).
//
// The graded cover's cap α_max is a quarter of the run's own radius for a ball refined for its
// own sake (larger than λ, or met by a ball of another curve). A neighbour refined only because
// its vertex ball shrank is not too large itself: it goes so that the gap the shrink opened is
// covered, and its cap is a quarter of the larger of its radius and the vertex ball's new radius.
// With its own quarter, every shrink of a vertex ball made the balls next to it four times
// smaller while the vertex ball only halved: on libcgal-demo's helmet.off (two curves leaving a
// corner 8.4° apart, balls there ~0.03 of their distance to the corner) three shrinks asked by
// the disk condition put balls of 3e-6 of the diagonal 0.002 from the corner, below Protect's
// floor, where the wedge allows ~50 times that. Lemma 2.5 still holds: a new ball is at most
// 7/6 α_max, i.e. at most 7/24 of the neighbour it replaces or of the vertex ball's radius
// before the shrink (twice the new one), the root of this refinement.
// refine_ball (protect.h) is RefineBall of one ball followed by Separate.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "protect_engine.h"

namespace delpsc::protect {

namespace detail {

namespace {

// Refines the run of consecutive marked interior balls that contains `seed`, unmarking them.
// `cap[id]` is the graded cover's α_max for a marked ball (the file comment); along the run each
// step of Cover is held to the envelope of its balls' caps (cap_envelope.h), under every
// ball's own cap on its segment, rather than to the smallest cap of the run.
void refine_run(Engine& engine, BallId seed, std::vector<bool>& marked, const std::vector<double>& cap) {
  BallSet& balls = engine.balls;
  BallId lo = seed, hi = seed;
  // Balls made by earlier runs of this round have ids past the marks: never marked.
  auto is_marked = [&](BallId id) { return id < marked.size() && marked[id]; };
  if (engine.options.refine_runs) {
    while (is_marked(balls[lo].prev)) lo = balls[lo].prev;
    while (is_marked(balls[hi].next)) hi = balls[hi].next;
  }
  const std::uint32_t curve = balls[seed].curve;
  const BallOnCurve left = balls.before(lo), right = balls.after(hi);
  double r_run = balls[lo].radius;  // the smallest radius in the run
  double alpha_max = 0;             // the largest cap: the envelope below bounds each place
  std::vector<CapEnvelope::Piece> pieces;
  for (BallId id = lo;; id = balls[id].next) {
    r_run = std::min(r_run, balls[id].radius);
    alpha_max = std::max(alpha_max, cap[id]);
    const CurveInterval seg = balls.segment_on(curve, {id, balls[id].s});
    pieces.push_back({seg.s0, std::max(seg.s0, seg.s1), cap[id]});
    if (id == hi) break;
  }
  const double r_left = balls[left.id].radius, r_right = balls[right.id].radius;
  CoverSizes sizes;
  std::optional<CapEnvelope> caps;
  if (engine.options.graded_cover) {
    sizes = graded_cover_sizes(alpha_max, r_left, r_right);
    caps.emplace(std::move(pieces), sizes.slope);
    sizes.caps = &*caps;
  } else {
    sizes.alpha = std::min({r_run, r_left, r_right}) / 4;  // r_σ / 4
  }
  for (BallId id = lo, stop = balls[hi].next; id != stop;) {
    const BallId next = balls[id].next;
    marked[id] = false;
    engine.remove_interior(id);
    ++engine.stats.refined;
    id = next;
  }
  cover(engine, curve, left, right, sizes);
}

}  // namespace

std::vector<BallId> refine_balls(Engine& engine, std::span<const BallId> to_refine) {
  BallSet& balls = engine.balls;
  const Complex& complex = engine.complex;
  const std::size_t first_created = engine.created().size();

  // Vertex balls first: shrinking one marks its neighbours, which join the runs below.
  std::vector<BallId> interior;
  std::vector<double> cap(balls.id_bound(), HUGE_VAL);
  const auto mark_for_shrink = [&](BallId id, double vertex_radius) {
    if (id == kNoBall) return;
    interior.push_back(id);
    cap[id] = std::min(cap[id], std::max(balls[id].radius, vertex_radius) / 4);
  };
  for (const BallId id : to_refine) {
    if (!balls.alive(id)) continue;  // a duplicate, or a vertex ball already shrunk this round
    const Ball& b = balls[id];
    if (!b.is_corner()) {
      interior.push_back(id);
      cap[id] = std::min(cap[id], b.radius / 4);
      continue;
    }
    const std::uint32_t corner = b.corner;
    const double shrunk = b.radius / 2;
    engine.set_corner_ball(corner, shrunk);
    ++engine.stats.vertex_shrinks;
    for (const std::uint32_t c : complex.corner_curve_ids(corner)) {
      if (complex.curves[c].start_corner == corner) mark_for_shrink(balls.first_interior(c), shrunk);
      if (complex.curves[c].end_corner == corner) mark_for_shrink(balls.last_interior(c), shrunk);
    }
  }

  std::vector<bool> marked(balls.id_bound(), false);
  for (const BallId id : interior)
    if (id != kNoBall && balls.alive(id)) marked[id] = true;
  for (const BallId id : interior)
    if (id != kNoBall && marked[id] && balls.alive(id)) refine_run(engine, id, marked, cap);

  const auto& created = engine.created();
  std::vector<BallId> made;
  for (std::size_t i = first_created; i < created.size(); ++i)
    if (balls.alive(created[i])) made.push_back(created[i]);
  return made;
}

}  // namespace detail

BallChanges refine_ball(BallSet& balls, BallId b, const ProtectOptions& options, ProtectStats* stats) {
  if (!balls.alive(b)) throw std::invalid_argument("refine_ball: the ball is not alive");
  ProtectStats local;
  detail::Engine engine(balls, options, stats ? *stats : local);
  const BallId one[] = {b};
  detail::separate(engine, detail::refine_balls(engine, one));

  BallChanges changes;
  changes.removed = engine.removed();
  for (const BallId id : engine.created())
    if (balls.alive(id)) changes.added.push_back(id);
  std::sort(changes.removed.begin(), changes.removed.end());
  return changes;
}

}  // namespace delpsc::protect
