// Exact paths of the predicates, the lower-dimensional predicates, and the symbolic perturbation.
//
// Error bounds of the filters (first-order forward analysis, u = 2^-53 the unit roundoff).
// Notation: a computed quantity x~ with |x~ - x| <= k u X carries "k u" relative to its magnitude
// bound X. Leaves are the coordinate differences, each correctly rounded: 1u, magnitude M_col
// (the largest |difference| of that column). A product adds the factors' k's plus 1; a sum takes
// the larger k plus 1 and adds the magnitudes.
//   orient3d:  2x2 minor 4u (mag 2MyMz); times a leaf 6u (2MxMyMz); sum of three 8u (6MxMyMz):
//              error <= 48u MxMyMz.                                      -> 49u with slack.
//   insphere / 5-point power test: xy-minors 4u (2MxMy); 3x3 minors 8u (6MxMyMz); lift
//              dx^2+dy^2+dz^2 (+ weight difference) 6u relative to ML, the largest row value of
//              |d_i|^2 + |w_t - w_i| (<= Mx^2+My^2+Mz^2+Mw; it bounds each lift and its error); lift * minor
//              15u (6 MxMyMz ML); two levels of sums 17u (24 MxMyMz ML):
//              error <= 408u MxMyMz ML.                                  -> 416u with slack.
//   orient2d:  4u on 2MiMj: error <= 8u MiMj.                            -> 9u.
//   4-point (planar) power test: (a,b)-minors 4u (2MaMb); lift 6u (ML); products 11u; sum of
//              three 13u (6 MaMb ML): error <= 78u MaMb ML.              -> 80u.
//   3-point (linear) power test: products 8u, difference 9u (2 Ma ML):
//              error <= 18u Ma ML.                                       -> 20u.
//   power distance: |d|^2 - w: 6u on (|d|^2 + |w|).                      -> 7u.
//   compare power distances: 7u on the sum of both magnitudes.           -> 8u.
// The slack absorbs second-order terms, the rounding of the bound's own product, and maxima taken
// over rounded differences. Range: coordinates 0 or |x| in [2^-140, 2^140] give differences 0 or
// in [2^-192, 2^141]; degree-5 products then stay in [2^-960, 2^705], normal doubles, so neither
// the filters nor the exact expansions (whose two_product tails would otherwise underflow) can be
// wrong. Weights 0 or |w| in [2^-280, 2^280] keep the lift terms inside the same window.
#include "predicates.h"

#include <algorithm>
#include <atomic>
#include <utility>

#include "expansion.h"
#include "power_test_stages.h"

