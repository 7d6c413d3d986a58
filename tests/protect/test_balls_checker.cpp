// The checker of C1, C2, C3.a, C3.b and coverage (protect/ball_checker.h) on ball sets built by
// hand on the unit square sheet (four straight unit curves meeting at right angles), where every
// condition can be worked out on paper: a good set passes, and each way of breaking one
// condition is reported under that condition.
#include <doctest/doctest.h>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/ball_checker.h>

#include "support/problem_lines.h"

using namespace delpsc;
using protect::BallId;
using protect::BallSet;
using protect::kNoBall;

namespace {

const protect::Complex& square() {
  static const protect::Complex c = protect::build_complex(io::make_square_sheet(2));
  return c;
}

// Corner balls of radius 0.1, and on every curve balls of radius 0.1 at s = 1/6 .. 5/6. Worked
// out: adjacent centres 1/6 apart, <= 0.1 + 6 (0.1) / 7 = 0.186 (C2) and outside each other's
// ball (C3.a holds vacuously); the first balls of two curves at a corner are sqrt(2)/6 = 0.236 >
// 0.2 apart (C3.b); the segments [s - 0.1, s + 0.1] overlap (coverage).
// `skip_corner` leaves one corner without a ball.
BallSet good_set(std::uint32_t skip_corner = kNoBall) {
  BallSet balls(square());
  for (std::uint32_t k = 0; k < square().corner_count(); ++k)
    if (k != skip_corner) balls.set_corner_ball(k, 0.1);
  for (std::uint32_t c = 0; c < square().curve_count(); ++c) {
    BallId after = kNoBall;
    for (int i = 1; i <= 5; ++i) after = balls.insert_interior(c, after, i / 6.0, 0.1);
  }
  return balls;
}

// The i-th interior ball (1-based) of curve c.
BallId interior(const BallSet& balls, std::uint32_t c, int i) {
  BallId id = balls.first_interior(c);
  while (--i > 0) id = balls[id].next;
  return id;
}

// Replaces interior ball i of curve c by one at parameter s and radius r.
void replace(BallSet& balls, std::uint32_t c, int i, double s, double r) {
  const BallId old = interior(balls, c, i);
  const BallId after = balls[old].prev;
  balls.remove_interior(old);
  balls.insert_interior(c, after, s, r);
}

}  // namespace

TEST_CASE("checker: the hand-made good set passes") {
  REQUIRE(square().curve_count() == 4);
  REQUIRE(square().corner_count() == 4);
  const protect::BallCheck check = protect::check_balls(good_set());
  CHECK_MESSAGE(check.ok(), test::problem_lines(check.problems));
  CHECK(check.problems.empty());
}

TEST_CASE("checker: C1") {
  // A corner without a ball.
  const protect::BallCheck missing = protect::check_balls(good_set(2));
  CHECK(missing.c1 >= 1);
  CHECK_FALSE(missing.ok());
  // Two corner balls that overlap (radius 0.6 at corners 1 apart).
  BallSet fat = good_set();
  fat.set_corner_ball(0, 0.6);
  fat.set_corner_ball(1, 0.6);
  CHECK(protect::check_balls(fat).c1 >= 1);
}

TEST_CASE("checker: C2, deep intersection of adjacent balls") {
  BallSet balls = good_set();
  // Ball 3 of curve 0 moved from 1/2 to 0.33: its neighbour at 2/3 is 0.337 away > 0.186.
  replace(balls, 0, 3, 0.33, 0.1);
  const protect::BallCheck check = protect::check_balls(balls);
  CHECK(check.c2 == 1);
  CHECK(check.c3a == 2);  // and it and the ball at 1/3 hold each other's centres, 0.0033 apart
  // A smaller neighbour must be reached deeper: radius 0.1 and 0.01 at 1/6 apart fail
  // (0.167 > 0.1 + 0.0086), though 0.167 <= 0.1 + 6 (0.1) / 7 would pass with equal radii.
  BallSet small = good_set();
  replace(small, 1, 3, 0.5, 0.01);
  const protect::BallCheck check_small = protect::check_balls(small);
  CHECK(check_small.c2 == 2);
  CHECK(check_small.coverage == 2);  // [1/3 + 0.1, 1/2 - 0.01] and [1/2 + 0.01, 2/3 - 0.1] uncovered
}

