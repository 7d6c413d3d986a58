// Exact geometric predicates on doubles, with one symbolic perturbation scheme.
//
// Every predicate returns the exact sign of a polynomial in its (double) inputs: -1, 0 or +1.
// Each first evaluates the polynomial in floating point next to a static error bound derived once
// (the constants below, derivations in predicates.cpp); only when the floating-point value is too
// close to zero to be trusted does it fall back to exact expansion arithmetic (expansion.h), so
// no rounding ever decides a combinatorial question.
//
// Range (documented once, checked by tests/oracle): the results are exact for every input whose
// coordinates are 0 or of magnitude in [2^-140, 2^140] and whose weights are 0 or of magnitude
// in [2^-280, 2^280]. Inside that range no product of the exact evaluation overflows or underflows
// (the largest polynomials have degree 5 in coordinates; weights count as degree 2). NaN and
// infinities are outside the contract: callers validate input (io/ rejects them).
//
// Sign conventions follow CGAL's kernel, so that a triangulation built on them can be compared
// with CGAL's Regular_triangulation_3 cell for cell:
//   orient3d(p,q,r,s)        = sign det[q-p; r-p; s-p]; +1 when p,q,r,s are positively oriented.
//   power_test(p,q,r,s,t)    = +1 when t is strictly inside the power sphere (orthosphere) of
//                              positively oriented p,q,r,s, i.e. t has negative power product
//                              with it ("t is in conflict"); -1 outside; flips with orientation.
//
// Symbolic perturbation (Devillers & Teillaud, "Perturbations for Delaunay and weighted Delaunay
// 3D triangulations", CGTA 44(3), 2011): the *weights* are perturbed, w_i - eps^(n-rank_i),
// where rank_i is the rank of point i in lexicographic (x, y, z) order. The perturbed power test
// is a polynomial in eps whose coefficients are orientations of subsets of the points; the
// *_perturbed functions return the sign of its first non-zero coefficient, looking at the
// lexicographically largest point first. The scheme depends only on the points, never on the
// order in which they are given or inserted, so the regular triangulation of a point set is
// unique, and it is the scheme of CGAL's Regular_triangulation_3 and Delaunay_triangulation_3.
// Orientations are not perturbed: the points themselves do not move, so orient3d may return 0 and
// the triangulation handles flat configurations through its dimension and its infinite vertex.
//
// Points are passed as pointers to 3 doubles (x, y, z); weighted points as pointers to 4
// doubles (x, y, z, w) with w = r^2 (WeightedPoint::data()). Overloads take Vec3/WeightedPoint.
//
// Cost: the filtered paths are a few dozen flops, inline; the exact paths allocate nothing
// for inputs of the documented range in practice (expansions live on the stack) and cost
// 1–20 µs. Thread-safe (the optional statistics counters are relaxed atomics).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "point.h"

