// Separate, DelPSC §2.2: while two balls centred on different curves intersect, refine the
// larger (the first if equal). Done in rounds (protect.h): each round looks at the candidate
// balls - at first all of them, then those the previous round made - collects the ball to
// refine of every intersecting pair and of every adjacent pair failing C2 or C3.a, and refines
// them together. A pair that intersected loses a ball in the round, so any pair still
// intersecting afterwards involves a new ball: the new balls are the next candidates.
#include <algorithm>

#include "ball_checker.h"
#include "protect_engine.h"

namespace delpsc::protect::detail {

namespace {

// The ball of an adjacent pair (a, b) that must be refined, or kNoBall if the pair satisfies C2
// and C3.a wherever it is adjacent (two corner balls are never adjacent; a corner ball and the
// only interior ball of a closed curve are adjacent on both sides of the corner).
BallId adjacent_culprit(const BallSet& balls, BallId a, BallId b) {
  if (!intersect_deeply(balls[a], balls[b])) return balls[a].radius >= balls[b].radius ? a : b;
  const BallId interior = balls[a].is_corner() ? b : a;
  const BallId other = interior == a ? b : a;
  const std::uint32_t curve = balls[interior].curve;
  const BallOnCurve vi{interior, balls[interior].s};
  // The other ball as the curve sees it, on each side where it is the interior ball's neighbour.
  BallOnCurve sides[2];
  int n = 0;
  const BallOnCurve before = balls.before(interior), after = balls.after(interior);
  if (before.id == other) sides[n++] = before;
  if (after.id == other) sides[n++] = after;
  for (int k = 0; k < n; ++k) {
    if (!c3a_holds(balls, vi, balls.segment_on(curve, vi), sides[k])) return interior;
    if (!c3a_holds(balls, sides[k], balls.segment_on(curve, sides[k]), vi)) return other;
  }
  return kNoBall;
}

}  // namespace

void separate(Engine& engine, std::vector<BallId> candidates) {
  BallSet& balls = engine.balls;
  std::vector<BallId> to_refine, near;
  while (!candidates.empty()) {
    to_refine.clear();
    for (const BallId id : candidates) {
      engine.poll_stop();  // a round scans every candidate: seconds at millions of balls
      if (!balls.alive(id)) continue;
      near.clear();
      balls.balls_meeting(balls[id].centre, balls[id].radius, near);
      for (const BallId other : near) {
        if (other == id || separated(balls, id, other)) continue;
        ++engine.stats.conflicts;
        to_refine.push_back(balls[id].radius >= balls[other].radius ? id : other);
      }
      for (const BallId other : balls.neighbours(id)) {
        const BallId culprit = adjacent_culprit(balls, id, other);
        if (culprit == kNoBall) continue;
        ++engine.stats.repairs;
        to_refine.push_back(culprit);
      }
    }
    if (to_refine.empty()) break;
    ++engine.stats.separate_rounds;
    std::sort(to_refine.begin(), to_refine.end());
    to_refine.erase(std::unique(to_refine.begin(), to_refine.end()), to_refine.end());
    candidates = refine_balls(engine, to_refine);
  }
}

}  // namespace delpsc::protect::detail
