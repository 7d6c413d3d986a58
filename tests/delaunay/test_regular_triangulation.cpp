// The public API: statuses and counters through degenerate starts, change reports, location,
// stars, rings around edges, duals, copies, input validation.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/kernel/predicates.h>

#include "support/generators.h"
#include "support/triangulation_checks.h"

using namespace delpsc;
using delaunay::CellId;
using delaunay::ChangeSet;
using delaunay::Facet;
using delaunay::kInfiniteVertex;
using delaunay::PointId;
using delaunay::PointStatus;
using delaunay::RegularTriangulation;

namespace {

RegularTriangulation random_triangulation(test::Rng& rng, std::size_t n, double wmax = 0) {
  RegularTriangulation t;
  t.insert(test::uniform_points(rng, n, -1, 1, 0, wmax));
  return t;
}

bool contains_closed(const RegularTriangulation& t, CellId c, const Vec3& p) {
  const double* q[4];
  for (int i = 0; i < 4; ++i) q[i] = t.point(t.vertex(c, i)).data();
  for (int i = 0; i < 4; ++i) {
    const double* saved = q[i];
    q[i] = p.data();
    const int o = kernel::orient3d(q[0], q[1], q[2], q[3]);
    q[i] = saved;
    if (o < 0) return false;
  }
  return true;
}

std::array<PointId, 3> sorted_facet(const RegularTriangulation& t, Facet f) {
  std::array<PointId, 3> v = t.facet_vertices(f);
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

TEST_CASE("dimension grows through pending points; counters follow") {
  RegularTriangulation t;
  CHECK(t.dimension() == -1);
  ChangeSet changes;
  const PointId a = t.insert({0, 0, 0, 0}, &changes);
  CHECK(a == 0);
  CHECK(t.dimension() == 0);
  CHECK(t.status(a) == PointStatus::pending);
  t.insert({0, 0, 0, 0});  // a duplicate does not raise the dimension
  CHECK(t.dimension() == 0);
  t.insert({2, 0, 0, 0});
  t.insert({1, 0, 0, 0});  // collinear
  CHECK(t.dimension() == 1);
  t.insert({0, 1, 0, 0});
  t.insert({1, 1, 0, 0});  // coplanar
  CHECK(t.dimension() == 2);
  CHECK(t.number_of_cells() == 0);
  CHECK(t.number_of_vertices() == 0);
  std::string why;
  CHECK_MESSAGE(t.is_valid(&why), why);
  // The first point off the plane builds everything, pending points included.
  const PointId apex = t.insert({0.5, 0.5, 1, 0}, &changes);
  CHECK(t.dimension() == 3);
  CHECK_MESSAGE(t.is_valid(&why), why);
  CHECK(t.status(apex) == PointStatus::vertex);
  CHECK(t.number_of_vertices() == 6);
  CHECK(t.number_of_hidden() == 1);  // the duplicate
  CHECK(t.status(1) == PointStatus::hidden);
  CHECK(changes.created.size() == t.number_of_cells());
  CHECK(changes.destroyed.empty());
  CHECK(changes.hidden == std::vector<PointId>{1});
  CHECK(t.number_of_points() == 7);
  CHECK(t.number_of_finite_cells() + 0 < t.number_of_cells());
  // Compare with the brute force on the distinct points (the duplicate, id 1, is skipped).
  const std::vector<std::uint32_t> names = {0, 99, 1, 2, 3, 4, 5};
  CHECK(test::finite_cell_quads(t, names) ==
        test::brute_force_regular_cells({{0, 0, 0, 0}, {2, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0},
                                         {1, 1, 0, 0}, {0.5, 0.5, 1, 0}}));
}

TEST_CASE("insert reports its changes; hidden and replacing duplicates") {
  test::Rng rng(41);
  RegularTriangulation t = random_triangulation(rng, 500, 0.001);
  std::string why;
  for (int k = 0; k < 300; ++k) {
    const std::size_t before = t.number_of_cells();
    ChangeSet changes;
    WeightedPoint p{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2),
                    rng.uniform(0, 0.02)};
    if (k % 10 == 0) {  // exactly on an existing point, heavier or lighter
      const auto& q = t.point(static_cast<PointId>(rng.index(t.number_of_points())));
      p = {q.x, q.y, q.z, q.w + (k % 20 == 0 ? 0.01 : -0.0001)};
    }
    // Every facet's vertices before the insertion, to check `replaced` against.
    std::vector<std::array<PointId, 3>> facets_before(4 * t.cell_capacity());
    for (CellId c = 0; c < t.cell_capacity(); ++c)
      for (int i = 0; t.is_cell_alive(c) && i < 4; ++i) facets_before[4 * c + i] = sorted_facet(t, {c, i});
    const PointId id = t.insert(p, &changes);
    CHECK(test::check_change_set(t, before, changes) == "");
    if (t.status(id) == PointStatus::hidden) {
      CHECK(changes.created.empty());
      CHECK(changes.replaced.empty());
      CHECK(std::find(changes.hidden.begin(), changes.hidden.end(), id) != changes.hidden.end());
    } else {
      // Every created cell is incident to the new vertex, and its facet opposite it is the
      // destroyed cell's facet `replaced` names.
      REQUIRE(changes.replaced.size() == changes.created.size());
      for (std::size_t j = 0; j < changes.created.size(); ++j) {
        const CellId c = changes.created[j];
        const int i = t.index_of(c, id);
        CHECK(i >= 0);
        const Facet old = changes.replaced[j];
        CHECK(std::find(changes.destroyed.begin(), changes.destroyed.end(), old.cell) != changes.destroyed.end());
        CHECK(sorted_facet(t, {c, i}) == facets_before[4 * old.cell + old.index]);
      }
    }
    for (const PointId h : changes.hidden) CHECK(t.status(h) == PointStatus::hidden);
  }
  REQUIRE_MESSAGE(t.is_valid(&why), why);
  CHECK(test::check_regular_against_all_points(t) == "");
  // Hidden points are listed by their cells.
  std::size_t listed = 0;
  std::vector<PointId> hidden;
  for (CellId c = 0; c < t.cell_capacity(); ++c) {
    if (!t.is_cell_alive(c)) continue;
    hidden.clear();
    t.hidden_points(c, hidden);
    for (const PointId h : hidden) CHECK(t.incident_cell(h) == c);
    listed += hidden.size();
  }
  CHECK(listed == t.number_of_hidden());
  CHECK(t.number_of_hidden() > 0);
}

TEST_CASE("locate finds a containing cell, or a hull facet seeing the point") {
  test::Rng rng(42);
  const RegularTriangulation t = random_triangulation(rng, 2000);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5));
    const CellId c = t.locate(p, static_cast<CellId>(rng.index(t.cell_capacity())));
    REQUIRE(t.is_cell_alive(c));
    const int inf = t.infinite_index(c);
    if (inf < 0) {
      CHECK(contains_closed(t, c, p));
    } else {
      const auto f = t.facet_vertices({c, inf});
      // The infinite cell's convention: p in place of the infinite vertex is positively oriented.
      CHECK(kernel::orient3d(t.point(f[0]).point(), t.point(f[1]).point(), t.point(f[2]).point(), p) > 0);
      CHECK(std::max({std::fabs(p.x()), std::fabs(p.y()), std::fabs(p.z())}) > 0.9);
    }
  }
  // Vertices themselves: the cell found has them as a vertex.
  for (PointId v = 0; v < 100; ++v) CHECK(t.index_of(t.locate(t.point(v).point()), v) >= 0);
}

