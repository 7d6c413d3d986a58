#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <span>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/complex.h>
#include <delpsc/refine/initial_sample.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/surface_lattice.h>
#include <delpsc/refine/triangle_clusters.h>

#include "support/generators.h"

using namespace delpsc;

namespace {

double power(const WeightedPoint& w, const Vec3& x) { return (w.point() - x).squaredNorm() - w.w; }

// The selection's contract, by brute force: every chosen point is power-farther than spacing from
// the fixed points and every point chosen before it, and than ball_clearance times the spacing
// from the balls; every candidate left out is within that of a ball, a fixed point or a chosen
// point (greedy: nothing it conflicts with is ever dropped, so what rejected it is still there).
void check_selection(std::span<const Vec3> candidates, const std::vector<WeightedPoint>& balls,
                     const std::vector<Vec3>& fixed, double spacing, const std::vector<std::uint32_t>& chosen,
                     const std::vector<double>& local = {}, double ball_clearance = 1) {
  const auto limit_of = [&](std::size_t i) { return local.empty() ? spacing * spacing : local[i] * local[i]; };
  std::vector<WeightedPoint> blockers(balls);
  for (const Vec3& p : fixed) blockers.push_back(WeightedPoint::from(p));
  // Blocker k rejects candidate i: within the spacing, or within the clearance for a ball.
  const auto blocks = [&](std::size_t k, std::size_t i) {
    const double scale = k < balls.size() ? ball_clearance * ball_clearance : 1;
    return power(blockers[k], candidates[i]) <= scale * limit_of(i);
  };
  std::vector<char> is_chosen(candidates.size(), 0);
  for (const std::uint32_t i : chosen) {
    REQUIRE(i < candidates.size());
    CHECK_FALSE(is_chosen[i]);
    is_chosen[i] = 1;
    for (std::size_t k = 0; k < blockers.size(); ++k) CHECK_FALSE(blocks(k, i));
    blockers.push_back(WeightedPoint::from(candidates[i]));
  }
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (is_chosen[i] || !candidates[i].allFinite()) continue;
    bool blocked = false;
    for (std::size_t k = 0; k < blockers.size() && !blocked; ++k) blocked = blocks(k, i);
    CHECK(blocked);
  }
}

