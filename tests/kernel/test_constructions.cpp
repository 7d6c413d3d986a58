// Constructions of kernel/constructions.h: known answers, the defining property of each result
// checked against the bounds the header states (power distances of an orthocentre, the plane of
// an intersection point, the sphere of a root, the minimality of a closest point), degenerate
// inputs, and the consistency of exact classification over a mesh. The comparison with exact
// rational references over many random inputs is tests/oracle/test_constructions_accuracy.cpp.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <delpsc/kernel/constructions.h>
#include <limits>
#include <vector>

#include "support/generators.h"

using namespace delpsc;
using namespace delpsc::kernel;
using delpsc::test::Rng;

namespace {

constexpr double kEps = 0x1p-53;
/// The orthocentre constant of the header: |c~ - c| <= 6 eps kappa S + eps |c|.
constexpr double kOrthocentreConstant = 6;

using LVec = Eigen::Matrix<long double, 3, 1>;
LVec wide(const Vec3& v) { return v.cast<long double>(); }
LVec wide(const WeightedPoint& p) { return wide(p.point()); }

/// Power distance evaluated in long double (64-bit mantissa on x86), so that its own rounding is
/// well below the double errors under test.
long double power(const WeightedPoint& c, const WeightedPoint& p) {
  return (wide(c) - wide(p)).squaredNorm() - static_cast<long double>(p.w);
}

Vec3 uniform_point(Rng& rng, double lo, double hi) {
  return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

Vec3 unit(Rng& rng) {
  for (;;) {
    const Vec3 v = uniform_point(rng, -1, 1);
    if (v.norm() > 0.1 && v.norm() <= 1) return v.normalized();
  }
}

std::optional<WeightedPoint> orthocentre_of(const std::vector<WeightedPoint>& p) {
  if (p.size() == 2) return orthocentre(p[0], p[1]);
  if (p.size() == 3) return orthocentre(p[0], p[1], p[2]);
  return orthocentre(p[0], p[1], p[2], p[3]);
}

/// The header's bound on the centre error: kappa, S from the inputs (in long double).
double centre_bound(const std::vector<WeightedPoint>& p, const WeightedPoint& c) {
  std::vector<LVec> e;
  long double len_product = 1, max_term = 0;
  for (std::size_t i = 1; i < p.size(); ++i) {
    e.push_back(wide(p[i]) - wide(p[0]));
    const long double len = e.back().norm();
    len_product *= len;
    max_term = std::max(max_term, len + std::fabs(static_cast<long double>(p[i].w) - p[0].w) / len);
  }
  long double volume = 1;
  if (e.size() == 2) volume = e[0].cross(e[1]).norm();
  if (e.size() == 3) volume = std::fabs(e[0].dot(e[1].cross(e[2])));
  const long double kappa = e.size() == 1 ? 1 : len_product / volume;
  const long double offset = (wide(c) - wide(p[0])).norm();
  return static_cast<double>(kOrthocentreConstant * kEps * kappa * (offset + max_term) +
                             kEps * wide(c).norm());
}

}  // namespace

// ---- orthocentres ---------------------------------------------------------------------------

TEST_CASE("orthocentre: known answers") {
  const WeightedPoint o{0, 0, 0, 0}, x{1, 0, 0, 0}, y{0, 1, 0, 0}, z{0, 0, 1, 0};
  const auto c4 = orthocentre(o, x, y, z);
  REQUIRE(c4);
  CHECK(c4->x == doctest::Approx(0.5));
  CHECK(c4->y == doctest::Approx(0.5));
  CHECK(c4->z == doctest::Approx(0.5));
  CHECK(c4->w == doctest::Approx(0.75));  // squared circumradius

  const auto c3 = orthocentre(WeightedPoint{0, 0, 0, 0}, WeightedPoint{2, 0, 0, 0}, WeightedPoint{0, 2, 0, 0});
  REQUIRE(c3);
  CHECK(c3->point().isApprox(Vec3(1, 1, 0)));
  CHECK(c3->w == doctest::Approx(2));

  // Balls of radius 1 at 0 and 3 at 4: the radical plane is x = 1, where both have power 0
  // (the balls touch there).
  const auto c2 = orthocentre(WeightedPoint{0, 0, 0, 1}, WeightedPoint{4, 0, 0, 9});
  REQUIRE(c2);
  CHECK(c2->point().isApprox(Vec3(1, 0, 0)));
  CHECK(std::fabs(c2->w) <= 1e-15);

  // Disjoint balls: positive weight; a ball inside the other's power: negative weight.
  const auto apart = orthocentre(WeightedPoint{0, 0, 0, 1}, WeightedPoint{10, 0, 0, 1});
  REQUIRE(apart);
  CHECK(apart->w == doctest::Approx(24));
  const auto deep = orthocentre(WeightedPoint{0, 0, 0, 4}, WeightedPoint{1, 0, 0, 4});
  REQUIRE(deep);
  CHECK(deep->w == doctest::Approx(-3.75));
}

TEST_CASE("orthocentre: equal power distances to every input, within the stated bound") {
  Rng rng(1);
  for (std::size_t k = 2; k <= 4; ++k) {
    for (int sample = 0; sample < 3000; ++sample) {
      std::vector<WeightedPoint> p;
      const int shape = sample % 4;
      const Vec3 base = shape == 1 ? uniform_point(rng, -1e3, 1e3) : Vec3::Zero();
      const double size = shape == 1 ? 1e-2 : 1;
      for (std::size_t i = 0; i < k; ++i) {
        Vec3 v = base + size * uniform_point(rng, -1, 1);
        if (shape == 2 && i == 3) {  // sliver
          const Vec3 n = (p[1].point() - p[0].point()).cross(p[2].point() - p[0].point()).normalized();
          v = p[0].point() + 0.3 * (p[1].point() - p[0].point()) + 0.4 * (p[2].point() - p[0].point()) +
              std::pow(10.0, -rng.uniform(0, 10)) * n;
        }
        const double w = shape == 3 ? rng.uniform(-50, 50) : rng.uniform(0, 0.2) * size * size;
        p.push_back(WeightedPoint::from(v, w));
      }
      const std::optional<WeightedPoint> c = orthocentre_of(p);
      REQUIRE(c);
      const double bound = centre_bound(p, *c);
      const long double p0 = power(*c, p[0]);
      for (std::size_t i = 1; i < k; ++i) {
        const long double e = (wide(p[i]) - wide(p[0])).norm();
        const long double slack = 8 * std::numeric_limits<long double>::epsilon() *
                                  (std::fabs(p0) + std::fabs(power(*c, p[i])) + std::fabs(p[0].w) +
                                   std::fabs(p[i].w) + (wide(*c) - wide(p[i])).squaredNorm());
        CHECK(std::fabs(power(*c, p[i]) - p0) <= 2 * e * bound + slack);
      }
      // The weight is that common power distance.
      CHECK(std::fabs(c->w - p0) <= 2 * (wide(*c) - wide(p[0])).norm() * bound + bound * bound +
                                        4 * kEps * ((wide(*c) - wide(p[0])).squaredNorm() + std::fabs(p[0].w)));
      // In the affine hull.
      const LVec off = wide(*c) - wide(p[0]);
      if (k == 2) {
        const LVec e1 = wide(p[1]) - wide(p[0]);
        CHECK(off.cross(e1).norm() / e1.norm() <= bound);
      }
      if (k == 3) {
        const LVec n = (wide(p[1]) - wide(p[0])).cross(wide(p[2]) - wide(p[0])).normalized();
        CHECK(std::fabs(off.dot(n)) <= bound);
      }
      // The 4-point orthosphere is orthogonal to the three balls, so its centre lies on the
      // normal line through their orthocentre, at power distance w4 - w3 from it.
      if (k == 4 && shape != 2) {
        const auto c3 = orthocentre(p[0], p[1], p[2]);
        REQUIRE(c3);
        const double bound3 = centre_bound({p[0], p[1], p[2]}, *c3);
        const double dist = (c->point() - c3->point()).norm();
        CHECK(std::fabs((c->w - c3->w) - dist * dist) <=
              4 * (dist + std::fabs(c->w) + std::fabs(c3->w) + 1) * (bound + bound3) +
                  8 * kEps * (dist * dist + std::fabs(c->w) + std::fabs(c3->w)));
      }
    }
  }
}

TEST_CASE("orthocentre: degenerate input is reported, never a NaN") {
  const WeightedPoint a{0, 0, 0, 1}, b{1, 1, 1, 0}, c{2, 0, 1, 0.5}, d{3, 1, 2, 0};  // d = b + c
  CHECK_FALSE(orthocentre(a, b, c, d));
  CHECK_FALSE(orthocentre(a, b, WeightedPoint{2, 2, 2, 3}));     // collinear
  CHECK_FALSE(orthocentre(a, WeightedPoint{0, 0, 0, 5}));        // same position, other weight
  CHECK_FALSE(orthocentre(a, b, c, WeightedPoint{0.5, 0.5, 0.5, 0}));  // coplanar (on ab)
  // One ulp off the plane: not degenerate, so a (finite, far) answer.
  const WeightedPoint d_off{3, 1, std::nextafter(2.0, 3.0), 0};
  const auto far = orthocentre(a, b, c, d_off);
  REQUIRE(far);
  CHECK(std::isfinite(far->x));
  CHECK(std::isfinite(far->w));
  // Squared lengths overflow: reported instead of returning inf or NaN.
  CHECK_FALSE(orthocentre(WeightedPoint{0, 0, 0, 0}, WeightedPoint{1e200, 0, 0, 0}));
  CHECK_FALSE(orthocentre(WeightedPoint{0, 0, 0, 0}, WeightedPoint{1e200, 0, 0, 0},
                          WeightedPoint{0, 1e200, 0, 0}));
}

// ---- segment / ray and triangle -------------------------------------------------------------

namespace {
const Vec3 T0(0, 0, 0), T1(4, 0, 0), T2(0, 4, 0);

TriangleHit seg(const Vec3& a, const Vec3& b) { return intersect_segment_triangle(a, b, T0, T1, T2); }
TriangleHit ray(const Vec3& o, const Vec3& d) { return intersect_ray_triangle(o, d, T0, T1, T2); }
}  // namespace

TEST_CASE("segment-triangle: each kind of contact, with the right feature") {
  TriangleHit h = seg({1, 1, -1}, {1, 1, 1});
  CHECK(h.contact == Contact::crossing);
  CHECK(h.feature == TriangleFeature{FeatureKind::face, 0});
  CHECK(h.t == 0.5);
  CHECK(h.point == Vec3(1, 1, 0));

  h = seg({2, 0, -1}, {2, 0, 3});  // through edge t0 t1, which is edge 2 (opposite t2)
  CHECK(h.contact == Contact::crossing);
  CHECK(h.feature == TriangleFeature{FeatureKind::edge, 2});
  CHECK(h.t == 0.25);
  CHECK(h.point == Vec3(2, 0, 0));

  h = seg({1, 3, 2}, {3, 1, -2});  // through (2, 2, 0) on edge t1 t2 = edge 0, obliquely
  CHECK(h.contact == Contact::crossing);
  CHECK(h.feature == TriangleFeature{FeatureKind::edge, 0});
  CHECK((h.point - Vec3(2, 2, 0)).norm() <= 1e-15);

  h = seg({4, 0, -1}, {4, 0, 1});  // through vertex t1, exactly at it
  CHECK(h.contact == Contact::crossing);
  CHECK(h.feature == TriangleFeature{FeatureKind::vertex, 1});
  CHECK(h.point == T1);

  h = seg({1, 1, 0}, {1, 1, 3});
  CHECK(h.contact == Contact::at_start);
  CHECK(h.feature.kind == FeatureKind::face);
  CHECK(h.t == 0);
  CHECK(h.point == Vec3(1, 1, 0));

  h = seg({2, 2, 5}, {2, 2, 0});
  CHECK(h.contact == Contact::at_end);
  CHECK(h.feature == TriangleFeature{FeatureKind::edge, 0});
  CHECK(h.t == 1);

  h = seg({5, 5, -1}, {0, 0, 9});  // plane crossed outside... at (4.5, 4.5, 0)
  CHECK(h.contact == Contact::none);
  CHECK_FALSE(h);
  CHECK_FALSE(seg({1, 1, 1}, {2, 1, 3}));  // same side
  CHECK_FALSE(seg({1, 1, 1}, {1, 1, 1}));  // a point off the plane

  h = seg({-1, 1, 0}, {5, 1, 0});  // in the plane, across the triangle from x = 0 to x + y = 4
  CHECK(h.contact == Contact::coplanar);
  CHECK(h.t == doctest::Approx(1.0 / 6));
  CHECK(h.t_exit == doctest::Approx(4.0 / 6));
  CHECK((h.point - Vec3(0, 1, 0)).norm() <= 1e-15);
  CHECK_FALSE(seg({5, 5, 0}, {6, 6, 0}));
  CHECK(seg({-1, 3, 0}, {3, -1, 0}).contact == Contact::coplanar);  // cuts the corner at t0
  CHECK_FALSE(seg({-2, 1, 0}, {1, -2, 0}));           // passes the corner outside
  h = seg({4, 0, 0}, {6, 0, 0});                      // touches the vertex only
  CHECK(h.contact == Contact::coplanar);
  CHECK(h.t_exit == 0);
  h = seg({1, 1, 0}, {1, 1, 0});  // a point-like segment on the triangle
  CHECK(h.contact == Contact::coplanar);

  const TriangleHit flat = intersect_segment_triangle({0, 0, -1}, {0, 0, 1}, {0, 0, 0}, {1, 1, 1}, {2, 2, 2});
  CHECK(flat.contact == Contact::degenerate);
  CHECK_FALSE(flat);
}

TEST_CASE("coplanar segment-triangle: the same decision as intersect_segment_triangle, without orient3d") {
  // Points of a small integer grid on a tilted plane (o + u e1 + v e2, all integers, so exactly
  // coplanar): many segments touch a vertex or run along an edge.
  Rng rng(7);
  const Vec3 o(3, -2, 5), e1(1, 2, -1), e2(-2, 1, 3);
  const auto grid_point = [&] {
    return Vec3(o + static_cast<double>(rng.integer(-3, 3)) * e1 + static_cast<double>(rng.integer(-3, 3)) * e2);
  };
  int meets = 0, misses = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 a = grid_point(), b = rng.chance(0.1) ? a : grid_point();
    const Vec3 t0 = grid_point(), t1 = grid_point(), t2 = grid_point();
    const bool expected = static_cast<bool>(intersect_segment_triangle(a, b, t0, t1, t2));
    CHECK(coplanar_segment_meets_triangle(a, b, t0, t1, t2) == expected);
    (expected ? meets : misses) += 1;
  }
  CHECK(meets > 1000);  // both answers well represented
  CHECK(misses > 1000);
  // A degenerate triangle decides nothing, as intersect_segment_triangle reports.
  CHECK_FALSE(coplanar_segment_meets_triangle(o, o + e1, o - e1, o + 2 * e1, o + 3 * e1));
}

