// Arc-length queries on the curves of a Complex: point at a parameter, curve distance, and
// seg_σ(b), the piece of a curve inside a ball that contains the ball's centre (DelPSC §2.1).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/kernel/predicates.h>

#include "complex.h"

namespace delpsc::protect {

namespace {

// Index i of the polyline segment [i, i+1] holding parameter s in [0, length]:
// params[i] <= s < params[i+1], the last segment for s == length.
std::size_t segment_of(std::span<const double> params, double s) {
  const auto it = std::upper_bound(params.begin(), params.end(), s);
  const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - params.begin() - 1, 0));
  return std::min(i, params.size() - 2);
}

}  // namespace

double Complex::wrap_parameter(std::uint32_t c, double s) const {
  const double length = curves[c].length;
  if (!curves[c].closed) return std::clamp(s, 0.0, length);
  if (s >= 0 && s < length) return s;
  double w = s - length * std::floor(s / length);
  if (w >= length) w = 0;  // rounding of the line above can land on length itself
  return w;
}

Vec3 Complex::point_at(std::uint32_t c, double s) const {
  s = wrap_parameter(c, s);
  const auto params = curve_parameters(c);
  const auto poly = curve_polyline(c);
  const std::size_t i = segment_of(params, s);
  const Vec3 &a = vertices[poly[i]], &b = vertices[poly[i + 1]];
  if (s == params[i]) return a;
  if (s == params[i + 1]) return b;
  return a + (b - a) * ((s - params[i]) / (params[i + 1] - params[i]));
}

double Complex::curve_distance(std::uint32_t c, double s0, double s1) const {
  if (!curves[c].closed) return std::abs(wrap_parameter(c, s1) - wrap_parameter(c, s0));
  return wrap_parameter(c, s1 - s0);
}

CurveInterval Complex::segment_in_ball(std::uint32_t c, double s, double r) const {
  const Curve& curve = curves[c];
  s = wrap_parameter(c, s);
  if (!(r > 0)) return {s, s, false};
  const auto params = curve_parameters(c);
  const auto poly = curve_polyline(c);
  const auto n_seg = static_cast<std::ptrdiff_t>(poly.size() - 1);
  const Vec3 centre = point_at(c, s);
  const WeightedPoint ball = WeightedPoint::from(centre, r * r);
  const double length = curve.length;
  auto inside = [&](const Vec3& p) { return kernel::power_distance_sign(p.data(), ball.data()) <= 0; };

  // Walk from the centre in direction dir (+1 forward, -1 backward) over polyline vertices,
  // keeping unwrapped parameters (a closed curve continues across its corner with +-length),
  // until a vertex lies outside the ball; the exit is on the segment leading to it. The ball is
  // convex and the walk starts inside, so that segment leaves the ball exactly once after its
  // start: the exit is its last sphere crossing. Returns nullopt if the walk covers the whole
  // curve (closed: a full turn) without leaving; for an open curve the end parameter instead.
  const std::ptrdiff_t seg0 = static_cast<std::ptrdiff_t>(segment_of(params, s));
  auto walk = [&](int dir) -> std::optional<double> {
    Vec3 a = centre;
    double sa = s;
    std::ptrdiff_t v = dir > 0 ? seg0 + 1 : seg0;  // next polyline vertex in walking order
    double offset = 0;                             // +-length after crossing the closing corner
    while (true) {
      if (v > n_seg || v < 0) {
        if (!curve.closed) return dir > 0 ? length : 0.0;
        // The closing corner is poly[0] == poly[n_seg]: continue on the other side of the seam.
        offset += dir * length;
        v = dir > 0 ? 1 : n_seg - 1;
      }
      const Vec3& b = vertices[poly[v]];
      const double sb = params[v] + offset;
      // A full turn inside the ball: only a closed curve can come round (on an open one, reaching
      // the far end is not a turn, and that vertex still has to be tested).
      if (curve.closed && std::abs(sb - s) >= length) return std::nullopt;
      if (!inside(b)) {
        const kernel::SphereHits hits = kernel::intersect_segment_sphere(a, b, ball);
        const double t = hits.count > 0 ? hits.t[hits.count - 1] : 0.0;
        return sa + t * (sb - sa);
      }
      a = b;
      sa = sb;
      v += dir;
    }
  };
  const auto s1 = walk(+1);
  const auto s0 = walk(-1);
  if (!s0 || !s1 || *s1 - *s0 >= length) return {0, length, true};
  return {std::min(*s0, s), std::max(*s1, s), !curve.closed && *s0 <= 0 && *s1 >= length};
}

double Complex::closest_parameter(std::uint32_t c, const Vec3& p) const {
  const auto params = curve_parameters(c);
  const auto poly = curve_polyline(c);
  double best = std::numeric_limits<double>::infinity(), best_s = 0;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    const auto q = kernel::closest_point_on_segment(p, vertices[poly[i]], vertices[poly[i + 1]]);
    const double d2 = (q.point - p).squaredNorm();
    if (d2 < best) {
      best = d2;
      best_s = params[i] + q.t * (params[i + 1] - params[i]);
    }
  }
  return best_s;
}

void Complex::closest_parameters(std::uint32_t c, std::span<const Vec3> points, std::span<double> out) const {
  const auto params = curve_parameters(c);
  const auto poly = curve_polyline(c);
  if (poly.size() < 2) {  // no segment: as closest_parameter, parameter 0
    std::fill(out.begin(), out.end(), 0.0);
    return;
  }
  // The segments as degenerate triangles (u, v, v) in an AABB tree, whose closest point on such
  // a triangle lies on its one edge (measure_approximation measures curves the same way).
  std::vector<std::array<std::uint32_t, 3>> segments;
  segments.reserve(poly.size() - 1);
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) segments.push_back({poly[i], poly[i + 1], poly[i + 1]});
  const kernel::AabbTree tree(vertices, segments);
  for (std::size_t q = 0; q < points.size(); ++q) {
    const auto closest = tree.closest_point(points[q]);
    const std::uint32_t i = closest->triangle;  // a tree over segments always has one
    const Vec3 &a = vertices[poly[i]], &b = vertices[poly[i + 1]];
    const double length2 = (b - a).squaredNorm();
    const double t = length2 > 0 ? std::clamp((closest->point - a).dot(b - a) / length2, 0.0, 1.0) : 0.0;
    out[q] = params[i] + t * (params[i + 1] - params[i]);
  }
}

std::optional<double> Complex::parameter_of_vertex(std::uint32_t c, std::uint32_t vertex) const {
  const auto poly = curve_polyline(c);
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (poly[i] == vertex) return curve_parameters(c)[i];
  return std::nullopt;
}

}  // namespace delpsc::protect
