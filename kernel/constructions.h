// Geometric constructions in double precision: orthocentres, intersection points, closest points.
//
// A construction computes a new point; its result becomes an input point (a Steiner vertex, an
// endpoint of a curve segment) and never decides a combinatorial question by itself. Where a
// construction must also *classify* (does this Voronoi edge cross this triangle, through which
// feature?), the classification is made with the exact predicates of predicates.h and only the
// point is computed in floating point, then snapped onto the feature the predicates chose. So two
// triangles sharing an edge always agree that a segment passes through that edge.
//
// Units: lengths in the units of the input coordinates, weights in squared length units.
// Notation used in the accuracy statements: eps = 2^-53 (unit roundoff of double), |.| the
// Euclidean norm. Every stated bound was measured against exact rational (GMP mpq) or 512-bit
// (mpf) references over random and near-degenerate inputs (slivers and needles with condition
// numbers up to 1e25, grazing segments, near-tangent spheres, configurations far from the
// origin) by tests/oracle/test_constructions_accuracy.cpp, which fails if any sample exceeds the
// stated constant; the measured worst case is quoted next to each, and the stated constants
// leave a margin of 2x or more above it.
//
// Every function is O(1), allocates nothing and is thread-safe. Inputs must be finite and within
// the range of predicates.h (coordinates 0 or of magnitude in [2^-140, 2^140]).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "point.h"

namespace delpsc::kernel {

// ---------------------------------------------------------------------------------------------
// Orthocentres (weighted circumcentres)
// ---------------------------------------------------------------------------------------------
//
// The orthocentre of weighted points p_0..p_k (k = 1, 2, 3) is the point c of their affine hull
// with equal power distance |c - p_i|^2 - w_i to all of them; that common value is its weight
// w_c, the squared radius of the smallest sphere orthogonal to all input spheres (negative when
// the point c is inside every input ball, i.e. no real orthogonal sphere exists). For k = 3 this
// is the dual Voronoi vertex of a cell of the regular triangulation; for k = 2 (resp. 1) the
// point of the dual Voronoi edge (resp. facet) closest to the affine hull. Returned as a
// WeightedPoint {c, w_c}.
//
// Method: translate to p_0 (e_i = p_i - p_0, computed once, exactly rounded), then the closed
// form solving 2 o.e_i = alpha_i, alpha_i = |e_i|^2 - w_i + w_0, o = c - p_0:
//   k = 3:  o = (alpha_1 e2 x e3 + alpha_2 e3 x e1 + alpha_3 e1 x e2) / (2 e1.(e2 x e3))
//   k = 2:  o = (alpha_1 e2 x n + alpha_2 n x e1) / (2 |n|^2),  n = e1 x e2
//   k = 1:  o = alpha_1 e1 / (2 |e1|^2)
// and w_c = |o|^2 - w_0. Degeneracy is decided by the exact predicates (orient3d = 0, collinear,
// equal positions): the functions then return nullopt, and also whenever the result would
// overflow, so a NaN or infinity is never returned.
//
// Accuracy (p_0 = first argument). Let kappa = |e1||e2||e3| / |e1.(e2 x e3)| (k = 3),
// |e1||e2| / |e1 x e2| (k = 2), 1 (k = 1) - the condition number of the simplex, 1 for a
// right-angled corner at p_0, large for slivers and needles - and
// S = |o| + max_i (|e_i| + |w_i - w_0| / |e_i|), about the circumradius plus the edge lengths for
// unweighted points. If kappa eps <= 1/16, the returned centre c~ and weight w~ satisfy
//     |c~ - c| <= delta := 6 eps kappa S + eps |c|
//         (measured: the first term at most 1.8 eps kappa S for k = 3, 1.9 for k = 2, 1.3 for
//          k = 1; the second is the final rounding of c = p_0 + o),
//     |w~ - w_c| <= (2 |o| + delta) delta + 4 eps (|o|^2 + |w_0|)   (measured at most 0.28 of it).
// The error is relative to the simplex, not to the coordinates, and grows only linearly with
// kappa (the Cramer forms are homogeneous in the cross products, so their rounding tilts rather
// than scales). Consequently the power distances of c~ to the inputs agree to within
// 2 max_i |e_i| delta, plus the rounding of evaluating them. A simplex flatter than that
// (kappa eps > 1/16, i.e. kappa above ~5.6e14) gets a centre that is finite but may be wrong by
// more than its own size - inherent to the problem, since the simplex is flat to working
// precision.

/// Orthocentre of two weighted points: the point of line p q with equal power distance to both
/// (the centre of the radical plane on the line), and that power distance as weight.
/// nullopt iff p and q have the same position (or on overflow).
std::optional<WeightedPoint> orthocentre(const WeightedPoint& p, const WeightedPoint& q);

/// Orthocentre of three weighted points, in their plane. nullopt iff they are collinear
/// (exact test) or on overflow.
std::optional<WeightedPoint> orthocentre(const WeightedPoint& p, const WeightedPoint& q,
                                         const WeightedPoint& r);

/// Orthocentre of four weighted points (the centre and weight of their orthogonal sphere).
/// nullopt iff they are coplanar (exact test) or on overflow.
std::optional<WeightedPoint> orthocentre(const WeightedPoint& p, const WeightedPoint& q,
                                         const WeightedPoint& r, const WeightedPoint& s);

// ---------------------------------------------------------------------------------------------
// Features of a triangle (t0, t1, t2)
// ---------------------------------------------------------------------------------------------

/// Which closed feature of a triangle a point lies on, smallest first: vertex k is t_k; edge k is
/// the edge opposite t_k, from t_{k+1} to t_{k+2} (indices mod 3), the edge on which the
/// barycentric coordinate of t_k vanishes - CGAL's convention for the facets of a cell.
enum class FeatureKind : std::uint8_t { vertex = 0, edge = 1, face = 2 };

struct TriangleFeature {
  FeatureKind kind = FeatureKind::face;
  int index = 0;  ///< vertex or edge number 0..2; 0 for the face
  friend bool operator==(const TriangleFeature&, const TriangleFeature&) = default;
};

// ---------------------------------------------------------------------------------------------
// Segment-triangle and ray-triangle intersection (exact classification, double point)
// ---------------------------------------------------------------------------------------------

/// How a segment [a, b] (or a ray from a) meets a closed triangle.
enum class Contact : std::uint8_t {
  none,        ///< no common point
  crossing,    ///< one common point, strictly between a and b, segment not in the plane
  at_start,    ///< a lies on the triangle, the segment is not in the plane (ray: the origin)
  at_end,      ///< b lies on the triangle, the segment is not in the plane (segments only)
  coplanar,    ///< the segment lies in the triangle's plane and meets the triangle
  degenerate,  ///< the triangle's vertices are collinear: nothing was decided
};

/// Result of intersect_segment_triangle / intersect_ray_triangle.
struct TriangleHit {
  Contact contact = Contact::none;
  /// The smallest feature of the triangle containing the common point (exact). Meaningful for
  /// crossing, at_start and at_end; for coplanar it is the face.
  TriangleFeature feature;
  /// Parameter of the common point along the segment: point = a + t (b - a), t in [0, 1]
  /// (ray: origin + t direction, t >= 0). Exactly 0 for at_start, exactly 1 for at_end.
  /// coplanar: the overlap is [t, t_exit].
  double t = 0;
  double t_exit = 0;  ///< coplanar: end of the overlap interval; otherwise equal to t
  /// The common point (coplanar: the first one, at t), computed in double and snapped onto the
  /// reported feature: exactly the vertex for a vertex; for an edge or the face, the closest
  /// point of that closed edge or triangle to the computed crossing (a projection on a convex
  /// set, so it never increases the error, however thin the triangle); exactly a (or b) for
  /// at_start (at_end).
  Vec3 point = Vec3::Zero();