TEST_CASE("stars, facets and rings around edges") {
  test::Rng rng(43);
  const RegularTriangulation t = random_triangulation(rng, 400, 0.002);
  // Brute-force incidences.
  for (PointId v = 0; v < t.number_of_points(); v += 7) {
    if (t.status(v) != PointStatus::vertex) continue;
    std::set<CellId> expected;
    for (CellId c = 0; c < t.cell_capacity(); ++c)
      if (t.is_cell_alive(c) && t.index_of(c, v) >= 0) expected.insert(c);
    std::vector<CellId> star;
    t.incident_cells(v, star);
    CHECK(std::set<CellId>(star.begin(), star.end()) == expected);
    CHECK(star.size() == expected.size());
    std::vector<Facet> facets;
    t.incident_facets(v, facets);
    std::set<std::array<PointId, 3>> seen;
    for (const Facet& f : facets) {
      auto tri = t.facet_vertices(f);
      CHECK(std::find(tri.begin(), tri.end(), v) != tri.end());
      std::sort(tri.begin(), tri.end());
      CHECK(seen.insert(tri).second);
    }
    // Facets containing v = (3 per cell) / 2.
    CHECK(facets.size() * 2 == expected.size() * 3);
  }
  // Rings: every cell containing the edge, each once, consecutive ones adjacent.
  int rings = 0;
  for (CellId c = 0; c < t.cell_capacity() && rings < 300; c += 3) {
    if (!t.is_cell_alive(c)) continue;
    ++rings;
    const PointId a = t.vertex(c, 0), b = t.vertex(c, 2);
    std::vector<CellId> ring;
    t.cells_around_edge(c, 0, 2, ring);
    std::set<CellId> expected;
    for (CellId d = 0; d < t.cell_capacity(); ++d)
      if (t.is_cell_alive(d) && t.index_of(d, a) >= 0 && t.index_of(d, b) >= 0) expected.insert(d);
    CHECK(ring.front() == c);
    CHECK(std::set<CellId>(ring.begin(), ring.end()) == expected);
    CHECK(ring.size() == expected.size());
    std::vector<Facet> facets;
    t.facets_around_edge(c, 0, 2, facets);
    REQUIRE(facets.size() == ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
      CHECK(facets[k].cell == ring[k]);
      CHECK(t.neighbour(ring[k], facets[k].index) == ring[(k + 1) % ring.size()]);
      const auto tri = t.facet_vertices(facets[k]);
      CHECK(std::find(tri.begin(), tri.end(), a) != tri.end());
      CHECK(std::find(tri.begin(), tri.end(), b) != tri.end());
    }
  }
  // The infinite vertex's star is the set of infinite cells.
  std::vector<CellId> hull;
  t.incident_cells(kInfiniteVertex, hull);
  CHECK(hull.size() == t.number_of_cells() - t.number_of_finite_cells());
}

