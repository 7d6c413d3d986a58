// Protect(D, λ) and RefineBall of DelPSC (Dey & Levine 2009, §2.2 and §3): protecting balls
// computed on the fly, with no local feature size and no gap size, only seg_σ(b) (curve ∩ ball).
//
// protect(complex, λ):
//  1. Vertex balls (protect.cpp): B(v, r_v), r_v one third of the distance from v to the
//     nearest other corner (a KD-tree query). Where the paper leaves it open: a corner with no
//     other corner uses one third of the bounding-box diagonal; a corner on a closed curve of
//     length L takes at most L/6 and is halved while its segment on that curve spans more than
//     half of it (else the corner ball could swallow its own loop and leave Cover nothing to
//     cover). Then r_v is halved until r_v <= λ — what step 3's RefineBall would do to a vertex
//     ball, done before the curves are covered so they are covered once.
//  2. Each curve σ(u, v) is covered by Cover(x, y, α), α = min(r_u, r_v) (cover.cpp): aiding
//     balls β = B(y_i, α/3), next centre where seg_σ(β) ends, radius α, and the end game with the
//     enlarged aiding ball (2α/3) or the last ball enlarged (7α/6), exactly as §2.2. Except
//     where min(r_u, r_v) < λ/16 (with graded_cover): two corners 10^-5 apart put a ball of
//     that size on every curve leaving either, and the paper's uniform α would then cover a
//     curve of length L with some L/α balls (on the libcgal-demo model mpi.off at λ = 2%, more
//     than 10,000 after its first 29 curves). Such a curve gets the graded size below with
//     α_max = 6λ/7 (its 7α/6 end game stays within λ), small next to the small vertex ball and
//     growing along the curve (a frustum with a top 1e-5 wide, test_protect: under 2,000 balls
//     in all, where the uniform cover passes 100,000).
//  3. Balls larger than λ are refined (refine_ball.cpp).
//  4. Separate (separate.cpp) until balls on different curves are disjoint (C3.b).
//
// RefineBall(b): a vertex ball is shrunk to half its radius and the ball next to it on every
// curve ending there is refined; another ball is removed and the curve between its neighbours'
// segments is covered again. The paper covers it with α = r_σ/4, r_σ the smallest radius among
// the ball and its two neighbours (graded_cover = false). That is the one rule here that is not
// the paper's by default, for this reason: when the neighbour b_1 was itself just refined, its
// radius is up to 6 times smaller than the others (an end-game ball of 2/3 of a quarter), so
// the whole gap is covered with balls 4 to 6 times smaller again, and the next ball along is
// refined next to those: refining the largest ball over and over, as the mesher does (§3),
// shrinks the balls along a curve geometrically. Measured on the cube at λ = 4% of the diagonal,
// 25 refinements of the largest ball: with α = r_σ/4 the 16th passes 200,000 balls (the 13th
// alone adds 20,000); graded, they add 4 to 24 balls each.
//   Graded cover (the default): α_max(b) = r_b/4 for each ball b of a run (for a neighbour
// refined only because its vertex ball shrank, the larger of its radius and the vertex ball's
// new one, refine_ball.cpp), and the α of each step of Cover, read at the parameter s where the
// step leaves seg(b_i), is
//     min(H(s), 0.6 r_1 + 0.1 d_σ(x, s), 0.6 r_2 + 0.1 d_σ(s, y)),
// small next to a small neighbour and growing along the curve, with
// H(s) = min_b (α_max(b) + 0.1 d_σ(s, seg(b))) over the run (cap_envelope.h): at most each
// ball's own α_max on its segment, and growing no faster than the other two terms. (Until
// session 19 one α_max, the run's smallest, held everywhere: where every ball along a needle
// meets the other side, that spread the size needed at the tip over the whole needle.)
// Why it keeps Lemma 2.4 (the derivation on a straight curve; on a winding one the repair
// below is the judge):
//  - consecutive balls of radii ρ, ρ' (ρ' the later): the next centre is at arc length at least
//    ρ + ρ'/3 from the last, so C2 holds for any ratio (ρ + ρ'/3 <= max + 6 min / 7), and C3.a
//    needs ρ + ρ'/3 >= 8ρ'/7, i.e. ρ'/ρ <= 21/17; the slope 0.1 bounds the ratio by 1 + 0.1 (4/3);
//  - next to b_1 the first α is at most 0.6 r_1, under the r_1 that the 7α/6 end game needs
//    (r_1 + α/3 >= 8 (7α/6) / 7 iff α <= r_1);
//  - next to b_2 the 7α/6 end game needs r_2 >= 4α/3 (the curve from that ball's centre to
//    seg(b_2) may be short); α <= 0.6 r_2 + 0.1 (4α/3) gives α <= 0.69 r_2;
//  - every new ball is at most 7/6 α_max(b) = 7/24 r_b for a refined ball b whose segment holds
//    the step's start (the run's segments cover the gap), Lemma 2.5's factor, so termination
//    holds.
// The paper's α = r_σ/4 is the special case of a flat size at a quarter of the smallest
// neighbour. Protect's first cover of a curve (step 2) keeps the paper's α = min(r_u, r_v)
// unless that is below λ/16; the same derivation holds there, the neighbours being vertex balls.
//
// Two more choices where the paper leaves the order open:
//  - Balls are refined in rounds: every ball that must be refined now (all balls above λ; the
//    larger ball of every intersecting pair on different curves) is collected first, and a run
//    of consecutive such balls on a curve is refined as one: removed together, the gap between
//    the run's two outer neighbours covered once (with r_b the smallest radius in the run, and
//    the paper's r_σ over the run and its neighbours). With the paper's α this is what keeps
//    Separate from the geometric shrinking above: refined one by one (refine_runs = false),
//    the 10° wedge at λ = 4% ends with 378,000 balls instead of 295, and the 2° wedge passes
//    2,000,000. With the graded cover both orders give a few hundred to a few thousand balls.
//  - After each round the new balls are checked against their neighbours for C2 and C3.a, and a
//    failing pair's culprit (C2: the larger ball; C3.a: the ball whose segment holds the other
//    centre) is refined in the next round (ProtectStats::repairs). Lemma 2.4 says Cover never
//    fails them; its proof glosses over the end games, and one case does fail: in step 2,
//    α = min(r_u, r_v) may equal r_v, and a last ball enlarged to 7α/6 then holds the centre v
//    at curve distance in (α, 7α/6) < 8 (7α/6) / 7 (crossed ridges, 2° wedge, disc: 2 to 16
//    repairs). Large balls on a polyline that winds back can also break the proof's picture of
//    the curve in a ball as one short arc. The checker (ball_checker.h) is the judge.
//
// Termination (Lemma 3.1) rests on radii never dropping below a positive constant. A safety cap
// turns a runaway into a ProtectionError instead of a hang: more than max_balls live balls, or a
// ball smaller than min_radius_fraction of the bounding-box diagonal.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "balls.h"