TEST_CASE("ray-triangle: direction, origin on the triangle, parallel and coplanar rays") {
  TriangleHit h = ray({1, 1, -1}, {0, 0, 1});
  CHECK(h.contact == Contact::crossing);
  CHECK(h.t == 1);
  CHECK(h.point == Vec3(1, 1, 0));
  CHECK_FALSE(ray({1, 1, -1}, {0, 0, -1}));  // pointing away
  h = ray({1, 1, -1e6}, {0, 0, 1e-3});       // far origin, short direction
  CHECK(h.contact == Contact::crossing);
  CHECK(h.t == doctest::Approx(1e9));
  h = ray({4, 0, 7}, {0, 0, -1});
  CHECK(h.feature == TriangleFeature{FeatureKind::vertex, 1});
  h = ray({1, 1, 0}, {0, 0, 1});
  CHECK(h.contact == Contact::at_start);
  CHECK_FALSE(ray({1, 1, 1}, {1, 0, 0}));  // parallel, off the plane

  h = ray({-1, 1, 0}, {1, 0, 0});  // coplanar, enters through edge 1 at x = 0
  CHECK(h.contact == Contact::coplanar);
  CHECK(h.t == doctest::Approx(1));
  CHECK(h.t_exit == doctest::Approx(4));
  CHECK_FALSE(ray({-1, 1, 0}, {-1, 0, 0}));  // coplanar, away
  h = ray({-1, -1, 0}, {1, 1, 0});            // coplanar, through vertex t0 then across
  CHECK(h.contact == Contact::coplanar);
  CHECK(h.t == doctest::Approx(1));
  CHECK(h.t_exit == doctest::Approx(3));
  CHECK_FALSE(ray({5, -1, 0}, {1, 0, 0}));      // coplanar, below the triangle
  CHECK(ray({-3, 0, 0}, {1, 0, 0}).contact == Contact::coplanar);   // along edge 2's line
  CHECK_FALSE(ray({-3, 0, 0}, {-1, 0, 0}));     // along edge 2's line, away
  CHECK(ray({2, 1, 0}, {1, 2, 0}).contact == Contact::coplanar);    // origin inside
}