// What select_sample asks of each candidate: the spacing for the lattice (the first `cover`),
// kGapFillSpacing times it for the random candidates after it.
std::vector<double> sample_spacings(std::size_t candidates, std::size_t cover, double spacing) {
  std::vector<double> local(candidates, refine::kGapFillSpacing * spacing);
  std::fill(local.begin(), local.begin() + static_cast<std::ptrdiff_t>(cover), spacing);
  return local;
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

// The grid keeps its chains in a flat array over the candidates' box when the box holds few
// cells for the points, and in a hash table otherwise: two clusters ten diagonals apart (~10^5
// cells of the largest ball's size for 1,200 points) take the table, one cluster alone the
// array; both keep the contract, balls far outside the box included.
TEST_CASE("select_separated_points: clusters far apart (hashed cells) and one cluster (a flat array)") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int round = 0; round < 10; ++round) {
    std::vector<Vec3> near, both;
    for (int i = 0; i < 600; ++i) near.emplace_back(u(rng), u(rng), 0.3 * u(rng));
    both = near;
    for (int i = 0; i < 600; ++i) both.push_back(Vec3(10, 10, 10) + Vec3(u(rng), 0.3 * u(rng), u(rng)));
    const std::vector<WeightedPoint> balls{WeightedPoint::from(Vec3(0.5, 0.5, 0), 0.01),
                                           WeightedPoint::from(Vec3(10.5, 10, 10.5), 0.04),
                                           WeightedPoint::from(Vec3(-50, 3, 3), 0.04)};
    const std::vector<Vec3> fixed{{0.2, 0.2, 0.1}, {10.8, 10.1, 10.2}, {-40, 0, 0}};
    const double spacing = 0.08 + 0.05 * u(rng);
    for (const auto* candidates : {&near, &both}) {
      const auto chosen = refine::select_separated_points(*candidates, balls, fixed, spacing);
      CHECK(chosen.size() > 20);
      check_selection(*candidates, balls, fixed, spacing, chosen);
    }
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

TEST_CASE("PolygonDomain::surface_candidates lie on their patches: a lattice first, random points near edges, a net") {
  const refine::PolygonDomain domain(io::make_cube(1));  // unit cube, six patches, 12 triangles
  const double spacing = 0.05;
  kernel::LargeVector<Vec3> points;
  kernel::LargeVector<std::uint32_t> patches;
  const refine::CandidateParts parts = domain.surface_candidates(spacing, 1u << 30, points, patches);
  const std::size_t cover = parts.lattice;
  REQUIRE(points.size() == patches.size());
  // The net last: every point of the faces within its radius of a net point; each triangle's
  // rows at most (√3/2) h apart cut into pieces <= h: ~1.15 / h² per unit area, plus the rows'
  // ends, plus the 8 corners.
  const double h = refine::kNetRadius * spacing;
  CHECK(parts.net_radius == h);
  CHECK(static_cast<double>(parts.net) > 6 / (h * h));
  CHECK(static_cast<double>(parts.net) < 6 * 1.2 / (h * h) + 12 * 4 / h + 8);
  REQUIRE(parts.net < points.size() - cover);
  const std::vector<Vec3> net(points.end() - static_cast<std::ptrdiff_t>(parts.net), points.end());
  std::mt19937 probe_rng(17);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 3000; ++k) {
    Vec3 p(unit(probe_rng), unit(probe_rng), unit(probe_rng));
    p[k % 3] = (k / 3) % 2;  // on a face
    double nearest = HUGE_VAL;
    for (const Vec3& q : net) nearest = std::min(nearest, (q - p).norm());
    CHECK(nearest <= h * (1 + 1e-12));
  }
  // The lattice: area 6 at 2 / (√3 step²) per unit area.
  const double step = refine::kLatticeStep * spacing;
  const double lattice_expected = 6 * 2 / (std::sqrt(3.0) * step * step);
  CHECK(std::abs(static_cast<double>(cover) - lattice_expected) < 0.05 * lattice_expected);
  // Random candidates at 4 per spacing², only within ~2.5 spacings of a face's border: their
  // count is the band's share of the area (~45%), well under the whole area's.
  const double random_everywhere = 6 * 4 / (spacing * spacing);
  const std::size_t random = points.size() - cover - parts.net;
  CHECK(static_cast<double>(random) > 0.35 * random_everywhere);
  CHECK(static_cast<double>(random) < 0.6 * random_everywhere);
  std::vector<std::size_t> per_patch(domain.patch_count(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto nearest = domain.closest_point(points[i]);
    REQUIRE(nearest);
    CHECK(nearest->squared_distance < 1e-28);
    REQUIRE(patches[i] < domain.patch_count());
    ++per_patch[patches[i]];
    if (i < cover || i >= points.size() - parts.net) continue;
    // A random candidate lies in the band: within 2.5 spacings of its face's border, give or take
    // a stratum (~1 spacing across). A face's two triangles are one cluster, with one lattice:
    // its diagonal gets none.
    const Vec3& p = points[i];
    int axis = 0;  // the face's normal axis: the coordinate at 0 or 1
    for (int k = 0; k < 3; ++k)
      if (std::min(std::abs(p[k]), std::abs(p[k] - 1)) < 1e-12) axis = k;
    const double x = p[(axis + 1) % 3], y = p[(axis + 2) % 3];
    CHECK(std::min({x, y, 1 - x, 1 - y}) <= 2.5 * spacing + std::sqrt(2.0) / 29 + 1e-12);
  }
  for (const std::size_t n : per_patch) CHECK(static_cast<double>(n) > 0.1 * static_cast<double>(points.size()));
  // The same points on every call; nothing for a spacing that is not a length.
  kernel::LargeVector<Vec3> again;
  kernel::LargeVector<std::uint32_t> again_patches;
  CHECK(domain.surface_candidates(spacing, 1u << 30, again, again_patches).lattice == cover);
  CHECK(again == points);
  kernel::LargeVector<Vec3> none;
  const auto nothing = [](const refine::CandidateParts& p) { return p.lattice == 0 && p.net == 0 && p.net_radius == 0; };
  CHECK(nothing(domain.surface_candidates(0, 1u << 30, none, again_patches)));
  CHECK(nothing(domain.surface_candidates(std::numeric_limits<double>::quiet_NaN(), 1u << 30, none, again_patches)));
  CHECK(none.empty());
  // More than the budget: none at all (~9,600 random candidates are expected here). A budget
  // that leaves too little for the net (~1,300) and the lattice's work: random candidates
  // alone, everywhere.
  CHECK(nothing(domain.surface_candidates(spacing, 9000, none, again_patches)));
  CHECK(none.empty());
  CHECK(nothing(domain.surface_candidates(spacing, 10000, none, again_patches)));
  CHECK(none.size() > 9000);
  none.clear();
  const refine::CandidateParts enough = domain.surface_candidates(spacing, 20000, none, again_patches);
  CHECK(enough.lattice > 0);
  CHECK(enough.net == parts.net);
}

TEST_CASE("PolygonDomain::surface_candidates bounds the lattice's work by the budget") {
  // A needle 10^8 spacings long and 10^-3 wide: ~7 10^7 lattice sites to try for a handful of
  // points. Within a budget of 10^6 (2 10^5 random candidates) the lattice is dropped at once,
  // the random candidates remain.
  io::TriangleSoup soup;
  soup.vertices = {Vec3(0, 0, 0), Vec3(1e8, 0, 0), Vec3(0, 1e-3, 0)};
  soup.triangles = {{0, 1, 2}};
  const refine::PolygonDomain domain(protect::build_complex(soup));
  kernel::LargeVector<Vec3> points;
  kernel::LargeVector<std::uint32_t> patches;
  const refine::CandidateParts parts = domain.surface_candidates(1.0, 1000000, points, patches);
  CHECK(parts.lattice == 0);
  CHECK(!points.empty());
  // Its net (~10^8 row pieces) does not fit either: left out, so no radius is promised.
  CHECK(parts.net == 0);
  CHECK(parts.net_radius == 0);
}

namespace {

// Every point of `probes` within `radius` of a point of `points` (brute force).
std::size_t uncovered(std::span<const Vec3> probes, std::span<const Vec3> points, double radius) {
  std::size_t out = 0;
  for (const Vec3& q : probes)
    out += std::none_of(points.begin(), points.end(), [&](const Vec3& p) { return (p - q).norm() <= radius; });
  return out;
}

// PolygonDomain::surface_candidates' output, with no budget in the way.
struct Candidates {
  kernel::LargeVector<Vec3> points;
  kernel::LargeVector<std::uint32_t> patches;
  refine::CandidateParts parts;
};
Candidates candidates_of(const refine::PolygonDomain& domain, double spacing) {
  Candidates c;
  c.parts = domain.surface_candidates(spacing, 1u << 30, c.points, c.patches);
  return c;
}

}  // namespace

TEST_CASE("jittered_lattice: on the triangle, spaced, covering, the same across coplanar triangles") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const double step = 0.1, jitter = 0.012;
  const double cover_radius = step / std::sqrt(3.0) + jitter;
  for (int round = 0; round < 4; ++round) {
    // A slanted unit square far from the origin, as two triangles sharing its diagonal.
    const Vec3 origin(100 * u(rng) - 50, 100 * u(rng) - 50, 100 * u(rng) - 50);
    const Vec3 e1 = Vec3(u(rng), u(rng), u(rng)).normalized();
    const Vec3 e2 = e1.cross(Vec3(u(rng), u(rng), u(rng))).normalized();
    const Vec3 a = origin, b = origin + e1, c = origin + e1 + e2, d = origin + e2;
    kernel::LargeVector<Vec3> first, second;
    refine::jittered_lattice(a, b, c, step, jitter, first);
    refine::jittered_lattice(a, c, d, step, jitter, second);  // the same plane: the same lattice
    // On its triangle (barycentric coordinates in [0, 1] up to rounding), ~0.5 / (√3/2 step²) each.
    for (const Vec3& p : first) {
      const double x = (p - a).dot(e1), y = (p - a).dot(e2), off = std::abs((p - a).dot(e1.cross(e2)));
      CHECK(off < 1e-12);
      CHECK(y <= x + 1e-12);
      CHECK(x <= 1 + 1e-12);
      CHECK(y >= -1e-12);
    }
    const double expected = 0.5 / (std::sqrt(3.0) / 2 * step * step);
    CHECK(std::abs(static_cast<double>(first.size()) - expected) < 0.1 * expected);
    // Spaced: at least step - 2 jitter apart, but for the points on the shared diagonal, which
    // both triangles make (the same point up to rounding).
    std::vector<Vec3> all(first.begin(), first.end());
    all.insert(all.end(), second.begin(), second.end());
    std::size_t duplicates = 0;
    for (std::size_t i = 0; i < all.size(); ++i)
      for (std::size_t j = i + 1; j < all.size(); ++j) {
        const double dist = (all[i] - all[j]).norm();
        if (dist < 1e-9) {
          ++duplicates;
          CHECK((i < first.size()) != (j < first.size()));
        } else {
          CHECK(dist >= step - 2 * jitter - 1e-12);
        }
      }
    CHECK(duplicates < 4);
    // Covering: every point of the square farther than the cover radius from its border is
    // within the cover radius of the union - no seam along the diagonal.
    std::vector<Vec3> probes;
    for (int k = 0; k < 3000; ++k) {
      const double x = cover_radius + (1 - 2 * cover_radius) * u(rng), y = cover_radius + (1 - 2 * cover_radius) * u(rng);
      probes.push_back(a + x * e1 + y * e2);
    }
    CHECK(uncovered(probes, all, cover_radius) == 0);
    // The bound is tight enough to mean something: at 0.9 of it, some probes are left out.
    CHECK(uncovered(probes, all, 0.9 * cover_radius) > 0);
  }
  // A triangle's lattice is the plane's lattice clipped to it: a square's two halves together
  // have exactly the points of a big triangle of the same plane that fall in the square.
  {
    kernel::LargeVector<Vec3> big, halves;
    refine::jittered_lattice(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), step, jitter, big);
    refine::jittered_lattice(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), step, jitter, halves);
    refine::jittered_lattice(Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), step, jitter, halves);
    const auto inside = [](const Vec3& p) { return p.x() > 1e-9 && p.y() > 1e-9 && p.x() < 1 - 1e-9 && p.y() < 1 - 1e-9; };
    const auto has = [](std::span<const Vec3> set, const Vec3& p) {
      return std::any_of(set.begin(), set.end(), [&](const Vec3& q) { return (q - p).norm() < 1e-12; });
    };
    std::size_t in_square = 0;
    for (const Vec3& p : big)
      if (inside(p)) {
        ++in_square;
        CHECK(has(halves, p));
      }
    for (const Vec3& p : halves)
      if (inside(p)) CHECK(has(big, p));
    CHECK(in_square > 50);
    // The same square in 2 x 48 x 48 triangles each far smaller than a lattice cell, most of
    // which hold no site (the case may_hold_site skips): together, again exactly those points.
    kernel::LargeVector<Vec3> tiny;
    constexpr int kCells = 48;
    const double h = 1.0 / kCells;
    for (int i = 0; i < kCells; ++i)
      for (int j = 0; j < kCells; ++j) {
        const Vec3 p0(i * h, j * h, 0), p1((i + 1) * h, j * h, 0), p2((i + 1) * h, (j + 1) * h, 0), p3(i * h, (j + 1) * h, 0);
        refine::jittered_lattice(p0, p1, p2, step, jitter, tiny);
        refine::jittered_lattice(p0, p2, p3, step, jitter, tiny);
      }
    for (const Vec3& p : big)
      if (inside(p)) CHECK(has(tiny, p));
    for (const Vec3& p : tiny)
      if (inside(p)) CHECK(has(big, p));
  }
  // A cluster's triangle at an angle to the lattice's plane: points on it, still spaced (the
  // projection only shortens), covering it to the cover radius over the cosine of the angle.
  {
    const double angle = 20 * 3.141592653589793 / 180;
    const refine::LatticeFrame frame = refine::lattice_frame(Vec3(0, 0, 1), Vec3(0, 0, 0.3), step);
    const Vec3 a(0, 0, 0.3), b(1, 0, 0.3 + std::tan(angle)), c(0, 1, 0.3);
    kernel::LargeVector<Vec3> tilted;
    refine::jittered_lattice(frame, a, b, c, step, jitter, tilted);
    const Vec3 n = (b - a).cross(c - a).normalized();
    for (const Vec3& p : tilted) {
      CHECK(std::abs((p - a).dot(n)) < 1e-12);
      CHECK(p.x() >= -1e-12);
      CHECK(p.y() >= -1e-12);
      CHECK(p.x() + p.y() <= 1 + 1e-12);
    }
    for (std::size_t i = 0; i < tilted.size(); ++i)
      for (std::size_t j = i + 1; j < tilted.size(); ++j) CHECK((tilted[i] - tilted[j]).norm() >= step - 2 * jitter - 1e-12);
    const double radius = cover_radius / std::cos(angle);
    std::vector<Vec3> probes;
    for (int k = 0; k < 2000; ++k) {
      const double x = u(rng), y = u(rng);
      if (x < radius || y < radius || (1 - x - y) / std::sqrt(2.0) < radius) continue;
      probes.push_back(a + x * (b - a) + y * (c - a));
    }
    REQUIRE(probes.size() > 100);
    CHECK(uncovered(probes, tilted, radius) == 0);
  }
  // Parallel planes get different jitters: the lattices of a cube's opposite faces were
  // translates of each other, whose rectangles of co-circular points sent the triangulation's
  // power tests to exact arithmetic.
  kernel::LargeVector<Vec3> bottom, top;
  refine::jittered_lattice(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), step, jitter, bottom);
  refine::jittered_lattice(Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1), step, jitter, top);
  std::size_t translated = 0;
  for (const Vec3& p : bottom)
    translated += std::any_of(top.begin(), top.end(), [&](const Vec3& q) { return (q - p - Vec3(0, 0, 1)).norm() < 1e-12; });
  CHECK(translated < bottom.size() / 10);
  // Nothing for a degenerate triangle, an impossible step, or a plane too far for the step.
  kernel::LargeVector<Vec3> none;
  refine::jittered_lattice(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), step, jitter, none);
  refine::jittered_lattice(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), 0, 0, none);
  refine::jittered_lattice(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), step, step, none);
  refine::jittered_lattice(Vec3(1e20, 0, 0), Vec3(2e20, 0, 0), Vec3(1e20, 1e20, 0), step, jitter, none);
  CHECK(none.empty());
}

