// GMP is a test-only dependency: without it (DELPSC_WITH_GMP=OFF on a machine lacking gmpxx.h)
// this file compiles to nothing and only the oracle tests, which are then not built, miss it.
#if __has_include(<gmpxx.h>)

#include "support/oracle.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace delpsc::test::oracle {

namespace {

int sgn(const mpz_class& v) { return mpz_sgn(v.get_mpz_t()); }

// ---- integer images -------------------------------------------------------------------------

// A double is m * 2^e with m an odd integer of at most 53 bits (or it is 0).
struct Dyadic {
  std::int64_t m = 0;
  int e = 0;
};

Dyadic split(double x) {
  if (x == 0) return {};
  int e = 0;
  const double f = std::frexp(x, &e);  // x = f 2^e, 0.5 <= |f| < 1
  auto m = static_cast<std::int64_t>(std::ldexp(f, 53));
  e -= 53;
  const int tz = std::countr_zero(static_cast<std::uint64_t>(m));
  m >>= tz;  // exact: m is a multiple of 2^tz (arithmetic shift, C++20)
  return {m, e + tz};
}

int floor_div2(int e) { return e >= 0 ? e / 2 : -((-e + 1) / 2); }

struct Input {
  const double* v;
  int dims;  // 3: a point; 4: a weighted point (the weight has degree 2)
};

// The inputs of one call, all multiplied by 2^-E (weights by 2^-2E) with E the largest exponent
// that makes every one of them an integer. The polynomials below are homogeneous of a fixed
// degree in these units, so their signs are those of the original inputs.
class IntegerImage {
 public:
  void load(std::initializer_list<Input> inputs) {
    Dyadic d[5][4];
    int lowest = 1 << 20;
    int i = 0;
    for (const Input& in : inputs) {
      for (int k = 0; k < in.dims; ++k) {
        d[i][k] = split(in.v[k]);
        if (d[i][k].m != 0) lowest = std::min(lowest, k == 3 ? floor_div2(d[i][k].e) : d[i][k].e);
      }
      dims_[i] = in.dims;
      ++i;
    }
    for (int j = 0; j < i; ++j) {
      for (int k = 0; k < dims_[j]; ++k) {
        mpz_class& z = v_[j][k];
        z = static_cast<long>(d[j][k].m);
        if (d[j][k].m != 0) {
          const int shift = d[j][k].e - (k == 3 ? 2 * lowest : lowest);
          mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
        }
      }
      if (dims_[j] == 3) v_[j][3] = 0;
    }
  }
  const mpz_class& operator()(int i, int k) const { return v_[i][k]; }

 private:
  mpz_class v_[5][4];
  int dims_[5] = {};
};

IntegerImage& image() {
  static IntegerImage img;
  return img;
}

// ---- one determinant routine for every predicate --------------------------------------------

// Polynomials in eps with integer coefficients, c[k] the coefficient of eps^k.
struct EpsPoly {
  std::vector<mpz_class> c;
};

void set_zero(mpz_class& x) { x = 0; }
void set_one(mpz_class& x) { x = 1; }
void add_product(mpz_class& acc, const mpz_class& a, const mpz_class& b, bool negate) {
  if (negate)
    mpz_submul(acc.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
  else
    mpz_addmul(acc.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
}

void set_zero(EpsPoly& x) { x.c.clear(); }
void set_one(EpsPoly& x) { x.c.assign(1, mpz_class(1)); }
void add_product(EpsPoly& acc, const EpsPoly& a, const EpsPoly& b, bool negate) {
  if (a.c.empty() || b.c.empty()) return;
  if (acc.c.size() < a.c.size() + b.c.size() - 1) acc.c.resize(a.c.size() + b.c.size() - 1);
  for (std::size_t i = 0; i < a.c.size(); ++i)
    for (std::size_t j = 0; j < b.c.size(); ++j) add_product(acc.c[i + j], a.c[i], b.c[j], negate);
}

// Determinant of the n x n matrix a (row-major, n <= 5) by Laplace expansion: minor[S] is the
// determinant of the rows in the set S against the first |S| columns, expanded along column
// |S|-1:  minor[S] = sum_{j-th row i of S} (-1)^(j + |S|-1) a[i][|S|-1] minor[S \ {i}].
// n 2^(n-1) products in all (80 for n = 5); valid over any commutative ring.
template <class Ring>
const Ring& determinant(const Ring* a, int n) {
  static Ring minor[1 << 5];
  set_one(minor[0]);
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    const int col = std::popcount(mask) - 1;
    Ring& m = minor[mask];
    set_zero(m);
    int j = 0;
    for (int i = 0; i < n; ++i) {
      if (!(mask >> i & 1u)) continue;
      add_product(m, a[i * n + col], minor[mask ^ (1u << i)], (j + col) % 2 != 0);
      ++j;
    }
  }
  return minor[(1u << n) - 1];
}

int sign_of_determinant(const mpz_class* a, int n) { return sgn(determinant(a, n)); }

// ---- shared pieces of the power tests -------------------------------------------------------

// Lift of point i translated by point t: |p_i - t|^2 + (w_t - w_i) (weights 0 when unweighted).
void translated_lift(const IntegerImage& z, int i, int t, mpz_class& out) {
  static mpz_class d;
  out = z(t, 3) - z(i, 3);
  for (int k = 0; k < 3; ++k) {
    d = z(i, k) - z(t, k);
    mpz_addmul(out.get_mpz_t(), d.get_mpz_t(), d.get_mpz_t());
  }
}

// orient2d of the integer images of points a, b, c on axes (i, j).
int image_orient2d(const IntegerImage& z, int a, int b, int c, int i, int j) {
  static mpz_class m[4];
  m[0] = z(b, i) - z(a, i);
  m[1] = z(b, j) - z(a, j);
  m[2] = z(c, i) - z(a, i);
  m[3] = z(c, j) - z(a, j);
  return sign_of_determinant(m, 2);
}

// 5-point power test on loaded images 0..4 (t = 4): -sign det of rows (p_i - t, lift_i).
int image_power_test_5(const IntegerImage& z) {
  static mpz_class m[16];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) m[4 * i + k] = z(i, k) - z(4, k);
    translated_lift(z, i, 4, m[4 * i + 3]);
  }
  return -sign_of_determinant(m, 4);
}

