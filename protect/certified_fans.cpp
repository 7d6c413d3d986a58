#include "certified_fans.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <delpsc/kernel/predicates.h>

#include "complex_build.h"

namespace delpsc::protect::detail {

namespace {

/// Angles about a fan's axis, exactly (see Fan). Every point asked about must be off the axis.
struct Angles {
  const double *c, *w, *side;
  const double* r;
  int r_side;

  /// The sign of the angle from p's direction to q's, anticlockwise about the axis (0: the same
  /// or opposite directions).
  int turn(const double* p, const double* q) const { return kernel::orient3d(c, w, p, q); }
  /// 0 for an angle in [0, pi), 1 in [pi, 2 pi).
  int half(const double* x) const {
    const int o = turn(r, x);
    return o > 0 || (o == 0 && kernel::orient3d(c, w, side, x) == r_side) ? 0 : 1;
  }
  /// x's angle below y's (within a half turn two directions differ by less than pi, so the
  /// turn between them decides).
  bool before(const double* x, const double* y) const {
    const int hx = half(x), hy = half(y);
    return hx != hy ? hx < hy : turn(x, y) > 0;
  }
};

Angles angles_of(const Complex& complex, const Fan& fan) {
  return {complex.vertices[fan.centre].data(), fan.axis_point.data(), fan.side_point.data(),
          complex.vertices[fan.r].data(), fan.r_side};
}

// Orients and sorts the sectors of `fan` (its centre and triangles given, in any order) about the
// axis through its centre and `axis_point`; whether they are disjoint there (certify_fans).
// `length`: a length near the fan's own, for the second plane's point. The points constructed
// here are the predicates' input too: one outside their exact range (a coordinate rounded below
// 2^-140, or past 2^140) is refused, and the fan then not certified about this axis.
bool sort_about(const Complex& complex, Fan& fan, const Vec3& axis_point, double length) {
  const Vec3& centre = complex.vertices[fan.centre];
  if (axis_point == centre || !kernel::in_exact_range(axis_point)) return false;
  fan.axis_point = axis_point;
  const auto point = [&](std::uint32_t u) { return complex.vertices[u].data(); };
  const double* c = centre.data();
  const double* w = fan.axis_point.data();
  for (Fan::Sector& s : fan.sectors) {
    const int o = kernel::orient3d(c, w, point(s.start), point(s.end));
    if (o == 0) return false;  // a triangle whose plane holds the axis: its sector is no sector
    if (o < 0) std::swap(s.start, s.end);
  }
  // Angle 0 at the first sector's start r; a second plane through the axis that misses r (some
  // coordinate direction gives one) tells r's ray from the opposite one.
  fan.r = fan.sectors[0].start;
  fan.r_side = 0;
  for (int k = 0; k < 3 && fan.r_side == 0; ++k) {
    fan.side_point = centre + length * Vec3::Unit(k);
    if (kernel::in_exact_range(fan.side_point)) fan.r_side = kernel::orient3d(c, w, fan.side_point.data(), point(fan.r));
  }
  if (fan.r_side == 0) return false;
  const Angles a = angles_of(complex, fan);
  const auto before = [&](std::uint32_t x, std::uint32_t y) { return a.before(point(x), point(y)); };
  std::sort(fan.sectors.begin(), fan.sectors.end(),
            [&](const Fan::Sector& s, const Fan::Sector& t) { return before(s.start, t.start); });
  // Disjoint: consecutive starts strictly increasing; a sector ends at the next one's start
  // vertex (a shared edge) or strictly before it; none wraps past r but the last, which then
  // ends at r's own vertex.
  const auto& sectors = fan.sectors;
  for (std::size_t i = 0; i < sectors.size(); ++i) {
    const Fan::Sector& s = sectors[i];
    const bool wraps = before(s.end, s.start);
    if (i + 1 < sectors.size()) {
      const Fan::Sector& next = sectors[i + 1];
      if (wraps || !before(s.start, next.start) || !(s.end == next.start || before(s.end, next.start))) return false;
    } else if (wraps && s.end != sectors[0].start) {
      return false;
    }
  }
  return true;
}

// The star of a vertex on the rim of a polygon that a CAD exporter fanned from that vertex (an
// STL cylinder's cap, a cone's base) is no fan: the few triangles of the side that meet the
// vertex cover the same angles as the cap's. Its triangles within 20 degrees of parallel to a
// reference triangle are tried alone (the reference: of the largest triangle and four spread
// over the star, the one most others are parallel to), then those within 1 degree (a shallow
// cone's side against its base), then those in its plane (a shallower one). The others stay
// out of the fan, and every pair they make is tested as for any other triangle (the proof at
// certify_fans holds for any set of a vertex's triangles). `fan.sectors` holds the whole star
// on entry, the certified part if this answers true. O(d log d) exact tests.
bool certify_part(const Complex& complex, Fan& fan, std::size_t min_degree, double length) {
  const Vec3& centre = complex.vertices[fan.centre];
  const auto normal = [&](const Fan::Sector& s) {
    return Vec3((complex.vertices[s.start] - centre).cross(complex.vertices[s.end] - centre));
  };
  const std::vector<Fan::Sector> star = fan.sectors;
  constexpr double kRoughly = 0.94;  // cos 20 degrees
  const auto parallel = [&](const Vec3& n, const Vec3& axis, double cosine) {
    return std::abs(n.dot(axis)) >= cosine * n.norm();
  };
  std::size_t reference = 0, most = 0;
  for (const std::size_t candidate : reference_candidates(complex, fan.centre, star)) {
    const Vec3 axis = normal(star[candidate]).normalized();
    if (!axis.allFinite()) continue;
    const auto count = static_cast<std::size_t>(
        std::count_if(star.begin(), star.end(), [&](const Fan::Sector& s) { return parallel(normal(s), axis, kRoughly); }));
    if (count > most) most = count, reference = candidate;
  }
  if (most < min_degree) return false;
  const Vec3 axis = normal(star[reference]).normalized();
  const double* plane[3] = {centre.data(), complex.vertices[star[reference].start].data(),
                            complex.vertices[star[reference].end].data()};
  const auto in_plane = [&](const Fan::Sector& s) {
    return kernel::orient3d(plane[0], plane[1], plane[2], complex.vertices[s.start].data()) == 0 &&
           kernel::orient3d(plane[0], plane[1], plane[2], complex.vertices[s.end].data()) == 0;
  };
  // 20 and 1 degrees, then exactly in the reference's plane (a base under a cone shallower
  // than that).
  for (const double cosine : {kRoughly, 0.9998, 1.0}) {
    fan.sectors.clear();
    Vec3 sum = Vec3::Zero();
    for (const Fan::Sector& s : star) {
      const Vec3 n = normal(s);
      if (cosine < 1 ? !parallel(n, axis, cosine) : !in_plane(s)) continue;
      fan.sectors.push_back(s);
      sum += n.dot(axis) < 0 ? Vec3(-n) : n;
    }
    const double size = sum.norm();
    if (fan.sectors.size() < min_degree || fan.sectors.size() == star.size() || !(size > 0) || !std::isfinite(size))
      continue;
    if (sort_about(complex, fan, centre + (length / size) * sum, length)) return true;
  }
  fan.sectors = star;
  return false;
}

}  // namespace

// Why disjoint sectors prove a fan. The axis is the line through the centre v and a point w (any
// point off v would do; the two tried below make the test succeed on flat fans and cones). A
// triangle (v, x, y) with orient3d(v, w, x, y) != 0 has a plane that does not contain the axis'
// direction, so the projection along the axis maps it one to one onto a triangle of the
// projection plane with a corner at v's image and an angle below pi there; orient3d(v, w, x, y)
// is the exact sign of that angle. If the sectors of two triangles that share only v meet only at
// v's image, a point of both projects there, and within each triangle only v does; two sectors
// that share the ray of a common vertex x meet only on it, whose preimage in each triangle is the
// edge vx. For a flat fan the axis crosses the plane and the projection is the plane itself, seen
// askew.
std::vector<Fan> certify_fans(const Complex& complex, std::size_t min_degree, std::vector<std::uint32_t>& fan_at) {
  const std::size_t nv = complex.vertices.size();
  fan_at.assign(nv, kNoFan);
  std::vector<Fan> fans;
  // Each vertex's triangles, in one flat array (offsets as the complex's builders make them).
  kernel::LargeVector<std::uint32_t> triangles_at(nv, 0);
  for (const auto& t : complex.triangles)
    for (const std::uint32_t v : t) ++triangles_at[v];
  // Most models have no vertex of that degree: no incidence lists for them.
  if (std::none_of(triangles_at.begin(), triangles_at.end(), [&](std::uint32_t d) { return d >= min_degree; }))
    return fans;
  const kernel::LargeVector<std::uint32_t> first = detail::offsets_from_counts(triangles_at);
  kernel::LargeVector<std::uint32_t> around(first.back());
  {
    kernel::LargeVector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t t = 0; t < complex.triangles.size(); ++t)
      for (const std::uint32_t v : complex.triangles[t]) around[fill[v]++] = t;
  }
  Fan fan;
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::size_t degree = first[v + 1] - first[v];
    if (degree < min_degree) continue;
    const auto others = [&](std::uint32_t t) {
      const auto& tri = complex.triangles[t];
      const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      return std::array<std::uint32_t, 2>{tri[(k + 1) % 3], tri[(k + 2) % 3]};
    };
    // Two axes are tried: through v and w = v + the sum of the triangles' normals as given (the
    // axis of a consistently oriented cone, however steep), then + the sum with each normal
    // turned to agree with the first one's (a flat fan or a shallow cone in any orientation).
    // Any w off v is exact input to the tests below; a good one is far from every triangle's
    // plane.
    const Vec3& centre = complex.vertices[v];
    Vec3 as_given = Vec3::Zero(), agreeing = Vec3::Zero(), reference = Vec3::Zero();
    fan.centre = v;
    fan.sectors.clear();
    for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
      const auto [x, y] = others(around[i]);
      fan.sectors.push_back({x, y, around[i]});
      const Vec3 n = (complex.vertices[x] - centre).cross(complex.vertices[y] - centre);
      if (i == first[v]) reference = n;
      as_given += n;
      agreeing += n.dot(reference) < 0 ? Vec3(-n) : n;
    }
    const double length = (complex.vertices[fan.sectors[0].start] - centre).norm();
    if (!(length > 0) || !std::isfinite(length)) continue;
    const auto disjoint_around = [&](const Vec3& normal) {
      const double size = normal.norm();
      return size > 0 && std::isfinite(size) && sort_about(complex, fan, centre + (length / size) * normal, length);
    };
    if (disjoint_around(as_given) || disjoint_around(agreeing) ||
        certify_part(complex, fan, min_degree, length)) {
      fan_at[v] = static_cast<std::uint32_t>(fans.size());
      fans.push_back(std::move(fan));
      fan = Fan{};
    }
  }
  return fans;
}