namespace delpsc::kernel {

/// The range above, for callers that validate input: coordinates 0 or of magnitude in
/// [kMinExactMagnitude, kMaxExactMagnitude], weights 0 or of magnitude in [kMinExactWeight,
/// kMaxExactWeight].
inline constexpr double kMinExactMagnitude = 0x1p-140, kMaxExactMagnitude = 0x1p140;
inline constexpr double kMinExactWeight = 0x1p-280, kMaxExactWeight = 0x1p280;
/// Whether every coordinate of p is 0 or of magnitude in [kMinExactMagnitude,
/// kMaxExactMagnitude] (false for NaN and infinities): for a point a caller constructs and then
/// hands to the predicates.
inline bool in_exact_range(const Vec3& p) {
  for (int k = 0; k < 3; ++k) {
    const double m = std::fabs(p[k]);
    if (!(m == 0 || (kMinExactMagnitude <= m && m <= kMaxExactMagnitude))) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// Plain predicates (exact, may return 0)
// ---------------------------------------------------------------------------------------------

/// Lexicographic comparison of (x, y, z): -1, 0, +1. Exact by nature.
int compare_xyz(const double* p, const double* q);

/// sign det[q-p; r-p; s-p]: +1 if s lies on the side of plane (p,q,r) toward which
/// (q-p) x (r-p) points, -1 on the other side, 0 if the four points are coplanar.
inline int orient3d(const double* p, const double* q, const double* r, const double* s);

/// Orientation of the projections of p, q, r on coordinate axes (i, j), i != j in {0,1,2}:
/// sign((q_i-p_i)(r_j-p_j) - (q_j-p_j)(r_i-p_i)).
int orient2d(const double* p, const double* q, const double* r, int i, int j);

/// Orientation of three points within their plane, CGAL's coplanar_orientation: the first
/// non-zero orient2d among the projections on the xy, yz and xz planes; 0 iff p, q, r collinear.
int coplanar_orientation(const double* p, const double* q, const double* r);

/// For coplanar p, q, r, s with p, q, r not collinear: +1 if r and s lie on the same side of
/// line pq within the plane, -1 on opposite sides, 0 if s is on line pq (CGAL's 4-argument
/// coplanar_orientation).
int coplanar_orientation(const double* p, const double* q, const double* r, const double* s);

/// True iff p, q, r are collinear (exact).
bool collinear(const double* p, const double* q, const double* r);

/// Unweighted in-sphere test: +1 if t is strictly inside the sphere through positively oriented
/// p, q, r, s (-1 outside, 0 on it); the sign flips with the orientation of p, q, r, s.
/// Equal to power_test with all weights 0.
inline int insphere(const double* p, const double* q, const double* r, const double* s,
                    const double* t);

/// Power test of weighted t against the power sphere of weighted p, q, r, s (pointers to 4
/// doubles): +1 when t is in conflict (negative power product) for positively oriented p,q,r,s;
/// the lifted value |x|^2 - w is never rounded before use. CGAL: power_side_of_oriented_power_sphere.
inline int power_test(const double* p, const double* q, const double* r, const double* s,
                      const double* t);

/// Power test within a plane, for coplanar weighted p, q, r, t with p, q, r not collinear:
/// +1 when t is in conflict with the power circle of p, q, r (negative power product with the
/// smallest sphere orthogonal to them), -1 outside, 0 orthogonal. Independent of the order of
/// p, q, r: it is evaluated in the first coordinate projection (xy, then xz, then yz) where it is
/// non-zero, times the orientation of p, q, r there. CGAL: power_side_of_oriented_power_sphere_3
/// with 4 points.
int power_test(const double* p, const double* q, const double* r, const double* t);

/// Power test on a line, for collinear weighted p, q, t with p != q in position: +1 when t is in
/// conflict with the smallest sphere orthogonal to p and q, -1 outside, 0 orthogonal; symmetric
/// in p, q (evaluated on the first axis where they differ).
int power_test(const double* p, const double* q, const double* t);

/// Power test of two weighted points at the same position: sign(w_q - w_p), +1 when q would
/// hide p.
int power_test(const double* p, const double* q);

/// sign(|x - c|^2 - w_c): the sign of the power distance of unweighted x (3 doubles) to
/// weighted c (4 doubles). Negative iff x lies strictly inside the ball.
int power_distance_sign(const double* x, const double* c);

/// sign(pow(x, p) - pow(x, q)) for unweighted x and weighted p, q: which is power-closer.
int compare_power_distance(const double* x, const double* p, const double* q);

// ---------------------------------------------------------------------------------------------
// Perturbed predicates (never return 0); one scheme, described in the file comment.
// ---------------------------------------------------------------------------------------------

/// power_test(p,q,r,s,t) under the symbolic perturbation. Precondition: orient3d(p,q,r,s) > 0 and
/// t differs in position from p, q, r, s. Returns +1 (conflict) or -1.
int power_test_perturbed(const double* p, const double* q, const double* r, const double* s,
                         const double* t);

/// Within a plane: power_test(p,q,r,t) under the perturbation. Precondition: p, q, r, t coplanar,
/// coplanar_orientation(p,q,r) > 0, t differs in position from p, q, r. Returns +1 or -1.
int power_test_perturbed(const double* p, const double* q, const double* r, const double* t);

/// Within a plane, whatever the orientation of p, q, r (not collinear): +1 iff t is in conflict
/// with the power circle of p, q, r under the perturbation (CGAL's side_of_bounded_power_circle).
int power_circle_side_perturbed(const double* p, const double* q, const double* r, const double* t);

/// On a line: +1 iff collinear t is in conflict with the power segment of p != q under the
/// perturbation (CGAL's side_of_bounded_power_segment); t differs in position from p and q.
int power_segment_side_perturbed(const double* p, const double* q, const double* t);

/// insphere under the same perturbation (weights 0). Precondition: orient3d(p,q,r,s) > 0.
int insphere_perturbed(const double* p, const double* q, const double* r, const double* s,
                       const double* t);

// ---------------------------------------------------------------------------------------------
// Statistics (a DELPSC_STATISTICS build counts; otherwise the counters stay at zero)
// ---------------------------------------------------------------------------------------------

enum class Predicate : int {
  orient3d,
  orient2d,
  insphere,
  power_test_3d,
  power_test_2d,
  power_test_1d,
  power_distance,
  count
};

struct PredicateCounters {
  std::uint64_t calls = 0;            ///< evaluations
  std::uint64_t filter_failures = 0;  ///< evaluations that needed the exact path
};

/// True when the library was built with DELPSC_STATISTICS.
bool statistics_enabled();
/// Counters per predicate, indexed by Predicate.
std::array<PredicateCounters, static_cast<int>(Predicate::count)> predicate_statistics();
void reset_predicate_statistics();

// ---------------------------------------------------------------------------------------------
// Overloads on the value types
// ---------------------------------------------------------------------------------------------

inline int orient3d(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s) {
  return orient3d(p.data(), q.data(), r.data(), s.data());
}
inline int insphere(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, const Vec3& t) {
  return insphere(p.data(), q.data(), r.data(), s.data(), t.data());
}
inline int power_test(const WeightedPoint& p, const WeightedPoint& q, const WeightedPoint& r,
                      const WeightedPoint& s, const WeightedPoint& t) {
  return power_test(p.data(), q.data(), r.data(), s.data(), t.data());
}
inline int power_test_perturbed(const WeightedPoint& p, const WeightedPoint& q,
                                const WeightedPoint& r, const WeightedPoint& s,
                                const WeightedPoint& t) {
  return power_test_perturbed(p.data(), q.data(), r.data(), s.data(), t.data());
}

}  // namespace delpsc::kernel

#include "predicates_inline.h"