// Lexicographic ranks (0 = smallest) of the n points, ties by argument order. Comparing
// doubles is exact; the integer image is not touched (it holds the caller's inputs).
std::array<int, 5> lexicographic_ranks(std::initializer_list<const double*> pts) {
  std::vector<const double*> v(pts);
  std::array<int, 5> rank{};
  for (std::size_t i = 0; i < v.size(); ++i) {
    int r = 0;
    for (std::size_t j = 0; j < v.size(); ++j) {
      const bool smaller = std::lexicographical_compare(v[j], v[j] + 3, v[i], v[i] + 3);
      const bool equal = std::equal(v[j], v[j] + 3, v[i]);
      if (smaller || (equal && j < i)) ++r;
    }
    rank[i] = r;
  }
  return rank;
}

// The lifted entry |p|^2 - w + eps^e as a polynomial (3D norm, as in the power tests).
EpsPoly perturbed_lift(const IntegerImage& z, int i, int e) {
  EpsPoly l;
  l.c.assign(static_cast<std::size_t>(e) + 1, mpz_class(0));
  l.c[0] = -z(i, 3);
  for (int k = 0; k < 3; ++k) mpz_addmul(l.c[0].get_mpz_t(), z(i, k).get_mpz_t(), z(i, k).get_mpz_t());
  l.c[static_cast<std::size_t>(e)] += 1;
  return l;
}

EpsPoly constant(const mpz_class& v) { return EpsPoly{{v}}; }

// First non-zero coefficient of det, with its power.
PerturbedSign leading_sign(const EpsPoly& det) {
  for (std::size_t k = 0; k < det.c.size(); ++k)
    if (const int s = sgn(det.c[k]); s != 0) return {s, static_cast<int>(k)};
  return {0, -1};
}

}  // namespace

// ---- plain predicates -------------------------------------------------------------------------

int compare_xyz(const double* p, const double* q) {
  IntegerImage& z = image();
  z.load({{p, 3}, {q, 3}});
  for (int k = 0; k < 3; ++k)
    if (const int c = cmp(z(0, k), z(1, k)); c != 0) return c < 0 ? -1 : 1;
  return 0;
}

int orient3d(const double* p, const double* q, const double* r, const double* s) {
  IntegerImage& z = image();
  z.load({{p, 3}, {q, 3}, {r, 3}, {s, 3}});
  static mpz_class m[9];  // rows q - p, r - p, s - p
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[3 * i + k] = z(i + 1, k) - z(0, k);
  return sign_of_determinant(m, 3);
}

int orient2d(const double* p, const double* q, const double* r, int i, int j) {
  IntegerImage& z = image();
  z.load({{p, 3}, {q, 3}, {r, 3}});
  return image_orient2d(z, 0, 1, 2, i, j);
}