TEST_CASE("segments through a fan's shared edges and vertex: reported consistently") {
  // A non-planar fan of six triangles around the origin.
  const std::array<Vec3, 6> ring = {Vec3(2, 0, 1),   Vec3(1, 2, -1), Vec3(-1, 2, 1),
                                    Vec3(-2, 0, -1), Vec3(-1, -2, 1), Vec3(1, -2, -1)};
  const Vec3 centre(0, 0, 0);
  auto hits = [&](const Vec3& a, const Vec3& b) {
    std::vector<std::pair<int, TriangleHit>> out;
    for (int i = 0; i < 6; ++i) {
      const TriangleHit h = intersect_segment_triangle(a, b, centre, ring[i], ring[(i + 1) % 6]);
      if (h) out.emplace_back(i, h);
    }
    return out;
  };

  // Through the centre vertex from many directions: every triangle reports its vertex 0.
  Rng rng(3);
  for (int n = 0; n < 200; ++n) {
    const Vec3 w(rng.uniform(-1, 1), rng.uniform(-1, 1), 3);  // the segment -w, w contains 0
    const auto hs = hits(-w, w);
    REQUIRE(hs.size() == 6);
    for (const auto& [i, h] : hs) {
      CHECK(h.feature == TriangleFeature{FeatureKind::vertex, 0});
      CHECK(h.point == centre);
    }
  }
  // Through the midpoint of each spoke: exactly the two triangles sharing it, each naming the
  // spoke by its local index (edge opposite the ring vertex not on it).
  for (int s = 0; s < 6; ++s) {
    const Vec3 mid = ring[s] / 2;  // exact
    const Vec3 w(0.25, -0.125, 2);
    const auto hs = hits(mid - w, mid + w);
    REQUIRE(hs.size() == 2);
    for (const auto& [i, h] : hs) {
      CHECK(h.contact == Contact::crossing);
      CHECK(h.feature.kind == FeatureKind::edge);
      // Triangle i = (centre, ring[i], ring[i+1]): spoke s is ring[i] (opposite local 2) or
      // ring[i+1] (opposite local 1).
      CHECK(h.feature.index == (i == s ? 2 : 1));
      CHECK((h.point - mid).norm() <= 4 * kEps * 2);
    }
  }
  // Random small-integer segments (through vertices and edges often): each feature of the fan
  // that the segment meets is reported by every triangle incident to it, all at one point: the
  // centre by 6, a ring vertex or a spoke by 2, a rim edge or a face by 1.
  auto global_feature = [](int i, TriangleFeature f) {
    // Ids: 0 centre, 1..6 ring vertices, 7..12 spokes, 13..18 rim edges, 19..24 faces.
    const int r0 = i, r1 = (i + 1) % 6;
    if (f.kind == FeatureKind::vertex) return f.index == 0 ? 0 : 1 + (f.index == 1 ? r0 : r1);
    if (f.kind == FeatureKind::edge) return f.index == 0 ? 13 + i : 7 + (f.index == 1 ? r1 : r0);
    return 19 + i;
  };
  int groups_seen = 0;
  for (int n = 0; n < 3000; ++n) {
    const Vec3 a(double(rng.integer(-3, 3)), double(rng.integer(-3, 3)), double(rng.integer(-3, 3)));
    const Vec3 b(double(rng.integer(-3, 3)), double(rng.integer(-3, 3)), double(rng.integer(-3, 3)));
    const auto hs = hits(a, b);
    if (std::any_of(hs.begin(), hs.end(), [](const auto& ih) { return ih.second.contact == Contact::coplanar; }))
      continue;
    std::array<int, 25> count{};
    std::array<Vec3, 25> where;
    for (const auto& [i, h] : hs) {
      const int g = global_feature(i, h.feature);
      if (count[g]++ == 0) where[g] = h.point;
      CHECK((h.point - where[g]).norm() <= 1e-14);
    }
    for (int g = 0; g < 25; ++g) {
      if (count[g] == 0) continue;
      ++groups_seen;
      CHECK(count[g] == (g == 0 ? 6 : g <= 12 ? 2 : 1));
    }
  }
  CHECK(groups_seen > 300);
}

