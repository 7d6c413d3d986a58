#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include <delpsc/io/shapes.h>
#include <delpsc/refine/initial_sample.h>
#include <delpsc/refine/polygon_domain.h>

using namespace delpsc;

namespace {

double power(const WeightedPoint& w, const Vec3& x) { return (w.point() - x).squaredNorm() - w.w; }

// The selection's contract, by brute force: every chosen point is power-farther than spacing from
// the balls, the fixed points and every point chosen before it; every candidate left out is
// within that of a ball, a fixed point or a chosen point (greedy: nothing it conflicts with is
// ever dropped, so what rejected it is still there).
void check_selection(const std::vector<Vec3>& candidates, const std::vector<WeightedPoint>& balls,
                     const std::vector<Vec3>& fixed, double spacing, const std::vector<std::uint32_t>& chosen,
                     const std::vector<double>& local = {}) {
  const auto limit_of = [&](std::size_t i) { return local.empty() ? spacing * spacing : local[i] * local[i]; };
  std::vector<WeightedPoint> blockers(balls);
  for (const Vec3& p : fixed) blockers.push_back(WeightedPoint::from(p));
  std::vector<char> is_chosen(candidates.size(), 0);
  for (const std::uint32_t i : chosen) {
    REQUIRE(i < candidates.size());
    CHECK_FALSE(is_chosen[i]);
    is_chosen[i] = 1;
    for (const WeightedPoint& b : blockers) CHECK(power(b, candidates[i]) > limit_of(i));
    blockers.push_back(WeightedPoint::from(candidates[i]));
  }
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (is_chosen[i] || !candidates[i].allFinite()) continue;
    bool blocked = false;
    for (const WeightedPoint& b : blockers) blocked |= power(b, candidates[i]) <= limit_of(i);
    CHECK(blocked);
  }
}

}  // namespace

TEST_CASE("select_separated_points keeps the spacing from balls, fixed and chosen points, and misses nothing") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int round = 0; round < 20; ++round) {
    std::vector<Vec3> candidates;
    for (int i = 0; i < 600; ++i) candidates.emplace_back(u(rng), u(rng), 0.2 * u(rng));
    std::vector<WeightedPoint> balls;
    for (int i = 0; i < 6; ++i) {
      const double r = 0.02 + 0.2 * u(rng);
      balls.push_back(WeightedPoint::from(Vec3(u(rng), u(rng), 0.1), r * r));
    }
    const std::vector<Vec3> fixed{{0.5, 0.5, 0.1}, {0.9, 0.1, 0.0}};
    const double spacing = 0.03 + 0.1 * u(rng);
    const auto chosen = refine::select_separated_points(candidates, balls, fixed, spacing);
    CHECK(!chosen.empty());
    check_selection(candidates, balls, fixed, spacing, chosen);
    CHECK(chosen == refine::select_separated_points(candidates, balls, fixed, spacing));  // deterministic
  }
}

TEST_CASE("select_separated_points with a spacing per candidate (a sizing function)") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int round = 0; round < 10; ++round) {
    std::vector<Vec3> candidates;
    std::vector<double> local;
    for (int i = 0; i < 800; ++i) {
      candidates.emplace_back(u(rng), u(rng), 0.1 * u(rng));
      local.push_back(candidates.back().x() < 0.5 ? 0.03 : 0.1);  // finer on the left
    }
    const std::vector<WeightedPoint> balls{WeightedPoint::from(Vec3(0.5, 0.5, 0), 0.01)};
    const auto chosen = refine::select_separated_points(candidates, balls, {}, 0.1, local);
    check_selection(candidates, balls, {}, 0.1, chosen, local);
    std::size_t left = 0;
    for (const std::uint32_t i : chosen) left += candidates[i].x() < 0.5;
    CHECK(left > 2 * (chosen.size() - left));  // the finer half holds most of the points
  }
  // A local spacing out of (0, spacing], or a wrong count: skipped, or nothing.
  const std::vector<Vec3> two{{0, 0, 0}, {1, 0, 0}};
  CHECK(refine::select_separated_points(two, {}, {}, 0.5, std::vector<double>{0.0, 0.5}) == std::vector<std::uint32_t>{1});
  CHECK(refine::select_separated_points(two, {}, {}, 0.5, std::vector<double>{0.6, 0.5}) == std::vector<std::uint32_t>{1});
  CHECK(refine::select_separated_points(two, {}, {}, 0.5, std::vector<double>{0.5}).empty());
}