TEST_CASE("cluster_triangles: nearly parallel triangles grouped, boundaries and distances") {
  // A cube of 4 x 4 quads per face: 6 clusters of 32 triangles, one per face; the face borders
  // (features) bound them and nothing else does.
  const protect::Complex cube = protect::build_complex(io::make_cube(4));
  const refine::TriangleClusters c = refine::cluster_triangles(cube, 25, 10);
  CHECK(c.seed.size() == 6);
  std::vector<int> size(c.seed.size(), 0);
  for (const std::uint32_t k : c.cluster_of) ++size[k];
  for (const int n : size) CHECK(n == 32);
  for (std::size_t t = 0; t < cube.triangles.size(); ++t) {
    CHECK(c.cluster_of[c.seed[c.cluster_of[t]]] == c.cluster_of[t]);
    for (int k = 0; k < 3; ++k)
      CHECK(((c.boundary_edges[t] >> k & 1u) != 0) == (cube.edge_feature[cube.triangle_edges[t][k]] != 0));
    // 0 on the border; inside, at most the centroid path to it (a face is 1 wide).
    CHECK(c.distance[t] >= 0);
    CHECK(c.distance[t] < 0.75);
    if (c.boundary_edges[t] != 0) CHECK(c.distance[t] == 0);
    else CHECK(c.distance[t] > 0);
  }
  // A sphere: normals turn by ~6° a triangle, so a 25° cone gathers several, a 0° one none;
  // clusters are never wider than the cone allows (normals within 25° of the seed's).
  const protect::Complex sphere = protect::build_complex(io::make_sphere(8));
  const refine::TriangleClusters wide = refine::cluster_triangles(sphere, 25, 1);
  const refine::TriangleClusters none = refine::cluster_triangles(sphere, 0, 1);
  CHECK(wide.seed.size() * 4 < sphere.triangles.size());
  CHECK(none.seed.size() == sphere.triangles.size());
  const auto normal = [&](std::uint32_t t) {
    const auto& v = sphere.triangles[t];
    return Vec3((sphere.vertices[v[1]] - sphere.vertices[v[0]]).cross(sphere.vertices[v[2]] - sphere.vertices[v[0]]).normalized());
  };
  for (std::uint32_t t = 0; t < sphere.triangles.size(); ++t)
    CHECK(normal(t).dot(normal(wide.seed[wide.cluster_of[t]])) >= std::cos(25 * M_PI / 180) - 1e-12);
}