TEST_CASE("segment-triangle: the point lies in the triangle's plane and inside it") {
  Rng rng(5);
  int crossings = 0;
  for (int n = 0; n < 100000 && crossings < 2000; ++n) {
    const Vec3 t0 = uniform_point(rng, -1, 1), t1 = uniform_point(rng, -1, 1), t2 = uniform_point(rng, -1, 1);
    const Vec3 a = uniform_point(rng, -2, 2), b = uniform_point(rng, -2, 2);
    const TriangleHit h = intersect_segment_triangle(a, b, t0, t1, t2);
    if (h.contact != Contact::crossing) continue;
    ++crossings;
    const Vec3 nrm = (t1 - t0).cross(t2 - t0);
    const double kappa = (t1 - t0).norm() * (t2 - t0).norm() / nrm.norm();
    // Off the plane by no more than the rounding of snapping (relative to the triangle's size).
    CHECK(std::fabs(nrm.normalized().dot(h.point - t0)) <= 16 * kEps * kappa * 4);
    // Inside: its own closest point on the triangle is itself (to rounding).
    CHECK((closest_point_on_triangle(h.point, t0, t1, t2).point - h.point).norm() <= 16 * kEps * kappa * 4);
    // And on the segment, at parameter t.
    CHECK((a + h.t * (b - a) - h.point).norm() <=
          1e-9 * (b - a).norm() / std::fabs(nrm.normalized().dot((b - a).normalized())));
  }
  CHECK(crossings == 2000);
}