TEST_CASE("select_separated_points: degenerate input") {
  const std::vector<Vec3> candidates{{0, 0, 0}, {0, 0, 0}, {1, 0, 0},
                                     {std::numeric_limits<double>::quiet_NaN(), 0, 0}};
  // Duplicates: one of them; a point not finite: never.
  const auto chosen = refine::select_separated_points(candidates, {}, {}, 0.5);
  CHECK(chosen == std::vector<std::uint32_t>{0, 2});
  check_selection(candidates, {}, {}, 0.5, chosen);
  CHECK(refine::select_separated_points(candidates, {}, {}, 0).empty());
  CHECK(refine::select_separated_points(candidates, {}, {}, -1).empty());
  CHECK(refine::select_separated_points(candidates, {}, {}, std::numeric_limits<double>::infinity()).empty());
  CHECK(refine::select_separated_points({}, {}, {}, 1).empty());
  // A spacing far below the candidates' extent: refused rather than a grid of 2^60 cells.
  CHECK(refine::select_separated_points(candidates, {}, {}, 1e-12).empty());
  // A point exactly at the spacing from another is too near (power distance must exceed it).
  const std::vector<Vec3> pair{{0, 0, 0}, {0.5, 0, 0}};
  CHECK(refine::select_separated_points(pair, {}, {}, 0.5).size() == 1);
  // A ball larger than the spacing still reaches across grid cells.
  const std::vector<WeightedPoint> big{WeightedPoint::from(Vec3(0, 0, 0), 4.0)};
  const std::vector<Vec3> ring{{2.0, 0, 0}, {0, 2.05, 0}, {0, 0, 2.1}};
  CHECK(refine::select_separated_points(ring, big, {}, 0.5) == std::vector<std::uint32_t>{2});  // 4.41 - 4 > 0.25
}

TEST_CASE("PolygonDomain::surface_candidates lie on their patches at the asked density") {
  const refine::PolygonDomain domain(io::make_cube(4));  // unit cube, six patches
  const double spacing = 0.05;
  std::vector<Vec3> points;
  std::vector<std::uint32_t> patches;
  domain.surface_candidates(spacing, 1u << 30, points, patches);
  REQUIRE(points.size() == patches.size());
  const double expected = 6 * 4 / (spacing * spacing);  // area 6, 4 per spacing²
  CHECK(std::abs(static_cast<double>(points.size()) - expected) < 0.05 * expected);
  std::vector<std::size_t> per_patch(domain.patch_count(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto c = domain.closest_point(points[i]);
    REQUIRE(c);
    CHECK(c->squared_distance < 1e-28);
    REQUIRE(patches[i] < domain.patch_count());
    ++per_patch[patches[i]];
  }
  for (const std::size_t n : per_patch) CHECK(std::abs(static_cast<double>(n) - expected / 6) < 0.1 * expected / 6);
  // The same points on every call; nothing for a spacing that is not a length.
  std::vector<Vec3> again;
  std::vector<std::uint32_t> again_patches;
  domain.surface_candidates(spacing, 1u << 30, again, again_patches);
  CHECK(again == points);
  std::vector<Vec3> none;
  domain.surface_candidates(0, 1u << 30, none, again_patches);
  domain.surface_candidates(std::numeric_limits<double>::quiet_NaN(), 1u << 30, none, again_patches);
  CHECK(none.empty());
  // More than the budget: none at all (~9,600 expected here).
  domain.surface_candidates(spacing, 9000, none, again_patches);
  CHECK(none.empty());
  domain.surface_candidates(spacing, 10000, none, again_patches);
  CHECK(!none.empty());
}