TEST_CASE("cluster_triangles: distances are the shortest centroid paths to the boundary, up to the horizon") {
  // Against a plain Dijkstra with a binary heap over the same graph (triangles of one cluster
  // across non-feature edges, centroid to centroid), on a finely divided sphere (many clusters)
  // and the cube (6 big ones), with horizons that cut paths short, that do not, that leave only
  // the boundary, and none at all (infinite or NaN).
  for (const auto& soup : {io::make_sphere(24), io::make_cube(12)}) {
    const protect::Complex complex = protect::build_complex(soup);
    const std::size_t n = complex.triangles.size();
    std::vector<Vec3> centroid(n);
    for (std::size_t t = 0; t < n; ++t) {
      const auto& v = complex.triangles[t];
      centroid[t] = (complex.vertices[v[0]] + complex.vertices[v[1]] + complex.vertices[v[2]]) / 3;
    }
    for (const double horizon : {0.05, 0.2, 10.0, 0.0, -1.0, HUGE_VAL, std::nan("")}) {
      const refine::TriangleClusters c = refine::cluster_triangles(complex, 25, horizon);
      const auto across = [&](std::uint32_t t, int k) -> std::int64_t {
        const std::uint32_t e = complex.triangle_edges[t][k];
        if (complex.edge_feature[e] != 0) return -1;
        for (std::uint32_t q = complex.edge_triangle_offsets[e]; q < complex.edge_triangle_offsets[e + 1]; ++q)
          if (complex.edge_triangles[q] != t) return complex.edge_triangles[q];
        return -1;
      };
      std::vector<double> reference(n, HUGE_VAL);
      using Entry = std::pair<double, std::uint32_t>;
      std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
      for (std::uint32_t t = 0; t < n; ++t)
        if (c.boundary_edges[t] != 0) heap.emplace(reference[t] = 0, t);
      while (!heap.empty()) {
        const auto [d, t] = heap.top();
        heap.pop();
        if (d > reference[t]) continue;
        for (int k = 0; k < 3; ++k) {
          const std::int64_t u = across(t, k);
          if (u < 0 || c.cluster_of[u] != c.cluster_of[t]) continue;
          const double du = d + (centroid[u] - centroid[t]).norm();
          if (du < reference[u]) heap.emplace(reference[u] = du, static_cast<std::uint32_t>(u));
        }
      }
      const bool none = !(horizon < HUGE_VAL);
      for (std::size_t t = 0; t < n; ++t) {
        INFO("triangle " << t << ", horizon " << horizon);
        if (reference[t] == HUGE_VAL)  // a cluster without boundary
          CHECK(c.distance[t] == HUGE_VAL);
        else if (none || reference[t] <= horizon)
          CHECK(c.distance[t] == doctest::Approx(reference[t]).epsilon(1e-12));
        else
          CHECK(c.distance[t] > horizon);
      }
    }
  }
}

