// Configurations shared by the oracle suites, built from support/generators.h: exactly degenerate
// integer sets (coplanar, collinear, cospherical, concyclic, grids), their few-ulps neighbours, and
// exactly degenerate sets whose magnitudes differ by many orders inside one configuration.
#pragma once

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "support/generators.h"

namespace delpsc::test::configs {

/// Squared radii whose spheres carry many lattice points (from 6 to several hundred).
inline const std::vector<std::vector<WeightedPoint>>& lattice_spheres() {
  static const std::vector<std::vector<WeightedPoint>> spheres = [] {
    std::vector<std::vector<WeightedPoint>> s;
    for (const std::int64_t r2 : {3, 9, 11, 17, 25, 27, 50, 75, 99, 125, 169, 325, 425, 625, 1105,
                                  2025, 5525, 27625})
      s.push_back(lattice_sphere_points(r2));
    return s;
  }();
  return spheres;
}

/// Circles of lattice points: a lattice sphere cut by planes n.x = c for a few small integer
/// normals n; only circles with at least 4 points.
inline const std::vector<std::vector<WeightedPoint>>& lattice_circles() {
  static const std::vector<std::vector<WeightedPoint>> circles = [] {
    static constexpr int kNormals[][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                          {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, -1, 0},
                                          {1, 2, 2}, {2, -1, 1}};
    std::vector<std::vector<WeightedPoint>> out;
    for (const auto& sphere : lattice_spheres()) {
      for (const auto& n : kNormals) {
        std::map<double, std::vector<WeightedPoint>> by_offset;
        for (const auto& p : sphere) by_offset[n[0] * p.x + n[1] * p.y + n[2] * p.z].push_back(p);
        for (auto& [c, pts] : by_offset)
          if (pts.size() >= 4) out.push_back(std::move(pts));
      }
    }
    return out;
  }();
  return circles;
}

/// With probability 1/2, translates the set by a random integer vector of up to 10..40 bits
/// (when exact), which makes every difference cancel many leading bits.
inline void maybe_translate(Rng& rng, std::vector<WeightedPoint>& pts) {
  if (rng.chance(0.5)) return;
  const int bits = static_cast<int>(rng.integer(10, 40));
  const std::int64_t b = std::int64_t{1} << bits;
  translate_exactly(pts, WeightedPoint{static_cast<double>(rng.integer(-b, b)),
                                       static_cast<double>(rng.integer(-b, b)),
                                       static_cast<double>(rng.integer(-b, b)), 0});
}

/// k distinct points of one random lattice sphere, maybe translated.
inline std::vector<WeightedPoint> cospherical(Rng& rng, std::size_t k) {
  const auto& spheres = lattice_spheres();
  const std::vector<WeightedPoint>* s = nullptr;
  do s = &spheres[rng.index(spheres.size())];
  while (s->size() < k);
  auto pts = sample_distinct(rng, *s, k);
  maybe_translate(rng, pts);
  return pts;
}

/// k distinct points of one random lattice circle (k <= 4 always possible), maybe translated.
inline std::vector<WeightedPoint> concyclic(Rng& rng, std::size_t k) {
  const auto& circles = lattice_circles();
  const std::vector<WeightedPoint>* c = nullptr;
  do c = &circles[rng.index(circles.size())];
  while (c->size() < k);
  auto pts = sample_distinct(rng, *c, k);
  maybe_translate(rng, pts);
  return pts;
}

/// k integer points of a random integer plane (slopes up to 3, any of the three axes as the
/// dependent one), maybe translated.
inline std::vector<WeightedPoint> integer_coplanar(Rng& rng, std::size_t k,
                                                   std::int64_t bound = 1 << 16) {
  const IntegerPlane plane = IntegerPlane::random(rng, 3, 1 << 20);
  auto pts = coplanar_points(rng, k, plane, bound);
  maybe_translate(rng, pts);
  return pts;
}

/// A random line direction: integer (up to 2^6), or parallel to an axis (1/3 of the time), or
/// parallel to a coordinate plane (1/3).
inline WeightedPoint random_direction(Rng& rng) {
  WeightedPoint d = random_integer_vector(rng, 64);
  const double r = rng.uniform(0, 1);
  const int axis = static_cast<int>(rng.integer(0, 2));
  if (r < 1.0 / 3) {
    d = {0, 0, 0, 0};
    d.data()[axis] = static_cast<double>(rng.sign() * rng.integer(1, 64));
  } else if (r < 2.0 / 3) {
    d.data()[axis] = 0;
    if (d.x == 0 && d.y == 0 && d.z == 0) d.data()[(axis + 1) % 3] = 1;
  }
  return d;
}

/// k distinct integer points of a random line, maybe translated.
inline std::vector<WeightedPoint> integer_collinear(Rng& rng, std::size_t k) {
  const WeightedPoint o = random_integer_vector(rng, 1 << 20);
  const WeightedPoint d = random_direction(rng);
  auto pts = collinear_points(rng, k, o.data(), d.data(), 1 << 12);
  maybe_translate(rng, pts);
  return pts;
}

/// k points of the grid {0..3}^3, distinct.
inline std::vector<WeightedPoint> grid(Rng& rng, std::size_t k) {
  static const std::vector<WeightedPoint> g = grid_points(4, 4, 4);
  return sample_distinct(rng, g, k);
}

/// Gives every point the weight |p - c|^2 - r2 for a random integer centre c and r2 of random
/// magnitudes (|c| up to 2^24, r2 up to 2^48), so that all are orthogonal to one sphere; false
/// if that is not exact for this set. A far centre or a large r2 makes the weights differ far
/// more than the squared distances between the points: a different balance of the lifted column.
inline bool orthogonal_to_random_sphere(Rng& rng, std::vector<WeightedPoint>& pts) {
  const WeightedPoint c = random_integer_vector(rng, std::int64_t{1} << rng.integer(0, 24));
  const double r2 = static_cast<double>(rng.integer(0, std::int64_t{1} << rng.integer(0, 48)));
  return set_orthogonal_weights(pts, c.data(), r2);
}

/// Moves 1..3 coordinates (those allowed by axes_mask, bit 3 = weight) by 1..4 ulps.
inline void nudge_a_little(Rng& rng, std::vector<WeightedPoint>& pts, unsigned axes_mask) {
  nudge_randomly(rng, pts, static_cast<int>(rng.integer(1, 3)), 4, axes_mask);
}

/// A coordinate of random magnitude over the whole range (0 with probability zero_chance).
inline double mixed_coordinate(Rng& rng, double zero_chance = 0.05) {
  return rng.chance(zero_chance) ? 0.0 : rng.log_uniform(kMinCoordinateExp, kMaxCoordinateExp - 1);
}

/// k points with magnitudes mixed over the whole range, all in the plane coordinate[axis] = c
/// (c itself of random magnitude): coplanar whatever the magnitudes.
inline std::vector<WeightedPoint> mixed_scale_axis_plane(Rng& rng, std::size_t k, int axis) {
  const double c = mixed_coordinate(rng, 0.2);
  std::vector<WeightedPoint> pts(k);
  for (auto& p : pts) {
    for (int a = 0; a < 3; ++a) p.data()[a] = a == axis ? c : mixed_coordinate(rng);
  }
  return pts;
}

/// k points with mixed magnitudes in the plane x_b = s x_a (s = +-2^j, |j| <= 3), which is exact
/// for any x_a: coplanar, and a plane not parallel to any axis.
inline std::vector<WeightedPoint> mixed_scale_diagonal_plane(Rng& rng, std::size_t k, int a,
                                                             int b) {
  const double s = rng.sign() * std::ldexp(1.0, static_cast<int>(rng.integer(-3, 3)));
  std::vector<WeightedPoint> pts(k);
  for (auto& p : pts) {
    double v = 0;
    do v = mixed_coordinate(rng);
    while (!coordinate_in_range(v * s));
    for (int c = 0; c < 3; ++c) p.data()[c] = mixed_coordinate(rng);
    p.data()[a] = v;
    p.data()[b] = v * s;
  }
  return pts;
}

/// k points lambda_i * (1, s, t) (axes permuted), s, t in {0, +-2^j}, lambda of mixed magnitude:
/// collinear whatever the magnitudes (a line through the origin).
inline std::vector<WeightedPoint> mixed_scale_line(Rng& rng, std::size_t k) {
  double dir[3] = {1, 0, 0};
  for (int a = 1; a < 3; ++a)
    if (rng.chance(0.6)) dir[a] = rng.sign() * std::ldexp(1.0, static_cast<int>(rng.integer(-3, 3)));
  const int shift = static_cast<int>(rng.integer(0, 2));
  std::vector<WeightedPoint> pts(k);
  for (auto& p : pts) {
    double l = 0;
    bool ok = false;
    while (!ok) {
      l = rng.log_uniform(kMinCoordinateExp + 3, kMaxCoordinateExp - 4);
      ok = true;
      for (int a = 0; a < 3; ++a) ok = ok && coordinate_in_range(l * dir[a]);
    }
    for (int a = 0; a < 3; ++a) p.data()[(a + shift) % 3] = l * dir[a];
  }
  return pts;
}

/// k points 2^(e_i) v_i with small integer vectors v_i and a different random e_i for each
/// point, weighted w_i = |p_i|^2 (exact): all orthogonal to the sphere of radius 0 at the
/// origin, so every power test among them is 0, across magnitudes up to 2^+-120. The coordinates
/// in zero_mask (bit a = coordinate a) are 0: one bit gives a coordinate plane through the
/// origin, two bits an axis.
inline std::vector<WeightedPoint> mixed_scale_orthogonal(Rng& rng, std::size_t k,
                                                         unsigned zero_mask = 0) {
  std::vector<WeightedPoint> pts(k);
  for (auto& p : pts) {
    WeightedPoint v;
    do {
      v = random_integer_vector(rng, 255);
      for (int a = 0; a < 3; ++a)
        if (zero_mask & (1u << a)) v.data()[a] = 0;
    } while (v.x == 0 && v.y == 0 && v.z == 0);
    const int e = static_cast<int>(rng.integer(-120, 120));
    p = {std::ldexp(v.x, e), std::ldexp(v.y, e), std::ldexp(v.z, e),
         std::ldexp(v.x * v.x + v.y * v.y + v.z * v.z, 2 * e)};
  }
  return pts;
}

}  // namespace delpsc::test::configs
