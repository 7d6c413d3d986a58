// Arc length, point at a parameter, curve distance and seg_σ(b) (DelPSC §2.1) against hand
// computations on the boundary of the unit square, and against their defining properties on
// curved polylines.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <delpsc/io/shapes.h>
#include <delpsc/protect/complex.h>

using namespace delpsc;
using protect::build_complex;
using protect::Complex;

namespace {

// The boundary of the unit square as one closed curve from its corner (0, 0, 0). Its direction
// is the builder's choice; `along(u)` gives the hand-computed point at arc length u either way.
struct SquareLoop {
  Complex complex = [] {
    protect::ComplexOptions o;
    o.corner_angle_degrees = 180;
    return build_complex(io::make_square_sheet(4), o);
  }();
  bool x_first = complex.point_at(0, 0.5).x() == 0.5;

  Vec3 along(double u) const {
    u = std::fmod(std::fmod(u, 4.0) + 4.0, 4.0);
    // Counter-clockwise from the origin: (u, 0), (1, u-1), (3-u, 1), (0, 4-u).
    Vec3 p = u < 1 ? Vec3(u, 0, 0) : u < 2 ? Vec3(1, u - 1, 0) : u < 3 ? Vec3(3 - u, 1, 0) : Vec3(0, 4 - u, 0);
    if (!x_first) std::swap(p.x(), p.y());  // clockwise: the mirror image in the diagonal
    return p;
  }
};

}  // namespace

TEST_CASE("square loop: arc length, point_at and wrapping") {
  const SquareLoop sq;
  const Complex& c = sq.complex;
  REQUIRE(c.curve_count() == 1);
  REQUIRE(c.curves[0].closed);
  CHECK(c.curves[0].length == 4);
  CHECK(c.vertices[c.corner_vertex[c.curves[0].start_corner]] == Vec3(0, 0, 0));
  for (double u : {0.0, 0.3, 1.0, 1.5, 2.25, 3.9, 4.0, 4.25, -0.25, -3.5, 11.0})
    CHECK((c.point_at(0, u) - sq.along(u)).norm() < 1e-15);
  // Vertices are returned exactly, and their parameters are found.
  const auto poly = c.curve_polyline(0);
  const auto params = c.curve_parameters(0);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    CHECK(c.point_at(0, params[i]) == c.vertices[poly[i]]);
    CHECK(c.parameter_of_vertex(0, poly[i]).has_value());
  }
  CHECK(c.wrap_parameter(0, 4.0) == 0);
  CHECK(c.wrap_parameter(0, -1.0) == 3);
}

TEST_CASE("square loop: curve distance is the forward arc") {
  const SquareLoop sq;
  const Complex& c = sq.complex;
  CHECK(c.curve_distance(0, 0.5, 3.5) == doctest::Approx(3.0));
  CHECK(c.curve_distance(0, 3.5, 0.5) == doctest::Approx(1.0));
  CHECK(c.curve_distance(0, 3.5, 4.5) == doctest::Approx(1.0));
  CHECK(c.curve_distance(0, 1.0, 1.0) == 0);
}

TEST_CASE("square loop: seg of a ball, by hand") {
  const SquareLoop sq;
  const Complex& c = sq.complex;
  auto check = [&](double s, double r, double s0, double s1) {
    const auto seg = c.segment_in_ball(0, s, r);
    CHECK(seg.s0 == doctest::Approx(s0).epsilon(1e-12));
    CHECK(seg.s1 == doctest::Approx(s1).epsilon(1e-12));
    CHECK_FALSE(seg.whole);
  };
  check(0.5, 0.3, 0.2, 0.8);          // inside one side
  check(0.0, 0.3, -0.3, 0.3);         // around the corner where the loop closes: unwrapped
  check(4.0, 0.3, -0.3, 0.3);
  const double h = std::sqrt(0.6 * 0.6 - 0.25);
  check(0.5, 0.6, -h, 1 + h);         // round both corners of the first side
  // r = 1.05 from (0.5, 0): the opposite side also enters the ball (|x - 0.5| <= 0.32), but
  // that piece is not connected to the centre's and is not part of the segment.
  const double k = std::sqrt(1.05 * 1.05 - 0.25);
  check(0.5, 1.05, -k, 1 + k);
  const auto all = c.segment_in_ball(0, 1.0, 10);
  CHECK(all.whole);
  CHECK(all.s0 == 0);
  CHECK(all.s1 == 4);
}

