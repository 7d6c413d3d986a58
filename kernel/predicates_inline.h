// Inline floating-point filters of the hottest predicates (orient3d, insphere, power_test with
// five points). Included by predicates.h; not a public header of its own.
//
// Each filter evaluates the determinant in double next to a static error bound
//   |computed − exact| <= C * (product of per-column maxima of |differences|),
// with C derived once by forward error analysis (derivations in predicates.cpp, next to the exact
// paths). Within the documented input range no intermediate overflows and no product underflows
// far enough to matter, so a value beyond the bound has the sign of the exact value. Otherwise the
// exact path (expansion arithmetic) decides.
#pragma once

#include <algorithm>
#include <cmath>

namespace delpsc::kernel {

namespace detail {

/// Unit roundoff of binary64.
inline constexpr double kUnitRoundoff = 0x1p-53;
/// orient3d: 48u first order (six triple products, see predicates.cpp) plus slack for the
/// rounding of the bound itself and second-order terms.
inline constexpr double kOrient3dBound = 49 * kUnitRoundoff;
/// insphere / 5-point power test: 408u first order, 416u with slack.
inline constexpr double kInsphereBound = 416 * kUnitRoundoff;

int orient3d_exact(const double* p, const double* q, const double* r, const double* s);
int power_test_exact(const double* p, const double* q, const double* r, const double* s,
                     const double* t, bool weighted);

#ifdef DELPSC_STATISTICS
void count(Predicate which, bool filter_failed);
#define DELPSC_COUNT(which, failed) ::delpsc::kernel::detail::count(which, failed)
#else
#define DELPSC_COUNT(which, failed) ((void)0)
#endif

inline double max_abs3(double a, double b, double c) {
  return std::max(std::max(std::fabs(a), std::fabs(b)), std::fabs(c));
}
inline double max_abs4(double a, double b, double c, double d) {
  return std::max(max_abs3(a, b, c), std::fabs(d));
}

// Shared by insphere and the 5-point power test: rows are p,q,r,s translated by -t, columns
// (x, y, z, lift); lift_i = |p_i - t|^2 + (w_t - w_i) when weighted. Returns the *negated*
// determinant's sign (CGAL's convention: +1 = conflict for positively oriented p,q,r,s), or 2
// when the filter cannot decide.
//
// Written for speed on the filter path (bench_predicates, BENCHMARKS.md): the column maxima are
// taken right after the differences, which are live then anyway (taken last, they kept all twelve
// alive across the minors and GCC spilled them); ML is the largest lift magnitude row by row, a
// bound at most the column-wise Mx^2+My^2+Mz^2+Mw of the derivation, so the same constant holds;
// and the sign leaves through one branch that is almost always taken, because on general input
// the sign itself is a coin toss no branch predictor learns.
template <bool Weighted>
inline int power_test_filter(const double* p, const double* q, const double* r, const double* s,
                             const double* t) {
  const double dpx = p[0] - t[0], dpy = p[1] - t[1], dpz = p[2] - t[2];
  const double dqx = q[0] - t[0], dqy = q[1] - t[1], dqz = q[2] - t[2];
  const double drx = r[0] - t[0], dry = r[1] - t[1], drz = r[2] - t[2];
  const double dsx = s[0] - t[0], dsy = s[1] - t[1], dsz = s[2] - t[2];
  const double mx = max_abs4(dpx, dqx, drx, dsx);
  const double my = max_abs4(dpy, dqy, dry, dsy);
  const double mz = max_abs4(dpz, dqz, drz, dsz);

  double lp = dpx * dpx + dpy * dpy + dpz * dpz;
  double lq = dqx * dqx + dqy * dqy + dqz * dqz;
  double lr = drx * drx + dry * dry + drz * drz;
  double ls = dsx * dsx + dsy * dsy + dsz * dsz;
  double ml;  // largest |d_i|^2 + |w_t - w_i| over the rows
  if constexpr (Weighted) {
    const double wp = t[3] - p[3], wq = t[3] - q[3], wr = t[3] - r[3], ws = t[3] - s[3];
    ml = std::max(std::max(lp + std::fabs(wp), lq + std::fabs(wq)),
                  std::max(lr + std::fabs(wr), ls + std::fabs(ws)));
    lp += wp;
    lq += wq;
    lr += wr;
    ls += ws;
  } else {
    ml = std::max(std::max(lp, lq), std::max(lr, ls));
  }

  // 2x2 minors of the (x, y) columns, then 3x3 minors with z, then the lift column.
  const double pq = dpx * dqy - dqx * dpy;
  const double pr = dpx * dry - drx * dpy;
  const double ps = dpx * dsy - dsx * dpy;
  const double qr = dqx * dry - drx * dqy;
  const double qs = dqx * dsy - dsx * dqy;
  const double rs = drx * dsy - dsx * dry;
  const double pqr = dpz * qr - dqz * pr + drz * pq;
  const double pqs = dpz * qs - dqz * ps + dsz * pq;
  const double prs = dpz * rs - drz * ps + dsz * pr;
  const double qrs = dqz * rs - drz * qs + dsz * qr;
  const double det = (ls * pqr - lr * pqs) + (lq * prs - lp * qrs);

  const double bound = kInsphereBound * (mx * my * mz) * ml;
  if (std::fabs(det) > bound) [[likely]] return (det < 0) - (det > 0);
  return 2;
}

}  // namespace detail

inline int orient3d(const double* p, const double* q, const double* r, const double* s) {
  const double ax = q[0] - p[0], ay = q[1] - p[1], az = q[2] - p[2];
  const double bx = r[0] - p[0], by = r[1] - p[1], bz = r[2] - p[2];
  const double cx = s[0] - p[0], cy = s[1] - p[1], cz = s[2] - p[2];
  const double det = ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  const double mx = detail::max_abs3(ax, bx, cx);
  const double my = detail::max_abs3(ay, by, cy);
  const double mz = detail::max_abs3(az, bz, cz);
  const double bound = detail::kOrient3dBound * (mx * my * mz);
  // One almost-always-taken branch, then a branch-free sign (see power_test_filter).
  if (std::fabs(det) > bound) [[likely]] {
    DELPSC_COUNT(Predicate::orient3d, false);
    return (det > 0) - (det < 0);
  }
  // A whole column of zero differences: the four points share that coordinate, det is exactly 0.
  if (mx == 0 || my == 0 || mz == 0) {
    DELPSC_COUNT(Predicate::orient3d, false);
    return 0;
  }
  DELPSC_COUNT(Predicate::orient3d, true);
  return detail::orient3d_exact(p, q, r, s);
}

inline int insphere(const double* p, const double* q, const double* r, const double* s,
                    const double* t) {
  const int f = detail::power_test_filter<false>(p, q, r, s, t);
  DELPSC_COUNT(Predicate::insphere, f == 2);
  if (f != 2) [[likely]] return f;
  return detail::power_test_exact(p, q, r, s, t, false);
}

inline int power_test(const double* p, const double* q, const double* r, const double* s,
                      const double* t) {
  const int f = detail::power_test_filter<true>(p, q, r, s, t);
  DELPSC_COUNT(Predicate::power_test_3d, f == 2);
  if (f != 2) [[likely]] return f;
  return detail::power_test_exact(p, q, r, s, t, true);
}

}  // namespace delpsc::kernel