namespace delpsc::protect {

/// Thrown when a safety cap of ProtectOptions is reached; what() says which and how far it got,
/// where() the centre of the ball that would have passed it (where the model needs balls that
/// small, for a caller that wants to say why), too_many_balls() whether it was max_balls (else
/// the radius floor) - a caller that set max_balls from its own limit may say so.
class ProtectionError : public std::runtime_error {
 public:
  ProtectionError(const std::string& message, const Vec3& where, bool too_many_balls = false)
      : std::runtime_error(message), where_(where), too_many_balls_(too_many_balls) {}
  const Vec3& where() const { return where_; }
  bool too_many_balls() const { return too_many_balls_; }

 private:
  Vec3 where_;
  bool too_many_balls_;
};

/// Thrown when ProtectOptions::stop asked protect() to stop; what() says how many balls it had.
/// Not a ProtectionError: nothing is wrong with the input, the caller ran out of patience.
class ProtectionStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ProtectOptions {
  std::size_t max_balls = 5'000'000;   ///< live balls
  double min_radius_fraction = 1e-10;  ///< of the bounding-box diagonal
  /// Refine a run of consecutive balls as one (see the file comment); false: one at a time.
  bool refine_runs = true;
  /// RefineBall covers with the graded size (see the file comment), and so does Protect's first
  /// cover of a curve whose smaller vertex ball is below λ/16; false: the paper's α = r_σ/4
  /// throughout the gap, and α = min(r_u, r_v) for every first cover.
  bool graded_cover = true;
  /// Polled every 4,096 units of work - ball edits, and balls scanned by Separate and by the
  /// refinement of balls above λ - never inside an edit; true makes protect() or refine_ball()
  /// throw ProtectionStopped, leaving the ball set half built. Empty: never. A caller's time
  /// limit (`delpsc mesh --max-seconds`); refine::ProtectedBalls drops it, as a RefineBall cut
  /// short inside the refinement loop would leave the mesher's triangulation without its balls.
  std::function<bool()> stop;
};

/// The smallest ball, as a fraction of λ, that a run at size λ may make (protect::protect's
/// first balls and RefineBall's inside the refinement loop alike). A ball 10^4 times smaller
/// than λ means the model has features λ cannot see - a sharp edge that is no curve at the
/// chosen feature angle, a surface folding back on itself, two curves 10^-5 apart - and with
/// the default floor (1e-10 of the diagonal) such a run went on for minutes before failing the
/// same way: the refinement loop halving balls, and Protect's Separate on the libcgal-demo
/// model mpi.off (curves 5e-6 apart, a diagonal of 35) passing 5,000,000 balls after 229 s at
/// λ = 2% where this floor stops it after 1 s. The acceptance tests mesh every test model with it.
inline constexpr double kSmallestBallOfLambda = 1e-4;

/// The floor above is never higher than this fraction of the bounding-box diagonal. The balls
/// a defect of the input needs have a size of their own, not one that grows with λ, and with
/// 1e-4 λ a coarse size refused models a fine one meshes (libcgal-demo, BENCHMARKS.md, session
/// 18): hand.off's flipped flap needs balls of 4.9e-6 (3.2e-6 of its diagonal) at every size;
/// mech-holes-shark.off's pleat ~8e-7 (5e-7 of the diagonal); dino.off's corner 5° wide next to
/// another 1.2e-3 away 1.4e-5 in Protect at 4% (2.4e-6). Session 18 set 5e-7; mpi.off, two
/// curves leaving a corner 0.069° apart whose ball another curve 0.0145 away keeps small, needs
/// balls of 6e-7 (1.7e-8 of its diagonal) at λ = 0.5%, and meshes at every size with 1e-8, its
/// Protect ending in 1-2 s with 75,000-99,000 balls. What the floor is there for still holds: a
/// runaway stops, some six halvings deeper than at 5e-7.
inline constexpr double kSmallestBallOfDiagonal = 1e-8;

/// `base` with the floor above for balls at size λ on a model whose bounding box has diagonal
/// `diagonal`, min(kSmallestBallOfLambda λ, kSmallestBallOfDiagonal diagonal) (never lower
/// than base's own floor).
inline ProtectOptions options_for_size(double lambda, double diagonal, ProtectOptions base = {}) {
  if (diagonal > 0)
    base.min_radius_fraction = std::max(base.min_radius_fraction,
                                        std::min(kSmallestBallOfLambda * lambda / diagonal, kSmallestBallOfDiagonal));
  return base;
}

/// What happened, for reports and benchmarks.
struct ProtectStats {
  std::size_t covers = 0;           ///< Cover calls
  std::size_t refined = 0;          ///< interior balls removed by RefineBall
  std::size_t vertex_shrinks = 0;   ///< vertex balls halved by RefineBall (not counting step 1)
  std::size_t separate_rounds = 0;  ///< rounds of Separate that found something to refine
  std::size_t conflicts = 0;        ///< intersecting pairs on different curves found (C3.b)
  std::size_t repairs = 0;          ///< adjacent pairs found failing C2 or C3.a after a Cover
  std::size_t irregular = 0;        ///< Cover centres put midway because the neighbours' segments overlapped past a centre
  std::size_t graded_first_covers = 0;  ///< curves whose first cover (step 2) was graded: min(r_u, r_v) < λ/16
};

/// Protect(D, λ): the protecting balls of every corner and curve of `complex`, all of radius
/// <= lambda (> 0, same units as the coordinates), satisfying C1, C2, C3.a, C3.b and covering
/// every curve (ball_checker.h). The complex must outlive the result. Throws
/// std::invalid_argument for lambda not positive and finite, ProtectionError at a cap.
BallSet protect(const Complex& complex, double lambda, const ProtectOptions& options = {},
                ProtectStats* stats = nullptr);

/// The balls a refinement removed (live before, dead after) and added (live after, created by
/// it), each increasing. A shrunk vertex ball appears in both, under its old and new id.
struct BallChanges {
  std::vector<BallId> removed, added;
};

/// RefineBall(b) followed by Separate of the balls it made, for the mesher (§3: refine the
/// largest ball when the disk condition fails and it is larger than the largest restricted
/// triangle): keeps C1, C2, C3.a, C3.b and coverage if they held. Precondition: b alive.
/// Throws std::invalid_argument for a dead b, ProtectionError at a cap.
BallChanges refine_ball(BallSet& balls, BallId b, const ProtectOptions& options = {},
                        ProtectStats* stats = nullptr);

}  // namespace delpsc::protect