TEST_CASE("open curves: seg stops at the curve's ends") {
  const Complex c = build_complex(io::make_cube(4));
  for (std::uint32_t k = 0; k < c.curve_count(); ++k) {
    REQUIRE_FALSE(c.curves[k].closed);
    REQUIRE(c.curves[k].length == doctest::Approx(1.0));
    const auto seg = c.segment_in_ball(k, 0.1, 0.3);
    CHECK(seg.s0 == 0);
    CHECK(seg.s1 == doctest::Approx(0.4));
    CHECK(c.segment_in_ball(k, 0.5, 0.2).s0 == doctest::Approx(0.3));
    CHECK(c.segment_in_ball(k, 0.5, 2).whole);
    CHECK(c.curve_distance(k, 0.75, 0.25) == doctest::Approx(0.5));
    CHECK(c.curve_distance(k, -3, 7) == doctest::Approx(1.0));  // clamped to the curve
  }
}

TEST_CASE("open single-segment curve: a ball at one end does not swallow the far end") {
  // make_cube(1): every curve is one polyline segment of length 1. Walking from s = 0 reaches
  // the far vertex at parameter = length; that vertex lies outside a ball of radius 0.3, so the
  // piece inside is [0, 0.3], not the whole curve (a regression: the full-turn test of closed
  // curves used to fire on open ones).
  const Complex c = build_complex(io::make_cube(1));
  for (std::uint32_t k = 0; k < c.curve_count(); ++k) {
    REQUIRE(c.curves[k].length == doctest::Approx(1.0));
    const auto from_start = c.segment_in_ball(k, 0.0, 0.3);
    CHECK_FALSE(from_start.whole);
    CHECK(from_start.s1 == doctest::Approx(0.3));
    const auto from_end = c.segment_in_ball(k, 1.0, 0.3);
    CHECK_FALSE(from_end.whole);
    CHECK(from_end.s0 == doctest::Approx(0.7));
  }
}

