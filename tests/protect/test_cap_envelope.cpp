// The graded cover's cap along a refined run (protect/cap_envelope.h): the envelope against its
// definition, and RefineBall of a run of mixed radii holding each part to its own ball's cap.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/ball_checker.h>
#include <delpsc/protect/cap_envelope.h>
#include <delpsc/protect/protect.h>
#include <delpsc/protect/protect_engine.h>

#include "support/problem_lines.h"

using namespace delpsc;
using protect::BallId;
using protect::BallSet;
using protect::detail::CapEnvelope;

namespace {

double by_definition(const std::vector<CapEnvelope::Piece>& pieces, double slope, double s) {
  double h = HUGE_VAL;
  for (const auto& p : pieces) {
    const double d = s < p.a ? p.a - s : s > p.b ? s - p.b : 0.0;
    h = std::min(h, p.cap + slope * d);
  }
  return h;
}

}  // namespace

TEST_CASE("CapEnvelope: min over pieces of cap + slope * distance, queried left to right") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int trial = 0; trial < 300; ++trial) {
    CAPTURE(trial);
    const int n = 1 + trial % 17;
    std::vector<CapEnvelope::Piece> pieces;
    double centre = 0;
    for (int i = 0; i < n; ++i) {  // overlapping segments of mixed lengths, as balls give
      centre += unit(rng);
      const double left = unit(rng) * 0.8, right = unit(rng) * 0.8;
      pieces.push_back({centre - left, centre + right, std::pow(10.0, -3 * unit(rng))});
    }
    const double slope = trial % 3 == 0 ? 0.0 : 0.1 * (1 + trial % 5);
    std::shuffle(pieces.begin(), pieces.end(), rng);  // any order
    CapEnvelope envelope(pieces, slope);
    double s = -1;
    for (int q = 0; q < 60; ++q) {
      s += (q % 7 == 0) ? 0.0 : unit(rng) * (centre + 2) / 30;  // repeated queries allowed
      CAPTURE(s);
      const double expected = by_definition(pieces, slope, s);
      CHECK(envelope.at(s) == doctest::Approx(expected).epsilon(1e-12));
    }
  }
}

TEST_CASE("RefineBall of a run of mixed radii: each part covered at its own ball's quarter") {
  // A 10 x 1 x 1 box: its long edges are covered by balls of about 1/3. Refining the first
  // interior ball of one of them three times leaves balls ~40 times smaller at one end of the
  // curve; refining that whole run at once must not spread their size along the edge.
  const protect::Complex complex = protect::build_complex(io::make_box(Vec3::Zero(), Vec3(10, 1, 1), {20, 2, 2}));
  BallSet balls = protect::protect(complex, 0.5);
  std::uint32_t curve = 0;
  while (complex.curves[curve].length < 5) ++curve;
  protect::ProtectOptions options;
  protect::ProtectStats stats;
  protect::detail::Engine engine(balls, options, stats);
  for (int k = 0; k < 3; ++k) {
    const BallId first = balls.first_interior(curve);
    const BallId one[] = {first};
    protect::detail::refine_balls(engine, one);
  }
  std::vector<BallId> run;
  double smallest = HUGE_VAL, largest = 0;
  for (BallId id = balls.first_interior(curve); id != protect::kNoBall; id = balls[id].next) {
    run.push_back(id);
    smallest = std::min(smallest, balls[id].radius);
    largest = std::max(largest, balls[id].radius);
  }
  REQUIRE(largest > 20 * smallest);
  const std::vector<BallId> made = protect::detail::refine_balls(engine, run);
  double made_largest = 0;
  for (const BallId id : made) made_largest = std::max(made_largest, balls[id].radius);
  // Lemma 2.5: nothing larger than 7/24 of the largest ball replaced ...
  CHECK(made_largest <= 7.0 / 24 * largest * (1 + 1e-12));
  // ... and, away from the small balls, far more than the smallest one's 7/24 (the run's
  // smallest cap applied everywhere).
  CHECK(made_largest > 4 * (7.0 / 24) * smallest);
  protect::detail::separate(engine, made);
  const protect::BallCheck check = protect::check_balls(balls);
  CHECK_MESSAGE(check.ok(), test::problem_lines(check.problems));
}
