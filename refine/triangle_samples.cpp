#include "triangle_samples.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace delpsc::refine {

namespace {

// The triangle relabelled so that ab is its longest edge, and its rows (triangle_samples.h).
// The longest edge is opposite the largest angle, so the angles at a and b are not obtuse: the
// cross-sections shrink from ab to c, and a point p between rows i and i + 1 is within
// (sqrt(3) / 2) h of its foot on row i, which lies in row i's segment, itself within h / 2 of a
// sample of that row: p is within sqrt(3/4 + 1/4) h = h of a sample.
struct RowLayout {
  Vec3 a, b, c;
  std::size_t rows = 0;  // 0: no samples

  RowLayout(const Vec3& a0, const Vec3& b0, const Vec3& c0, double h) {
    const std::array<Vec3, 3> v{a0, b0, c0};
    int k = 0;
    double longest = -1;
    for (int i = 0; i < 3; ++i)
      if (const double l = (v[(i + 1) % 3] - v[i]).squaredNorm(); l > longest) longest = l, k = i;
    a = v[k], b = v[(k + 1) % 3], c = v[(k + 2) % 3];
    // Not finite (a NaN or infinite coordinate, or h): nothing, rather than a count cast from NaN.
    if (!a0.allFinite() || !b0.allFinite() || !c0.allFinite() || !(h > 0) || !std::isfinite(h)) return;
    // No edge longer than h: one row (the height is at most (sqrt(3) / 2) h) of one piece, whose
    // ends are corners - nothing, found without a square root (most triangles of a fine input).
    if (!(longest > 0) || longest <= h * h) return;
    // Height of c over ab, through the area: |ab x ac| / |ab|.
    const double height = (b - a).cross(c - a).norm() / std::sqrt(longest);
    rows = sample_pieces(height, std::sqrt(3.0) / 2 * h);
  }

  // Row i joins the points at fraction f of the way from a to c and from b to c (row 0 is ab).
  std::array<Vec3, 2> row(std::size_t i) const {
    const double f = static_cast<double>(i) / static_cast<double>(rows);
    return {a + f * (c - a), b + f * (c - b)};
  }
};

}  // namespace

std::size_t sample_pieces(double length, double h) {
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / h)));
}

void triangle_samples(const Vec3& a0, const Vec3& b0, const Vec3& c0, double h, kernel::LargeVector<Vec3>& out) {
  const RowLayout layout(a0, b0, c0, h);
  for (std::size_t i = 0; i < layout.rows; ++i) {
    const auto [left, right] = layout.row(i);
    const std::size_t n = sample_pieces((right - left).norm(), h);
    for (std::size_t j = 0; j <= n; ++j) {
      if (i == 0 && (j == 0 || j == n)) continue;  // a and b: corners
      const double g = static_cast<double>(j) / static_cast<double>(n);
      out.push_back(left + g * (right - left));
    }
  }
}

double triangle_sample_count(const Vec3& a0, const Vec3& b0, const Vec3& c0, double h) {
  const RowLayout layout(a0, b0, c0, h);
  double count = 0;
  for (std::size_t i = 0; i < layout.rows; ++i) {
    const auto [left, right] = layout.row(i);
    // As sample_pieces, in doubles: a length / h beyond 2^64 must not wrap.
    const double n = std::max(1.0, std::ceil((right - left).norm() / h));
    count += i == 0 ? n - 1 : n + 1;
  }
  return count;
}

}  // namespace delpsc::refine
