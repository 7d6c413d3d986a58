// The disk condition D1-D4 (refine/disk_condition.h, Dey & Levine §3) on hand-made umbrellas: each
// of its branches must be able to fail on its own. The mesher tests only see the verdicts of
// the mesher's own DiskCondition, which decided when refinement ended; here every verdict is
// stated from the definition, on the places a real complex gives (an open square sheet, and a
// box with a fin, whose bottom patch lies on both sides of the fin's curve: a slit).
#include <doctest/doctest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include <delpsc/io/shapes.h>
#include <delpsc/refine/disk_condition.h>
#include <delpsc/refine/polygon_domain.h>

using namespace delpsc;
using refine::BallKey;
using refine::DiskFailure;
using refine::Incidence;
using refine::VertexPlace;

namespace {

// The only thing DiskCondition asks of the balls is their adjacency along a curve (D3).
class ListedBalls final : public refine::BallSource {
 public:
  explicit ListedBalls(std::vector<std::pair<BallKey, BallKey>> adjacent_pairs) : pairs_(std::move(adjacent_pairs)) {}
  std::vector<BallKey> live_balls() const override { return {}; }
  refine::ProtectingBall ball(BallKey) const override { return {}; }
  bool adjacent(BallKey a, BallKey b) const override {
    return std::any_of(pairs_.begin(), pairs_.end(),
                       [&](const auto& e) { return (e.first == a && e.second == b) || (e.first == b && e.second == a); });
  }
  std::vector<BallKey> curve_chain(std::uint32_t) const override { return {}; }
  BallKey largest() const override { return refine::kNoBallKey; }
  refine::BallUpdate refine(BallKey) override { return {}; }

 private:
  std::vector<std::pair<BallKey, BallKey>> pairs_;
};

VertexPlace surface(std::uint32_t patch) {
  VertexPlace v;
  v.kind = VertexPlace::Kind::surface;
  v.patch = patch;
  return v;
}

// The centre of ball `ball`, on a curve's interior or at a corner (the other kNoElement).
VertexPlace ball_centre(BallKey ball, std::uint32_t curve, std::uint32_t corner) {
  VertexPlace v;
  v.kind = VertexPlace::Kind::ball;
  v.ball = ball;
  v.curve = curve;
  v.corner = corner;
  return v;
}
VertexPlace on_curve(BallKey ball, std::uint32_t curve) { return ball_centre(ball, curve, refine::kNoElement); }
VertexPlace at_corner(BallKey ball, std::uint32_t corner) { return ball_centre(ball, refine::kNoElement, corner); }

// The umbrella of vertex 0 on `patch` whose link is the path or cycle through `ring` (the
// triangles (0, ring[i], ring[i + 1])).
std::vector<Incidence> fan(std::uint32_t patch, const std::vector<delaunay::PointId>& ring, bool closed) {
  std::vector<Incidence> out;
  const std::size_t n = ring.size(), edges = closed ? n : n - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    const delaunay::PointId a = ring[i], b = ring[(i + 1) % n];
    out.push_back({static_cast<std::uint32_t>(out.size()), patch, {std::min(a, b), std::max(a, b)}});
  }
  return out;
}

