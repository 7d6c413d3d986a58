#include "surface_lattice.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <delpsc/kernel/bits.h>

namespace delpsc::refine {

namespace {

struct Point2 {
  double x, y;
};

// The x-range of the triangle's part in the strip lo <= y <= hi (Sutherland-Hodgman against the
// strip's two lines); empty (x0 > x1) when the strip misses it.
std::array<double, 2> strip_range(const std::array<Point2, 3>& t, double lo, double hi) {
  std::array<Point2, 5> a{}, b{};
  std::size_t na = 3, nb = 0;
  std::copy(t.begin(), t.end(), a.begin());
  const auto clip = [&](double level, double sign) {  // keeps sign * (y - level) >= 0
    nb = 0;
    for (std::size_t k = 0; k < na; ++k) {
      const Point2 p = a[k], q = a[(k + 1) % na];
      const double dp = sign * (p.y - level), dq = sign * (q.y - level);
      if (dp >= 0) b[nb++] = p;
      if ((dp < 0) != (dq < 0) && nb < b.size()) b[nb++] = {p.x + (q.x - p.x) * (dp / (dp - dq)), level};
    }
    a = b;
    na = nb;
  };
  clip(lo, 1);
  if (na > 0) clip(hi, -1);
  std::array<double, 2> range{HUGE_VAL, -HUGE_VAL};
  for (std::size_t k = 0; k < na; ++k) {
    range[0] = std::min(range[0], a[k].x);
    range[1] = std::max(range[1], a[k].x);
  }
  return range;
}

// Whether some lattice site of the few rows a small triangle spans lies within `jitter` of the
// triangle's box: most triangles of a finely tessellated model (fandisk's 13,000 at 2%) hold
// none, and this spares them the clipping below (the lattice was 40% of the candidates' time
// there). Triangles whose padded box spans more than seven rows are not tested (true): the row
// loop, whose work the caller caps, handles them.
bool may_hold_site(const std::array<Point2, 3>& t, double step, double row, double jitter) {
  const double xlo = std::min({t[0].x, t[1].x, t[2].x}) - jitter, xhi = std::max({t[0].x, t[1].x, t[2].x}) + jitter;
  const double ylo = std::min({t[0].y, t[1].y, t[2].y}) - jitter, yhi = std::max({t[0].y, t[1].y, t[2].y}) + jitter;
  // One row more on each side and a site more on each end than the box needs: rounding of the
  // divisions never hides a site.
  const auto first_row = static_cast<std::int64_t>(std::floor(ylo / row)) - 1;
  const auto last_row = static_cast<std::int64_t>(std::ceil(yhi / row)) + 1;
  if (last_row - first_row > 6) return true;
  for (std::int64_t j = first_row; j <= last_row; ++j) {
    const double y0 = static_cast<double>(j) * row;
    if (y0 < ylo - 1e-9 * row || y0 > yhi + 1e-9 * row) continue;
    const double shift = 0.5 * step * static_cast<double>(j & 1);
    // The first site at or right of xlo is one of these three.
    const double first = std::floor((xlo - shift) / step);
    for (double i = first; i <= first + 2; ++i) {
      const double cx = i * step + shift;
      if (cx >= xlo - 1e-9 * step) {
        if (cx <= xhi + 1e-9 * step) return true;
        break;
      }
    }
  }
  return false;
}

}  // namespace

LatticeFrame lattice_frame(const Vec3& normal, const Vec3& point, double step) {
  LatticeFrame f;
  Vec3 n = normal.normalized();
  if (!n.allFinite() || !(step > 0) || !std::isfinite(step)) return f;
  // The frame depends on the plane alone: the unit normal with its largest component positive,
  // u across it and the coordinate axis it leans on least, the origin the plane's point nearest
  // the coordinate origin.
  int largest = 0, smallest = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::fabs(n[k]) > std::fabs(n[largest])) largest = k;
    if (std::fabs(n[k]) < std::fabs(n[smallest])) smallest = k;
  }
  if (n[largest] < 0) n = -n;
  f.normal = n;
  f.u = n.cross(Vec3::Unit(smallest)).normalized();
  f.v = n.cross(f.u);
  const double offset = n.dot(point);
  f.origin = offset * n;
  // The jitter also depends on the plane's offset, quantised (coplanar triangles agree on it but
  // in the ~1e-12 chance that rounding puts them on two sides of a quantum: a seam, no error).
  // Without it two parallel planes, such as a cube's opposite faces, got translated copies of one
  // pattern: rectangles of four co-circular points across the model, co-spherical sets whose
  // power tests all fell to exact arithmetic (9% of meshing the cube).
  const double quantum = std::floor(offset / (0.5 * step));
  f.key = kernel::mix64(std::fabs(quantum) < 0x1.0p62 ? static_cast<std::uint64_t>(static_cast<std::int64_t>(quantum)) : 0);
  f.valid = true;
  return f;
}

void jittered_lattice(const Vec3& a, const Vec3& b, const Vec3& c, double step, double jitter,
                      kernel::LargeVector<Vec3>& out) {
  jittered_lattice(lattice_frame((b - a).cross(c - a), a, step), a, b, c, step, jitter, out);
}

