// PolygonDomain's segment queries around fans of thin triangles, searched by angle (exactly,
// protect/certified_fans.h) instead of through the tree, must find the tree's hits bit for bit:
// the same triangles, contacts, features, parameters and points. Segments of every kind a dual
// edge can be: random, short and crossing a fan near its centre, parallel to the axis (both ends
// in one direction about it), through the centre, along and across the axis, through rim
// vertices, with an end on the axis.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <delpsc/refine/initial_sample.h>
#include <delpsc/refine/polygon_domain.h>
#include <delpsc/refine/triangle_samples.h>

#include "../support/acceptance.h"

using namespace delpsc;
using refine::PolygonDomain;

namespace {

constexpr double kPi = std::numbers::pi;

struct Soup {
  io::TriangleSoup soup;
  std::uint32_t add(const Vec3& p) {
    soup.vertices.push_back(p);
    return static_cast<std::uint32_t>(soup.vertices.size() - 1);
  }
};

// A closed cylinder of n rim points (radius 1, height `height`), each cap fanned from its
// centre, the top cap's centre lifted by `lift` (a cone when nonzero); or, `from_rim`, each cap
// fanned from its rim's first point (an STL export's: that point's fan is certified with the
// side's triangles there, which the segment search takes out to search the cap as a plane).
io::TriangleSoup fanned_cylinder(int n, double height, double lift, bool from_rim = false) {
  Soup s;
  std::vector<std::uint32_t> low, high;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    low.push_back(s.add({std::cos(t), std::sin(t), 0}));
    high.push_back(s.add({std::cos(t), std::sin(t), height}));
  }
  const std::uint32_t bottom = from_rim ? low[0] : s.add({0, 0, 0});
  const std::uint32_t top = from_rim ? high[0] : s.add({0, 0, height + lift});
  for (int i = 0; i < n; ++i) {
    const auto j = static_cast<std::size_t>((i + 1) % n), k = static_cast<std::size_t>(i);
    s.soup.triangles.push_back({low[k], low[j], high[j]});
    s.soup.triangles.push_back({low[k], high[j], high[k]});
    if (from_rim && (k == 0 || j == 0)) continue;
    s.soup.triangles.push_back({bottom, low[j], low[k]});
    s.soup.triangles.push_back({top, high[k], high[j]});
  }
  return s.soup;
}

// A cone of n rim points (radius 1, apex at height 1) on a base fanned from its first rim
// point, as an STL exporter triangulates a polygon: that point's star is no fan, its chords are
// (certified_fans.h), and the side's two triangles there stay in the tree.
io::TriangleSoup cone_on_rim_fanned_base(int n) {
  Soup s;
  std::vector<std::uint32_t> rim;
  for (int i = 0; i < n; ++i) rim.push_back(s.add({std::cos(2 * kPi * i / n), std::sin(2 * kPi * i / n), 0}));
  const std::uint32_t apex = s.add({0, 0, 1});
  for (std::size_t i = 0; i < rim.size(); ++i) s.soup.triangles.push_back({rim[i], rim[(i + 1) % rim.size()], apex});
  for (std::size_t i = 1; i + 1 < rim.size(); ++i) s.soup.triangles.push_back({rim[0], rim[i + 1], rim[i]});
  return s.soup;
}

bool same_hits(const std::vector<kernel::TriangleIntersection>& x, const std::vector<kernel::TriangleIntersection>& y) {
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const kernel::TriangleHit &a = x[i].hit, &b = y[i].hit;
    if (x[i].triangle != y[i].triangle || a.contact != b.contact || !(a.feature == b.feature) || a.t != b.t ||
        a.t_exit != b.t_exit || a.point != b.point)
      return false;
  }
  return true;
}

// Every kind of segment of the file comment, around the z axis (the fans' axis) at heights
// `levels`; the hits of the domain with fans against those of the one without.
void check_segments(const io::TriangleSoup& soup, std::size_t fans, std::vector<double> levels, std::uint32_t seed) {
  const PolygonDomain with(protect::build_complex(soup)), without(protect::build_complex(soup), false);
  REQUIRE(with.segment_fan_count() == fans);
  REQUIRE(without.segment_fan_count() == 0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.3, 1.3), small(-0.02, 0.02), unit(0, 1);
  std::vector<std::pair<Vec3, Vec3>> segments;
  for (int i = 0; i < 400; ++i) segments.push_back({Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng))});
  for (const double z : levels)
    for (int i = 0; i < 400; ++i) {
      const double r = unit(rng) * unit(rng), t = 2 * kPi * unit(rng);
      const Vec3 at(r * std::cos(t), r * std::sin(t), z);
      segments.push_back({at + Vec3(small(rng), small(rng), -0.03), at + Vec3(small(rng), small(rng), 0.03)});
      segments.push_back({at - Vec3(0, 0, 0.01 + unit(rng)), at + Vec3(0, 0, 0.01 + unit(rng))});  // parallel to z
      segments.push_back({at, Vec3(0, 0, z)});                                                       // to the centre
      segments.push_back({at, -at + Vec3(0, 0, 2 * z)});                            // across the axis
      segments.push_back({Vec3(0, 0, z - unit(rng)), at + Vec3(0, 0, small(rng))});  // an end on the axis
    }
  for (const double z : levels) {
    segments.push_back({Vec3(0, 0, z - 1), Vec3(0, 0, z + 1)});  // along the axis, through the centre
    segments.push_back({Vec3(-1, 0, z), Vec3(1, 0, z)});          // in the plane, through the centre
  }
  for (std::size_t v = 0; v < soup.vertices.size(); v += 7)  // through rim vertices
    segments.push_back({soup.vertices[v] + Vec3(small(rng), small(rng), 0.05), soup.vertices[v] - Vec3(0, 0, 0.05)});
  std::vector<kernel::TriangleIntersection> a, b;
  int different = 0, met = 0;
  for (const auto& [p, q] : segments) {
    with.triangle_hits(p, q, a);
    without.triangle_hits(p, q, b);
    different += !same_hits(a, b);
    met += !b.empty();
  }
  CHECK(different == 0);
  CHECK(met > static_cast<int>(segments.size()) / 3);
}

}  // namespace