// ---- segment and sphere ---------------------------------------------------------------------

TEST_CASE("segment-sphere: crossings, tangency and endpoints on the sphere") {
  const WeightedPoint ball{0, 0, 0, 25};
  SphereHits h = intersect_segment_sphere({-10, 5, 0}, {10, 5, 0}, ball);  // tangent at (0, 5)
  CHECK(h.count == 1);
  CHECK(h.t[0] == 0.5);
  h = intersect_segment_sphere({-10, 0, 0}, {10, 0, 0}, ball);
  REQUIRE(h.count == 2);
  CHECK(h.t[0] == doctest::Approx(0.25));
  CHECK(h.t[1] == doctest::Approx(0.75));
  CHECK(h.side_a == 1);
  CHECK(h.side_b == 1);
  CHECK(intersect_segment_sphere({-10, 6, 0}, {10, 6, 0}, ball).count == 0);  // misses
  CHECK(intersect_segment_sphere({6, 0, 0}, {10, 0, 0}, ball).count == 0);    // points away
  CHECK(intersect_segment_sphere({1, 0, 0}, {0, 2, 1}, ball).count == 0);     // inside
  h = intersect_segment_sphere({0, 0, 0}, {10, 0, 0}, ball);  // leaves the ball
  REQUIRE(h.count == 1);
  CHECK(h.t[0] == doctest::Approx(0.5));
  CHECK(h.side_a == -1);
  CHECK(h.side_b == 1);
  h = intersect_segment_sphere({10, 0, 0}, {0, 0, 0}, ball);  // enters it
  REQUIRE(h.count == 1);
  CHECK(h.t[0] == doctest::Approx(0.5));

  // Endpoints exactly on the sphere give exact roots.
  h = intersect_segment_sphere({3, 4, 0}, {10, 4, 0}, ball);  // leaves outward at once
  REQUIRE(h.count == 1);
  CHECK(h.t[0] == 0);
  CHECK(h.side_a == 0);
  h = intersect_segment_sphere({3, 4, 0}, {-10, 4, 0}, ball);  // chord to (-3, 4), then out
  REQUIRE(h.count == 2);
  CHECK(h.t[0] == 0);
  CHECK(h.t[1] == doctest::Approx(6.0 / 13));
  h = intersect_segment_sphere({-10, 4, 0}, {3, 4, 0}, ball);  // the same, reversed
  REQUIRE(h.count == 2);
  CHECK(h.t[0] == doctest::Approx(7.0 / 13));
  CHECK(h.t[1] == 1);
  h = intersect_segment_sphere({3, 4, 0}, {-3, 4, 0}, ball);  // a chord
  REQUIRE(h.count == 2);
  CHECK(h.t[0] == 0);
  CHECK(h.t[1] == 1);
  h = intersect_segment_sphere({3, 4, 0}, {0, 0, 0}, ball);  // from the sphere inwards
  REQUIRE(h.count == 1);
  CHECK(h.t[0] == 0);
  h = intersect_segment_sphere({3, 4, 0}, {3, 4, 0}, ball);  // a point on the sphere
  CHECK(h.count == 1);
}

