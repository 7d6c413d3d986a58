// orient3d, orient2d, coplanar_orientation (3 and 4 points), collinear and compare_xyz against
// the GMP oracle, at least one million inputs each (tests/oracle/oracle_harness.h).
#include <doctest/doctest.h>

#include <delpsc/kernel/predicates.h>

#include "oracle_families.h"
#include "support/oracle.h"

namespace kernel = delpsc::kernel;
namespace oracle = delpsc::test::oracle;
using namespace delpsc::test;
using namespace delpsc::test::configs;
using delpsc::WeightedPoint;

namespace {

// Two lines through one integer point: k points on the first, the rest on the second; all
// coplanar.
Points two_crossing_lines(Rng& rng, std::size_t on_first, std::size_t on_second) {
  const WeightedPoint o = random_integer_vector(rng, 1 << 20);
  const WeightedPoint d1 = random_direction(rng), d2 = random_direction(rng);
  Points a = collinear_points(rng, on_first, o.data(), d1.data(), 1 << 12);
  const Points b = collinear_points(rng, on_second, o.data(), d2.data(), 1 << 12);
  a.insert(a.end(), b.begin(), b.end());
  maybe_translate(rng, a);
  return a;
}

Points axis_plane_uniform(Rng& rng, std::size_t k, int axis) {
  Points pts = uniform_points(rng, k, -1, 1);
  const double c = rng.uniform(-1, 1);
  for (auto& p : pts) p.data()[axis] = c;
  return pts;
}

}  // namespace