TEST_CASE("seg of a ball on curved polylines: ends on the sphere, inside between") {
  // The rims of a 60-gon cylinder as closed curves; and cut into open arcs by two vertical user
  // polylines on the side, at angles 0 and 90 degrees.
  const io::TriangleSoup soup = io::make_capped_cylinder(1, 1, 60, 4, 2);
  protect::ComplexOptions cut;
  for (const double angle : {0.0, 90.0}) {
    std::vector<std::pair<double, std::uint32_t>> line;  // (z, vertex)
    const Vec3 dir(std::cos(angle * std::numbers::pi / 180), std::sin(angle * std::numbers::pi / 180), 0);
    for (std::uint32_t v = 0; v < soup.vertices.size(); ++v) {
      const Vec3& p = soup.vertices[v];
      if ((Vec3(p.x(), p.y(), 0) - dir).norm() < 1e-9) line.push_back({p.z(), v});
    }
    std::sort(line.begin(), line.end());
    REQUIRE(line.size() == 5);
    cut.feature_polylines.emplace_back();
    for (const auto& zv : line) cut.feature_polylines.back().push_back(zv.second);
  }
  const Complex arcs = build_complex(soup, cut);
  REQUIRE(arcs.curve_count() == 6);  // 2 vertical lines, 4 rim arcs
  REQUIRE(arcs.closed_curve_count() == 0);
  for (const Complex& c : {build_complex(soup), arcs}) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (int q = 0; q < 400; ++q) {
      const auto k = static_cast<std::uint32_t>(rng() % c.curve_count());
      const double length = c.curves[k].length;
      const double s = u(rng) * length, r = 0.01 + u(rng) * 1.5;
      const Vec3 centre = c.point_at(k, s);
      const auto seg = c.segment_in_ball(k, s, r);
      CHECK(seg.s0 <= s);
      CHECK(s <= seg.s1);
      if (seg.whole) {
        for (double t = 0; t < length; t += length / 200) CHECK((c.point_at(k, t) - centre).norm() <= r * (1 + 1e-12));
        continue;
      }
      CHECK(seg.s1 - seg.s0 < length);
      for (int i = 0; i <= 100; ++i) {
        const double t = seg.s0 + (seg.s1 - seg.s0) * i / 100;
        CHECK((c.point_at(k, t) - centre).norm() <= r * (1 + 1e-12));
      }
      // An end of the interval is either an end of an open curve or a point on the sphere
      // beyond which the curve is outside.
      for (double end : {seg.s0, seg.s1}) {
        const bool curve_end = !c.curves[k].closed && (end == 0 || end == length);
        if (curve_end) continue;
        CHECK((c.point_at(k, end) - centre).norm() == doctest::Approx(r).epsilon(1e-12));
        const double beyond = end + (end == seg.s1 ? 1e-7 : -1e-7);
        CHECK((c.point_at(k, beyond) - centre).norm() > r);
      }
    }
  }
}

TEST_CASE("closest parameter finds points back") {
  const Complex c = build_complex(io::make_capped_cylinder(1, 1, 40, 2, 2));
  for (std::uint32_t k = 0; k < c.curve_count(); ++k)
    for (double s = 0; s < c.curves[k].length; s += 0.37) {
      const double back = c.closest_parameter(k, c.point_at(k, s));
      CHECK(std::abs(back - s) < 1e-12);
      CHECK((c.point_at(k, back) - c.point_at(k, s)).norm() < 1e-12);
    }
}

TEST_CASE("closest parameters of a batch agree with closest_parameter point by point") {
  // A circle of 4,000 segments (the capped cylinder's rims) and the square's four-segment loop:
  // points on the curves, near them, far off, at a rim's centre (every segment equally far: the
  // tree's worst case) and on a corner.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (const Complex& c : {build_complex(io::make_capped_cylinder(1, 1, 4000, 2, 2)), SquareLoop().complex}) {
    for (std::uint32_t k = 0; k < c.curve_count(); ++k) {
      std::vector<Vec3> points;
      for (double s = 0; s < c.curves[k].length; s += c.curves[k].length / 97) {
        const Vec3 on = c.point_at(k, s);
        points.push_back(on);
        for (const double scale : {1e-9, 1e-3, 0.3, 5.0})
          points.push_back(on + scale * Vec3(unit(rng), unit(rng), unit(rng)));
      }
      const Vec3 first = c.point_at(k, 0), middle = c.point_at(k, 0.5 * c.curves[k].length);
      points.push_back(0.5 * (first + middle));  // the centre of a rim
      points.push_back(first);
      std::vector<double> batch(points.size());
      c.closest_parameters(k, points, batch);
      for (std::size_t i = 0; i < points.size(); ++i) {
        CAPTURE(i);
        const double one = c.closest_parameter(k, points[i]);
        const double d_batch = (c.point_at(k, batch[i]) - points[i]).norm(), d_one = (c.point_at(k, one) - points[i]).norm();
        CHECK(d_batch == doctest::Approx(d_one).epsilon(1e-12));
        // Off the circle's centre the closest point is unique: the same point (a closed curve's
        // start may come as 0 or as its length).
        if (i + 2 < points.size() || i + 1 == points.size()) CHECK((c.point_at(k, batch[i]) - c.point_at(k, one)).norm() < 1e-9);
      }
    }
  }
}