TEST_CASE("segment-sphere: roots on the sphere and counts equal to sign changes along the segment") {
  Rng rng(9);
  for (int n = 0; n < 3000; ++n) {
    const Vec3 c = uniform_point(rng, -1, 1);
    const double r = rng.uniform(0.1, 1);
    const WeightedPoint ball = WeightedPoint::from(c, r * r);
    const Vec3 a = c + rng.uniform(0, 2) * r * unit(rng);
    const Vec3 b = c + rng.uniform(0, 2) * r * unit(rng);
    const SphereHits h = intersect_segment_sphere(a, b, ball);
    for (int i = 0; i < h.count; ++i) {
      CHECK(h.t[i] >= 0);
      CHECK(h.t[i] <= 1);
      const Vec3 x = a + h.t[i] * (b - a);
      // Near tangency a root is only known to ~sqrt(eps); elsewhere to a few eps.
      CHECK(std::fabs((x - c).norm() - r) <= 1e-7 * r);
    }
    if (h.count == 2) CHECK(h.t[0] <= h.t[1]);
    // Count the sign changes of |x - c| - r over a fine sampling; skip near-tangent segments,
    // where a sampling cannot see a short chord.
    const Vec3 d = b - a;
    const double dist_line = (a - c).cross(d).norm() / d.norm();
    if (std::fabs(dist_line - r) < 1e-3 * r) continue;
    int changes = 0;
    double previous = (a - c).norm() - r;
    for (int s = 1; s <= 4000; ++s) {
      const double now = (a + (s / 4000.0) * d - c).norm() - r;
      if ((previous < 0) != (now < 0)) ++changes;
      previous = now;
    }
    CHECK(h.count == changes);
  }
}