TEST_CASE("segment queries with fans searched by angle find the tree's hits exactly") {
  SUBCASE("a cylinder with both caps fanned") { check_segments(fanned_cylinder(300, 1, 0), 2, {0, 1}, 1); }
  SUBCASE("a cone on a fanned base") { check_segments(fanned_cylinder(300, 0, 1), 2, {0, 0.5, 1}, 2); }
  SUBCASE("a shallow cone on a cylinder") { check_segments(fanned_cylinder(256, 0.5, 0.05), 2, {0, 0.5, 0.55}, 3); }
  SUBCASE("a cone on a base fanned from a rim point") { check_segments(cone_on_rim_fanned_base(300), 2, {0, 0.5}, 4); }
  SUBCASE("a cylinder with both caps fanned from rim points") {
    check_segments(fanned_cylinder(300, 1, 0, true), 2, {0, 1}, 5);
  }
  SUBCASE("a tall one (the side's triangles at a corner larger than any chord)") {
    check_segments(fanned_cylinder(300, 10, 0, true), 2, {0, 10}, 6);
  }
}

// Two half cones whose apexes share a triangle: it is in both fans' sectors, and must be
// reported once.
TEST_CASE("a triangle of two fans is searched in one") {
  Soup s;
  const std::uint32_t a = s.add({0, 0, 0}), b = s.add({3, 0, 0});
  std::vector<std::uint32_t> rim;
  for (int i = 0; i < 200; ++i) rim.push_back(s.add(Vec3(1.5, std::cos(kPi * i / 199), std::sin(kPi * i / 199))));
  for (std::size_t i = 0; i + 1 < rim.size(); ++i) {
    s.soup.triangles.push_back({a, rim[i], rim[i + 1]});
    s.soup.triangles.push_back({b, rim[i + 1], rim[i]});
  }
  s.soup.triangles.push_back({a, b, rim[0]});
  const PolygonDomain with(protect::build_complex(s.soup)), without(protect::build_complex(s.soup), false);
  REQUIRE(with.segment_fan_count() == 2);
  std::vector<kernel::TriangleIntersection> x, y;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  int different = 0, met = 0;
  for (int i = 0; i < 500; ++i) {
    // Through the shared triangle's plane (y = 0, z <= 0 side of the rim's first point) and about.
    const Vec3 p(1.5 + 3 * u(rng), u(rng), 0.5 + u(rng)), q(1.5 + 3 * u(rng), u(rng), -0.5 + u(rng));
    with.triangle_hits(p, q, x);
    without.triangle_hits(p, q, y);
    different += !same_hits(x, y);
    met += !y.empty();
  }
  CHECK(different == 0);
  CHECK(met > 100);
}

TEST_CASE("a fan below the degree searched stays in the tree") {
  const PolygonDomain domain(fanned_cylinder(40, 1, 0));
  CHECK(domain.segment_fan_count() == 0);
}

TEST_CASE("the net of fanned caps is thinned, reaches every point within its radius, and the mesh is right") {
  // 3,000 needles per cap and 6,000 on the side: triangle_samples gives each a row along its long
  // edge, ~266,000 samples against ~30,000 lattice and random candidates at this spacing.
  const io::TriangleSoup soup = fanned_cylinder(3000, 1, 0);
  const PolygonDomain domain(soup);
  const double spacing = 0.03;
  kernel::LargeVector<Vec3> points;
  kernel::LargeVector<std::uint32_t> patches;
  const refine::CandidateParts parts = domain.surface_candidates(spacing, 1u << 30, points, patches);
  const double unthinned_radius = refine::kNetRadius * spacing;
  CHECK(parts.net_radius == doctest::Approx((1 + refine::kNetThinning) * unthinned_radius).epsilon(1e-15));
  double unthinned = static_cast<double>(soup.vertices.size());
  for (const auto& t : soup.triangles)
    unthinned += refine::triangle_sample_count(soup.vertices[t[0]], soup.vertices[t[1]], soup.vertices[t[2]], unthinned_radius);
  CHECK(static_cast<double>(parts.net) * 8 < unthinned);  // 27,375 of 270,002
  CHECK(static_cast<double>(parts.net) > 1000);
  // The reach the mesher's cover bound assumes: every point of every triangle within net_radius
  // of a net point (probed at random points of random triangles, brute force).
  const std::vector<Vec3> net(points.end() - static_cast<std::ptrdiff_t>(parts.net), points.end());
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::size_t> which(0, soup.triangles.size() - 1);
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 1500; ++k) {
    const auto& t = soup.triangles[which(rng)];
    double u = unit(rng), v = unit(rng);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const Vec3 p = soup.vertices[t[0]] + u * (soup.vertices[t[1]] - soup.vertices[t[0]]) +
                   v * (soup.vertices[t[2]] - soup.vertices[t[0]]);
    double nearest = HUGE_VAL;
    for (const Vec3& q : net) nearest = std::min(nearest, (q - p).squaredNorm());
    CHECK(std::sqrt(nearest) <= parts.net_radius);
  }
  // The whole mesher on it (the thinned net's radius goes into the cover bound of the first
  // examination): disk condition, G1, G2 and orientation.
  test::check_acceptance("fanned cylinder", soup, 0.01);
}
