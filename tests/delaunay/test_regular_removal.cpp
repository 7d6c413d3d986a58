// Removal: after any sequence of insertions and removals the triangulation equals the one built
// from scratch on the remaining points (cells as sorted quadruples of the user's point ids), hidden
// points come back when they should, and every operation reports its changes consistently.
#include <doctest/doctest.h>

#include <algorithm>
#include <map>
#include <numeric>

#include <delpsc/delaunay/regular_triangulation.h>

#include "support/generators.h"
#include "support/triangulation_checks.h"

using namespace delpsc;
using delaunay::ChangeSet;
using delaunay::PointId;
using delaunay::PointStatus;
using delaunay::RegularTriangulation;

namespace {

bool live(const RegularTriangulation& t, PointId p) {
  return t.status(p) == PointStatus::vertex || t.status(p) == PointStatus::hidden;
}

// Canonical name of each live point: identical weighted points (which of them is the vertex
// depends on the order, CGAL's rule) share the smallest id among them.
std::vector<std::uint32_t> canonical_names(const RegularTriangulation& t) {
  std::map<std::array<double, 4>, std::uint32_t> first;
  std::vector<std::uint32_t> names(t.number_of_points());
  for (PointId p = 0; p < t.number_of_points(); ++p) {
    const auto& q = t.point(p);
    names[p] = live(t, p) ? first.emplace(std::array<double, 4>{q.x, q.y, q.z, q.w}, p).first->second : p;
  }
  return names;
}

// Rebuilds from the live points in a shuffled order and compares cells and hidden points.
void check_equals_rebuild(const RegularTriangulation& t, test::Rng& rng) {
  std::vector<PointId> ids;
  for (PointId p = 0; p < t.number_of_points(); ++p)
    if (live(t, p)) ids.push_back(p);
  std::shuffle(ids.begin(), ids.end(), rng.engine());
  RegularTriangulation fresh;
  for (const PointId p : ids) fresh.insert(t.point(p));
  const auto names = canonical_names(t);
  std::vector<std::uint32_t> fresh_names(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) fresh_names[k] = names[ids[k]];
  REQUIRE(fresh.dimension() == t.dimension());
  CHECK(test::finite_cell_quads(t, names) == test::finite_cell_quads(fresh, fresh_names));
  CHECK(test::points_with_status(t, PointStatus::hidden, names) ==
        test::points_with_status(fresh, PointStatus::hidden, fresh_names));
}

// Removes random live points one at a time down to `keep`, checking everything after each step.
void remove_down_to(std::vector<WeightedPoint> pts, std::size_t keep, test::Rng& rng, const char* what) {
  CAPTURE(what);
  RegularTriangulation t;
  t.insert(pts);
  std::string why;
  REQUIRE_MESSAGE(t.is_valid(&why), why);
  std::vector<PointId> alive(pts.size());
  std::iota(alive.begin(), alive.end(), 0u);
  std::size_t refused = 0;
  while (alive.size() > keep) {
    const std::size_t k = rng.index(alive.size());
    const PointId p = alive[k];
    const std::size_t cells_before = t.number_of_cells();
    const bool was_hidden = t.status(p) == PointStatus::hidden;
    ChangeSet changes;
    std::string error;
    if (!t.remove(p, &changes, &error)) {
      // Only refusals that keep dimension 3 are allowed; stop when that is all that is left.
      CHECK(t.status(p) == PointStatus::vertex);
      CHECK(error.find("dimension") != std::string::npos);
      if (++refused > 20) break;
      continue;
    }
    CAPTURE(p);
    CHECK(t.status(p) == PointStatus::removed);
    alive.erase(alive.begin() + static_cast<std::ptrdiff_t>(k));
    REQUIRE_MESSAGE(t.is_valid(&why), why);
    CHECK(test::check_change_set(t, cells_before, changes) == "");
    if (was_hidden) CHECK(changes.created.empty());
    for (const PointId r : changes.revealed) CHECK(t.status(r) == PointStatus::vertex);
    for (const PointId h : changes.hidden) CHECK(t.status(h) == PointStatus::hidden);
    check_equals_rebuild(t, rng);
  }
}

}  // namespace

TEST_CASE("removal equals rebuild: generic sets") {
  test::Rng rng(21);
  remove_down_to(test::uniform_points(rng, 200, 0, 1), 5, rng, "uniform");
  remove_down_to(test::uniform_points(rng, 200, 0, 1, 0, 0.02), 5, rng, "weighted");
  // Big weights: many hidden points, which must come back as their hiders go.
  remove_down_to(test::uniform_points(rng, 200, 0, 1, 0, 0.2), 5, rng, "heavy weights");
}

TEST_CASE("removal equals rebuild: degenerate sets") {
  test::Rng rng(22);
  remove_down_to(test::grid_points(5, 5, 5), 5, rng, "grid");
  auto sphere = test::lattice_sphere_points(101);
  remove_down_to(sphere, 5, rng, "lattice sphere");
  sphere.push_back(WeightedPoint{0, 0, 0, 0});  // the centre: in conflict with everything
  remove_down_to(sphere, 5, rng, "lattice sphere and centre");
  auto equal = test::grid_points(4, 4, 4);
  test::set_weights(equal, 0.3);
  remove_down_to(equal, 5, rng, "grid, equal weights");
  auto mixed = test::grid_points(4, 4, 4);
  for (auto& p : mixed) p.w = static_cast<double>(rng.integer(0, 8)) / 8;
  remove_down_to(mixed, 5, rng, "grid, mixed weights");
  const double centre[3] = {1.5, 1.5, 1.5};
  auto ortho = test::grid_points(4, 4, 4);
  REQUIRE(test::set_orthogonal_weights(ortho, centre, 5.0));
  remove_down_to(ortho, 5, rng, "orthogonal weights");
}