// ---- closest points -------------------------------------------------------------------------

TEST_CASE("closest point on a triangle: the region's feature, and no sample is closer") {
  const Vec3 a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  CHECK(closest_point_on_triangle({1, 1, 5}, a, b, c).feature == TriangleFeature{FeatureKind::face, 0});
  CHECK(closest_point_on_triangle({1, 1, 5}, a, b, c).point == Vec3(1, 1, 0));
  CHECK(closest_point_on_triangle({-1, -1, 2}, a, b, c).feature == TriangleFeature{FeatureKind::vertex, 0});
  CHECK(closest_point_on_triangle({6, -1, 2}, a, b, c).feature == TriangleFeature{FeatureKind::vertex, 1});
  CHECK(closest_point_on_triangle({-1, 6, 2}, a, b, c).feature == TriangleFeature{FeatureKind::vertex, 2});
  CHECK(closest_point_on_triangle({2, -3, 1}, a, b, c).feature == TriangleFeature{FeatureKind::edge, 2});
  CHECK(closest_point_on_triangle({3, 3, 1}, a, b, c).feature == TriangleFeature{FeatureKind::edge, 0});
  CHECK(closest_point_on_triangle({-2, 1, 1}, a, b, c).feature == TriangleFeature{FeatureKind::edge, 1});
  CHECK(closest_point_on_triangle({3, 3, 1}, a, b, c).point.isApprox(Vec3(2, 2, 0)));
  // Degenerate triangle: the closest point of its edges.
  const ClosestOnTriangle flat = closest_point_on_triangle({1, 1, 3}, a, Vec3(2, 2, 0), Vec3(4, 4, 0));
  CHECK(flat.point.isApprox(Vec3(1, 1, 0)));

  Rng rng(21);
  const int grid = 150;
  for (int n = 0; n < 60; ++n) {
    const Vec3 t0 = uniform_point(rng, -1, 1), t1 = uniform_point(rng, -1, 1), t2 = uniform_point(rng, -1, 1);
    for (int m = 0; m < 10; ++m) {
      const Vec3 p = uniform_point(rng, -2, 2);
      const ClosestOnTriangle got = closest_point_on_triangle(p, t0, t1, t2);
      const Vec3 from_bary = got.barycentric[0] * t0 + got.barycentric[1] * t1 + got.barycentric[2] * t2;
      CHECK((from_bary - got.point).norm() <= 1e-12);
      CHECK(got.barycentric.minCoeff() >= 0);
      const double mine = (got.point - p).norm();
      double best = std::numeric_limits<double>::infinity();
      for (int i = 0; i <= grid; ++i)
        for (int j = 0; i + j <= grid; ++j) {
          const Vec3 s = t0 + (double(i) / grid) * (t1 - t0) + (double(j) / grid) * (t2 - t0);
          best = std::min(best, (s - p).norm());
        }
      CHECK(mine <= best + 1e-14);
      // The minimiser is unique, so a sampling fine enough finds points near it.
      CHECK(mine >= best - 2 * ((t1 - t0).norm() + (t2 - t0).norm()) / grid);
    }
  }
}

TEST_CASE("closest point on a segment: clamped projection, no sample closer") {
  const ClosestOnSegment s = closest_point_on_segment({1, 5, 0}, {0, 0, 0}, {4, 0, 0});
  CHECK(s.t == 0.25);
  CHECK(s.point == Vec3(1, 0, 0));
  CHECK(closest_point_on_segment({-3, 1, 0}, {0, 0, 0}, {4, 0, 0}).t == 0);
  CHECK(closest_point_on_segment({9, 1, 0}, {0, 0, 0}, {4, 0, 0}).point == Vec3(4, 0, 0));
  CHECK(closest_point_on_segment({9, 1, 0}, {1, 1, 1}, {1, 1, 1}).point == Vec3(1, 1, 1));
  Rng rng(23);
  for (int n = 0; n < 2000; ++n) {
    const Vec3 a = uniform_point(rng, -1, 1), b = uniform_point(rng, -1, 1), p = uniform_point(rng, -2, 2);
    const ClosestOnSegment got = closest_point_on_segment(p, a, b);
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 2000; ++i) best = std::min(best, (a + (i / 2000.0) * (b - a) - p).norm());
    CHECK((got.point - p).norm() <= best + 1e-14);
  }
}
