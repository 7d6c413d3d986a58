// Scale: 10^5 insertions, then 10^4 interleaved removals and insertions, on uniform, spherical
// (exactly and nearly cospherical), integer-grid, equal-weight and mixed-weight inputs. The full
// validity check runs at the end of each phase, and the final triangulation must equal the one
// built from scratch on the remaining points.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/io/point_generators.h>

#include "support/generators.h"
#include "support/triangulation_checks.h"

using namespace delpsc;
using delaunay::PointId;
using delaunay::PointStatus;
using delaunay::RegularTriangulation;

namespace {

bool live(const RegularTriangulation& t, PointId p) {
  return t.status(p) == PointStatus::vertex || t.status(p) == PointStatus::hidden;
}

// Identical weighted points share the smallest id among the live ones (which of them is the
// vertex depends on the insertion order).
std::vector<std::uint32_t> canonical_names(const RegularTriangulation& t) {
  std::map<std::array<double, 4>, std::uint32_t> first;
  std::vector<std::uint32_t> names(t.number_of_points());
  for (PointId p = 0; p < t.number_of_points(); ++p) {
    const auto& q = t.point(p);
    names[p] = live(t, p) ? first.emplace(std::array<double, 4>{q.x, q.y, q.z, q.w}, p).first->second : p;
  }
  return names;
}

// Batch insertion of `initial`, then `steps` operations alternating at random between removing a
// random live point and inserting a point from `extra`.
void stress(const std::vector<WeightedPoint>& initial, const std::vector<WeightedPoint>& extra,
            std::size_t steps, test::Rng& rng, const char* what) {
  CAPTURE(what);
  RegularTriangulation t;
  t.insert(initial);
  std::string why;
  REQUIRE_MESSAGE(t.is_valid(&why), why);
  CHECK(t.number_of_vertices() + t.number_of_hidden() == initial.size());

  std::vector<PointId> alive;
  for (PointId p = 0; p < t.number_of_points(); ++p) alive.push_back(p);
  std::size_t next_extra = 0, removed = 0, refused = 0;
  for (std::size_t step = 0; step < steps; ++step) {
    if (rng.chance(0.5) && next_extra < extra.size()) {
      alive.push_back(t.insert(extra[next_extra++]));
      continue;
    }
    const std::size_t k = rng.index(alive.size());
    std::string error;
    if (t.remove(alive[k], nullptr, &error)) {
      alive[k] = alive.back();
      alive.pop_back();
      ++removed;
    } else {
      ++refused;
    }
  }
  CHECK(refused == 0);
  CHECK(removed > steps / 3);
  REQUIRE_MESSAGE(t.is_valid(&why), why);

  // Equal to the triangulation built from scratch on what remains.
  std::vector<WeightedPoint> remaining;
  std::vector<PointId> ids;
  for (PointId p = 0; p < t.number_of_points(); ++p)
    if (live(t, p)) {
      remaining.push_back(t.point(p));
      ids.push_back(p);
    }
  RegularTriangulation fresh;
  std::vector<PointId> fresh_ids;
  fresh.insert(remaining, &fresh_ids);
  const auto names = canonical_names(t);
  std::vector<std::uint32_t> fresh_names(remaining.size());
  for (std::size_t k = 0; k < remaining.size(); ++k) fresh_names[fresh_ids[k]] = names[ids[k]];
  CHECK(test::finite_cell_quads(t, names) == test::finite_cell_quads(fresh, fresh_names));
  CHECK(test::points_with_status(t, PointStatus::hidden, names) ==
        test::points_with_status(fresh, PointStatus::hidden, fresh_names));
}

std::vector<WeightedPoint> with_weights(std::vector<WeightedPoint> pts, test::Rng& rng, double lo, double hi) {
  for (auto& p : pts) p.w = lo == hi ? lo : rng.uniform(lo, hi);
  return pts;
}

}  // namespace

TEST_CASE("stress: uniform points") {
  test::Rng rng(31);
  stress(io::uniform_points(100000, 1), io::uniform_points(20000, 2), 20000, rng, "uniform");
}

TEST_CASE("stress: cospherical points") {
  test::Rng rng(32);
  // Nearly cospherical (rounded normalised vectors) and exactly cospherical integer points,
  // with the centre and a few interior points: the worst cases for the conflict regions.
  stress(io::sphere_points(100000, 3), io::sphere_points(20000, 4), 20000, rng, "sphere");
  auto lattice = test::lattice_sphere_points(99225);  // 315^2: 4590 integer points
  REQUIRE(lattice.size() > 4000);
  std::shuffle(lattice.begin(), lattice.end(), rng.engine());
  std::vector<WeightedPoint> extra(lattice.end() - 300, lattice.end());
  lattice.resize(lattice.size() - 300);
  extra.push_back({0, 0, 0, 0});
  extra.push_back({1, 2, 3, 0});
  stress(lattice, extra, 1000, rng, "lattice sphere");
}

TEST_CASE("stress: integer grid") {
  test::Rng rng(33);
  auto grid = test::grid_points(46, 46, 46);
  std::shuffle(grid.begin(), grid.end(), rng.engine());
  std::vector<WeightedPoint> extra(grid.end() - 10000, grid.end());
  grid.resize(grid.size() - 10000);
  // Some extra points land exactly on occupied positions: duplicates.
  for (int k = 0; k < 500; ++k) extra.push_back(grid[rng.index(grid.size())]);
  std::shuffle(extra.begin(), extra.end(), rng.engine());
  stress(grid, extra, 20000, rng, "grid");
}

TEST_CASE("stress: equal weights") {
  test::Rng rng(34);
  // Mean spacing ~0.02; balls of radius 0.01 overlap their neighbours a little.
  stress(with_weights(io::uniform_points(100000, 5), rng, 1e-4, 1e-4),
         with_weights(io::uniform_points(20000, 6), rng, 1e-4, 1e-4), 20000, rng, "equal weights");
  // Equal weights on the grid: every power test among grid points is a tie.
  stress(with_weights(test::grid_points(30, 30, 30), rng, 0.25, 0.25),
         with_weights(test::uniform_points(rng, 5000, 0, 29), rng, 0.25, 0.25), 5000, rng,
         "grid, equal weights");
}

TEST_CASE("stress: mixed weights") {
  test::Rng rng(35);
  // Weights up to (2 x spacing)^2: a good share of the points end up hidden.
  auto initial = with_weights(io::uniform_points(100000, 7), rng, 0, 1.6e-3);
  auto extra = with_weights(io::uniform_points(20000, 8), rng, 0, 1.6e-3);
  RegularTriangulation probe;
  probe.insert(initial);
  CHECK(probe.number_of_hidden() > 1000);
  stress(initial, extra, 20000, rng, "mixed weights");
}
