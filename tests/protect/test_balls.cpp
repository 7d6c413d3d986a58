// BallSet (protect/balls.h) as a data structure: curve order, adjacency, the largest ball and the
// spatial index against brute force under random insertions and removals; seg_σ in the curve
// view (open ends, closed curves); the text format.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <set>
#include <sstream>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/balls.h>

using namespace delpsc;
using protect::Ball;
using protect::BallId;
using protect::BallSet;
using protect::kNoBall;

namespace {

// Every live ball meeting B(c, r), by brute force over all ids.
std::vector<BallId> meeting_brute(const BallSet& balls, const Vec3& c, double r) {
  std::vector<BallId> out;
  for (BallId id = 0; id < balls.id_bound(); ++id)
    if (balls.alive(id) && (balls[id].centre - c).norm() <= r + balls[id].radius) out.push_back(id);
  return out;
}

std::vector<BallId> sorted(std::vector<BallId> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST_CASE("ball set: random edits keep order, heap and spatial index right") {
  const protect::Complex cube = protect::build_complex(io::make_cube(4));
  BallSet balls(cube);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  // Radii over five orders of magnitude, so the index has many levels and wide queries.
  auto radius = [&] { return std::pow(10.0, -5 + 5 * unit(rng)); };

  for (std::uint32_t k = 0; k < cube.corner_count(); ++k) balls.set_corner_ball(k, 0.01 * (k + 1));
  CHECK(balls.size() == 8);
  CHECK(balls.corner_ball_count() == 8);

  for (int step = 0; step < 3000; ++step) {
    const auto c = static_cast<std::uint32_t>(rng() % cube.curve_count());
    if (balls.interior_count(c) > 0 && unit(rng) < 0.35) {
      // Remove a random interior ball of curve c.
      std::vector<BallId> ids;
      for (BallId id = balls.first_interior(c); id != kNoBall; id = balls[id].next) ids.push_back(id);
      balls.remove_interior(ids[rng() % ids.size()]);
    } else {
      // Insert between two consecutive balls of the sequence, at a random parameter between.
      const auto seq = balls.curve_sequence(c);
      const std::size_t i = rng() % (seq.size() - 1);
      const double s = seq[i].s + (seq[i + 1].s - seq[i].s) * (0.1 + 0.8 * unit(rng));
      const BallId after = balls[seq[i].id].is_corner() ? kNoBall : seq[i].id;
      const BallId id = balls.insert_interior(c, after, s, radius());
      CHECK(balls[id].centre == cube.point_at(c, s));
    }
    if (step % 7 == 0) balls.set_corner_ball(static_cast<std::uint32_t>(rng() % 8), radius());

    if (step % 50 != 0) continue;
    // Curve order and the counts.
    std::size_t live_interior = 0;
    for (std::uint32_t cc = 0; cc < cube.curve_count(); ++cc) {
      const auto seq = balls.curve_sequence(cc);
      REQUIRE(seq.size() == balls.interior_count(cc) + 2);
      CHECK(seq.front().id == balls.corner_ball(cube.curves[cc].start_corner));
      CHECK(seq.back().id == balls.corner_ball(cube.curves[cc].end_corner));
      for (std::size_t i = 0; i + 1 < seq.size(); ++i) CHECK(seq[i].s < seq[i + 1].s);
      for (std::size_t i = 1; i + 1 < seq.size(); ++i) {
        CHECK(balls.before(seq[i].id).id == seq[i - 1].id);
        CHECK(balls.after(seq[i].id).id == seq[i + 1].id);
        CHECK(balls.on_curve(seq[i].id, cc));
        CHECK(sorted(balls.neighbours(seq[i].id)) == sorted({seq[i - 1].id, seq[i + 1].id}));
      }
      live_interior += balls.interior_count(cc);
    }
    CHECK(balls.size() == live_interior + 8);
    CHECK(balls.live_ids().size() == balls.size());

    // The largest ball.
    double best = 0;
    BallId best_id = kNoBall;
    for (const BallId id : balls.live_ids())
      if (balls[id].radius > best) best = balls[id].radius, best_id = id;
    CHECK(balls.largest() == best_id);
    const auto [lo, hi] = balls.radius_range();
    CHECK(hi == best);
    CHECK(lo > 0);

    // The spatial index, with query radii from far below to far above the balls'.
    for (int q = 0; q < 40; ++q) {
      const Vec3 centre(unit(rng), unit(rng), unit(rng));
      const double r = std::pow(10.0, -6 + 7 * unit(rng));
      std::vector<BallId> got;
      balls.balls_meeting(centre, r, got);
      CHECK(sorted(got) == meeting_brute(balls, centre, r));
    }
  }
}

TEST_CASE("ball set: corner balls, their neighbours and shared curves") {
  const protect::Complex cube = protect::build_complex(io::make_cube(2));
  BallSet balls(cube);
  for (std::uint32_t k = 0; k < 8; ++k) balls.set_corner_ball(k, 0.1);
  std::vector<BallId> middle(cube.curve_count());
  for (std::uint32_t c = 0; c < cube.curve_count(); ++c) middle[c] = balls.insert_interior(c, kNoBall, 0.5, 0.2);
  for (std::uint32_t k = 0; k < 8; ++k) {
    const BallId corner = balls.corner_ball(k);
    std::vector<BallId> want;
    for (const std::uint32_t c : cube.corner_curve_ids(k)) want.push_back(middle[c]);
    CHECK(sorted(balls.neighbours(corner)) == sorted(want));
    for (std::uint32_t c = 0; c < cube.curve_count(); ++c) {
      const bool incident = cube.curves[c].start_corner == k || cube.curves[c].end_corner == k;
      CHECK(balls.on_curve(corner, c) == incident);
      CHECK(balls.share_curve(corner, middle[c]) == incident);
      CHECK(balls.share_curve(middle[c], corner) == incident);
    }
  }
  // Two corners share a curve iff a cube edge joins them.
  for (std::uint32_t a = 0; a < 8; ++a)
    for (std::uint32_t b = 0; b < 8; ++b) {
      bool edge = a == b;
      for (const auto& curve : cube.curves)
        edge = edge || (curve.start_corner == a && curve.end_corner == b) || (curve.start_corner == b && curve.end_corner == a);
      CHECK(balls.share_curve(balls.corner_ball(a), balls.corner_ball(b)) == edge);
    }
  // Shrinking a corner ball gives a new id; the old one is dead but still readable.
  const BallId old = balls.corner_ball(0);
  const BallId now = balls.set_corner_ball(0, 0.35);
  CHECK(now != old);
  CHECK_FALSE(balls.alive(old));
  CHECK(balls[old].radius == 0.1);
  CHECK(balls.corner_ball_count() == 8);
  // It reaches the middle balls of its three edges (0.5 <= 0.35 + 0.2) and nothing else.
  std::vector<BallId> want;
  for (const std::uint32_t c : cube.corner_curve_ids(0)) want.push_back(middle[c]);
  CHECK(sorted(balls.balls_meeting(now)) == sorted(want));
}

TEST_CASE("seg in the curve view: corner balls at the ends of open and closed curves") {
  // One polyline segment per curve: the walk from one end reaches the other end's vertex at once.
  const protect::Complex square = protect::build_complex(io::make_square_sheet(1));
  REQUIRE(square.curve_count() == 4);
  BallSet balls(square);
  for (std::uint32_t k = 0; k < 4; ++k) balls.set_corner_ball(k, 0.25);
  for (std::uint32_t c = 0; c < 4; ++c) {
    REQUIRE(square.curves[c].count == 2);
    const auto seq = balls.curve_sequence(c);
    const protect::CurveInterval start = balls.segment_on(c, seq.front());
    const protect::CurveInterval end = balls.segment_on(c, seq.back());
    CHECK_FALSE(start.whole);
    CHECK(start.s0 == 0);
    CHECK(start.s1 == doctest::Approx(0.25).epsilon(1e-12));
    CHECK_FALSE(end.whole);
    CHECK(end.s0 == doctest::Approx(0.75).epsilon(1e-12));
    CHECK(end.s1 == 1);
  }
  // A ball that really holds a whole open curve says so.
  balls.set_corner_ball(0, 2.0);
  const std::uint32_t c0 = square.corner_curve_ids(0)[0];
  const bool at_start = square.curves[c0].start_corner == 0;
  CHECK(balls.segment_on(c0, {balls.corner_ball(0), at_start ? 0.0 : 1.0}).whole);

  // A closed curve: the corner ball's segment at the end of the unrolled view is shifted by
  // the length and mirrors the one at the start (the disc's outline is symmetric about its
  // corner only approximately, so compare lengths loosely).
  const protect::Complex disc = protect::build_complex(io::make_disc_sheet(32, 2));
  REQUIRE(disc.curve_count() == 1);
  REQUIRE(disc.curves[0].closed);
  BallSet loop(disc);
  loop.set_corner_ball(0, 0.3);
  loop.insert_interior(0, kNoBall, disc.curves[0].length / 2, 0.3);
  const auto seq = loop.curve_sequence(0);
  REQUIRE(seq.size() == 3);
  CHECK(seq.front().id == seq.back().id);
  const double L = disc.curves[0].length;
  const protect::CurveInterval start = loop.segment_on(0, seq.front());
  const protect::CurveInterval end = loop.segment_on(0, seq.back());
  CHECK(start.s0 < 0);
  CHECK(start.s1 > 0);
  CHECK(end.s0 < L);
  CHECK(end.s1 > L);
  CHECK(end.s0 == doctest::Approx(L + start.s0));
  CHECK(end.s1 == doctest::Approx(L + start.s1));
  CHECK(loop.neighbours(seq.front().id) == std::vector<BallId>{seq[1].id});
  CHECK(loop.neighbours(seq[1].id) == std::vector<BallId>{seq.front().id});
}

TEST_CASE("balls as text: the issue's format, exact numbers") {
  const protect::Complex cube = protect::build_complex(io::make_cube(2));
  BallSet balls(cube);
  for (std::uint32_t k = 0; k < 8; ++k) balls.set_corner_ball(k, 0.1 + k / 3.0 * 1e-3);
  for (std::uint32_t c = 0; c < cube.curve_count(); ++c) {
    BallId after = kNoBall;
    for (int i = 1; i <= static_cast<int>(c % 3) + 1; ++i) after = balls.insert_interior(c, after, i / 4.0 + 1e-3 / 7, 0.1 / 3);
  }
  std::istringstream in(protect::balls_to_text(balls));
  std::string word;
  std::size_t corners = 0, curves = 0;
  while (in >> word) {
    if (word == "corner") {
      std::uint32_t id;
      double x, y, z, r;
      in >> id >> x >> y >> z >> r;
      const Ball& b = balls[balls.corner_ball(id)];
      CHECK(Vec3(x, y, z) == b.centre);
      CHECK(r == b.radius);
      ++corners;
    } else {
      REQUIRE(word == "curve");
      std::uint32_t id, start, end;
      std::size_t n;
      in >> id >> start >> end >> n;
      CHECK(start == cube.curves[id].start_corner);
      CHECK(end == cube.curves[id].end_corner);
      REQUIRE(n == balls.interior_count(id));
      BallId b = balls.first_interior(id);
      for (std::size_t i = 0; i < n; ++i, b = balls[b].next) {
        double x, y, z, r;
        in >> x >> y >> z >> r;
        CHECK(Vec3(x, y, z) == balls[b].centre);
        CHECK(r == balls[b].radius);
      }
      ++curves;
    }
  }
  CHECK(corners == 8);
  CHECK(curves == 12);
}