namespace delpsc::kernel {

using exact::Expansion;

namespace {

constexpr double u = detail::kUnitRoundoff;
constexpr double kOrient2dBound = 9 * u;
constexpr double kPlanarPowerBound = 80 * u;
constexpr double kLinearPowerBound = 20 * u;
constexpr double kPowerDistanceBound = 7 * u;
constexpr double kComparePowerBound = 8 * u;

#ifdef DELPSC_STATISTICS
std::atomic<std::uint64_t> g_calls[static_cast<int>(Predicate::count)];
std::atomic<std::uint64_t> g_failures[static_cast<int>(Predicate::count)];
#endif

inline void count_call([[maybe_unused]] Predicate which, [[maybe_unused]] bool failed) {
  DELPSC_COUNT(which, failed);
}

// ---- exact building blocks ----------------------------------------------------------------

Expansion det2(const Expansion& a, const Expansion& b, const Expansion& c, const Expansion& d) {
  return a * d - b * c;  // | a b ; c d |
}

// Determinant of rows (a0 a1 a2), (b0 b1 b2), (c0 c1 c2) by cofactors along the last column.
Expansion det3(const Expansion* a, const Expansion* b, const Expansion* c) {
  Expansion r = a[2] * det2(b[0], b[1], c[0], c[1]) - b[2] * det2(a[0], a[1], c[0], c[1]) +
                c[2] * det2(a[0], a[1], b[0], b[1]);
  r.compress();
  return r;
}

// The translated coordinates x_k - t_k of a point, as exact expansions.
struct ExactRow {
  Expansion c[4];  // three coordinates and, when used, the lift
};

ExactRow translated(const double* p, const double* t, int dims) {
  ExactRow row;
  for (int k = 0; k < dims; ++k) row.c[k] = Expansion::difference(p[k], t[k]);
  return row;
}

// |p - t|^2 (+ w_t - w_p when weighted), never rounded.
Expansion exact_lift(const double* p, const double* t, bool weighted) {
  Expansion l;
  for (int k = 0; k < 3; ++k) {
    const Expansion d = Expansion::difference(p[k], t[k]);
    l = l + d * d;
  }
  if (weighted) l = l + Expansion::difference(t[3], p[3]);
  l.compress();
  return l;
}

int exact_orient2d(const double* p, const double* q, const double* r, int i, int j) {
  const Expansion qi = Expansion::difference(q[i], p[i]), qj = Expansion::difference(q[j], p[j]);
  const Expansion ri = Expansion::difference(r[i], p[i]), rj = Expansion::difference(r[j], p[j]);
  return det2(qi, qj, ri, rj).sign();
}

int filtered_orient2d(const double* p, const double* q, const double* r, int i, int j) {
  const double ai = q[i] - p[i], aj = q[j] - p[j], bi = r[i] - p[i], bj = r[j] - p[j];
  const double det = ai * bj - aj * bi;
  const double bound = kOrient2dBound * std::max(std::fabs(ai), std::fabs(bi)) *
                       std::max(std::fabs(aj), std::fabs(bj));
  // bound == 0: a column of differences is zero and det = ai*bj - aj*bi is exactly zero.
  const bool decided = det > bound || det < -bound || bound == 0;
  count_call(Predicate::orient2d, !decided);
  if (decided) return (det > 0) - (det < 0);
  return exact_orient2d(p, q, r, i, j);
}

// Planar power test projected on axes (a, b): sign of det rows (da, db, lift) of p, q, r
// translated by t; 2 when undecided by the filter.
int planar_power_filter(const double* p, const double* q, const double* r, const double* t, int a,
                        int b) {
  const double* pts[3] = {p, q, r};
  double da[3], db[3], lift[3];
  double ma = 0, mb = 0, ml = 0;
  double mxyz[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    const double dx = pts[i][0] - t[0], dy = pts[i][1] - t[1], dz = pts[i][2] - t[2];
    const double dw = t[3] - pts[i][3];
    const double d[3] = {dx, dy, dz};
    lift[i] = dx * dx + dy * dy + dz * dz + dw;
    da[i] = d[a];
    db[i] = d[b];
    ma = std::max(ma, std::fabs(d[a]));
    mb = std::max(mb, std::fabs(d[b]));
    for (int k = 0; k < 3; ++k) mxyz[k] = std::max(mxyz[k], std::fabs(d[k]));
    ml = std::max(ml, std::fabs(dw));
  }
  ml += mxyz[0] * mxyz[0] + mxyz[1] * mxyz[1] + mxyz[2] * mxyz[2];
  const double det = lift[0] * (da[1] * db[2] - da[2] * db[1]) -
                     lift[1] * (da[0] * db[2] - da[2] * db[0]) +
                     lift[2] * (da[0] * db[1] - da[1] * db[0]);
  const double bound = kPlanarPowerBound * ma * mb * ml;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 2;
}

int planar_power_exact(const double* p, const double* q, const double* r, const double* t, int a,
                       int b) {
  const double* pts[3] = {p, q, r};
  Expansion rows[3][3];
  for (int i = 0; i < 3; ++i) {
    rows[i][0] = Expansion::difference(pts[i][a], t[a]);
    rows[i][1] = Expansion::difference(pts[i][b], t[b]);
    rows[i][2] = exact_lift(pts[i], t, true);
  }
  return det3(rows[0], rows[1], rows[2]).sign();
}

int planar_power_sign(const double* p, const double* q, const double* r, const double* t, int a,
                      int b) {
  const int f = planar_power_filter(p, q, r, t, a, b);
  count_call(Predicate::power_test_2d, f == 2);
  return f != 2 ? f : planar_power_exact(p, q, r, t, a, b);
}

// Linear power test projected on axis a: sign(dp_a * lift_q - dq_a * lift_p).
int linear_power_sign(const double* p, const double* q, const double* t, int a) {
  const double dpa = p[a] - t[a], dqa = q[a] - t[a];
  double lp = 0, lq = 0, m2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double dp = p[k] - t[k], dq = q[k] - t[k];
    lp += dp * dp;
    lq += dq * dq;
    m2 += std::max(dp * dp, dq * dq);
  }
  const double wp = t[3] - p[3], wq = t[3] - q[3];
  lp += wp;
  lq += wq;
  const double det = dpa * lq - dqa * lp;
  const double bound = kLinearPowerBound * std::max(std::fabs(dpa), std::fabs(dqa)) *
                       (m2 + std::max(std::fabs(wp), std::fabs(wq)));
  if (det > bound) {
    count_call(Predicate::power_test_1d, false);
    return 1;
  }
  if (det < -bound) {
    count_call(Predicate::power_test_1d, false);
    return -1;
  }
  count_call(Predicate::power_test_1d, true);
  const Expansion ea = Expansion::difference(p[a], t[a]), eb = Expansion::difference(q[a], t[a]);
  return (ea * exact_lift(q, t, true) - eb * exact_lift(p, t, true)).sign();
}

}  // namespace

