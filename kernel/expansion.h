// Exact expansion arithmetic on doubles (Shewchuk, "Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates", DCG 18, 1997).
//
// A real number is held as an *expansion*: a sum of doubles, sorted by increasing magnitude,
// pairwise nonoverlapping, with zero components removed. Sums, differences and products of
// expansions are exact (no rounding at all) as long as no partial product underflows or overflows;
// the sign of an expansion is the sign of its largest component. This is the exact back end of the
// predicates; it is only reached when a floating-point filter cannot decide.
//
// Error-free transformations used (round-to-nearest-even binary64, no extended precision, no
// contraction: the library is compiled with -ffp-contract=off):
//   two_sum(a, b)     = (x, y) with x = fl(a + b), x + y = a + b exactly       (Knuth)
//   fast_two_sum      = the same when |a| >= |b|                              (Dekker)
//   two_product(a, b) = (x, y) with x = fl(a * b), x + y = a * b exactly, via one fma.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>

namespace delpsc::kernel::exact {

inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  y = (a - av) + (bv - b);
}

inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

/// h = e * b for an expansion e of n components (Scale-Expansion with zero elimination); h has
/// room for 2n and must not alias e. Returns h's length. For fixed-size stack arrays where the
/// Expansion class's inline buffer would cost more than the arithmetic (predicates.cpp).
inline std::uint32_t scale_expansion(const double* e, std::uint32_t n, double b, double* h) {
  if (n == 0 || b == 0) return 0;
  std::uint32_t len = 0;
  double q, hh;
  two_product(e[0], b, q, hh);
  if (hh != 0) h[len++] = hh;
  for (std::uint32_t i = 1; i < n; ++i) {
    double p1, p0, s;
    two_product(e[i], b, p1, p0);
    two_sum(q, p0, s, hh);
    if (hh != 0) h[len++] = hh;
    fast_two_sum(p1, s, q, hh);
    if (hh != 0) h[len++] = hh;
  }
  if (q != 0) h[len++] = q;
  return len;
}

/// h = e + fsign * f (fsign = ±1) for expansions of m and n components: the two merged by
/// increasing magnitude and accumulated with two_sum, zeros dropped. h has room for m + n and
/// aliases neither. Returns h's length.
inline std::uint32_t sum_expansions(const double* e, std::uint32_t m, const double* f, std::uint32_t n,
                                    double fsign, double* h) {
  if (m + n == 0) return 0;
  std::uint32_t ei = 0, fi = 0, len = 0;
  auto next = [&]() {
    // e's component first when f is used up, or when (fn > en) == (fn > -en): |en| < |fn|, and
    // for a tie the order the class always used (the value is the same either way, and so, with
    // this order, are the components).
    if (ei < m) {
      if (fi == n) return e[ei++];
      const double en = e[ei], fn = fsign * f[fi];
      if ((fn > en) == (fn > -en)) return e[ei++];
    }
    return fsign * f[fi++];
  };
  double q = next();
  for (std::uint32_t k = 1; k < m + n; ++k) {
    double qnew, hh;
    two_sum(q, next(), qnew, hh);
    if (hh != 0) h[len++] = hh;
    q = qnew;
  }
  if (q != 0) h[len++] = q;
  return len;
}

/// An exact real number as a nonoverlapping expansion (see the file comment).
/// Components live inline up to kInline doubles (enough for every predicate on the documented
/// input range in practice); larger expansions spill to the heap, so correctness never depends
/// on the inline size. Value semantics; moves are cheap only for heap-backed values.
class Expansion {
 public:
  static constexpr std::uint32_t kInline = 48;

  Expansion() = default;
  explicit Expansion(double a) {
    if (a != 0) push_unchecked(a);
  }
  /// a - b exactly (two components at most).
  static Expansion difference(double a, double b) {
    double x, y;
    two_diff(a, b, x, y);
    return from_pair(y, x);
  }
  /// a + b exactly.
  static Expansion sum(double a, double b) {
    double x, y;
    two_sum(a, b, x, y);
    return from_pair(y, x);
  }
  /// a * b exactly.
  static Expansion product(double a, double b) {
    double x, y;
    two_product(a, b, x, y);
    return from_pair(y, x);
  }

  Expansion(const Expansion& o) { assign(o.data_, o.size_); }
  Expansion& operator=(const Expansion& o) {
    if (this != &o) {
      size_ = 0;
      assign(o.data_, o.size_);
    }
    return *this;
  }
  Expansion(Expansion&& o) noexcept { steal(o); }
  Expansion& operator=(Expansion&& o) noexcept {
    if (this != &o) {
      heap_.reset();
      data_ = inline_;
      capacity_ = kInline;
      size_ = 0;
      steal(o);
    }
    return *this;
  }
  ~Expansion() = default;