TEST_CASE("checker: C3.a, read for the open ball") {
  BallSet balls = good_set();
  // Radius 0.2 at s = 1/2: its neighbours at 1/3 and 2/3 are inside, 1/6 < 8 (0.2) / 7 along
  // the curve - two violations. (C2 still holds: 1/6 <= 0.2 + 6 (0.1) / 7.)
  replace(balls, 2, 3, 0.5, 0.2);
  const protect::BallCheck check = protect::check_balls(balls);
  CHECK(check.c3a == 2);
  CHECK(check.c2 == 0);
  // A neighbour exactly on the sphere is not inside: radius 1/6 reaches the neighbours'
  // centres exactly (on a straight curve d = d_σ = r < 8r/7), as Cover's end game does.
  BallSet on_sphere = good_set();
  replace(on_sphere, 2, 3, 0.5, 1.0 / 6);
  CHECK(protect::check_balls(on_sphere).c3a == 0);
  // A hair inside is inside.
  BallSet inside = good_set();
  replace(inside, 2, 3, 0.5, 1.0 / 6 * (1 + 1e-6));
  CHECK(protect::check_balls(inside).c3a == 2);
}

TEST_CASE("checker: C3.b, and how corner balls count") {
  // The first balls of two curves at a corner grown to radius 0.15: 0.236 < 0.3 apart.
  BallSet balls = good_set();
  const std::uint32_t k = 0;
  const auto curves = square().corner_curve_ids(k);
  REQUIRE(curves.size() == 2);
  for (const std::uint32_t c : curves) {
    const bool at_start = square().curves[c].start_corner == k;
    const int i = at_start ? 1 : 5;
    replace(balls, c, i, at_start ? 1.0 / 6 : 5.0 / 6, 0.15);
  }
  CHECK(protect::check_balls(balls).c3b == 1);

  // A corner ball meeting interior balls of its own curves that are not adjacent to it is fine
  // for C3.b (it shares their curves) - C3.a counts the neighbours inside it.
  BallSet big = good_set();
  big.set_corner_ball(0, 0.4);
  const protect::BallCheck own = protect::check_balls(big);
  CHECK(own.c3b == 0);
  CHECK(own.c3a == 2);
  // ... but meeting the balls of a curve not ending at its corner is not: radius 0.95 at a
  // corner reaches the far curves' nearest balls, sqrt(1 + 1/36) = 1.014 <= 1.05 away, and no
  // others (the next ones are 1.054 away).
  big.set_corner_ball(0, 0.95);
  CHECK(protect::check_balls(big).c3b == 2);
}

TEST_CASE("checker: coverage and messages") {
  BallSet balls = good_set();
  replace(balls, 3, 3, 0.5, 0.02);
  const protect::BallCheck check = protect::check_balls(balls, 3);
  CHECK(check.coverage == 2);  // [1/3 + 0.1, 1/2 - 0.02] and [1/2 + 0.02, 2/3 - 0.1]
  CHECK(check.problems.size() == 3);  // capped at the requested count
  CHECK_FALSE(check.ok());
}

TEST_CASE("checker: C3 itself, counted apart: a thin loop whose two sides face each other") {
  // The outline of a 1 x 0.1 rectangle sheet as one closed curve of length 2.2 (no turning
  // corners). Fifteen balls of radius 0.12 every 2.2/15 = 0.147 along it satisfy C1, C2 (0.147
  // <= 0.12 + 6 (0.12) / 7), C3.a (a neighbour is inside only across a 90° turn, 0.104 away
  // in space but 0.147 >= 8 (0.12) / 7 along the curve), C3.b (one curve) and cover it; yet a
  // ball on one long side reaches 0.066 either way along the other side, 0.1 away, into the
  // segments of the balls there: C3 fails while C3.a and C3.b hold - Lemma 2.3 needs small balls.
  io::TriangleSoup soup;
  const int n = 10;
  for (int j = 0; j <= 1; ++j)
    for (int i = 0; i <= n; ++i) soup.vertices.emplace_back(double(i) / n, 0.1 * j, 0.0);
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
    const std::uint32_t a = i, b = i + 1, c = i + 1 + n + 1, d = i + n + 1;
    soup.triangles.push_back({a, b, c});
    soup.triangles.push_back({a, c, d});
  }
  protect::ComplexOptions options;
  options.corner_angle_degrees = 180;
  const protect::Complex loop = protect::build_complex(soup, options);
  REQUIRE(loop.curve_count() == 1);
  REQUIRE(loop.curves[0].closed);
  REQUIRE(loop.curves[0].length == doctest::Approx(2.2));
  BallSet balls(loop);
  balls.set_corner_ball(0, 0.12);
  BallId after = kNoBall;
  for (int k = 1; k <= 14; ++k) after = balls.insert_interior(0, after, loop.curves[0].length * k / 15, 0.12);
  const protect::BallCheck thin = protect::check_balls(balls);
  CHECK_MESSAGE(thin.ok(), test::problem_lines(thin.problems));
  CHECK(thin.c3 > 0);
  // The hand-made set on the square, whose sides are 1 apart, has none.
  CHECK(protect::check_balls(good_set()).c3 == 0);
}