// ---- exact paths of the inline filters ----------------------------------------------------

namespace detail {

#ifdef DELPSC_STATISTICS
void count(Predicate which, bool filter_failed) {
  g_calls[static_cast<int>(which)].fetch_add(1, std::memory_order_relaxed);
  if (filter_failed) g_failures[static_cast<int>(which)].fetch_add(1, std::memory_order_relaxed);
}
#endif

// orient3d when the filter cannot decide. Most such calls have four points exactly coplanar (the
// flat regions of CAD models: neighbouring input triangles tested by the self-intersection check,
// ~20,000 calls on fandisk) and coordinates close enough that every difference q_k - p_k is a
// double with no rounding (Sterbenz). Then the 3x3 determinant of doubles is exact in short
// expansions on the stack: each 2x2 minor two products (four components), scaled by the third
// entry (eight), the three summed (24): ~600 instructions a call under callgrind, against
// ~3,100 for the general path's products of two-component differences in Expansion objects.
// Any rounded difference takes the general path.
int orient3d_exact(const double* p, const double* q, const double* r, const double* s) {
  double d[3][3];
  bool exact_differences = true;
  const double* rows[3] = {q, r, s};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      double tail;
      exact::two_diff(rows[i][k], p[k], d[i][k], tail);
      exact_differences = exact_differences && tail == 0;
    }
  if (exact_differences) {
    // Cofactors along the last column, as det3 below: rows i, j of the (x, y) columns, scaled
    // by the z entry of the third row k.
    double scaled[3][8];
    std::uint32_t len[3];
    const int cofactor[3][3] = {{1, 2, 0}, {0, 2, 1}, {0, 1, 2}};
    for (int c = 0; c < 3; ++c) {
      const auto [i, j, k] = cofactor[c];
      double plus[2], minus[2], minor[4];
      exact::two_product(d[i][0], d[j][1], plus[1], plus[0]);
      exact::two_product(d[i][1], d[j][0], minus[1], minus[0]);
      const std::uint32_t m = exact::sum_expansions(plus, 2, minus, 2, -1.0, minor);
      len[c] = exact::scale_expansion(minor, m, c == 1 ? -d[k][2] : d[k][2], scaled[c]);
    }
    double two[16], det[24];
    const std::uint32_t n2 = exact::sum_expansions(scaled[0], len[0], scaled[1], len[1], 1.0, two);
    const std::uint32_t n3 = exact::sum_expansions(two, n2, scaled[2], len[2], 1.0, det);
    return n3 == 0 ? 0 : (det[n3 - 1] > 0 ? 1 : -1);
  }
  const ExactRow a = translated(q, p, 3), b = translated(r, p, 3), c = translated(s, p, 3);
  return det3(a.c, b.c, c.c).sign();
}