std::optional<Fan> fan_about(const Complex& complex, const Fan& fan, const Vec3& through,
                             std::vector<std::uint32_t>* left_out) {
  Fan turned = fan;
  const double length = (complex.vertices[fan.sectors[0].start] - complex.vertices[fan.centre]).norm();
  if (left_out != nullptr) {
    // A triangle whose plane holds the new axis has no sector about it: the side triangles at a
    // cap's rim vertex when the axis is turned through the other cap's (certified_fans.h).
    left_out->clear();
    if (!kernel::in_exact_range(through)) return std::nullopt;
    const double* c = complex.vertices[fan.centre].data();
    std::erase_if(turned.sectors, [&](const Fan::Sector& s) {
      if (kernel::orient3d(c, through.data(), complex.vertices[s.start].data(), complex.vertices[s.end].data()) != 0)
        return false;
      left_out->push_back(s.triangle);
      return true;
    });
    if (left_out->size() > kMostLeftOut || turned.sectors.empty()) {
      left_out->clear();
      return std::nullopt;
    }
  }
  if (!sort_about(complex, turned, through, length)) {
    if (left_out != nullptr) left_out->clear();
    return std::nullopt;
  }
  return turned;
}

// Why the shadow suffices. Project along the fan's axis. A sector of the fan holds its triangle's
// shadow, which meets the axis' image only in the centre's (the centre is the triangle's only
// point on the axis). If triangle t's shadow misses the axis' image, or meets it only in the
// image of one vertex u of t while t's plane does not hold the axis (so that t meets the axis in
// u alone), then a point common to t and a fan triangle whose closed sector misses t's shadow
// (but for the axis' image) projects onto the axis' image: it is the centre, as a point of the
// fan triangle, and u, as a point of t, so u is the centre, a vertex both share. t's shadow lies
// in the union of the closed wedges between the directions of every two of its vertices off the
// axis (each under pi when the shadow misses the axis' image; a pair in opposite directions puts
// the axis' image on the shadow). The sectors meeting a closed wedge [a, b] are the one holding
// a, the one before it (which may end exactly at a), and those starting within [a, b], which
// follow it in angular order: the sectors are disjoint and each under pi.
// A segment's shadow is the same argument's with two points: it lies in the closed wedge between
// its ends' directions when those differ by less than pi, and a pair in one direction or in
// opposite ones is searched as for a triangle (one ray, or every sector).
void sectors_near(const Complex& complex, const Fan& fan, const std::array<std::uint32_t, 3>& triangle,
                  std::vector<std::uint32_t>& out) {
  const std::array<const double*, 3> points{complex.vertices[triangle[0]].data(), complex.vertices[triangle[1]].data(),
                                            complex.vertices[triangle[2]].data()};
  sectors_near(complex, fan, points, out);
}