int coplanar_orientation(const double* p, const double* q, const double* r) {
  IntegerImage& z = image();
  z.load({{p, 3}, {q, 3}, {r, 3}});
  // CGAL coplanar_orientationC3 (3 points): xy, then yz, then xz.
  if (const int o = image_orient2d(z, 0, 1, 2, 0, 1); o != 0) return o;
  if (const int o = image_orient2d(z, 0, 1, 2, 1, 2); o != 0) return o;
  return image_orient2d(z, 0, 1, 2, 0, 2);
}

int coplanar_orientation(const double* p, const double* q, const double* r, const double* s) {
  IntegerImage& z = image();
  z.load({{p, 3}, {q, 3}, {r, 3}, {s, 3}});
  // CGAL coplanar_orientationC3 (4 points): the first projection (xy, yz, xz) in which p, q, r
  // are not collinear; orientation of pqr times orientation of pqs there.
  static constexpr int kAxes[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  for (const auto& ax : kAxes) {
    const int o = image_orient2d(z, 0, 1, 2, ax[0], ax[1]);
    if (o != 0 || (ax[0] == 0 && ax[1] == 2)) return o * image_orient2d(z, 0, 1, 3, ax[0], ax[1]);
  }
  return 0;
}

bool collinear(const double* p, const double* q, const double* r) {
  IntegerImage& z = image();
  z.load({{p, 3}, {q, 3}, {r, 3}});
  return image_orient2d(z, 0, 1, 2, 0, 1) == 0 && image_orient2d(z, 0, 1, 2, 1, 2) == 0 &&
         image_orient2d(z, 0, 1, 2, 0, 2) == 0;
}

int insphere(const double* p, const double* q, const double* r, const double* s, const double* t) {
  IntegerImage& z = image();
  z.load({{p, 3}, {q, 3}, {r, 3}, {s, 3}, {t, 3}});
  return image_power_test_5(z);
}

int power_test(const double* p, const double* q, const double* r, const double* s,
               const double* t) {
  IntegerImage& z = image();
  z.load({{p, 4}, {q, 4}, {r, 4}, {s, 4}, {t, 4}});
  return image_power_test_5(z);
}

int power_test(const double* p, const double* q, const double* r, const double* t) {
  IntegerImage& z = image();
  z.load({{p, 4}, {q, 4}, {r, 4}, {t, 4}});
  // CGAL power_side_of_oriented_power_sphereC3 (4 points): translate by t; in the projections
  // xy, then xz, then yz, the first non-zero det of rows (d_a, d_b, lift) of p, q, r decides,
  // times det[p - r; q - r] in that projection.
  static mpz_class lift[3];
  for (int i = 0; i < 3; ++i) translated_lift(z, i, 3, lift[i]);
  static constexpr int kAxes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  static mpz_class m[9], o[4];
  for (const auto& ax : kAxes) {
    for (int i = 0; i < 3; ++i) {
      m[3 * i + 0] = z(i, ax[0]) - z(3, ax[0]);
      m[3 * i + 1] = z(i, ax[1]) - z(3, ax[1]);
      m[3 * i + 2] = lift[i];
    }
    const int cmp = sign_of_determinant(m, 3);
    if (cmp == 0) continue;
    o[0] = z(0, ax[0]) - z(2, ax[0]);
    o[1] = z(0, ax[1]) - z(2, ax[1]);
    o[2] = z(1, ax[0]) - z(2, ax[0]);
    o[3] = z(1, ax[1]) - z(2, ax[1]);
    return cmp * sign_of_determinant(o, 2);
  }
  return 0;
}

int power_test(const double* p, const double* q, const double* t) {
  IntegerImage& z = image();
  z.load({{p, 4}, {q, 4}, {t, 4}});
  // CGAL (3 points): translate by t; on the first axis a where p and q differ,
  // compare(p_a, q_a) * det[d_pa, lift_p; d_qa, lift_q].
  static mpz_class m[4];
  for (int a = 0; a < 3; ++a) {
    const int c = cmp(z(0, a), z(1, a));
    if (c == 0) continue;
    m[0] = z(0, a) - z(2, a);
    translated_lift(z, 0, 2, m[1]);
    m[2] = z(1, a) - z(2, a);
    translated_lift(z, 1, 2, m[3]);
    return (c < 0 ? -1 : 1) * sign_of_determinant(m, 2);
  }
  return 0;
}

int power_test(const double* p, const double* q) {
  IntegerImage& z = image();
  z.load({{p, 4}, {q, 4}});
  const int c = cmp(z(1, 3), z(0, 3));  // CGAL: compare(w_q, w_p)
  return (c > 0) - (c < 0);
}

int power_distance_sign(const double* x, const double* c) {
  IntegerImage& z = image();
  z.load({{x, 3}, {c, 4}});
  static mpz_class v;
  translated_lift(z, 0, 1, v);  // |x - c|^2 + (w_c - w_x), w_x = 0
  v -= 2 * z(1, 3);             // |x - c|^2 - w_c
  return sgn(v);
}

int compare_power_distance(const double* x, const double* p, const double* q) {
  IntegerImage& z = image();
  z.load({{x, 3}, {p, 4}, {q, 4}});
  // (|x - p|^2 - w_p) - (|x - q|^2 - w_q); translated_lift(p, x) = |p - x|^2 + (0 - w_p).
  static mpz_class a, b;
  translated_lift(z, 1, 0, a);
  translated_lift(z, 2, 0, b);
  return sgn(a - b);
}

// ---- perturbed predicates -------------------------------------------------------------------

PerturbedSign power_test_perturbed(const double* p, const double* q, const double* r,
                                   const double* s, const double* t) {
  IntegerImage& z = image();
  z.load({{p, 4}, {q, 4}, {r, 4}, {s, 4}, {t, 4}});
  const auto rank = lexicographic_ranks({p, q, r, s, t});
  static EpsPoly m[25];
  for (int i = 0; i < 5; ++i) {
    for (int k = 0; k < 3; ++k) m[5 * i + k] = constant(z(i, k));
    m[5 * i + 3] = perturbed_lift(z, i, 5 - rank[i]);
    m[5 * i + 4] = constant(1);
  }
  PerturbedSign out = leading_sign(determinant(m, 5));
  out.sign = -out.sign;  // CGAL: minus the sign of the 5x5 determinant
  return out;
}

PerturbedSign insphere_perturbed(const double* p, const double* q, const double* r,
                                 const double* s, const double* t) {
  const double pw[4] = {p[0], p[1], p[2], 0}, qw[4] = {q[0], q[1], q[2], 0},
               rw[4] = {r[0], r[1], r[2], 0}, sw[4] = {s[0], s[1], s[2], 0},
               tw[4] = {t[0], t[1], t[2], 0};
  return power_test_perturbed(pw, qw, rw, sw, tw);
}

PerturbedSign power_circle_side_perturbed(const double* p, const double* q, const double* r,
                                          const double* t) {
  IntegerImage& z = image();
  z.load({{p, 4}, {q, 4}, {r, 4}, {t, 4}});
  static constexpr int kAxes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  int a = 0, b = 0, orientation = 0;
  for (const auto& ax : kAxes) {
    orientation = image_orient2d(z, 0, 1, 2, ax[0], ax[1]);
    a = ax[0];
    b = ax[1];
    if (orientation != 0) break;
  }
  if (orientation == 0) return {0, -1};  // p, q, r collinear: precondition violated
  const auto rank = lexicographic_ranks({p, q, r, t});
  static EpsPoly m[16];
  for (int i = 0; i < 4; ++i) {
    m[4 * i + 0] = constant(z(i, a));
    m[4 * i + 1] = constant(z(i, b));
    m[4 * i + 2] = perturbed_lift(z, i, 4 - rank[i]);
    m[4 * i + 3] = constant(1);
  }
  PerturbedSign out = leading_sign(determinant(m, 4));
  out.sign *= orientation;
  return out;
}

PerturbedSign power_segment_side_perturbed(const double* p, const double* q, const double* t) {
  IntegerImage& z = image();
  z.load({{p, 4}, {q, 4}, {t, 4}});
  int a = 0;
  while (a < 3 && z(0, a) == z(1, a)) ++a;
  if (a == 3) return {0, -1};  // p == q: precondition violated
  const int direction = cmp(z(0, a), z(1, a)) < 0 ? -1 : 1;
  const auto rank = lexicographic_ranks({p, q, t});
  static EpsPoly m[9];
  for (int i = 0; i < 3; ++i) {
    m[3 * i + 0] = constant(z(i, a));
    m[3 * i + 1] = perturbed_lift(z, i, 3 - rank[i]);
    m[3 * i + 2] = constant(1);
  }
  PerturbedSign out = leading_sign(determinant(m, 3));
  out.sign *= direction;
  return out;
}

}  // namespace delpsc::test::oracle

#endif  // __has_include(<gmpxx.h>)