TEST_CASE("duplicates: the heavier point is the vertex, the other comes back on removal") {
  test::Rng rng(23);
  auto pts = test::uniform_points(rng, 60, 0, 1, 0, 0.001);
  // Every point twice, with another weight; and a few exact copies.
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) pts.push_back({pts[i].x, pts[i].y, pts[i].z, rng.uniform(0, 0.001)});
  for (std::size_t i = 0; i < 10; ++i) pts.push_back(pts[i]);
  RegularTriangulation t;
  for (const auto& p : pts) t.insert(p);
  std::string why;
  REQUIRE_MESSAGE(t.is_valid(&why), why);
  CHECK(test::check_regular_against_all_points(t) == "");
  for (std::size_t i = 0; i < n; ++i) {
    // At most one of the two is a vertex; if one is, it is the heavier.
    const PointId a = static_cast<PointId>(i), b = static_cast<PointId>(i + n);
    CHECK(!(t.status(a) == PointStatus::vertex && t.status(b) == PointStatus::vertex));
    if (t.status(a) == PointStatus::vertex) CHECK(pts[a].w >= pts[b].w);
    if (t.status(b) == PointStatus::vertex) CHECK(pts[b].w > pts[a].w);
  }
  // An exact copy of a vertex is hidden (equal weights: the first one stays).
  for (std::size_t i = 0; i < 10; ++i)
    if (t.status(static_cast<PointId>(i)) == PointStatus::vertex)
      CHECK(t.status(static_cast<PointId>(2 * n + i)) == PointStatus::hidden);
  remove_down_to(pts, 5, rng, "duplicates");
}

TEST_CASE("removing hull vertices, and refusing to go flat") {
  test::Rng rng(24);
  // A square pyramid: removing the apex would leave a flat set.
  {
    RegularTriangulation t;
    for (const auto& p : test::grid_points(3, 3, 1)) t.insert(p);
    CHECK(t.dimension() == 2);
    const PointId apex = t.insert({1, 1, 1, 0});
    CHECK(t.dimension() == 3);
    std::string error;
    CHECK_FALSE(t.remove(apex, nullptr, &error));
    CHECK(error.find("coplanar") != std::string::npos);
    CHECK(t.status(apex) == PointStatus::vertex);
    std::string why;
    CHECK_MESSAGE(t.is_valid(&why), why);
    // Removing points of the base is fine while four independent vertices remain.
    CHECK(t.remove(0));
    CHECK_MESSAGE(t.is_valid(&why), why);
    check_equals_rebuild(t, rng);
  }
  // A bipyramid: each apex's link is the flat square; removing one leaves a pyramid.
  {
    RegularTriangulation t;
    for (const auto& p : test::grid_points(3, 3, 1)) t.insert(p);
    const PointId top = t.insert({1, 1, 1, 0});
    t.insert({1.25, 0.75, -1, 0});
    ChangeSet changes;
    const std::size_t before = t.number_of_cells();
    std::string why;
    REQUIRE(t.remove(top, &changes));
    CHECK_MESSAGE(t.is_valid(&why), why);
    CHECK(test::check_change_set(t, before, changes) == "");
    check_equals_rebuild(t, rng);
  }
  // The last four vertices stay.
  {
    RegularTriangulation t;
    for (const auto& p : test::grid_points(2, 2, 1)) t.insert(p);
    t.insert({0.5, 0.5, 1, 0});
    CHECK(t.remove(0));
    std::string error;
    CHECK_FALSE(t.remove(1, nullptr, &error));
    CHECK(t.number_of_vertices() == 4);
  }
  // Errors: unknown id, removed twice; pending points just go.
  {
    RegularTriangulation t;
    const PointId a = t.insert({0, 0, 0, 0});
    t.insert({1, 0, 0, 0});
    std::string error;
    CHECK_FALSE(t.remove(99, nullptr, &error));
    CHECK(t.remove(a));
    CHECK_FALSE(t.remove(a, nullptr, &error));
    CHECK(t.dimension() == 0);
    std::string why;
    CHECK_MESSAGE(t.is_valid(&why), why);
  }
}

TEST_CASE("interleaved insertions and removals equal rebuild") {
  test::Rng rng(25);
  for (const double wmax : {0.0, 0.002, 0.05}) {
    RegularTriangulation t;
    std::vector<PointId> alive;
    std::string why;
    for (int step = 0; step < 1500; ++step) {
      const bool remove = alive.size() > 20 && rng.chance(0.4);
      const std::size_t cells_before = t.number_of_cells();
      ChangeSet changes;
      if (remove) {
        const std::size_t k = rng.index(alive.size());
        if (!t.remove(alive[k], &changes)) continue;
        alive.erase(alive.begin() + static_cast<std::ptrdiff_t>(k));
      } else {
        WeightedPoint p{rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, wmax)};
        if (rng.chance(0.05)) {  // on a grid now and then: degenerate configurations
          p.x = std::round(p.x * 4) / 4;
          p.y = std::round(p.y * 4) / 4;
          p.z = std::round(p.z * 4) / 4;
        }
        alive.push_back(t.insert(p, &changes));
      }
      if (t.dimension() == 3 && cells_before > 0) CHECK(test::check_change_set(t, cells_before, changes) == "");
      if (step % 100 == 99) {
        REQUIRE_MESSAGE(t.is_valid(&why), why);
        check_equals_rebuild(t, rng);
      }
    }
  }
}
