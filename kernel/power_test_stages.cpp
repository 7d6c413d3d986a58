// The two middle stages of the 5-point power test (and insphere), tried in this order when the
// inline double filter fails, before exact expansion arithmetic:
//
//  1. Integer stage. When every translated coordinate and weight difference is an integer of
//     modest size (integer grids, lattice models, most hand-made degenerate tests), the
//     determinant is computed exactly in 128-bit integers. Exact, including an exact zero, which
//     no floating-point stage can ever certify.
//  2. Double-double stage. The same evaluation order as the double filter, in double-double
//     arithmetic (double_double.h) from exact differences. Error analysis as in predicates.cpp
//     with leaves exact and every operation carrying at most eps = 4u^2 relative error: the
//     first-order count gives 17 * 24 = 408 eps = 1632 u^2 times MxMyMz*ML; we use 2048 u^2 =
//     2^-95, whose slack covers second-order terms and maxima taken over the high words. Within
//     the documented input range (predicates.h) no partial result underflows far enough to matter:
//     every non-zero leaf is >= 2^-192, so the bound is >= 2^-95 * 2^-960 >> 2^-1074 * #ops.
#include <cmath>
#include <cstdint>

#include "double_double.h"
#include "power_test_stages.h"
#include "predicates.h"

namespace delpsc::kernel::detail {

namespace {

__extension__ typedef __int128 Int128;

// Integer stage limits: |coordinate difference| <= 2^20 and |weight difference| <= 2^40 keep
// every minor and the determinant below 24 * 2^60 * 2^42 < 2^107, far inside Int128.
constexpr double kMaxIntegerCoordinate = 0x1p20;
constexpr double kMaxIntegerWeight = 0x1p40;

bool small_integer(double v, double limit) { return std::fabs(v) <= limit && v == std::trunc(v); }

}  // namespace

int power_test_integer(const double* const pts[4], const double* t, bool weighted) {
  std::int64_t d[4][3];
  Int128 lift[4];
  for (int i = 0; i < 4; ++i) {
    Int128 l = 0;
    for (int k = 0; k < 3; ++k) {
      // The difference of two doubles need not be exact; check it is (then it is an integer).
      const double a = pts[i][k], b = t[k];
      const double v = a - b;
      if (!small_integer(v, kMaxIntegerCoordinate) || v + b != a || a - v != b) return 2;
      d[i][k] = static_cast<std::int64_t>(v);
      l += Int128(d[i][k]) * d[i][k];
    }
    if (weighted) {
      const double v = t[3] - pts[i][3];
      if (!small_integer(v, kMaxIntegerWeight) || v + pts[i][3] != t[3] || t[3] - v != pts[i][3])
        return 2;
      l += static_cast<std::int64_t>(v);
    }
    lift[i] = l;
  }
  const auto m2 = [&](int i, int j) { return Int128(d[i][0]) * d[j][1] - Int128(d[j][0]) * d[i][1]; };
  const Int128 m01 = m2(0, 1), m02 = m2(0, 2), m03 = m2(0, 3), m12 = m2(1, 2), m13 = m2(1, 3),
               m23 = m2(2, 3);
  const Int128 pqr = d[0][2] * m12 - d[1][2] * m02 + d[2][2] * m01;
  const Int128 pqs = d[0][2] * m13 - d[1][2] * m03 + d[3][2] * m01;
  const Int128 prs = d[0][2] * m23 - d[2][2] * m03 + d[3][2] * m02;
  const Int128 qrs = d[1][2] * m23 - d[2][2] * m13 + d[3][2] * m12;
  const Int128 det = (lift[3] * pqr - lift[2] * pqs) + (lift[1] * prs - lift[0] * qrs);
  return det > 0 ? -1 : det < 0 ? 1 : 0;
}

int power_test_double_double(const double* const pts[4], const double* t, bool weighted) {
  using dd::DD;
  DD x[4], y[4], z[4], lift[4];
  double mx = 0, my = 0, mz = 0, mw = 0;
  for (int i = 0; i < 4; ++i) {
    x[i] = dd::diff(pts[i][0], t[0]);
    y[i] = dd::diff(pts[i][1], t[1]);
    z[i] = dd::diff(pts[i][2], t[2]);
    lift[i] = dd::add(dd::add(dd::mul(x[i], x[i]), dd::mul(y[i], y[i])), dd::mul(z[i], z[i]));
    if (weighted) {
      const DD w = dd::diff(t[3], pts[i][3]);
      lift[i] = dd::add(lift[i], w);
      mw = std::fmax(mw, std::fabs(w.hi));
    }
    mx = std::fmax(mx, std::fabs(x[i].hi));
    my = std::fmax(my, std::fabs(y[i].hi));
    mz = std::fmax(mz, std::fabs(z[i].hi));
  }
  const auto m2 = [&](int i, int j) { return dd::sub(dd::mul(x[i], y[j]), dd::mul(x[j], y[i])); };
  const DD m01 = m2(0, 1), m02 = m2(0, 2), m03 = m2(0, 3), m12 = m2(1, 2), m13 = m2(1, 3),
           m23 = m2(2, 3);
  const auto m3 = [&](int i, int j, int k, DD mjk, DD mik, DD mij) {
    return dd::add(dd::sub(dd::mul(z[i], mjk), dd::mul(z[j], mik)), dd::mul(z[k], mij));
  };
  const DD pqr = m3(0, 1, 2, m12, m02, m01);
  const DD pqs = m3(0, 1, 3, m13, m03, m01);
  const DD prs = m3(0, 2, 3, m23, m03, m02);
  const DD qrs = m3(1, 2, 3, m23, m13, m12);
  const DD det = dd::add(dd::sub(dd::mul(lift[3], pqr), dd::mul(lift[2], pqs)),
                         dd::sub(dd::mul(lift[1], prs), dd::mul(lift[0], qrs)));
  const double ml = mx * mx + my * my + mz * mz + mw;
  const double bound = 0x1p-95 * (mx * my * mz) * ml;
  if (det.hi > bound) return -1;
  if (det.hi < -bound) return 1;
  return 2;
}

}  // namespace delpsc::kernel::detail