  /// True when the segment meets the triangle (degenerate counts as no).
  explicit operator bool() const { return contact != Contact::none && contact != Contact::degenerate; }
};

/// Intersection of the closed segment [a, b] with the closed triangle (t0, t1, t2).
///
/// Classification (contact and feature) is exact: up to 4 orient3d calls when the segment does
/// not reach the triangle's plane, 5 when it does, plus orient2d calls in the coplanar case; the
/// signs of the three Pluecker volumes orient3d(a, b, t_{k+1}, t_{k+2}) tell through which
/// feature the line passes, and their sum is n.(b - a), n the triangle normal. A segment through
/// an edge shared by two triangles is therefore reported by both with kind edge and never missed.
/// A point-like segment (a == b) on the triangle is reported as coplanar with t = t_exit = 0.
/// The coplanar overlap [t, t_exit] is clipped in floating point (its existence is exact).
///
/// Accuracy of the point (crossing): with d = b - a, n = (t1 - t0) x (t2 - t0), diam the longest
/// edge, the distance to the exact intersection point x is at most
///     4 eps (|t1 - t0| |t2 - t0| |d| (|a - t0| + |b - t0|) / |n.d| + 2 diam + |x|)
/// (measured at most 1.0 eps times the bracket; 1.7 for rays): about eps kappa times the
/// distance of the ends from the triangle divided by the sine of the segment's angle with it.
TriangleHit intersect_segment_triangle(const Vec3& a, const Vec3& b, const Vec3& t0,
                                       const Vec3& t1, const Vec3& t2);

/// Whether the closed segment [a, b] meets the closed triangle (t0, t1, t2) when the caller knows
/// all five points to be coplanar (orient3d zero): the decision intersect_segment_triangle makes
/// in that case, without its two orient3d, which are exactly zero and so always reach exact
/// arithmetic. Exact (orient2d on the projection the triangle's normal picks); false for a
/// degenerate triangle. Unspecified when the points are not coplanar.
bool coplanar_segment_meets_triangle(const Vec3& a, const Vec3& b, const Vec3& t0, const Vec3& t1,
                                     const Vec3& t2);

/// Intersection of the ray {origin + t direction, t >= 0} with the closed triangle.
///
/// Precondition: direction != 0. The ray is classified exactly as the ray from origin through the
/// point q = origin + s direction, s a power of two chosen from origin and direction only (so
/// that |s direction| >= |origin| in the max norm): q is exact whenever that sum is representable
/// (e.g. small integers), and otherwise the ray's direction is rounded by at most ~eps radians.
/// Because s depends only on the ray, every triangle of a mesh sees the same ray, so a ray
/// through a shared edge is reported by both triangles. contact is never at_end; t is in units of
/// direction. Accuracy of the point as for segments, with b := q.
TriangleHit intersect_ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& t0,
                                   const Vec3& t1, const Vec3& t2);