int power_test_exact(const double* p, const double* q, const double* r, const double* s,
                     const double* t, bool weighted) {
  const double* pts[4] = {p, q, r, s};
  // Cheaper stages first (power_test_stages.cpp); each returns 2 when it cannot decide.
  if (const int v = power_test_integer(pts, t, weighted); v != 2) return v;
  if (const int v = power_test_double_double(pts, t, weighted); v != 2) return v;
  return power_test_expansion(pts, t, weighted);
}

int power_test_expansion(const double* const pts[4], const double* t, bool weighted) {
  ExactRow rows[4];
  for (int i = 0; i < 4; ++i) {
    rows[i] = translated(pts[i], t, 3);
    rows[i].c[3] = exact_lift(pts[i], t, weighted);
  }
  // The six 2x2 minors of the (x, y) columns are shared by the four 3x3 minors: computing them
  // once halves the work of the exact path (as in the filter and in Shewchuk's insphere).
  const auto xy = [&](int i, int j) {
    return det2(rows[i].c[0], rows[i].c[1], rows[j].c[0], rows[j].c[1]);
  };
  const Expansion m01 = xy(0, 1), m02 = xy(0, 2), m03 = xy(0, 3), m12 = xy(1, 2), m13 = xy(1, 3),
                  m23 = xy(2, 3);
  const auto z = [&](int i) -> const Expansion& { return rows[i].c[2]; };
  // 3x3 minors by cofactors along z: M(ijk) = z_i m_jk - z_j m_ik + z_k m_ij.
  const auto minor3 = [&](int i, int j, int k, const Expansion& mjk, const Expansion& mik,
                          const Expansion& mij) {
    Expansion m = z(i) * mjk - z(j) * mik + z(k) * mij;
    m.compress();
    return m;
  };
  const Expansion m_pqr = minor3(0, 1, 2, m12, m02, m01);
  const Expansion m_pqs = minor3(0, 1, 3, m13, m03, m01);
  const Expansion m_prs = minor3(0, 2, 3, m23, m03, m02);
  const Expansion m_qrs = minor3(1, 2, 3, m23, m13, m12);
  // Cofactors along the lift column: det = -L_p M(qrs) + L_q M(prs) - L_r M(pqs) + L_s M(pqr).
  const Expansion det = (rows[3].c[3] * m_pqr - rows[2].c[3] * m_pqs) +
                        (rows[1].c[3] * m_prs - rows[0].c[3] * m_qrs);
  return -det.sign();
}

}  // namespace detail

// ---- plain predicates -----------------------------------------------------------------------

int compare_xyz(const double* p, const double* q) {
  for (int k = 0; k < 3; ++k) {
    if (p[k] < q[k]) return -1;
    if (p[k] > q[k]) return 1;
  }
  return 0;
}

int orient2d(const double* p, const double* q, const double* r, int i, int j) {
  return filtered_orient2d(p, q, r, i, j);
}

int coplanar_orientation(const double* p, const double* q, const double* r) {
  // CGAL's order of projections: xy, then yz, then xz.
  if (const int o = orient2d(p, q, r, 0, 1); o != 0) return o;
  if (const int o = orient2d(p, q, r, 1, 2); o != 0) return o;
  return orient2d(p, q, r, 0, 2);
}

int coplanar_orientation(const double* p, const double* q, const double* r, const double* s) {
  if (const int o = orient2d(p, q, r, 0, 1); o != 0) return o * orient2d(p, q, s, 0, 1);
  if (const int o = orient2d(p, q, r, 1, 2); o != 0) return o * orient2d(p, q, s, 1, 2);
  const int o = orient2d(p, q, r, 0, 2);
  return o * orient2d(p, q, s, 0, 2);
}

bool collinear(const double* p, const double* q, const double* r) {
  return coplanar_orientation(p, q, r) == 0;
}