std::vector<Incidence> joined(std::vector<Incidence> a, const std::vector<Incidence>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST_CASE("disk condition on an open square sheet: D1, D2, D3 and D4 each fail alone") {
  const refine::PolygonDomain domain(io::make_square_sheet(4));
  REQUIRE(domain.patch_count() == 1);
  REQUIRE(domain.curve_count() == 4);
  REQUIRE(domain.corner_count() == 4);
  const std::uint32_t curve = 0;
  REQUIRE(domain.curve_patches(curve).size() == 1);  // a boundary curve: the sheet on one side
  // Vertex 0 is the centre of each umbrella; 1-6 surface points of the sheet; 7-9 balls on the
  // boundary curve (7 adjacent to 8, 8 to 9; 7 and 9 not adjacent); 10 a point of another
  // patch (there is none: patch 1 does not exist in this domain); 11 outside the domain.
  kernel::LargeVector<VertexPlace> places(12);
  for (int i = 1; i <= 6; ++i) places[i] = surface(0);
  places[7] = on_curve(7, curve);
  places[8] = on_curve(8, curve);
  places[9] = on_curve(9, curve);
  places[10] = surface(1);
  const ListedBalls balls({{7, 8}, {8, 9}});
  const refine::DiskCondition disk(domain, balls, places);

  SUBCASE("an interior point: a cycle passes, a path or nothing fails D1/D2") {
    places[0] = surface(0);
    CHECK(disk.check(0, fan(0, {1, 2, 3, 4, 5}, true)).failure == DiskFailure::none);
    CHECK(disk.check(0, std::vector<Incidence>{}).failure == DiskFailure::d1);  // empty umbrella
    const auto path = disk.check(0, fan(0, {1, 2, 3, 4, 5}, false));
    CHECK(path.failure == DiskFailure::d2);  // p in int σ must be inside its disk
    CHECK(path.patch == 0);
    // Two disks touching at p (the link is two cycles), and a link vertex of degree three.
    CHECK(disk.check(0, joined(fan(0, {1, 2, 3}, true), fan(0, {4, 5, 6}, true))).failure == DiskFailure::d1);
    CHECK(disk.check(0, joined(fan(0, {1, 2, 3, 4}, true), fan(0, {1, 5}, false))).failure == DiskFailure::d1);
    // Two paths: connected nowhere.
    CHECK(disk.check(0, joined(fan(0, {1, 2}, false), fan(0, {3, 4}, false))).failure == DiskFailure::d1);
  }
  SUBCASE("a ball on the boundary curve: a path passes, a cycle fails D2") {
    places[0] = on_curve(100, curve);
    CHECK(disk.check(0, fan(0, {1, 2, 3, 4}, false)).failure == DiskFailure::none);
    CHECK(disk.check(0, fan(0, {1, 2, 3, 4}, true)).failure == DiskFailure::d2);
  }
  SUBCASE("D3: a ball joined to a ball that is not its neighbour on the curve") {
    places[0] = places[8];  // vertex 0 is ball 8: adjacent to 7 and 9
    CHECK(disk.check(0, fan(0, {7, 1, 2, 9}, false)).failure == DiskFailure::none);
    places[0] = places[7];  // ball 7: 9 is not its neighbour
    const auto d3 = disk.check(0, fan(0, {8, 1, 2, 9}, false));
    CHECK(d3.failure == DiskFailure::d3);
    CHECK(d3.facet == 2);  // the triangle (0, 2, 9)
    // A surface point joined to any ball is fine (D3 is about balls only).
    places[0] = surface(0);
    CHECK(disk.check(0, fan(0, {7, 1, 2, 9, 3}, true)).failure == DiskFailure::none);
  }
  SUBCASE("D4: a vertex of the umbrella off σ, or a triangle restricted to a patch without p") {
    places[0] = surface(0);
    const auto off = disk.check(0, fan(0, {1, 2, 10, 3}, true));
    CHECK(off.failure == DiskFailure::d4);
    CHECK(off.facet == 1);  // (0, 2, 10), the first with vertex 10
    CHECK(disk.check(0, fan(0, {1, 2, 11, 3}, true)).failure == DiskFailure::d4);  // outside the domain
    // Every umbrella of p fine, but one more triangle restricted to patch 1, which p is not on.
    auto extra = fan(0, {1, 2, 3, 4}, true);
    extra.push_back({99, 1, {5, 6}});
    const auto foreign = disk.check(0, extra);
    CHECK(foreign.failure == DiskFailure::d4);
    CHECK(foreign.patch == 1);
    CHECK(foreign.facet == 99);
  }
  SUBCASE("D1/D2 are reported before D3/D4 found on an earlier umbrella") {
    places[0] = surface(0);
    // Link vertex 10 is off σ (D4) and the link is a path (D2): D2 wins.
    CHECK(disk.check(0, fan(0, {1, 10, 2}, false)).failure == DiskFailure::d2);
  }
  SUBCASE("a point outside the domain, or unknown to the places, has no umbrella to check") {
    CHECK(disk.check(11, std::vector<Incidence>{}).failure == DiskFailure::none);
    CHECK(disk.check(50, std::vector<Incidence>{}).failure == DiskFailure::none);
  }
}

TEST_CASE("disk condition at a slit: a ball on the fin's curve is interior to the bottom patch") {
  const refine::PolygonDomain domain(io::make_box_with_fin(4));
  // The fin's curve: one patch (the bottom) on both of its sides, and the fin.
  std::uint32_t slit = refine::kNoElement, bottom = refine::kNoElement, fin = refine::kNoElement;
  for (std::uint32_t c = 0; c < domain.curve_count(); ++c) {
    auto patches = std::vector<std::uint32_t>(domain.curve_patches(c).begin(), domain.curve_patches(c).end());
    if (patches.size() != 3) continue;
    std::sort(patches.begin(), patches.end());
    slit = c;
    bottom = patches[0] == patches[1] ? patches[0] : patches[2];
    fin = patches[0] == patches[1] ? patches[2] : patches[0];
  }
  REQUIRE(slit != refine::kNoElement);
  REQUIRE(bottom != fin);
  // A corner at an end of the slit.
  const std::uint32_t corner = domain.curve_start_corner(slit);
  REQUIRE(corner != refine::kNoElement);

  kernel::LargeVector<VertexPlace> places(8);
  for (int i = 1; i <= 5; ++i) places[i] = surface(bottom);
  places[6] = surface(fin);
  places[7] = surface(fin);
  const refine::NoBalls balls;
  const refine::DiskCondition disk(domain, balls, places);
  const auto bottom_ring = fan(bottom, {1, 2, 3, 4, 5}, true);
  const auto fin_path = fan(fin, {6, 7}, false);

  for (const VertexPlace& p : {on_curve(0, slit), at_corner(0, corner)}) {
    CAPTURE(p.corner);
    places[0] = p;
    std::vector<std::pair<std::uint32_t, bool>> patches;
    disk.patches_of(0, patches);
    CHECK(patches.size() == 2);
    // Interior to the bottom patch (its disk is a cycle), on the fin's boundary (a path).
    CHECK(disk.check(0, joined(bottom_ring, fin_path)).failure == DiskFailure::none);
    CHECK(disk.check(0, joined(fan(bottom, {1, 2, 3, 4, 5}, false), fin_path)).failure == DiskFailure::d2);
    CHECK(disk.check(0, joined(bottom_ring, fan(fin, {6, 7, 1}, true))).failure == DiskFailure::d2);
    // No umbrella on the fin at all.
    CHECK(disk.check(0, bottom_ring).failure == DiskFailure::d1);
    // A fin point in the bottom's umbrella (D4) and a cycle on the fin (D2), whichever patch
    // comes first: D2.
    CHECK(disk.check(0, joined(fan(bottom, {1, 2, 6, 3, 4}, true), fan(fin, {6, 7, 5}, true))).failure ==
          DiskFailure::d2);
    CHECK(disk.check(0, joined(fan(bottom, {1, 2, 6, 3, 4}, true), fin_path)).failure == DiskFailure::d4);
  }
}

TEST_CASE("disk condition at a pinch: one disk per fan, each between its own two curves") {
  const refine::PolygonDomain domain(io::make_pinched_sheet(4));
  REQUIRE(domain.complex().pinches.size() == 1);
  const std::uint32_t corner = domain.complex().vertex_corner[domain.complex().pinches[0][0]];
  const auto fans = domain.corner_pinch_fans(corner, 0);
  REQUIRE(fans.size() == 2);
  // Four curves leave the pinch, two per fan.
  std::vector<std::uint32_t> curves{fans[0][0], fans[0][1], fans[1][0], fans[1][1]};
  std::sort(curves.begin(), curves.end());
  REQUIRE(std::unique(curves.begin(), curves.end()) == curves.end());
  // Vertex 0: the corner's ball; 1, 2 balls on fan 0's curves, 3, 4 on fan 1's; 5-8 surface.
  kernel::LargeVector<VertexPlace> places(9);
  places[0] = at_corner(0, corner);
  places[1] = on_curve(1, fans[0][0]);
  places[2] = on_curve(2, fans[0][1]);
  places[3] = on_curve(3, fans[1][0]);
  places[4] = on_curve(4, fans[1][1]);
  for (int i = 5; i <= 8; ++i) places[i] = surface(0);
  const ListedBalls balls({{0, 1}, {0, 2}, {0, 3}, {0, 4}});
  const refine::DiskCondition disk(domain, balls, places);
  const auto fan_a = fan(0, {1, 5, 2}, false), fan_b = fan(0, {4, 6, 7, 3}, false);
  CHECK(disk.check(0, joined(fan_a, fan_b)).failure == DiskFailure::none);
  // One disk where the input has two (the paper's D1 as written fails at every pinch).
  CHECK(disk.check(0, fan(0, {1, 5, 2, 6, 3}, false)).failure == DiskFailure::d1);
  CHECK(disk.check(0, fan_a).failure == DiskFailure::d1);
  // Two paths, but each joining curves of different fans; a path ending off the curves.
  CHECK(disk.check(0, joined(fan(0, {1, 5, 3}, false), fan(0, {2, 6, 4}, false))).failure == DiskFailure::d2);
  CHECK(disk.check(0, joined(fan(0, {1, 5, 8}, false), fan_b)).failure == DiskFailure::d2);
  // A cycle for an open fan; a link vertex of degree three.
  CHECK(disk.check(0, joined(fan(0, {1, 5, 2}, true), fan_b)).failure == DiskFailure::d2);
  CHECK(disk.check(0, joined(joined(fan_a, fan_b), fan(0, {5, 8}, false))).failure == DiskFailure::d1);
}