void sectors_near(const Complex& complex, const Fan& fan, std::span<const double* const> points,
                  std::vector<std::uint32_t>& out) {
  const std::size_t n = fan.sectors.size();
  const Angles a = angles_of(complex, fan);
  std::array<const double*, 3> off{};  // the points off the axis
  int count = 0;
  for (const double* p : points.first(std::min<std::size_t>(points.size(), 3)))
    if (!kernel::collinear(a.c, a.w, p)) off[count++] = p;
  const auto all = [&] {
    for (std::uint32_t k = 0; k < n; ++k) out.push_back(k);
  };
  // Two vertices on the axis (t's plane holds it), or one with t's plane holding it: t may meet
  // the axis anywhere along a segment, perhaps at the centre. A segment (two points) with both
  // ends in one direction - parallel to the axis, as a dual edge near a flat fan is - has its
  // shadow on that ray (searched below); with them in opposite ones it crosses the axis' image.
  if (count < 2) return all();
  if (count == 2 && a.turn(off[0], off[1]) == 0 && (points.size() == 3 || a.half(off[0]) != a.half(off[1])))
    return all();
  if (count == 3) {
    const int s0 = a.turn(off[0], off[1]), s1 = a.turn(off[1], off[2]), s2 = a.turn(off[2], off[0]);
    if ((s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0)) return all();  // t meets the axis
  }
  const auto wedge = [&](const double* from, const double* to) {
    // The last sector starting at or before `from` (the last one, wrapping, if none does).
    const auto after = std::upper_bound(fan.sectors.begin(), fan.sectors.end(), from, [&](const double* x, const Fan::Sector& s) {
      return a.before(x, complex.vertices[s.start].data());
    });
    const std::size_t holder = after == fan.sectors.begin() ? n - 1 : static_cast<std::size_t>(after - fan.sectors.begin()) - 1;
    out.push_back(static_cast<std::uint32_t>((holder + n - 1) % n));
    out.push_back(static_cast<std::uint32_t>(holder));
    for (std::size_t step = 1; step < n; ++step) {
      const std::size_t k = (holder + step) % n;
      const double* s = complex.vertices[fan.sectors[k].start].data();
      if (a.turn(from, s) < 0 || a.turn(s, to) < 0) break;  // start beyond the closed wedge
      out.push_back(static_cast<std::uint32_t>(k));
    }
  };
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      const int o = a.turn(off[i], off[j]);
      if (o > 0) wedge(off[i], off[j]);
      else if (o < 0) wedge(off[j], off[i]);
      else wedge(off[i], off[i]), wedge(off[j], off[j]);  // one direction (opposite ones met the axis above)
    }
}