int power_test(const double* p, const double* q, const double* r, const double* t) {
  // CGAL's order here differs from coplanar_orientation's: xy, then xz, then yz. The first
  // projection in which the lifted determinant is non-zero decides, times the orientation of
  // p, q, r in it; a projection in which p, q, r are collinear has a zero determinant (t is in
  // the same plane), so it never decides. The result does not depend on the order of p, q, r.
  static constexpr int kAxes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (const auto& ax : kAxes) {
    // A projection in which p, q, r are collinear has an exactly zero lifted determinant; the
    // cheap orientation says so at once, where the lifted filter could only fail and go exact.
    const int o = orient2d(p, q, r, ax[0], ax[1]);
    if (o == 0) continue;
    const int cmp = planar_power_sign(p, q, r, t, ax[0], ax[1]);
    if (cmp != 0) return cmp * o;
  }
  return 0;
}

int power_test(const double* p, const double* q, const double* t) {
  // Project on the first axis where p and q differ; compare(p_a, q_a) orients the result.
  for (int a = 0; a < 3; ++a) {
    if (p[a] != q[a]) {
      const int cmp = p[a] < q[a] ? -1 : 1;
      return cmp * linear_power_sign(p, q, t, a);
    }
  }
  return 0;  // p == q: precondition violated; no side.
}

int power_test(const double* p, const double* q) {
  return (q[3] > p[3]) - (q[3] < p[3]);
}

int power_distance_sign(const double* x, const double* c) {
  const double dx = x[0] - c[0], dy = x[1] - c[1], dz = x[2] - c[2];
  const double d2 = dx * dx + dy * dy + dz * dz;
  const double v = d2 - c[3];
  const double bound = kPowerDistanceBound * (d2 + std::fabs(c[3]));
  const bool decided = v > bound || v < -bound;
  count_call(Predicate::power_distance, !decided);
  if (decided) return v > 0 ? 1 : -1;
  Expansion l;
  for (int k = 0; k < 3; ++k) {
    const Expansion d = Expansion::difference(x[k], c[k]);
    l = l + d * d;
  }
  return (l - Expansion(c[3])).sign();
}

int compare_power_distance(const double* x, const double* p, const double* q) {
  double dp2 = 0, dq2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double a = x[k] - p[k], b = x[k] - q[k];
    dp2 += a * a;
    dq2 += b * b;
  }
  const double v = (dp2 - p[3]) - (dq2 - q[3]);
  const double bound = kComparePowerBound * (dp2 + std::fabs(p[3]) + dq2 + std::fabs(q[3]));
  const bool decided = v > bound || v < -bound;
  count_call(Predicate::power_distance, !decided);
  if (decided) return v > 0 ? 1 : -1;
  Expansion e;
  for (int k = 0; k < 3; ++k) {
    const Expansion a = Expansion::difference(x[k], p[k]), b = Expansion::difference(x[k], q[k]);
    e = e + (a * a - b * b);
  }
  return (e - Expansion::difference(p[3], q[3])).sign();
}

// ---- perturbed predicates (Devillers & Teillaud 2011) ---------------------------------------
//
// With the weights perturbed to w_i - eps^(n - rank_i), the determinant of the power test is
// det + sum_i (+-) eps^(n - rank_i) * (cofactor of the lift entry of point i). Cofactors are
// orientations of the other points, so the first non-zero term, in decreasing order of eps
// powers' dominance (the lexicographically largest point first), is an orientation. For the query
// point the cofactor is the orientation of p0..p3 itself (positive by precondition), which means
// "outside" (-1). The paper shows that at most three terms are ever needed (the four other points
// of a finite cell are not coplanar); the loops below run over all points and stop at the first
// non-zero cofactor. The same scheme, one dimension down, with coplanar orientations, serves the
// planar test; on a line it reduces to "strictly between the two lexicographically".

namespace {

template <int N>
void sort_lexicographic(const double* (&pts)[N]) {
  std::sort(pts, pts + N, [](const double* a, const double* b) { return compare_xyz(a, b) < 0; });
}

}  // namespace

