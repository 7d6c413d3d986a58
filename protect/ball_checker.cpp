// Checker of C1, C2, C3.a, C3.b and coverage (ball_checker.h).
#include "ball_checker.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

#include <delpsc/kernel/constructions.h>

namespace delpsc::protect {

namespace {

class Report {
 public:
  Report(BallCheck& check, std::size_t max_messages) : check_(check), max_(max_messages) {}

  // Counts one violation and keeps its description while there is room.
  void add(std::size_t& counter, const char* format, ...) __attribute__((format(printf, 3, 4))) {
    ++counter;
    if (check_.problems.size() >= max_) return;
    char line[320];
    va_list args;
    va_start(args, format);
    std::vsnprintf(line, sizeof line, format, args);
    va_end(args);
    check_.problems.emplace_back(line);
  }

 private:
  BallCheck& check_;
  std::size_t max_;
};

void check_corners(const BallSet& balls, BallCheck& check, Report& report) {
  const Complex& complex = balls.complex();
  for (std::uint32_t k = 0; k < complex.corner_count(); ++k) {
    const BallId id = balls.corner_ball(k);
    if (id == kNoBall || !balls.alive(id)) {
      report.add(check.c1, "C1: corner %u has no ball", k);
      continue;
    }
    const Ball& b = balls[id];
    if (b.corner != k || b.centre != complex.vertices[complex.corner_vertex[k]] || !(b.radius > 0))
      report.add(check.c1, "C1: ball %u of corner %u is not centred on it with a positive radius", id, k);
    std::vector<BallId> near;
    balls.balls_meeting(b.centre, b.radius, near);
    for (const BallId other : near)
      if (other > id && balls[other].is_corner())
        report.add(check.c1, "C1: corner balls %u and %u (corners %u, %u) overlap", id, other, k,
                   balls[other].corner);
  }
}

// Distance from p to the curve piece [s0, s1] (the curve's view: may pass a closed curve's
// corner), through the polyline pieces it covers. O(log n + pieces).
double distance_to_piece(const Complex& complex, std::uint32_t c, double s0, double s1, const Vec3& p) {
  const auto params = complex.curve_parameters(c);
  const double length = complex.curves[c].length;
  double best = std::numeric_limits<double>::infinity();
  // A closed curve's piece may run over its corner at either end: look one turn either way.
  const int turns = complex.curves[c].closed ? 1 : 0;
  for (int turn = -turns; turn <= turns; ++turn) {
    const double shift = turn * length;
    const double lo = std::max(s0, shift), hi = std::min(s1, shift + length);
    if (lo > hi) continue;
    // Pieces [params[i], params[i+1]] (shifted) overlapping [lo, hi].
    std::size_t i = static_cast<std::size_t>(std::upper_bound(params.begin(), params.end(), lo - shift) - params.begin());
    i = i > 0 ? i - 1 : 0;
    for (; i + 1 < params.size() && params[i] + shift <= hi; ++i) {
      const double a = std::max(lo, params[i] + shift), b = std::min(hi, params[i + 1] + shift);
      if (a > b) continue;
      const auto q = kernel::closest_point_on_segment(p, complex.point_at(c, a), complex.point_at(c, b));
      best = std::min(best, (q.point - p).norm());
    }
  }
  return best;
}

// C3 on one curve: balls of the whole set inside which some point of seg_σ(b) lies, b's
// neighbours excepted.
void check_c3(const BallSet& balls, std::uint32_t c, const std::vector<BallOnCurve>& seq,
              const std::vector<CurveInterval>& segs, BallCheck& check, Report& report) {
  const Complex& complex = balls.complex();
  std::vector<BallId> near;
  for (std::size_t i = 0; i < seq.size(); ++i) {
    const Ball& b = balls[seq[i].id];
    const std::vector<BallId> adjacent = balls.neighbours(seq[i].id);
    double s0 = segs[i].s0, s1 = segs[i].s1;
    if (!complex.curves[c].closed) s0 = std::max(s0, 0.0), s1 = std::min(s1, complex.curves[c].length);
    // Any ball meeting seg_σ(b) meets b.
    near.clear();
    balls.balls_meeting(b.centre, b.radius, near);
    for (const BallId other : near) {
      if (other == seq[i].id || std::find(adjacent.begin(), adjacent.end(), other) != adjacent.end()) continue;
      const Ball& o = balls[other];
      if (distance_to_piece(complex, c, s0, s1, o.centre) < o.radius * (1 - kCheckTolerance))
        report.add(check.c3, "C3 (information): curve %u: ball %u (r=%.6g) holds a point of seg of ball %u", c, other,
                   o.radius, seq[i].id);
    }
  }
}

// One curve: its sequence (C1), its adjacent pairs (C2, C3.a), the union of its segments.
void check_curve(const BallSet& balls, std::uint32_t c, BallCheck& check, Report& report) {
  const Complex& complex = balls.complex();
  const Curve& curve = complex.curves[c];
  const BallId start = balls.corner_ball(curve.start_corner), end = balls.corner_ball(curve.end_corner);
  if (start == kNoBall || end == kNoBall) return;  // reported by check_corners
  const std::vector<BallOnCurve> seq = balls.curve_sequence(c);
  for (std::size_t i = 1; i + 1 < seq.size(); ++i) {
    const Ball& b = balls[seq[i].id];
    if (!b.alive || b.curve != c || b.is_corner())
      report.add(check.c1, "C1: curve %u lists ball %u, not a live interior ball of it", c, seq[i].id);
    if (!(seq[i - 1].s < b.s && b.s < curve.length))
      report.add(check.c1, "C1: curve %u: ball %u at s=%.17g is out of order", c, seq[i].id, b.s);
    if (b.centre != complex.point_at(c, b.s))
      report.add(check.c1, "C1: curve %u: ball %u is not centred on the curve at its parameter", c, seq[i].id);
  }

  std::vector<CurveInterval> segs(seq.size());
  for (std::size_t i = 0; i < seq.size(); ++i) segs[i] = balls.segment_on(c, seq[i]);
  for (std::size_t i = 0; i + 1 < seq.size(); ++i) {
    const Ball& a = balls[seq[i].id];
    const Ball& b = balls[seq[i + 1].id];
    if (!intersect_deeply(a, b))
      report.add(check.c2, "C2: curve %u: balls %u (r=%.6g) and %u (r=%.6g) at distance %.6g do not intersect deeply",
                 c, seq[i].id, a.radius, seq[i + 1].id, b.radius, (a.centre - b.centre).norm());
    if (!c3a_holds(balls, seq[i], segs[i], seq[i + 1]))
      report.add(check.c3a, "C3.a: curve %u: seg of ball %u (r=%.6g) holds the centre of %u at curve distance %.6g",
                 c, seq[i].id, a.radius, seq[i + 1].id, seq[i + 1].s - seq[i].s);
    if (!c3a_holds(balls, seq[i + 1], segs[i + 1], seq[i]))
      report.add(check.c3a, "C3.a: curve %u: seg of ball %u (r=%.6g) holds the centre of %u at curve distance %.6g",
                 c, seq[i + 1].id, b.radius, seq[i].id, seq[i + 1].s - seq[i].s);
  }

  check_c3(balls, c, seq, segs, check, report);

  // Coverage: sweep the segments by their start.
  std::sort(segs.begin(), segs.end(), [](const CurveInterval& x, const CurveInterval& y) { return x.s0 < y.s0; });
  double reached = 0;
  for (const CurveInterval& seg : segs) {
    if (seg.whole) reached = curve.length;
    if (std::max(seg.s0, 0.0) > reached) {
      report.add(check.coverage, "coverage: curve %u: [%.17g, %.17g] lies in no ball's segment", c, reached,
                 std::min(seg.s0, curve.length));
    }
    reached = std::max(reached, seg.s1);
  }
  if (reached < curve.length)
    report.add(check.coverage, "coverage: curve %u: [%.17g, %.17g] lies in no ball's segment", c, reached, curve.length);
}

}  // namespace

bool intersect_deeply(const Ball& a, const Ball& b) {
  const double big = std::max(a.radius, b.radius), small = std::min(a.radius, b.radius);
  return (a.centre - b.centre).norm() <= (big + 6 * small / 7) * (1 + kCheckTolerance);
}

bool c3a_holds(const BallSet& balls, const BallOnCurve& a, const CurveInterval& seg_a, const BallOnCurve& b) {
  const Ball& A = balls[a.id];
  const Ball& B = balls[b.id];
  const bool on_segment = seg_a.whole || (seg_a.s0 <= b.s && b.s <= seg_a.s1);
  const bool in_open_ball = (A.centre - B.centre).norm() < A.radius * (1 - kCheckTolerance);
  if (!on_segment || !in_open_ball) return true;
  return std::abs(b.s - a.s) >= 8 * A.radius / 7 * (1 - kCheckTolerance);
}

bool separated(const BallSet& balls, BallId a, BallId b) {
  if (balls.share_curve(a, b)) return true;
  return (balls[a].centre - balls[b].centre).norm() > balls[a].radius + balls[b].radius;
}

BallCheck check_balls(const BallSet& balls, std::size_t max_messages) {
  BallCheck check;
  Report report(check, max_messages);
  const Complex& complex = balls.complex();
  check_corners(balls, check, report);
  for (std::uint32_t c = 0; c < complex.curve_count(); ++c) check_curve(balls, c, check, report);
  std::vector<BallId> near;
  for (const BallId id : balls.live_ids()) {
    near.clear();
    balls.balls_meeting(balls[id].centre, balls[id].radius, near);
    for (const BallId other : near)
      if (other > id && !separated(balls, id, other))
        report.add(check.c3b, "C3.b: balls %u and %u share no curve but intersect (r=%.6g, r'=%.6g, d=%.6g)", id,
                   other, balls[id].radius, balls[other].radius, (balls[id].centre - balls[other].centre).norm());
  }
  return check;
}

}  // namespace delpsc::protect