TEST_CASE("PolygonDomain::surface_candidates lays a lattice on clusters of small triangles") {
  // A sphere of 6,912 triangles of ~0.0018 each, under half the spacing²: no triangle alone gets
  // a lattice, the clusters of nearly parallel ones do.
  const refine::PolygonDomain domain(io::make_sphere(24));
  const double spacing = 0.1;
  const auto [points, patches, parts] = candidates_of(domain, spacing);
  const std::size_t cover = parts.lattice;
  CHECK(cover > points.size() / 20);
  for (const Vec3& p : points) {
    const auto nearest = domain.closest_point(p);
    REQUIRE(nearest);
    CHECK(nearest->squared_distance < 1e-24);
  }
  // The lattice is chosen first and most of the sample comes from it.
  const auto chosen = refine::select_sample(points, parts, {}, {}, spacing);
  check_selection(points, {}, {}, spacing, chosen, sample_spacings(points.size(), cover, spacing));
  const auto from_lattice = std::count_if(chosen.begin(), chosen.end(), [&](std::uint32_t i) { return i < cover; });
  CHECK(static_cast<std::size_t>(from_lattice) > chosen.size() / 2);
}

TEST_CASE("select_sample leaves no hole away from the edges of a cube's faces") {
  // The lattice chosen first covers each face (one cluster of 32 triangles) but near its border;
  // random candidates fill there. Every point of a face 3 spacings from its border is then within
  // the spacing of a chosen point: step 2(b) finds no restricted facet larger than the spacing.
  const refine::PolygonDomain domain(io::make_cube(4));
  const double spacing = 0.05;
  const auto [points, patches, parts] = candidates_of(domain, spacing);
  const std::size_t cover = parts.lattice;
  const std::vector<Vec3> fixed{{0.5, 0.5, 0}};
  const auto chosen = refine::select_sample(points, parts, {}, fixed, spacing);
  // The order: the lattice's points first; the random ones at the closer gap-filling spacing.
  check_selection(points, {}, fixed, spacing, chosen, sample_spacings(points.size(), cover, spacing));
  std::vector<Vec3> sample(fixed);
  for (const std::uint32_t i : chosen) sample.push_back(points[i]);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(3 * spacing, 1 - 3 * spacing);
  std::vector<Vec3> probes;
  for (int k = 0; k < 2000; ++k) {
    Vec3 p(u(rng), u(rng), u(rng));
    p[k % 3] = (k / 3) % 2;  // on a face
    probes.push_back(p);
  }
  CHECK(uncovered(probes, sample, spacing) == 0);
  // Random candidates filled in near the edges, after every lattice point.
  const auto first_random = std::find_if(chosen.begin(), chosen.end(), [&](std::uint32_t i) { return i >= cover; });
  CHECK(first_random != chosen.end());
  CHECK(std::all_of(first_random, chosen.end(), [&](std::uint32_t i) { return i >= cover; }));
}