bool jittered_lattice(const LatticeFrame& frame, const Vec3& a, const Vec3& b, const Vec3& c, double step,
                      double jitter, kernel::LargeVector<Vec3>& out, std::size_t* work) {
  if (!frame.valid || !(step > 0) || !std::isfinite(step) || !(jitter >= 0) || !(jitter < step / 2)) return true;
  const Vec3 &u = frame.u, &v = frame.v, &origin = frame.origin;
  const auto in_plane = [&](const Vec3& p) { return Point2{u.dot(p - origin), v.dot(p - origin)}; };
  // The triangle projected on the frame's plane (itself, or a nearly parallel triangle of the
  // same cluster); the points found in the projection are mapped back by their barycentric
  // coordinates, so they lie on the triangle.
  const std::array<Point2, 3> t{in_plane(a), in_plane(b), in_plane(c)};
  const double det = (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
  if (!(std::fabs(det) > 0)) return true;
  // Lattice indices must stay exact integers in doubles (and fit the index type): a plane this
  // far from the origin for its step gets no lattice (the random candidates still come).
  for (const Point2& p : t)
    if (!(std::max(std::fabs(p.x), std::fabs(p.y)) < 0x1.0p50 * step)) return true;
  const double row = step * std::sqrt(3.0) / 2;
  if (!may_hold_site(t, step, row, jitter)) return true;
  // How far each barycentric coordinate can move under the jitter (gradient norm times radius),
  // with a relative margin for the rounding of both evaluations.
  const double reach_s = 1.0001 * jitter * std::sqrt((t[2].y - t[0].y) * (t[2].y - t[0].y) + (t[2].x - t[0].x) * (t[2].x - t[0].x)) / std::fabs(det) + 1e-12;
  const double reach_r = 1.0001 * jitter * std::sqrt((t[1].y - t[0].y) * (t[1].y - t[0].y) + (t[1].x - t[0].x) * (t[1].x - t[0].x)) / std::fabs(det) + 1e-12;
  const double reach_q = reach_s + reach_r;
  const double ylo = std::min({t[0].y, t[1].y, t[2].y}) - jitter;
  const double yhi = std::max({t[0].y, t[1].y, t[2].y}) + jitter;
  const auto first_row = static_cast<std::int64_t>(std::floor(ylo / row));
  const auto last_row = static_cast<std::int64_t>(std::ceil(yhi / row));
  // The work is rows plus lattice sites tried, ~perimeter / step + area / step²: for a long
  // needle far more than the points it yields, hence the caller's cap.
  const auto charge = [&](std::int64_t units) {
    if (work == nullptr) return true;
    if (static_cast<std::uint64_t>(units) > *work) return false;
    *work -= static_cast<std::size_t>(units);
    return true;
  };
  for (std::int64_t j = first_row; j <= last_row; ++j) {
    if (!charge(1)) return false;
    const double y0 = static_cast<double>(j) * row;
    // Points of this row move by at most `jitter`: the triangle's part within it of the row.
    const auto [x0, x1] = strip_range(t, y0 - jitter, y0 + jitter);
    if (!(x0 <= x1)) continue;
    const double shift = 0.5 * step * static_cast<double>(j & 1);  // odd rows half a step over
    const auto first = static_cast<std::int64_t>(std::floor((x0 - jitter - shift) / step));
    const auto last = static_cast<std::int64_t>(std::ceil((x1 + jitter - shift) / step));
    if (!charge(last - first + 1)) return false;
    for (std::int64_t i = first; i <= last; ++i) {
      // A site whose whole jitter disk is outside the triangle is skipped before its jitter is
      // drawn (sin and cos are most of a site's cost, and on triangles smaller than the step most
      // sites tried fall outside): a barycentric coordinate moves by at most its gradient's norm
      // times the jitter.
      const double cx = static_cast<double>(i) * step + shift;
      const double s0 = ((cx - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (y0 - t[0].y)) / det;
      const double r0 = ((t[1].x - t[0].x) * (y0 - t[0].y) - (cx - t[0].x) * (t[1].y - t[0].y)) / det;
      if (s0 < -reach_s || r0 < -reach_r || 1 - s0 - r0 < -reach_q) continue;
      // The jitter, uniform in the disk of radius `jitter`, from the lattice index and plane.
      const std::uint64_t h = kernel::mix64(static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ull ^
                                            static_cast<std::uint64_t>(j) * 0xc2b2ae3d27d4eb4full ^
                                            frame.key);
      const double angle = static_cast<double>(h >> 40) * 0x1.0p-24 * 6.283185307179586;
      const double radius = jitter * std::sqrt(static_cast<double>(h & 0xffffff) * 0x1.0p-24);
      const double x = cx + radius * std::cos(angle);
      const double y = y0 + radius * std::sin(angle);
      // Barycentric coordinates in the plane; the point is made from the triangle's own corners,
      // so it lies on the triangle up to rounding.
      const double s = ((x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (y - t[0].y)) / det;
      const double r = ((t[1].x - t[0].x) * (y - t[0].y) - (x - t[0].x) * (t[1].y - t[0].y)) / det;
      if (s >= 0 && r >= 0 && s + r <= 1) out.push_back(a + s * (b - a) + r * (c - a));
    }
  }
  return true;
}

}  // namespace delpsc::refine