TEST_CASE("duals: orthocentres and Voronoi edges") {
  test::Rng rng(44);
  const RegularTriangulation t = random_triangulation(rng, 300, 0.01);
  auto power = [&](const Vec3& x, PointId v) { return (x - t.point(v).point()).squaredNorm() - t.point(v).w; };
  int rays = 0, segments = 0;
  for (CellId c = 0; c < t.cell_capacity(); ++c) {
    if (!t.is_cell_alive(c) || t.is_infinite(c)) continue;
    const Vec3 o = t.orthocentre(c);
    const double w = t.orthoradius_squared(c);
    for (int i = 0; i < 4; ++i) CHECK(power(o, t.vertex(c, i)) == doctest::Approx(w).epsilon(1e-9).scale(1));
    for (int i = 0; i < 4; ++i) {
      const Facet f{c, i};
      const auto e = t.dual(f);
      const auto tri = t.facet_vertices(f);
      const Vec3 a = t.point(tri[0]).point(), b = t.point(tri[1]).point(), cc = t.point(tri[2]).point();
      const Vec3 ab = b - a, ac = cc - a;
      const Vec3 n = ab.cross(ac);
      if (e.is_ray) {
        ++rays;
        CHECK(t.is_infinite(t.neighbour(c, i)));
        CHECK(e.source == o);
        // Perpendicular to the facet, pointing away from the cell's fourth vertex.
        CHECK(e.direction.cross(n).norm() <= 1e-12 * e.direction.norm() * n.norm());
        CHECK(e.direction.dot(t.point(t.vertex(c, i)).point() - a) < 0);
      } else {
        ++segments;
        CHECK(e.source == o);
        CHECK(e.target == t.orthocentre(t.neighbour(c, i)));
        // The Voronoi edge is perpendicular to the facet.
        const Vec3 d = e.target - e.source;
        CHECK(d.cross(n).norm() <= 1e-8 * (d.norm() * n.norm() + 1e-300));
      }
    }
  }
  CHECK(rays > 0);
  CHECK(segments > 0);
}