TEST_CASE("orient3d agrees with the exact oracle") {
  auto coplanar = [](Rng& rng, Case& c) {
    c.set(integer_coplanar(rng, 4));
    return true;
  };
  auto coplanar_near = [](Rng& rng, Case& c) {
    Points p = integer_coplanar(rng, 4);
    nudge_a_little(rng, p, 0b0111);
    c.set(p);
    return true;
  };
  const std::vector<Family> families = {
      {"uniform", "4 points in [-1,1]^3", 200'000, kGeneric,
       [](Rng& rng, Case& c) { c.set(uniform_points(rng, 4, -1, 1)); return true; }},
      {"uniform", "4 points in [2^20, 2^20+1]^3", 50'000, kGeneric,
       [](Rng& rng, Case& c) { c.set(uniform_points(rng, 4, 0x1p20, 0x1p20 + 1)); return true; }},
      {"degenerate", "integer plane (slopes <= 3)", 100'000, kDegenerate, coplanar},
      {"degenerate", "two crossing lines, 2 + 2 points", 50'000, kDegenerate,
       [](Rng& rng, Case& c) { c.set(two_crossing_lines(rng, 2, 2)); return true; }},
      {"degenerate", "three collinear + one arbitrary", 25'000, kDegenerate,
       [](Rng& rng, Case& c) {
         Points p = integer_collinear(rng, 3);
         p.insert(p.begin() + rng.integer(0, 3), random_integer_vector(rng, 1 << 20));
         c.set(p);
         return true;
       }},
      {"degenerate", "grid {0..3}^3 (many coplanar)", 75'000, ZeroRate{0.05, 0.9},
       [](Rng& rng, Case& c) { c.set(grid(rng, 4)); return true; }},
      {"near-degenerate", "integer plane, 1-3 coords moved 1-4 ulps", 150'000, kNearDegenerate,
       coplanar_near},
      {"near-degenerate", "two crossing lines, moved", 50'000, kNearDegenerate,
       [](Rng& rng, Case& c) {
         Points p = two_crossing_lines(rng, 2, 2);
         nudge_a_little(rng, p, 0b0111);
         c.set(p);
         return true;
       }},
      {"near-degenerate", "grid, moved", 50'000, kNearDegenerate,
       [](Rng& rng, Case& c) {
         Points p = grid(rng, 4);
         nudge_a_little(rng, p, 0b0111);
         c.set(p);
         return true;
       }},
      {"multi-scale", "integer plane x 2^k", 75'000, kDegenerate, scaled(coplanar)},
      {"multi-scale", "integer plane moved, x 2^k", 75'000, kNearDegenerate, scaled(coplanar_near)},
      {"multi-scale", "mixed magnitudes 2^-140..2^140", 50'000, kGeneric,
       [](Rng& rng, Case& c) { c.set(mixed_scale_points(rng, 4, false)); return true; }},
      {"multi-scale", "mixed magnitudes on a plane x_a = c", 50'000, kDegenerate,
       [](Rng& rng, Case& c) {
         c.set(mixed_scale_axis_plane(rng, 4, static_cast<int>(rng.integer(0, 2))));
         return true;
       }},
      {"multi-scale", "mixed magnitudes on a plane x_b = +-2^j x_a", 50'000, kDegenerate,
       [](Rng& rng, Case& c) {
         const int a = static_cast<int>(rng.integer(0, 2));
         c.set(mixed_scale_diagonal_plane(rng, 4, a, (a + 1 + static_cast<int>(rng.integer(0, 1))) % 3));
         return true;
       }},
      {"multi-scale", "integer plane moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(coplanar_near)},
      {"degenerate", "repeated points (4 draws from 4 grid points)", 25'000, ZeroRate{0.85, 1},
       with_repeats(always([](Rng& rng) { return grid(rng, 4); }), 4)},
      {"multi-scale", "mixed magnitudes on x_a = c, moved off it", 25'000, kNearDegenerate,
       [](Rng& rng, Case& c) {
         const int a = static_cast<int>(rng.integer(0, 2));
         Points p = mixed_scale_axis_plane(rng, 4, a);
         nudge_a_little(rng, p, 1u << a);
         c.set(p);
         return true;
       }},
  };
  const long n = run_families(
      "orient3d", 1, families,
      [](const Case& c) { return kernel::orient3d(c[0], c[1], c[2], c[3]); },
      [](const Case& c) { return oracle::orient3d(c[0], c[1], c[2], c[3]); });
  CHECK(n >= required_total());
}

TEST_CASE("orient2d agrees with the exact oracle on every ordered pair of axes") {
  auto with_axes = [](Rng& rng, Case& c) {
    c.i = static_cast<int>(rng.integer(0, 2));
    c.j = (c.i + static_cast<int>(rng.integer(1, 2))) % 3;
  };
  // Points whose projection on (i, j) is the integer line x_i = a x_j + c (any x_k).
  auto projected_collinear = [with_axes](Rng& rng, Case& c) {
    with_axes(rng, c);
    const std::int64_t a = rng.integer(-3, 3), off = rng.integer(-(1 << 20), 1 << 20);
    const int k = 3 - c.i - c.j;
    Points p(3);
    for (auto& q : p) {
      const std::int64_t xj = rng.integer(-(1 << 16), 1 << 16);
      q.data()[c.j] = static_cast<double>(xj);
      q.data()[c.i] = static_cast<double>(a * xj + off);
      q.data()[k] = static_cast<double>(rng.integer(-(1 << 20), 1 << 20));
    }
    maybe_translate(rng, p);
    c.set(p);
    return true;
  };
  auto collinear3 = [with_axes](Rng& rng, Case& c) {
    with_axes(rng, c);
    c.set(integer_collinear(rng, 3));
    return true;
  };
  auto collinear3_near = [with_axes](Rng& rng, Case& c) {
    with_axes(rng, c);
    Points p = integer_collinear(rng, 3);
    nudge_a_little(rng, p, (1u << c.i) | (1u << c.j));
    c.set(p);
    return true;
  };
  const std::vector<Family> families = {
      {"uniform", "3 points in [-1,1]^3", 250'000, kGeneric,
       [with_axes](Rng& rng, Case& c) {
         with_axes(rng, c);
         c.set(uniform_points(rng, 3, -1, 1));
         return true;
       }},
      {"degenerate", "integer line", 100'000, kDegenerate, collinear3},
      {"degenerate", "collinear in the projection only", 100'000, kDegenerate, projected_collinear},
      {"degenerate", "grid {0..3}^3", 50'000, ZeroRate{0.05, 0.9},
       [with_axes](Rng& rng, Case& c) {
         with_axes(rng, c);
         c.set(grid(rng, 3));
         return true;
       }},
      {"near-degenerate", "integer line, moved in the projection", 150'000, kNearDegenerate,
       collinear3_near},
      {"near-degenerate", "collinear in the projection, moved", 100'000, kNearDegenerate,
       [projected_collinear](Rng& rng, Case& c) {
         projected_collinear(rng, c);
         Points p(c.pts.begin(), c.pts.begin() + 3);
         nudge_a_little(rng, p, (1u << c.i) | (1u << c.j));
         c.set(p);
         return true;
       }},
      {"multi-scale", "integer line x 2^k", 75'000, kDegenerate, scaled(collinear3)},
      {"multi-scale", "integer line moved, x 2^k", 75'000, kNearDegenerate, scaled(collinear3_near)},
      {"multi-scale", "mixed magnitudes", 50'000, kGeneric,
       [with_axes](Rng& rng, Case& c) {
         with_axes(rng, c);
         c.set(mixed_scale_points(rng, 3, false));
         return true;
       }},
      {"multi-scale", "mixed magnitudes on a line through 0", 50'000, kDegenerate,
       [with_axes](Rng& rng, Case& c) {
         with_axes(rng, c);
         c.set(mixed_scale_line(rng, 3));
         return true;
       }},
      {"multi-scale", "integer line moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(collinear3_near)},
      {"degenerate", "repeated points (3 draws from 3)", 25'000, ZeroRate{0.7, 1},
       [with_axes](Rng& rng, Case& c) {
         with_axes(rng, c);
         const int i = c.i, j = c.j;
         if (!with_repeats(always([](Rng& r) { return uniform_points(r, 3, -1, 1); }), 3)(rng, c))
           return false;
         c.i = i;
         c.j = j;
         return true;
       }},
      {"multi-scale", "mixed magnitudes, x_i = c", 50'000, kDegenerate,
       [with_axes](Rng& rng, Case& c) {
         with_axes(rng, c);
         c.set(mixed_scale_axis_plane(rng, 3, c.i));
         return true;
       }},
  };
  const long n = run_families(
      "orient2d", 2, families,
      [](const Case& c) { return kernel::orient2d(c[0], c[1], c[2], c.i, c.j); },
      [](const Case& c) { return oracle::orient2d(c[0], c[1], c[2], c.i, c.j); });
  CHECK(n >= required_total());
}

namespace {

// Families of triples shared by coplanar_orientation(p, q, r) and collinear(p, q, r).
std::vector<Family> triple_families() {
  auto collinear3 = [](Rng& rng, Case& c) {
    c.set(integer_collinear(rng, 3));
    return true;
  };
  auto collinear3_near = [](Rng& rng, Case& c) {
    Points p = integer_collinear(rng, 3);
    nudge_a_little(rng, p, 0b0111);
    c.set(p);
    return true;
  };
  return {
      {"uniform", "3 points in [-1,1]^3", 200'000, kGeneric,
       [](Rng& rng, Case& c) { c.set(uniform_points(rng, 3, -1, 1)); return true; }},
      {"uniform", "3 points on x = c or y = c (xy, yz fall through)", 60'000, kGeneric,
       [](Rng& rng, Case& c) {
         c.set(axis_plane_uniform(rng, 3, static_cast<int>(rng.integer(0, 1))));
         return true;
       }},
      {"degenerate", "integer line (axis-parallel 1/3)", 200'000, kDegenerate, collinear3},
      // About 1% of the triples of a 4x4x4 grid are collinear.
      {"degenerate", "grid {0..3}^3", 50'000, ZeroRate{0.002, 0.05},
       [](Rng& rng, Case& c) { c.set(grid(rng, 3)); return true; }},
      {"near-degenerate", "integer line, moved", 200'000, kNearDegenerate, collinear3_near},
      {"multi-scale", "integer line x 2^k", 75'000, kDegenerate, scaled(collinear3)},
      {"multi-scale", "integer line moved, x 2^k", 75'000, kNearDegenerate, scaled(collinear3_near)},
      {"multi-scale", "mixed magnitudes", 50'000, kGeneric,
       [](Rng& rng, Case& c) { c.set(mixed_scale_points(rng, 3, false)); return true; }},
      {"multi-scale", "mixed magnitudes on a line through 0", 75'000, kDegenerate,
       [](Rng& rng, Case& c) { c.set(mixed_scale_line(rng, 3)); return true; }},
      {"multi-scale", "integer line moved, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(collinear3_near)},
      {"degenerate", "repeated points (3 draws from 3)", 25'000, ZeroRate{0.7, 1},
       with_repeats(always([](Rng& rng) { return uniform_points(rng, 3, -1, 1); }), 3)},
      {"multi-scale", "mixed magnitudes on x = c or y = c", 50'000, kGeneric,
       [](Rng& rng, Case& c) {
         c.set(mixed_scale_axis_plane(rng, 3, static_cast<int>(rng.integer(0, 1))));
         return true;
       }},
  };
}

}  // namespace

TEST_CASE("coplanar_orientation (3 points) agrees with the exact oracle") {
  const long n = run_families(
      "coplanar_orientation(3)", 3, triple_families(),
      [](const Case& c) { return kernel::coplanar_orientation(c[0], c[1], c[2]); },
      [](const Case& c) { return oracle::coplanar_orientation(c[0], c[1], c[2]); });
  CHECK(n >= required_total());
}

TEST_CASE("collinear agrees with the exact oracle") {
  // 0 = collinear, so that the families' zero rates read the same as for coplanar_orientation.
  const long n = run_families(
      "collinear", 4, triple_families(),
      [](const Case& c) { return kernel::collinear(c[0], c[1], c[2]) ? 0 : 1; },
      [](const Case& c) { return oracle::collinear(c[0], c[1], c[2]) ? 0 : 1; });
  CHECK(n >= required_total());
}

TEST_CASE("coplanar_orientation (4 points) agrees with the exact oracle") {
  // Precondition: p, q, r, s coplanar, p, q, r not collinear. Draws that miss it are rejected.
  auto accept = [](Case& c, const Points& p) {
    c.set(p);
    return !oracle::collinear(c[0], c[1], c[2]);
  };
  // s = p + m (q - p) on line pq, in a plane from `plane`.
  auto on_line_pq = [accept](Rng& rng, Case& c, const IntegerPlane& plane) {
    Points p = coplanar_points(rng, 3, plane, 1 << 16);
    const auto m = static_cast<double>(rng.integer(-8, 8));
    p.push_back({p[0].x + m * (p[1].x - p[0].x), p[0].y + m * (p[1].y - p[0].y),
                 p[0].z + m * (p[1].z - p[0].z), 0});
    maybe_translate(rng, p);
    return accept(c, p);
  };
  auto tilted = [on_line_pq](Rng& rng, Case& c) {
    return on_line_pq(rng, c, IntegerPlane::random(rng, 3, 1 << 20));
  };
  // Planes containing an axis direction (b = 0): xy (and for y = c also yz) degenerate, so the
  // later projections of CGAL's order decide.
  auto vertical = [on_line_pq](Rng& rng, Case& c) {
    IntegerPlane plane = IntegerPlane::random(rng, 3, 1 << 20);
    plane.axis = static_cast<int>(rng.integer(0, 1));
    plane.b = 0;
    return on_line_pq(rng, c, plane);
  };
  // Axis planes: s near line pq by moving its in-plane coordinates, which stays coplanar.
  auto axis_near = [on_line_pq](Rng& rng, Case& c) {
    IntegerPlane plane;
    plane.axis = static_cast<int>(rng.integer(0, 2));
    plane.c = rng.integer(-(1 << 20), 1 << 20);
    if (!on_line_pq(rng, c, plane)) return false;
    const std::size_t which = rng.index(4);
    const int in_plane = (plane.axis + static_cast<int>(rng.integer(1, 2))) % 3;
    double& v = c.pts[which].data()[in_plane];
    v = nudge(v, static_cast<int>(rng.integer(1, 4)) * rng.sign());
    return !oracle::collinear(c[0], c[1], c[2]);
  };
  auto diagonal_uniform = [accept](Rng& rng, Case& c) {
    const int a = static_cast<int>(rng.integer(0, 2));
    const int b = (a + static_cast<int>(rng.integer(1, 2))) % 3;
    Points p = uniform_points(rng, 4, -1, 1);
    const double s = rng.sign() * std::ldexp(1.0, static_cast<int>(rng.integer(-2, 2)));
    for (auto& q : p) q.data()[b] = s * q.data()[a];
    return accept(c, p);
  };
  const std::vector<Family> families = {
      {"uniform", "4 points on x_a = c", 100'000, kGeneric,
       [accept](Rng& rng, Case& c) {
         return accept(c, axis_plane_uniform(rng, 4, static_cast<int>(rng.integer(0, 2))));
       }},
      {"uniform", "4 points on x_b = +-2^j x_a", 100'000, kGeneric, diagonal_uniform},
      {"uniform", "4 points on an integer plane, 17 bits", 50'000, kGeneric,
       [accept](Rng& rng, Case& c) { return accept(c, integer_coplanar(rng, 4)); }},
      {"degenerate", "s on line pq, tilted integer plane", 150'000, kDegenerate, tilted},
      {"degenerate", "s on line pq, plane containing an axis", 100'000, kDegenerate, vertical},
      {"degenerate", "grid {0..3}^2 x {k}", 50'000, ZeroRate{0.05, 0.9},
       [accept](Rng& rng, Case& c) {
         static const Points g = grid_points(4, 4, 1);
         Points p = sample_distinct(rng, g, 4);
         const int axis = static_cast<int>(rng.integer(0, 2));
         for (auto& q : p) std::swap(q.data()[2], q.data()[axis]);
         return accept(c, p);
       }},
      {"near-degenerate", "s near line pq, axis plane", 150'000, kNearDegenerate, axis_near},
      {"near-degenerate", "s near line pq, x_b = x_a, moved along x_k", 100'000, kNearDegenerate,
       [accept](Rng& rng, Case& c) {
         const int a = static_cast<int>(rng.integer(0, 2));
         const int b = (a + 1) % 3, k = (a + 2) % 3;
         Points p(4);
         for (int i = 0; i < 3; ++i) {
           p[i].data()[a] = p[i].data()[b] = static_cast<double>(rng.integer(-(1 << 20), 1 << 20));
           p[i].data()[k] = static_cast<double>(rng.integer(-(1 << 20), 1 << 20));
         }
         const auto m = static_cast<double>(rng.integer(-8, 8));
         for (int d = 0; d < 3; ++d) p[3].data()[d] = p[0].data()[d] + m * (p[1].data()[d] - p[0].data()[d]);
         p[3].data()[k] = nudge(p[3].data()[k], static_cast<int>(rng.integer(1, 4)) * rng.sign());
         return accept(c, p);
       }},
      {"multi-scale", "s on line pq x 2^k", 75'000, kDegenerate, scaled(tilted)},
      {"multi-scale", "s near line pq x 2^k", 75'000, kNearDegenerate, scaled(axis_near)},
      {"multi-scale", "s near line pq, at the range's ends", 25'000, kNearDegenerate,
       scaled_to_extreme(axis_near)},
      {"multi-scale", "mixed magnitudes on x_a = c", 50'000, kGeneric,
       [accept](Rng& rng, Case& c) {
         return accept(c, mixed_scale_axis_plane(rng, 4, static_cast<int>(rng.integer(0, 2))));
       }},
      {"multi-scale", "mixed magnitudes on x_b = +-2^j x_a", 50'000, kGeneric,
       [accept](Rng& rng, Case& c) {
         const int a = static_cast<int>(rng.integer(0, 2));
         return accept(c, mixed_scale_diagonal_plane(rng, 4, a, (a + 1) % 3));
       }},
      {"multi-scale", "mixed magnitudes, s on line pq through 0", 50'000, kDegenerate,
       [accept](Rng& rng, Case& c) {
         // p, q, s on a line through the origin; when the line lies in a coordinate plane
         // x_a = 0, r anywhere in that plane.
         Points line = mixed_scale_line(rng, 3);
         int zero_axis = -1;
         for (int a = 0; a < 3; ++a)
           if (line[0].data()[a] == 0) zero_axis = a;
         if (zero_axis < 0) return false;
         WeightedPoint r = mixed_scale_axis_plane(rng, 1, zero_axis)[0];
         r.data()[zero_axis] = 0;
         return accept(c, {line[0], line[1], r, line[2]});
       }},
  };
  const long n = run_families(
      "coplanar_orientation(4)", 5, families,
      [](const Case& c) { return kernel::coplanar_orientation(c[0], c[1], c[2], c[3]); },
      [](const Case& c) { return oracle::coplanar_orientation(c[0], c[1], c[2], c[3]); });
  CHECK(n >= required_total());
}

TEST_CASE("compare_xyz agrees with the exact oracle") {
  const std::vector<Family> families = {
      {"uniform", "2 points in [-1,1]^3", 300'000, kGeneric,
       [](Rng& rng, Case& c) { c.set(uniform_points(rng, 2, -1, 1)); return true; }},
      {"degenerate", "equal points", 200'000, kDegenerate,
       [](Rng& rng, Case& c) {
         Points p = uniform_points(rng, 1, -1, 1);
         p.push_back(p[0]);
         c.set(p);
         return true;
       }},
      {"degenerate", "equal x, or equal x and y", 200'000, kGeneric,
       [](Rng& rng, Case& c) {
         Points p = uniform_points(rng, 2, -1, 1);
         p[1].x = p[0].x;
         if (rng.chance(0.5)) p[1].y = p[0].y;
         c.set(p);
         return true;
       }},
      {"near-degenerate", "equal points, one coordinate moved", 200'000, ZeroRate{0, 0.05},
       [](Rng& rng, Case& c) {
         Points p = uniform_points(rng, 1, -1, 1);
         p.push_back(p[0]);
         nudge_randomly(rng, p, 1, 2);
         c.set(p);
         return true;
       }},
      {"multi-scale", "mixed magnitudes, sharing coordinates", 100'000, kAnyRate,
       [](Rng& rng, Case& c) {
         Points p = mixed_scale_points(rng, 2, false, 0.3);
         if (rng.chance(0.5)) p[1].x = p[0].x;
         if (rng.chance(0.5)) p[1].y = p[0].y;
         c.set(p);
         return true;
       }},
  };
  const long n = run_families(
      "compare_xyz", 6, families,
      [](const Case& c) { return kernel::compare_xyz(c[0], c[1]); },
      [](const Case& c) { return oracle::compare_xyz(c[0], c[1]); });
  CHECK(n >= required_total());
}