TEST_CASE("select_sample decides the whole net, and the sample then reaches every patch point within sample_cover_power") {
  // The unit cube with balls along its twelve edges (as protection puts them), radius 0.6
  // spacing, one per spacing.
  const refine::PolygonDomain domain(io::make_cube(2));
  const double spacing = 0.05, radius = 0.6 * spacing;
  const std::vector<WeightedPoint> balls = test::unit_cube_edge_balls(spacing, radius);
  const auto [points, patches, parts] = candidates_of(domain, spacing);
  REQUIRE(parts.net > 0);
  bool decided = false;
  const auto chosen = refine::select_sample(points, parts, balls, {}, spacing, {}, &decided);
  CHECK(decided);
  check_selection(points, balls, {}, spacing, chosen, sample_spacings(points.size(), parts.lattice, spacing),
                  refine::kBallClearance);
  // The clearance is used: some chosen point is nearer a ball than a spacing would allow.
  CHECK(std::any_of(chosen.begin(), chosen.end(), [&](std::uint32_t i) {
    return std::any_of(balls.begin(), balls.end(), [&](const WeightedPoint& b) { return power(b, points[i]) <= spacing * spacing; });
  }));
  // The full clearance (MesherOptions::sample_ball_clearance = 1, `delpsc mesh`'s retry): the
  // balls at the whole spacing, fewer points; a clearance outside (0, 1] chooses nothing.
  bool full_decided = false;
  const auto full = refine::select_sample(points, parts, balls, {}, spacing, {}, &full_decided, 1);
  CHECK(full_decided);
  check_selection(points, balls, {}, spacing, full, sample_spacings(points.size(), parts.lattice, spacing), 1);
  CHECK(full.size() < chosen.size());
  for (const double bad : {0.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    bool bad_decided = true;
    CHECK(refine::select_sample(points, parts, balls, {}, spacing, {}, &bad_decided, bad).empty());
    CHECK_FALSE(bad_decided);
  }
  std::vector<WeightedPoint> sample(balls);
  for (const std::uint32_t i : chosen) sample.push_back(WeightedPoint::from(points[i]));
  const double bound =
      refine::sample_cover_power(refine::kGapFillSpacing * spacing, parts.net_radius, radius, refine::kBallClearance);
  CHECK(bound < refine::sample_cover_power(refine::kGapFillSpacing * spacing, parts.net_radius, radius));
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    Vec3 p(unit(rng), unit(rng), unit(rng));
    p[k % 3] = (k / 3) % 2;
    double nearest = HUGE_VAL;
    for (const WeightedPoint& w : sample) nearest = std::min(nearest, (w.point() - p).squaredNorm() - w.w);
    worst = std::max(worst, nearest);
  }
  CHECK(worst <= bound);
  // The sample reaches much closer than the proof's bound (2.5 spacings here): what rebuild() gives up.
  CHECK(worst < 0.5 * bound);

  // Nothing decided: no net, or a net point skipped (its local spacing not valid).
  refine::CandidateParts no_net = parts;
  no_net.net = 0;
  (void)refine::select_sample(points, no_net, balls, {}, spacing, {}, &decided);
  CHECK_FALSE(decided);
  std::vector<double> local(points.size(), spacing);
  local.back() = 0;
  (void)refine::select_sample(points, parts, balls, {}, spacing, local, &decided);
  CHECK_FALSE(decided);
  local.back() = spacing;
  (void)refine::select_sample(points, parts, balls, {}, spacing, local, &decided);
  CHECK(decided);
}

TEST_CASE("sample_cover_power: attained by a net point just refused by the largest ball, or by a point") {
  // A net point q just outside the reach of ball B(0, r) at clearance k (power distance (k s)²),
  // and a patch point y a net radius h beyond it: nothing nearer than B, at power distance the
  // ball's term. A net point refused by a point p at distance s, y a net radius beyond: (s + h)².
  // The bound is the larger of the two.
  for (const auto& [s, h, r] : {std::array<double, 3>{1, 1.5, 1}, {0.3, 0.2, 0}, {2, 0.5, 3}, {0.9, 1.35, 0.6}})
    for (const double k : {1.0, refine::kBallClearance, 0.1}) {
      CAPTURE(s);
      CAPTURE(k);
      const Vec3 q(std::sqrt(k * k * s * s + r * r), 0, 0), y = q + Vec3(h, 0, 0);
      const double ball_term = y.squaredNorm() - r * r;
      const double point_term = (s + h) * (s + h);
      CHECK(refine::sample_cover_power(s, h, r, k) == doctest::Approx(std::max(ball_term, point_term)));
      if (k == 1) CHECK(ball_term >= point_term);  // the ball's term bounds both at full clearance
    }
}
