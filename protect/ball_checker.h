// The conditions DelPSC asks of its protecting balls (Dey & Levine 2009, §2.1 and §2.2), checked
// on a BallSet. Used by the tests, by `delpsc protect --check`, and by Protect itself, which
// refines any adjacent pair failing C2 or C3.a (protect.h says when that can happen).
//
//  C1   every corner has a live ball centred exactly on its vertex, radius > 0; every curve's
//       sequence (balls.h) starts and ends with its corners' balls, its interior centres lie on
//       it (centre == point_at(s)) with parameters strictly increasing in (0, length); and,
//       which Protect guarantees beyond the paper, corner balls are pairwise disjoint.
//  C2   adjacent balls b = B(c, r), b' = B(c', r'), r' <= r, intersect deeply:
//       d(c, c') <= r + 6 r'/7.
//  C3.a for adjacent balls b, b' on a curve σ: if c' is in seg_σ(b) then d_σ(c, c') >= 8 r / 7.
//       "In seg_σ(b)" is read for the open ball: c' on the parameter interval of seg_σ(b) and
//       d(c, c') < r. The end game of Cover centres the enlarged aiding ball exactly where the
//       curve leaves the previous ball, on its sphere, at curve distance r from its centre on a
//       straight curve: with the closed ball C3.a would fail there by the paper's own
//       construction, and nothing in Lemma 2.3 needs the boundary.
//  C3.b two balls that share no curve are disjoint: |c - c'| > r + r'. A corner ball lies on
//       every curve ending at its corner, so it is compared only with balls of other curves and
//       with corner balls with which it shares no curve.
//  coverage  every point of every curve lies in seg_σ(b) of some ball of its sequence (the
//       union of the segments, clamped to [0, length], is [0, length]).
//  C3   (counted for information, not part of ok(): the paper replaces it by C3.a and C3.b,
//       which imply it once the balls are small, Lemma 2.3) no point of seg_σ(b) lies inside
//       (open ball, same slack) a ball not adjacent to b. Lemma 2.1, on which the mesher's
//       disk condition rests, needs it. Found exactly touching in a few cases where Cover's
//       steps land on rational multiples of α on straight curves; never inside so far.
//
// Metric comparisons (C2, C3.a) allow a relative slack of kCheckTolerance for the rounding of
// the constructed centres; C3.b and coverage are exact comparisons of the doubles.
// Cost: O(n (log n + k)) for n balls and k polyline vertices per ball, plus the grid queries.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "balls.h"

namespace delpsc::protect {

inline constexpr double kCheckTolerance = 1e-9;

/// Violations found, by condition, and the first few described in words.
struct BallCheck {
  std::size_t c1 = 0, c2 = 0, c3a = 0, c3b = 0, coverage = 0;
  std::size_t c3 = 0;  ///< informational (see above); not part of ok()
  std::vector<std::string> problems;  ///< at most the requested number of lines
  bool ok() const { return c1 + c2 + c3a + c3b + coverage == 0; }
};

/// Checks every condition above on the live balls.
BallCheck check_balls(const BallSet& balls, std::size_t max_messages = 20);

/// C2 for two adjacent balls.
bool intersect_deeply(const Ball& a, const Ball& b);

/// C3.a from ball `a`'s side: false when b's centre is in seg_σ(a) (open reading above) and
/// d_σ(c_a, c_b) < 8 r_a / 7. seg_a is segment_on(curve, a).
bool c3a_holds(const BallSet& balls, const BallOnCurve& a, const CurveInterval& seg_a, const BallOnCurve& b);

/// C3.b for two balls: true when they share a curve or are disjoint.
bool separated(const BallSet& balls, BallId a, BallId b);

}  // namespace delpsc::protect
