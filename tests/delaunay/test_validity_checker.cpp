// RegularTriangulation::is_valid must be able to fail: every mesher test relies on it alone for
// the triangulation's regularity after thousands of insertions and ball removals. A valid
// triangulation of weighted points (some hidden) is damaged one way at a time - a cell turned
// over, a neighbour link broken, a vertex made heavy enough to conflict with the cells across
// its star's facets, a counter, a vertex's cell, a hidden point's list - and the checker must
// name each.
#include <doctest/doctest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>

#include "support/generators.h"

namespace delpsc::delaunay {

// The friend the triangulation declares for these tests: raw access to the arrays is_valid reads.
struct RegularTriangulationTestAccess {
  static std::array<PointId, 4>& cell_vertices(RegularTriangulation& t, CellId c) { return t.cells_[c].v; }
  static std::array<std::uint32_t, 4>& cell_links(RegularTriangulation& t, CellId c) { return t.cells_[c].n; }
  static WeightedPoint& point(RegularTriangulation& t, PointId p) { return t.points_[p]; }
  static std::size_t& vertex_count(RegularTriangulation& t) { return t.vertex_count_; }
  static CellId& point_cell(RegularTriangulation& t, PointId p) { return t.point_cell_[p]; }
  static PointId& first_hidden(RegularTriangulation& t, CellId c) { return t.cell_hidden_[c]; }
};

}  // namespace delpsc::delaunay

using namespace delpsc;
using delaunay::CellId;
using delaunay::PointId;
using delaunay::PointStatus;
using delaunay::RegularTriangulation;
using Access = delaunay::RegularTriangulationTestAccess;

namespace {

// 60 weighted points in a cube; some are hidden.
RegularTriangulation sample() {
  test::Rng rng(20261206);
  RegularTriangulation t;
  t.insert(test::uniform_points(rng, 60, 0, 10, 0, 4));
  return t;
}

CellId first_finite_cell(const RegularTriangulation& t) {
  for (CellId c = 0; c < t.cell_capacity(); ++c)
    if (t.is_cell_alive(c) && !t.is_infinite(c)) return c;
  return delaunay::kNoCell;
}

// A vertex of t with no infinite cell around it.
PointId interior_vertex(const RegularTriangulation& t) {
  for (PointId v = 0; v < t.number_of_points(); ++v) {
    if (t.status(v) != PointStatus::vertex) continue;
    std::vector<CellId> star;
    t.incident_cells(v, star);
    if (std::none_of(star.begin(), star.end(), [&](CellId c) { return t.is_infinite(c); })) return v;
  }
  return delaunay::kNoPoint;
}

// What is_valid says of a copy of t after `damage`; "" when it says valid.
std::string verdict_after(const RegularTriangulation& t, const std::function<void(RegularTriangulation&)>& damage) {
  RegularTriangulation copy(t);
  damage(copy);
  std::string why;
  return copy.is_valid(&why) ? std::string() : why;
}

}  // namespace

TEST_CASE("is_valid reports each kind of damage to a valid triangulation") {
  const RegularTriangulation t = sample();
  std::string why;
  REQUIRE_MESSAGE(t.is_valid(&why), why);
  REQUIRE(t.dimension() == 3);
  REQUIRE(t.number_of_hidden() > 0);  // else the hidden-list damage below would test nothing
  const CellId c = first_finite_cell(t);
  REQUIRE(c != delaunay::kNoCell);
  const PointId v = interior_vertex(t);
  REQUIRE(v != delaunay::kNoPoint);

  // The copy itself is valid: every verdict below comes from the damage.
  CHECK(verdict_after(t, [](RegularTriangulation&) {}).empty());
  // Two vertices of a finite cell swapped: the cell is negatively oriented, and its facets no
  // longer match their neighbours' reversed.
  CHECK(!verdict_after(t, [&](RegularTriangulation& u) {
           std::swap(Access::cell_vertices(u, c)[0], Access::cell_vertices(u, c)[1]);
         }).empty());
  // A neighbour link pointing back at the cell itself.
  CHECK(verdict_after(t, [&](RegularTriangulation& u) {
          Access::cell_links(u, c)[0] = (c << 2) | 1u;
        }).find("neighbour link not symmetric") != std::string::npos);
  // A vertex far heavier: the cells across its star's facets now conflict with it. Positions,
  // links and orientations are untouched, so only the regularity test can see it.
  CHECK(verdict_after(t, [&](RegularTriangulation& u) { Access::point(u, v).w += 1e4; })
            .find("is not locally regular") != std::string::npos);
  // The vertex counter off by one.
  CHECK(verdict_after(t, [&](RegularTriangulation& u) { ++Access::vertex_count(u); })
            .find("counters disagree") != std::string::npos);
  // A vertex pointing to a cell it is not in.
  CHECK(verdict_after(t, [&](RegularTriangulation& u) {
          for (CellId d = 0; d < u.cell_capacity(); ++d)
            if (u.is_cell_alive(d) && u.index_of(d, v) < 0) {
              Access::point_cell(u, v) = d;
              return;
            }
        }).find("points to a cell not incident to it") != std::string::npos);
  // A hidden point dropped from its cell's list.
  CHECK(verdict_after(t, [&](RegularTriangulation& u) {
          for (CellId d = 0; d < u.cell_capacity(); ++d)
            if (u.is_cell_alive(d) && Access::first_hidden(u, d) != delaunay::kNoPoint) {
              Access::first_hidden(u, d) = delaunay::kNoPoint;
              return;
            }
        }).find("hidden") != std::string::npos);
}