/// The second point q that intersect_ray_triangle uses to represent the ray (see there).
Vec3 ray_through_point(const Vec3& origin, const Vec3& direction);

// ---------------------------------------------------------------------------------------------
// Segment-sphere intersection
// ---------------------------------------------------------------------------------------------

/// The parameters t in [0, 1] at which a + t (b - a) lies on the sphere bounding `ball`
/// (centre (x, y, z), squared radius w), in increasing order.
struct SphereHits {
  int count = 0;                   ///< 0, 1 or 2 (a tangent point is counted once)
  std::array<double, 2> t = {0, 0};  ///< t[0] <= t[1]; only the first `count` are meaningful
  /// Exact signs of the power distance |x - centre|^2 - w of the endpoints: -1 inside the ball,
  /// 0 on the sphere, +1 outside. A curve leaves the ball between a and b iff side_a <= 0 < side_b.
  int side_a = 0, side_b = 0;
};

/// Intersection of the segment [a, b] with the sphere of a ball (weight = squared radius > 0).
///
/// Which roots exist is decided from the exact sides of a and b wherever that suffices: one
/// endpoint strictly inside and one strictly outside always gives exactly one root, an endpoint on
/// the sphere gives the root 0 (or 1) exactly, both inside gives none. Only when both endpoints
/// are outside does the count (0, 1 tangent, 2) come from the floating-point discriminant,
/// computed without cancellation as |d|^2 r^2 - |f x d|^2 (f = a - centre, d = b - a), and the
/// roots from the stable q = -(B + sign(B) sqrt(disc)) form; near tangency the count is only as
/// good as that discriminant.
///
/// Accuracy: each returned t differs from an exact root by at most
///     4 eps ((r^2 + |f|^2) / h + |f| + r) / |d|,      h = half-chord sqrt(r^2 - dist(centre, line)^2)
/// (measured at most 1.8 eps times the bracket): relative accuracy for transversal crossings,
/// degrading like 1/h as the segment approaches tangency, which is inherent.
SphereHits intersect_segment_sphere(const Vec3& a, const Vec3& b, const WeightedPoint& ball);

// ---------------------------------------------------------------------------------------------
// Closest points
// ---------------------------------------------------------------------------------------------

struct ClosestOnSegment {
  Vec3 point = Vec3::Zero();
  double t = 0;  ///< point = a + t (b - a), t in [0, 1]; 0 when a == b
};

/// Closest point of the segment [a, b] to p (the clamped projection; exactly a or b when clamped).
/// Accuracy: within 4 eps (|p - a| + |b - a|) + eps |x| of the exact closest point x (measured
/// first term at most 1.2 eps (|p - a| + |b - a|)).
ClosestOnSegment closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b);

struct ClosestOnTriangle {
  Vec3 point = Vec3::Zero();
  /// Barycentric coordinates of point, each >= 0, sum 1 (to rounding; for a needle triangle
  /// they are ill-conditioned, the point is not).
  Vec3 barycentric = Vec3::Zero();
  TriangleFeature feature;  ///< the feature whose Voronoi region (normal cone) contains p
};

/// Closest point of the closed triangle (t0, t1, t2) to p, by the Voronoi-region method (Ericson,
/// Real-Time Collision Detection, 5.1.5): find the feature whose region contains p, then project
/// p on it. Ericson's region tests multiply dot products, which loses kappa^2 eps for needle
/// triangles; here the side of each edge line is the triple product n.(edge x (p - t)), and the
/// vertex regions are told apart by one dot product, so only the direction of n is uncertain.
/// The region is decided in floating point, so near a region boundary it may be the neighbouring
/// one; the point is continuous across those boundaries, so this does not affect its accuracy:
/// within 8 eps kappa (|p - t0| + diam) + eps |x| of the exact closest point x, kappa =
/// |e1||e2|/|e1 x e2| the triangle's condition number (measured first term at most
/// 3.4 eps kappa (|p - t0| + diam)). A degenerate (collinear) triangle is handled as the union of
/// its edges.
ClosestOnTriangle closest_point_on_triangle(const Vec3& p, const Vec3& t0, const Vec3& t1,
                                            const Vec3& t2);

}  // namespace delpsc::kernel
