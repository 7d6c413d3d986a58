// Double-double numbers (an unevaluated sum hi + lo of two doubles, |lo| <= ulp(hi)/2): about 106
// bits of precision at a few times the cost of double. Used as the middle stage of the power
// test, between the double filter and exact expansions: on nearly degenerate input (points rounded
// onto a sphere) the double filter fails almost always, while a double-double evaluation with its
// own error bound decides nearly every case at a fraction of the exact cost.
//
// Algorithms and error bounds: Joldes, Muller & Popescu, "Tight and rigorous error bounds for basic
// building blocks of double-word arithmetic", ACM TOMS 44(2), 2017: AccurateDWPlusDW (relative
// error <= 3u^2 / (1 - 4u)) and DWTimesDW3 with fma (relative error <= 4u^2), u = 2^-53, barring
// underflow and overflow.
#pragma once

#include "expansion.h"

namespace delpsc::kernel::dd {

struct DD {
  double hi = 0, lo = 0;
};

/// a - b exactly.
inline DD diff(double a, double b) {
  DD r;
  exact::two_diff(a, b, r.hi, r.lo);
  return r;
}

/// AccurateDWPlusDW.
inline DD add(DD x, DD y) {
  double sh, sl, th, tl;
  exact::two_sum(x.hi, y.hi, sh, sl);
  exact::two_sum(x.lo, y.lo, th, tl);
  const double c = sl + th;
  double vh, vl;
  exact::fast_two_sum(sh, c, vh, vl);
  const double w = tl + vl;
  DD r;
  exact::fast_two_sum(vh, w, r.hi, r.lo);
  return r;
}

inline DD neg(DD x) { return {-x.hi, -x.lo}; }
inline DD sub(DD x, DD y) { return add(x, neg(y)); }

/// DWTimesDW3 (fma).
inline DD mul(DD x, DD y) {
  double ch, cl1;
  exact::two_product(x.hi, y.hi, ch, cl1);
  const double tl0 = x.lo * y.lo;
  const double tl1 = std::fma(x.hi, y.lo, tl0);
  const double cl2 = std::fma(x.lo, y.hi, tl1);
  const double cl3 = cl1 + cl2;
  DD r;
  exact::fast_two_sum(ch, cl3, r.hi, r.lo);
  return r;
}

}  // namespace delpsc::kernel::dd
