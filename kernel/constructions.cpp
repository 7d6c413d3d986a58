// Constructions in double; see constructions.h for the contracts and the measured accuracy.
#include "constructions.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "predicates.h"

namespace delpsc::kernel {

namespace {

bool is_finite(const WeightedPoint& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(p.w);
}

/// c = base + o, weight |o|^2 - w_base; nullopt if anything overflowed (or 0/0 slipped through).
std::optional<WeightedPoint> centre_from_offset(const WeightedPoint& base, const Vec3& o) {
  const WeightedPoint c{base.x + o.x(), base.y + o.y(), base.z + o.z(), o.squaredNorm() - base.w};
  if (!is_finite(c)) return std::nullopt;
  return c;
}

/// alpha_i = |e_i|^2 - w_i + w_0: twice the offset's projection on e_i (see the header). The
/// weight difference first, because neighbouring protecting balls have similar weights and then
/// it is exact (Sterbenz).
double alpha(const Vec3& e, const WeightedPoint& pi, const WeightedPoint& p0) {
  return e.squaredNorm() - (pi.w - p0.w);
}

Vec3 offset(const WeightedPoint& p, const WeightedPoint& base) {
  return {p.x - base.x, p.y - base.y, p.z - base.z};
}

constexpr int next(int k) { return k == 2 ? 0 : k + 1; }
constexpr int after_next(int k) { return k == 0 ? 2 : k - 1; }

/// The three vertices of a triangle, as pointers for the predicates and as vectors.
struct Triangle {
  const Vec3* v[3];
  const double* p(int k) const { return v[k]->data(); }
  const Vec3& operator[](int k) const { return *v[k]; }
};

/// Signs of the Pluecker volumes orient3d(a, b, t_{k+1}, t_{k+2}), k = 0, 1, 2. They sum (as
/// values) to n.(b - a), n = (t1 - t0) x (t2 - t0). When they are not all zero (the line is not
/// parallel to the plane), the line ab meets the closed triangle iff no two of them have opposite
/// signs, through edge k iff only the k-th is zero, through vertex k iff only the k-th is
/// non-zero (they are the barycentric coordinates of the crossing, times n.(b - a)).
std::array<int, 3> pluecker_signs(const double* a, const double* b, const Triangle& tri) {
  std::array<int, 3> s{};
  for (int k = 0; k < 3; ++k) s[k] = orient3d(a, b, tri.p(next(k)), tri.p(after_next(k)));
  return s;
}

bool mixed_signs(const std::array<int, 3>& s) {
  const bool pos = s[0] > 0 || s[1] > 0 || s[2] > 0;
  const bool neg = s[0] < 0 || s[1] < 0 || s[2] < 0;
  return pos && neg;
}

/// Feature pierced by a line whose Pluecker signs agree and are not all zero.
TriangleFeature feature_from_pluecker(const std::array<int, 3>& s) {
  const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
  assert(zeros < 3);
  if (zeros == 0) return {FeatureKind::face, 0};
  for (int k = 0; k < 3; ++k) {
    if (zeros == 1 && s[k] == 0) return {FeatureKind::edge, k};
    if (zeros == 2 && s[k] != 0) return {FeatureKind::vertex, k};
  }
  return {FeatureKind::face, 0};  // unreachable
}

/// Moves x (a floating-point approximation of a point known exactly to lie on `f`) onto f: the
/// vertex itself, or the closest point of the edge's segment or of the closed triangle.
Vec3 snap_to_feature(const Vec3& x, const Triangle& tri, TriangleFeature f) {
  switch (f.kind) {
    case FeatureKind::vertex:
      return tri[f.index];
    case FeatureKind::edge:
      return closest_point_on_segment(x, tri[next(f.index)], tri[after_next(f.index)]).point;
    case FeatureKind::face:
      break;
  }
  // The projection on a convex set moves no point farther from any point of the set, so the
  // error of x is not amplified, however thin the triangle (barycentric clamping would be).
  return closest_point_on_triangle(x, tri[0], tri[1], tri[2]).point;
}

/// Parameter t (in units of d) at which the line a + t d crosses the triangle's plane. Callers
/// measure from the nearer end of a segment, so that a long segment loses no accuracy there.
double plane_parameter(const Vec3& a, const Vec3& d, const Triangle& tri) {
  const Vec3 n = (tri[1] - tri[0]).cross(tri[2] - tri[0]);
  return -n.dot(a - tri[0]) / n.dot(d);
}

/// A projection on two coordinate axes in which the triangle is not flat, so that it maps the
/// triangle's plane one-to-one: orientations of points of that plane are those of their
/// projections times `sign`. The axis along which the normal is largest is dropped when its
/// projection is not exactly flat, which keeps the floating-point clipping accurate.
struct PlaneProjection {
  int i = 0, j = 1;
  int sign = 0;  ///< orient2d(t0, t1, t2, i, j); 0 if the triangle is degenerate
};

PlaneProjection projection_for(const Triangle& tri) {
  const Vec3 n = (tri[1] - tri[0]).cross(tri[2] - tri[0]);
  int dominant = 0;
  n.cwiseAbs().maxCoeff(&dominant);
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int drop = (dominant + attempt) % 3;
    PlaneProjection pr{(drop + 1) % 3, (drop + 2) % 3, 0};
    pr.sign = orient2d(tri.p(0), tri.p(1), tri.p(2), pr.i, pr.j);
    if (pr.sign != 0) return pr;
  }
  return {};
}

/// >= 0 iff coplanar x is on the triangle's side of the line of edge k (exact).
int edge_side(const PlaneProjection& pr, const Triangle& tri, int k, const double* x) {
  return pr.sign * orient2d(tri.p(next(k)), tri.p(after_next(k)), x, pr.i, pr.j);
}

bool inside_closed(const PlaneProjection& pr, const Triangle& tri, const double* x) {
  for (int k = 0; k < 3; ++k)
    if (edge_side(pr, tri, k, x) < 0) return false;
  return true;
}

/// True iff the coplanar segment [a, b] (a != b) meets the closed triangle. Two convex sets of
/// the plane are disjoint iff a line through an edge of one separates them; for a segment and a
/// triangle that leaves the three edge lines and the segment's own line, all tested exactly.
bool coplanar_segment_meets(const PlaneProjection& pr, const Triangle& tri, const double* a,
                            const double* b) {
  for (int k = 0; k < 3; ++k)
    if (edge_side(pr, tri, k, a) < 0 && edge_side(pr, tri, k, b) < 0) return false;
  int pos = 0, neg = 0;
  for (int m = 0; m < 3; ++m) {
    const int s = orient2d(a, b, tri.p(m), pr.i, pr.j);
    pos += s > 0;
    neg += s < 0;
  }
  return pos < 3 && neg < 3;
}

/// True iff the coplanar ray from o through q meets the closed triangle: o inside, or the ray
/// crosses the segment of an edge ahead of o. For an edge uv whose ends are not strictly on one
/// side of the ray's line, name L the end on the left (orient2d(o, q, L) >= 0) and R the other;
/// the crossing is ahead of o iff orient2d(o, L, R) <= 0 (in a frame where the ray is the positive
/// x axis, the crossing abscissa is det(L, R) / (R_y - L_y) with R_y - L_y < 0). Edges lying on
/// the ray's line are covered by their neighbours, which share their ends.
bool coplanar_ray_meets(const PlaneProjection& pr, const Triangle& tri, const double* o,
                        const double* q) {
  if (inside_closed(pr, tri, o)) return true;
  std::array<int, 3> side{};
  for (int m = 0; m < 3; ++m) side[m] = orient2d(o, q, tri.p(m), pr.i, pr.j);
  for (int k = 0; k < 3; ++k) {
    const int u = next(k), v = after_next(k);
    const int su = side[u], sv = side[v];
    if (su * sv > 0 || (su == 0 && sv == 0)) continue;
    const bool u_left = su > 0 || (su == 0 && sv < 0);
    const double* left = tri.p(u_left ? u : v);
    const double* right = tri.p(u_left ? v : u);
    if (orient2d(o, left, right, pr.i, pr.j) <= 0) return true;
  }
  return false;
}

/// Overlap [lo, hi] of the coplanar line a + t d with the triangle, intersected with
/// [lo, hi] as given (Cyrus-Beck clipping against the three edge lines in the projection). Only
/// called once the exact tests said the overlap is non-empty, so a rounding-empty interval is
/// collapsed to a point rather than reported as a miss.
void clip_coplanar(const PlaneProjection& pr, const Triangle& tri, const Vec3& a, const Vec3& d,
                   double& lo, double& hi) {
  const int i = pr.i, j = pr.j;
  for (int k = 0; k < 3; ++k) {
    const Vec3& u = tri[next(k)];
    const Vec3& v = tri[after_next(k)];
    const double ex = v[i] - u[i], ey = v[j] - u[j];
    const double at_a = pr.sign * (ex * (a[j] - u[j]) - ey * (a[i] - u[i]));
    const double slope = pr.sign * (ex * d[j] - ey * d[i]);
    if (slope > 0) lo = std::max(lo, -at_a / slope);
    if (slope < 0) hi = std::min(hi, -at_a / slope);
  }
  if (!std::isfinite(hi)) hi = lo;
  if (lo > hi) lo = hi = 0.5 * (lo + hi);
}

/// Whether the coplanar segment [a, b] (a point when a == b) meets the closed triangle.
bool coplanar_meets(const PlaneProjection& pr, const Triangle& tri, const Vec3& a, const Vec3& b) {
  return a == b ? inside_closed(pr, tri, a.data()) : coplanar_segment_meets(pr, tri, a.data(), b.data());
}

/// The coplanar branch shared by segments (is_ray false, b the end) and rays (b the point that
/// represents the ray, d the user's direction).
TriangleHit coplanar_hit(const Vec3& a, const Vec3& b, const Vec3& d, bool is_ray,
                         const Triangle& tri) {
  TriangleHit hit;
  const PlaneProjection pr = projection_for(tri);
  if (pr.sign == 0) {
    hit.contact = Contact::degenerate;
    return hit;
  }
  const bool point_like = !is_ray && a == b;
  const bool meets = is_ray ? coplanar_ray_meets(pr, tri, a.data(), b.data()) : coplanar_meets(pr, tri, a, b);
  if (!meets) return hit;
  hit.contact = Contact::coplanar;
  double lo = 0, hi = is_ray ? std::numeric_limits<double>::infinity() : 1.0;
  if (point_like) {
    hi = 0;
  } else {
    clip_coplanar(pr, tri, a, d, lo, hi);
  }
  hit.t = lo;
  hit.t_exit = hi;
  hit.point = lo == 0 ? a : Vec3(a + lo * d);
  return hit;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Orthocentres
// ---------------------------------------------------------------------------------------------

std::optional<WeightedPoint> orthocentre(const WeightedPoint& p, const WeightedPoint& q) {
  // x - y == 0 in IEEE arithmetic (with gradual underflow) iff x == y: exact test.
  if (p.x == q.x && p.y == q.y && p.z == q.z) return std::nullopt;
  const Vec3 e = offset(q, p);
  const Vec3 o = (alpha(e, q, p) / (2 * e.squaredNorm())) * e;
  return centre_from_offset(p, o);
}

std::optional<WeightedPoint> orthocentre(const WeightedPoint& p, const WeightedPoint& q,
                                         const WeightedPoint& r) {
  if (collinear(p.data(), q.data(), r.data())) return std::nullopt;
  const Vec3 e1 = offset(q, p), e2 = offset(r, p);
  const Vec3 n = e1.cross(e2);
  // The system 2 o.e1 = alpha1, 2 o.e2 = alpha2, o.n = 0 solved by Cramer's rule; the formula is
  // homogeneous in n, so the rounding of n only tilts the plane, it does not scale the result.
  const Vec3 num = alpha(e1, q, p) * e2.cross(n) + alpha(e2, r, p) * n.cross(e1);
  return centre_from_offset(p, num / (2 * n.squaredNorm()));
}

std::optional<WeightedPoint> orthocentre(const WeightedPoint& p, const WeightedPoint& q,
                                         const WeightedPoint& r, const WeightedPoint& s) {
  if (orient3d(p.data(), q.data(), r.data(), s.data()) == 0) return std::nullopt;
  const Vec3 e1 = offset(q, p), e2 = offset(r, p), e3 = offset(s, p);
  const Vec3 c23 = e2.cross(e3), c31 = e3.cross(e1), c12 = e1.cross(e2);
  const double det = e1.dot(c23);
  const Vec3 num = alpha(e1, q, p) * c23 + alpha(e2, r, p) * c31 + alpha(e3, s, p) * c12;
  return centre_from_offset(p, num / (2 * det));
}

// ---------------------------------------------------------------------------------------------
// Segment / ray and triangle
// ---------------------------------------------------------------------------------------------

TriangleHit intersect_segment_triangle(const Vec3& a, const Vec3& b, const Vec3& t0,
                                       const Vec3& t1, const Vec3& t2) {
  const Triangle tri{{&t0, &t1, &t2}};
  const int sa = orient3d(t0, t1, t2, a);
  const int sb = orient3d(t0, t1, t2, b);
  if (sa == 0 && sb == 0) return coplanar_hit(a, b, b - a, false, tri);
  TriangleHit hit;
  if (sa == sb) return hit;  // both strictly on the same side of the plane
  // Now the line ab is not parallel to the plane and meets it at a point of [a, b].
  const std::array<int, 3> pl = pluecker_signs(a.data(), b.data(), tri);
  if (mixed_signs(pl)) return hit;
  hit.feature = feature_from_pluecker(pl);
  if (sa == 0) {
    hit.contact = Contact::at_start;
    hit.point = a;
    hit.t = hit.t_exit = 0;
    return hit;
  }
  if (sb == 0) {
    hit.contact = Contact::at_end;
    hit.point = b;
    hit.t = hit.t_exit = 1;
    return hit;
  }
  hit.contact = Contact::crossing;
  // Parameter from the nearer end, then the point from that end.
  const double ta = plane_parameter(a, b - a, tri);
  const double tb = plane_parameter(b, a - b, tri);
  Vec3 x;
  if (std::fabs(ta) <= std::fabs(tb)) {
    hit.t = std::isfinite(ta) ? std::clamp(ta, 0.0, 1.0) : 0.5;
    x = a + hit.t * (b - a);
  } else {
    const double u = std::isfinite(tb) ? std::clamp(tb, 0.0, 1.0) : 0.5;
    hit.t = 1 - u;
    x = b + u * (a - b);
  }
  hit.t_exit = hit.t;
  hit.point = snap_to_feature(x, tri, hit.feature);
  return hit;
}

bool coplanar_segment_meets_triangle(const Vec3& a, const Vec3& b, const Vec3& t0, const Vec3& t1,
                                     const Vec3& t2) {
  const Triangle tri{{&t0, &t1, &t2}};
  const PlaneProjection pr = projection_for(tri);
  return pr.sign != 0 && coplanar_meets(pr, tri, a, b);
}

Vec3 ray_through_point(const Vec3& origin, const Vec3& direction) {
  // Scale the direction by a power of two (exact) until it is at least as long as the origin's
  // coordinates, so that rounding origin + direction perturbs the ray by at most ~eps radians.
  const double dmax = direction.cwiseAbs().maxCoeff();
  const double omax = origin.cwiseAbs().maxCoeff();
  double scale = 1;
  if (dmax > 0 && omax > dmax) {
    int e = 0;
    std::frexp(omax / dmax, &e);
    scale = std::ldexp(1.0, e);
  }
  return origin + scale * direction;
}

TriangleHit intersect_ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& t0,
                                   const Vec3& t1, const Vec3& t2) {
  const Triangle tri{{&t0, &t1, &t2}};
  TriangleHit hit;
  const Vec3 q = ray_through_point(origin, direction);
  if (q == origin) return hit;  // zero direction: outside the contract
  const int so = orient3d(t0, t1, t2, origin);
  const int sq = orient3d(t0, t1, t2, q);
  if (so == 0 && sq == 0) return coplanar_hit(origin, q, direction, true, tri);
  const std::array<int, 3> pl = pluecker_signs(origin.data(), q.data(), tri);
  if (mixed_signs(pl)) return hit;
  // sum of the Pluecker volumes = n.(q - origin): all zero means parallel to the plane (and,
  // since so, sq are not both zero, off it); otherwise their common sign is the side toward
  // which the ray travels, and the ray reaches the plane iff the origin is not on that side.
  const int travel = pl[0] != 0 ? pl[0] : pl[1] != 0 ? pl[1] : pl[2];
  if (travel == 0 || so * travel > 0) return hit;
  hit.feature = feature_from_pluecker(pl);
  if (so == 0) {
    hit.contact = Contact::at_start;
    hit.point = origin;
    return hit;
  }
  hit.contact = Contact::crossing;
  const double t = plane_parameter(origin, direction, tri);
  hit.t = hit.t_exit = std::isfinite(t) ? std::max(t, 0.0) : 0.0;
  hit.point = snap_to_feature(origin + hit.t * direction, tri, hit.feature);
  return hit;
}

// ---------------------------------------------------------------------------------------------
// Segment and sphere
// ---------------------------------------------------------------------------------------------

SphereHits intersect_segment_sphere(const Vec3& a, const Vec3& b, const WeightedPoint& ball) {
  SphereHits h;
  h.side_a = power_distance_sign(a.data(), ball.data());
  h.side_b = power_distance_sign(b.data(), ball.data());
  auto push = [&h](double t) { h.t[h.count++] = t; };

  const Vec3 d = b - a;
  const double dd = d.squaredNorm();
  if (a == b) {
    if (h.side_a == 0) push(0);
    return h;
  }
  if (h.side_a < 0 && h.side_b < 0) return h;  // the ball is convex

  const Vec3 c = ball.point();
  const Vec3 f = a - c;
  // Endpoints on the sphere are exact roots; the other root of the quadratic follows from the
  // sum of the roots, -2 f.d / |d|^2, measured from the endpoint that is on the sphere.
  if (h.side_a == 0 || h.side_b == 0) {
    if (h.side_a == 0) push(0);
    if (h.side_a == 0 && h.side_b > 0) {
      const double other = -2 * f.dot(d) / dd;
      if (other > 0 && other < 1) push(other);
    }
    if (h.side_b == 0 && h.side_a > 0) {
      const double other = -2 * (b - c).dot(-d) / dd;  // from b towards a
      if (other > 0 && other < 1) push(1 - other);
    }
    if (h.side_b == 0) push(1);
    return h;
  }

  // a t^2 + 2 B t + C = 0 with a = |d|^2, B = f.d, C = |f|^2 - r^2; its reduced discriminant
  // B^2 - |d|^2 C equals |d|^2 r^2 - |f x d|^2 (Lagrange's identity), which has no cancellation
  // beyond the one inherent in |d| dist(c, line) ~ |d| r.
  const double B = f.dot(d);
  const double C = f.squaredNorm() - ball.w;
  const double disc = dd * ball.w - f.cross(d).squaredNorm();
  auto roots = [&](double dsc) {
    const double qv = -(B + std::copysign(std::sqrt(std::max(dsc, 0.0)), B));
    if (qv == 0) return std::array<double, 2>{-B / dd, -B / dd};
    const double r1 = qv / dd, r2 = C / qv;
    return std::array<double, 2>{std::min(r1, r2), std::max(r1, r2)};
  };

  if (h.side_a != h.side_b) {
    // One end strictly inside, the other strictly outside: exactly one root, in (0, 1).
    const std::array<double, 2> r = roots(disc);
    push(std::clamp(h.side_a < 0 ? r[1] : r[0], 0.0, 1.0));
    return h;
  }
  // Both ends strictly outside: the segment enters the ball only if the point of its line
  // closest to the centre lies strictly between them.
  const double closest = -B / dd;
  if (!(closest > 0 && closest < 1) || disc < 0) return h;
  if (disc == 0) {
    push(closest);
    return h;
  }
  const std::array<double, 2> r = roots(disc);
  push(std::clamp(r[0], 0.0, 1.0));
  push(std::clamp(r[1], 0.0, 1.0));
  return h;
}

// ---------------------------------------------------------------------------------------------
// Closest points
// ---------------------------------------------------------------------------------------------

ClosestOnSegment closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  ClosestOnSegment out;
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  out.t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  out.point = out.t == 1.0 ? b : Vec3(a + out.t * ab);
  return out;
}