void sectors_within(const Complex& complex, const Fan& fan, const Vec3& p, double distance,
                    std::vector<std::uint32_t>& out) {
  const auto all = [&] {
    for (std::uint32_t k = 0; k < fan.sectors.size(); ++k) out.push_back(k);
  };
  const Vec3& c = complex.vertices[fan.centre];
  const Vec3 axis = (fan.axis_point - c).normalized();
  const Vec3 from_axis = (p - c) - axis.dot(p - c) * axis;
  const double rho = from_axis.norm();
  // The wedge's sides are p turned by +-half about the axis, each rounded by a few units in the
  // last place of the largest coordinate: that much more angle is added.
  const double largest = std::max({p.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff(), 1e-300});
  const double reach = 2 * distance + 16 * std::numeric_limits<double>::epsilon() * largest;
  if (!(rho > 4 * reach) || !axis.allFinite()) return all();  // near the axis: every direction
  const double half = std::asin(reach / rho);
  const Vec3 on_axis = p - from_axis, across = axis.cross(from_axis);
  const Vec3 below = on_axis + std::cos(half) * from_axis - std::sin(half) * across;
  const Vec3 above = on_axis + std::cos(half) * from_axis + std::sin(half) * across;
  if (!kernel::in_exact_range(below) || !kernel::in_exact_range(above)) return all();
  const std::array<const double*, 2> sides{below.data(), above.data()};
  sectors_near(complex, fan, sides, out);
}

std::array<std::size_t, 5> reference_candidates(const Complex& complex, std::uint32_t centre,
                                                std::span<const Fan::Sector> sectors) {
  const Vec3& c = complex.vertices[centre];
  const auto twice_area = [&](const Fan::Sector& s) {
    return (complex.vertices[s.start] - c).cross(complex.vertices[s.end] - c).squaredNorm();
  };
  std::array<std::size_t, 5> tried{};
  for (std::size_t i = 0; i < sectors.size(); ++i)
    if (twice_area(sectors[i]) > twice_area(sectors[tried[0]])) tried[0] = i;
  for (std::size_t k = 1; k < tried.size(); ++k) tried[k] = (k - 1) * sectors.size() / (tried.size() - 1);
  return tried;
}

}  // namespace delpsc::protect::detail