namespace {

// The 3D tie-break: called only when the unperturbed 5-point determinant is exactly zero.
// Looks at the points from the lexicographically largest down; the cofactor of point x's lift
// entry is the orientation of the four others with x replaced by the query point.
int perturbed_tiebreak_3d(const double* p0, const double* p1, const double* p2, const double* p3,
                          const double* p) {
  const double* pts[5] = {p0, p1, p2, p3, p};
  sort_lexicographic(pts);
  for (int i = 4; i >= 0; --i) {
    const double* x = pts[i];
    if (x == p) return -1;  // cofactor = orient3d(p0,p1,p2,p3) > 0: p is outside
    int o = 0;
    if (x == p3) o = orient3d(p0, p1, p2, p);
    else if (x == p2) o = orient3d(p0, p1, p, p3);
    else if (x == p1) o = orient3d(p0, p, p2, p3);
    else if (x == p0) o = orient3d(p, p1, p2, p3);
    if (o != 0) return o;
  }
  return -1;  // unreachable for valid input (p0..p3 positively oriented)
}

}  // namespace

int power_test_perturbed(const double* p0, const double* p1, const double* p2, const double* p3,
                         const double* p) {
  const int os = power_test(p0, p1, p2, p3, p);
  return os != 0 ? os : perturbed_tiebreak_3d(p0, p1, p2, p3, p);
}

int insphere_perturbed(const double* p0, const double* p1, const double* p2, const double* p3,
                       const double* p) {
  // With all weights zero the perturbed determinant is the same polynomial in eps.
  const int os = insphere(p0, p1, p2, p3, p);
  return os != 0 ? os : perturbed_tiebreak_3d(p0, p1, p2, p3, p);
}

int power_test_perturbed(const double* p0, const double* p1, const double* p2, const double* p) {
  const int os = power_test(p0, p1, p2, p);
  if (os != 0) return os;
  const double* pts[4] = {p0, p1, p2, p};
  sort_lexicographic(pts);
  for (int i = 3; i >= 0; --i) {
    const double* x = pts[i];
    if (x == p) return -1;
    int o = 0;
    if (x == p2) o = coplanar_orientation(p0, p1, p);
    else if (x == p1) o = coplanar_orientation(p0, p, p2);
    else if (x == p0) o = coplanar_orientation(p, p1, p2);
    if (o != 0) return o;
  }
  return -1;
}

int power_circle_side_perturbed(const double* p0, const double* p1, const double* p2,
                                const double* p) {
  if (coplanar_orientation(p0, p1, p2) > 0) return power_test_perturbed(p0, p1, p2, p);
  return power_test_perturbed(p0, p2, p1, p);
}

int power_segment_side_perturbed(const double* p0, const double* p1, const double* p) {
  const int os = power_test(p0, p1, p);
  if (os != 0) return os;
  // On the boundary: p is inside iff it lies strictly between p0 and p1 (lexicographically),
  // CGAL's collinear_position rule.
  const int ps = compare_xyz(p, p0);
  const int st = compare_xyz(p0, p1);
  if (ps == 0 || ps == st) return -1;  // at or before the source
  const int pt = compare_xyz(p, p1);
  if (pt == st) return 1;              // strictly between
  return -1;                           // at or after the target
}

// ---- statistics ---------------------------------------------------------------------------------

bool statistics_enabled() {
#ifdef DELPSC_STATISTICS
  return true;
#else
  return false;
#endif
}

std::array<PredicateCounters, static_cast<int>(Predicate::count)> predicate_statistics() {
  std::array<PredicateCounters, static_cast<int>(Predicate::count)> out{};
#ifdef DELPSC_STATISTICS
  for (int i = 0; i < static_cast<int>(Predicate::count); ++i) {
    out[i].calls = g_calls[i].load(std::memory_order_relaxed);
    out[i].filter_failures = g_failures[i].load(std::memory_order_relaxed);
  }
#endif
  return out;
}

void reset_predicate_statistics() {
#ifdef DELPSC_STATISTICS
  for (int i = 0; i < static_cast<int>(Predicate::count); ++i) {
    g_calls[i].store(0, std::memory_order_relaxed);
    g_failures[i].store(0, std::memory_order_relaxed);
  }
#endif
}

}  // namespace delpsc::kernel