namespace {

/// Closest point of edge k (from t_{k+1} to t_{k+2}) to p, as a triangle feature: the edge, or
/// one of its vertices when the projection is clamped to an end.
ClosestOnTriangle closest_on_edge(const Vec3& p, const Triangle& tri, int k) {
  const int u = next(k), v = after_next(k);
  const ClosestOnSegment s = closest_point_on_segment(p, tri[u], tri[v]);
  ClosestOnTriangle out;
  out.point = s.point;
  out.barycentric[u] = 1 - s.t;
  out.barycentric[v] = s.t;
  out.feature = s.t == 0 ? TriangleFeature{FeatureKind::vertex, u}
                : s.t == 1 ? TriangleFeature{FeatureKind::vertex, v}
                           : TriangleFeature{FeatureKind::edge, k};
  return out;
}

/// Closest point on the union of the three edges, by comparing distances: only for degenerate
/// (flat) triangles, where the region tests below have no normal to work with.
ClosestOnTriangle closest_on_edges(const Vec3& p, const Triangle& tri) {
  ClosestOnTriangle best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const ClosestOnTriangle c = closest_on_edge(p, tri, k);
    const double d2 = (c.point - p).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

}  // namespace

ClosestOnTriangle closest_point_on_triangle(const Vec3& p, const Vec3& t0, const Vec3& t1,
                                            const Vec3& t2) {
  const Triangle tri{{&t0, &t1, &t2}};
  const Vec3 n = (t1 - t0).cross(t2 - t0);
  const double nn = n.squaredNorm();
  if (!(nn > 0)) return closest_on_edges(p, tri);

  // side[k] = n.((t_{k+2} - t_{k+1}) x (p - t_{k+1})) = |n|^2 times the k-th barycentric
  // coordinate of p's projection on the plane: negative iff p is beyond the line of edge k.
  // Unlike the products of dot products of Ericson's version, whose error grows like kappa^2
  // for needle triangles, this loses only the direction of n, kappa eps.
  std::array<double, 3> side{};
  int beyond = 0;
  for (int k = 0; k < 3; ++k) {
    const Vec3& u = tri[next(k)];
    side[k] = n.dot((tri[after_next(k)] - u).cross(p - u));
    beyond += side[k] < 0;
  }
  if (beyond == 0) {
    ClosestOnTriangle out;
    out.point = p - (n.dot(p - t0) / nn) * n;
    const double sum = side[0] + side[1] + side[2];
    out.barycentric = Vec3(side[0], side[1], side[2]) / sum;
    out.feature = {FeatureKind::face, 0};
    return out;
  }
  // Beyond one edge line only: the closest point is on that edge (a constraint that p already
  // satisfies cannot be the only active one at the minimiser).
  if (beyond == 1) {
    const int k = side[0] < 0 ? 0 : side[1] < 0 ? 1 : 2;
    return closest_on_edge(p, tri, k);
  }
  if (beyond == 3) return closest_on_edges(p, tri);  // only through absurd rounding
  // Beyond the lines of both edges at vertex m: in that opposite wedge at most one of the two
  // edge directions from m has a positive dot product with p - t_m (Cauchy-Schwarz), and it
  // names the edge holding the closest point; neither means the vertex itself.
  const int m = side[0] >= 0 ? 0 : side[1] >= 0 ? 1 : 2;
  const Vec3 pm = p - tri[m];
  if (pm.dot(tri[after_next(m)] - tri[m]) > 0) return closest_on_edge(p, tri, next(m));
  if (pm.dot(tri[next(m)] - tri[m]) > 0) return closest_on_edge(p, tri, after_next(m));
  ClosestOnTriangle out;
  out.point = tri[m];
  out.barycentric[m] = 1;
  out.feature = {FeatureKind::vertex, m};
  return out;
}

}  // namespace delpsc::kernel
