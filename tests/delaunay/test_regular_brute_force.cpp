// The triangulation against an O(n^5) brute force on small sets, generic and degenerate: same
// finite cells, same hidden points, and every cell free of conflicts with every live point.
#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>

#include <delpsc/delaunay/regular_triangulation.h>

#include "support/generators.h"
#include "support/triangulation_checks.h"

using namespace delpsc;
using delaunay::PointStatus;
using delaunay::RegularTriangulation;

namespace {

// Inserts the points one at a time (in the given order) and compares with the brute force.
void check_against_brute_force(const std::vector<WeightedPoint>& pts, const char* what) {
  CAPTURE(what);
  CAPTURE(pts.size());
  RegularTriangulation t;
  for (const auto& p : pts) t.insert(p);
  std::string why;
  REQUIRE_MESSAGE(t.is_valid(&why), why);
  const auto expected = test::brute_force_regular_cells(pts);
  if (expected.empty()) {
    CHECK(t.dimension() < 3);
    return;
  }
  REQUIRE(t.dimension() == 3);
  CHECK(test::finite_cell_quads(t) == expected);
  // Hidden = the points that are a vertex of no regular cell.
  std::set<std::uint32_t> used;
  for (const auto& q : expected) used.insert(q.begin(), q.end());
  std::vector<std::uint32_t> hidden;
  for (std::uint32_t i = 0; i < pts.size(); ++i)
    if (!used.count(i)) hidden.push_back(i);
  CHECK(test::points_with_status(t, PointStatus::hidden) == hidden);
  CHECK(test::check_regular_against_all_points(t) == "");
}

// Same set, inserted in several orders and as a batch: the cells must not depend on the order.
void check_orders(std::vector<WeightedPoint> pts, test::Rng& rng, const char* what) {
  check_against_brute_force(pts, what);
  std::vector<std::uint32_t> perm(pts.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::shuffle(perm.begin(), perm.end(), rng.engine());
  std::vector<WeightedPoint> shuffled(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) shuffled[i] = pts[perm[i]];
  check_against_brute_force(shuffled, what);
  // A batch is stored in its insertion order: name its points by their input index.
  RegularTriangulation batch;
  std::vector<delaunay::PointId> ids;
  batch.insert(pts, &ids);
  std::string why;
  CHECK_MESSAGE(batch.is_valid(&why), why);
  std::vector<std::uint32_t> names(pts.size());
  for (std::uint32_t k = 0; k < pts.size(); ++k) {
    CHECK(batch.point(ids[k]) == pts[k]);
    names[ids[k]] = k;
  }
  RegularTriangulation one;
  for (const auto& p : pts) one.insert(p);
  CHECK(test::finite_cell_quads(batch, names) == test::finite_cell_quads(one));
  CHECK(test::points_with_status(batch, PointStatus::hidden, names) ==
        test::points_with_status(one, PointStatus::hidden));
  // The first points leading the batch (the mesher's far frame): the same cells and the same
  // numbering as the plain batch.
  const std::size_t lead = std::min<std::size_t>(4, pts.size());
  RegularTriangulation led;
  std::vector<delaunay::PointId> led_ids;
  led.insert(pts, &led_ids, {}, lead);
  CHECK_MESSAGE(led.is_valid(&why), why);
  std::vector<std::uint32_t> led_names(pts.size());
  for (std::uint32_t k = 0; k < pts.size(); ++k) {
    CHECK(led.point(led_ids[k]) == pts[k]);
    led_names[led_ids[k]] = k;
  }
  CHECK(led_ids == ids);
  CHECK(test::finite_cell_quads(led, led_names) == test::finite_cell_quads(one));
  CHECK(test::points_with_status(led, PointStatus::hidden, led_names) ==
        test::points_with_status(one, PointStatus::hidden));
  CHECK_THROWS_AS(RegularTriangulation().insert(pts, nullptr, {}, pts.size() + 1), std::invalid_argument);
}

}  // namespace

TEST_CASE("small generic sets equal the brute force") {
  test::Rng rng(11);
  for (int trial = 0; trial < 30; ++trial) {
    const std::size_t n = 5 + rng.index(20);
    check_orders(test::uniform_points(rng, n, -1, 1), rng, "uniform");
    check_orders(test::uniform_points(rng, n, -1, 1, 0, 0.3), rng, "weighted");
  }
}

TEST_CASE("small degenerate sets equal the brute force") {
  test::Rng rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    // Integer grid samples: coplanar and cospherical subsets everywhere.
    const auto grid = test::grid_points(4, 4, 4);
    check_orders(test::sample_distinct(rng, grid, 8 + rng.index(16)), rng, "grid sample");
    // Integer points on one sphere: every power test among them is zero.
    const auto sphere = test::lattice_sphere_points(50 + 3 * trial);
    if (sphere.size() >= 5)
      check_orders(test::sample_distinct(rng, sphere, std::min<std::size_t>(sphere.size(), 24)), rng,
                   "lattice sphere");
    // Equal non-zero weights.
    auto equal = test::sample_distinct(rng, grid, 20);
    test::set_weights(equal, 0.25);
    check_orders(equal, rng, "grid, equal weights");
    // Weights making every point orthogonal to one sphere: all power tests zero again.
    auto ortho = test::sample_distinct(rng, grid, 20);
    const double centre[3] = {1.5, 1.5, 1.5};
    if (test::set_orthogonal_weights(ortho, centre, 4.0)) check_orders(ortho, rng, "orthogonal weights");
    // Mixed weights on the grid, large enough to hide points.
    auto mixed = test::sample_distinct(rng, grid, 20);
    for (auto& p : mixed) p.w = static_cast<double>(rng.integer(0, 6)) / 4;
    check_orders(mixed, rng, "grid, mixed weights");
  }
  // The full 3x3x3 grid and the whole cube corners.
  check_orders(test::grid_points(3, 3, 3), rng, "full grid");
  check_orders(test::grid_points(2, 2, 2), rng, "cube");
}

TEST_CASE("degenerate starts: coplanar and collinear prefixes") {
  test::Rng rng(13);
  for (int trial = 0; trial < 20; ++trial) {
    const auto plane = test::IntegerPlane::random(rng, 3, 5);
    auto pts = test::coplanar_points(rng, 10, plane, 6);
    const double origin[3] = {0, 0, 0};
    const auto dir = test::random_integer_vector(rng, 3);
    auto line = test::collinear_points(rng, 5, origin, dir.data(), 5);
    // Drop exact duplicates (the brute force needs distinct positions).
    std::vector<WeightedPoint> all;
    auto add = [&](const WeightedPoint& p) {
      for (const auto& q : all)
        if (q.x == p.x && q.y == p.y && q.z == p.z) return;
      all.push_back(p);
    };
    for (const auto& p : line) add(p);
    for (const auto& p : pts) add(p);
    // Until something leaves the plane, nothing is triangulated.
    RegularTriangulation t;
    for (const auto& p : pts) t.insert(p);
    CHECK(t.dimension() <= 2);
    CHECK(t.number_of_cells() == 0);
    std::string why;
    CHECK_MESSAGE(t.is_valid(&why), why);
    add(WeightedPoint{0.5, 0.25, 7.125, 0});
    add(WeightedPoint{-3.5, 1.25, -6.5, 0});
    check_against_brute_force(all, "line, then plane, then off-plane points");
  }
}