TEST_CASE("copies, moves, clear, input validation") {
  test::Rng rng(45);
  RegularTriangulation t = random_triangulation(rng, 200);
  RegularTriangulation copy = t;
  std::string why;
  CHECK_MESSAGE(copy.is_valid(&why), why);
  CHECK(test::finite_cell_quads(copy) == test::finite_cell_quads(t));
  // The copy lives on its own.
  copy.insert({0, 0, 0, 0});
  copy.remove(3);
  CHECK_MESSAGE(copy.is_valid(&why), why);
  CHECK_MESSAGE(t.is_valid(&why), why);
  CHECK(copy.number_of_points() == t.number_of_points() + 1);
  RegularTriangulation moved = std::move(copy);
  CHECK_MESSAGE(moved.is_valid(&why), why);
  moved.insert({0.25, 0.5, 0.125, 0});
  CHECK_MESSAGE(moved.is_valid(&why), why);
  t = moved;
  CHECK(test::finite_cell_quads(t) == test::finite_cell_quads(moved));
  CHECK(t.memory_bytes() > t.number_of_cells() * 32);
  t.clear();
  CHECK(t.dimension() == -1);
  CHECK(t.number_of_points() == 0);
  CHECK_MESSAGE(t.is_valid(&why), why);
  CHECK_THROWS_AS(t.insert({std::numeric_limits<double>::quiet_NaN(), 0, 0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(t.insert({0, std::numeric_limits<double>::infinity(), 0, 0}), std::invalid_argument);
  CHECK(t.number_of_points() == 0);
  // A bad point in a batch leaves the triangulation untouched.
  t.insert(test::uniform_points(rng, 50, 0, 1));
  const auto before = test::finite_cell_quads(t);
  auto batch = test::uniform_points(rng, 20, 0, 1);
  batch[13].w = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(t.insert(batch), std::invalid_argument);
  CHECK(t.number_of_points() == 50);
  CHECK(test::finite_cell_quads(t) == before);
  CHECK_MESSAGE(t.is_valid(&why), why);
}

// The batch's `lead` points go in before the others (the mesher's far frame: left to the
// spatial order, a corner inserted late replaces every hull cell it sees). Observable through
// the progress report: after the first 2^16 insertions of 2^17 points every lead point is a
// vertex, which the spatial order alone would leave to chance (~1 in 2^8 for eight corners).
TEST_CASE("a batch inserts its lead points first, numbered as without them") {
  test::Rng rng(5);
  std::vector<WeightedPoint> pts;
  for (int k = 0; k < 8; ++k)
    pts.push_back(WeightedPoint::from(Vec3(k & 1 ? 30 : -30, k & 2 ? 30 : -30, k & 4 ? 30 : -30)));
  const auto inner = test::uniform_points(rng, (std::size_t{1} << 17) - 8, -1, 1);
  pts.insert(pts.end(), inner.begin(), inner.end());
  RegularTriangulation plain, led;
  std::vector<PointId> plain_ids, led_ids;
  plain.insert(pts, &plain_ids);
  int reports = 0;
  bool frame_in_first = true;
  led.insert(pts, &led_ids, [&](std::size_t inserted) {
    if (reports++ == 0) {
      CHECK(inserted == std::size_t{1} << 16);
      for (int k = 0; k < 8; ++k) frame_in_first = frame_in_first && led.status(led_ids[k]) == PointStatus::vertex;
    }
  }, 8);
  CHECK(reports == 2);
  CHECK(frame_in_first);
  CHECK(led_ids == plain_ids);
  CHECK(led.number_of_finite_cells() == plain.number_of_finite_cells());
  std::string why;
  CHECK_MESSAGE(led.is_valid(&why), why);
}