  std::uint32_t size() const { return size_; }
  const double* begin() const { return data_; }
  const double* end() const { return data_ + size_; }
  double operator[](std::uint32_t i) const { return data_[i]; }
  bool is_zero() const { return size_ == 0; }

  /// Exact sign: the sign of the largest (last) component.
  int sign() const { return size_ == 0 ? 0 : (data_[size_ - 1] > 0 ? 1 : -1); }
  /// An approximation of the value (the components summed in double).
  double estimate() const {
    double s = 0;
    for (std::uint32_t i = 0; i < size_; ++i) s += data_[i];
    return s;
  }

  Expansion operator-() const {
    Expansion r(*this);
    for (std::uint32_t i = 0; i < r.size_; ++i) r.data_[i] = -r.data_[i];
    return r;
  }

  /// e + f (Shewchuk's Fast-Expansion-Sum with zero elimination). Output length <= |e| + |f|.
  friend Expansion operator+(const Expansion& e, const Expansion& f) {
    if (e.size_ == 0) return f;
    if (f.size_ == 0) return e;
    Expansion h;
    h.reserve(e.size_ + f.size_);
    merge_sum(e, f, 1.0, h);
    return h;
  }
  /// e - f, exact.
  friend Expansion operator-(const Expansion& e, const Expansion& f) {
    if (f.size_ == 0) return e;
    if (e.size_ == 0) return -f;
    Expansion h;
    h.reserve(e.size_ + f.size_);
    merge_sum(e, f, -1.0, h);
    return h;
  }

  /// e * b (Scale-Expansion with zero elimination). Output length <= 2|e|.
  Expansion scaled(double b) const {
    Expansion h;
    if (size_ == 0 || b == 0) return h;
    h.reserve(2 * size_);
    h.size_ = scale_expansion(data_, size_, b, h.data_);
    return h;
  }

  /// e * f, exact: the sum of e scaled by each component of the shorter factor.
  friend Expansion operator*(const Expansion& e, const Expansion& f) {
    const Expansion& longer = e.size_ >= f.size_ ? e : f;
    const Expansion& shorter = e.size_ >= f.size_ ? f : e;
    if (shorter.size_ == 0) return Expansion();
    Expansion acc = longer.scaled(shorter.data_[0]);
    for (std::uint32_t i = 1; i < shorter.size_; ++i) acc = acc + longer.scaled(shorter.data_[i]);
    acc.compress();
    return acc;
  }

  /// Rewrites the expansion with as few components as possible (Shewchuk's Compress); the value
  /// and the nonoverlapping property are kept. Cheap, and it keeps products short.
  void compress() {
    if (size_ < 2) return;
    double* g = data_;
    std::int64_t bottom = static_cast<std::int64_t>(size_) - 1;
    double q = g[bottom];
    for (std::int64_t i = static_cast<std::int64_t>(size_) - 2; i >= 0; --i) {
      double qnew, small;
      fast_two_sum(q, g[i], qnew, small);
      if (small != 0) {
        g[bottom--] = qnew;
        q = small;
      } else {
        q = qnew;
      }
    }
    std::uint32_t top = 0;
    for (std::int64_t i = bottom + 1; i < static_cast<std::int64_t>(size_); ++i) {
      double qnew, small;
      fast_two_sum(g[i], q, qnew, small);
      if (small != 0) g[top++] = small;
      q = qnew;
    }
    if (q != 0) g[top++] = q;
    size_ = top;
  }

 private:
  static Expansion from_pair(double low, double high) {
    Expansion e;
    if (low != 0) e.push_unchecked(low);
    if (high != 0) e.push_unchecked(high);
    return e;
  }

  // Merges e and ±f by increasing magnitude and accumulates with two_sum, dropping zeros.
  static void merge_sum(const Expansion& e, const Expansion& f, double fsign, Expansion& h) {
    h.size_ = sum_expansions(e.data_, e.size_, f.data_, f.size_, fsign, h.data_);
  }

  void reserve(std::uint32_t n) {
    if (n <= capacity_) return;
    auto bigger = std::make_unique<double[]>(n);
    std::memcpy(bigger.get(), data_, size_ * sizeof(double));
    heap_ = std::move(bigger);
    data_ = heap_.get();
    capacity_ = n;
  }
  void push_unchecked(double v) { data_[size_++] = v; }
  void assign(const double* src, std::uint32_t n) {
    reserve(n);
    std::memcpy(data_, src, n * sizeof(double));
    size_ = n;
  }
  void steal(Expansion& o) {
    if (o.heap_) {
      heap_ = std::move(o.heap_);
      data_ = heap_.get();
      capacity_ = o.capacity_;
      size_ = o.size_;
      o.data_ = o.inline_;
      o.capacity_ = kInline;
      o.size_ = 0;
    } else {
      assign(o.data_, o.size_);
    }
  }

  double inline_[kInline];
  double* data_ = inline_;
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = kInline;
  std::unique_ptr<double[]> heap_;
};

}  // namespace delpsc::kernel::exact
