#include "sample_part.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace delpsc::io {

namespace {

constexpr double kLength = 4, kWidth = 2, kHeight = 1;  // the block [0,4] x [0,2] x [0,1]
constexpr double kHoleRadius = 0.45;
constexpr double kFinHeight = 0.6;

// Rounds to a multiple of 2^-20: a 1-ulp difference in sin or cos between C libraries then
// (almost surely) vanishes, and samples/part.off is the same file everywhere.
double snap(double x) {
  constexpr double scale = 1 << 20;
  return std::round(x * scale) / scale + 0.0;  // + 0.0 folds -0 into +0
}

// Collects the part's triangles with one index per point. All copies of a shared point are
// computed by the same expression from the same integers, so equality of the snapped doubles
// is the right identity.
class PartBuilder {
 public:
  std::uint32_t vertex(const Vec3& p) {
    const std::array<double, 3> key{snap(p.x()), snap(p.y()), snap(p.z())};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<std::uint32_t>(soup_.vertices.size()));
    if (inserted) soup_.vertices.emplace_back(key[0], key[1], key[2]);
    return it->second;
  }
  /// Quad a b c d, counter-clockwise seen from the side its normal points to, split along its
  /// shorter diagonal (the O-grid's quads near the squares' corners are skewed).
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const std::uint32_t ia = vertex(a), ib = vertex(b), ic = vertex(c), id = vertex(d);
    if ((a - c).squaredNorm() <= (b - d).squaredNorm()) {
      soup_.triangles.push_back({ia, ib, ic});
      soup_.triangles.push_back({ia, ic, id});
    } else {
      soup_.triangles.push_back({ia, ib, id});
      soup_.triangles.push_back({ib, ic, id});
    }
  }
  TriangleSoup take() { return std::move(soup_); }

 private:
  TriangleSoup soup_;
  std::map<std::array<double, 3>, std::uint32_t> index_;
};

// Positions on the lattice of the block's outline: x = 4 i / nx, y = 2 j / ny, z = k / nz.
// Every point on a lattice line is computed from its integer index, never accumulated.
struct Lattice {
  int nx, ny, nz;
  double x(int i) const { return kLength * i / nx; }
  double y(int j) const { return kWidth * j / ny; }
  double z(int k) const { return kHeight * k / nz; }
};

// The k-th of the 4m points of the outline of an m x m lattice square, counter-clockwise from
// the middle of its right side (m even): (i, j) offsets within the square. Point k sits at the
// direction 2 pi k / 4m from the square's centre up to the corners, which fall at the 45°
// directions: exactly where the hole's k-th point looks.
std::array<int, 2> square_outline(int k, int m) {
  const int half = m / 2;
  if (k <= half) return {m, half + k};  // right side, going up
  k -= half;
  if (k <= m) return {m - k, m};  // top, going left
  k -= m;
  if (k <= m) return {0, m - k};  // left, going down
  k -= m;
  if (k <= m) return {k, 0};  // bottom, going right
  k -= m;
  return {m, k};  // right side again, up to its middle
}

// Top and bottom faces of the square around hole h (x from 2h to 2h + 2): rings of quads from
// the hole's polygon out to the square's outline.
void add_o_grids(PartBuilder& b, const Lattice& lat, int h, int around, int rings) {
  const int m = around / 4;
  const double cx = 2.0 * h + 1, cy = 1;
  auto ring_point = [&](int k, int r, double z) -> Vec3 {
    k %= around;
    const double angle = 2 * std::numbers::pi * k / around;
    const Vec3 inner(cx + kHoleRadius * std::cos(angle), cy + kHoleRadius * std::sin(angle), z);
    const auto [i, j] = square_outline(k, m);
    const Vec3 outer(lat.x(h * m + i), lat.y(j), z);
    if (r == 0) return inner;
    if (r == rings) return outer;
    return inner + (outer - inner) * (static_cast<double>(r) / rings);
  };
  for (int k = 0; k < around; ++k)
    for (int r = 0; r < rings; ++r) {
      // Seen from +z: k + 1 is counter-clockwise of k, r + 1 outside r.
      const double top = lat.z(lat.nz), bottom = lat.z(0);
      b.quad(ring_point(k, r, top), ring_point(k, r + 1, top), ring_point(k + 1, r + 1, top),
             ring_point(k + 1, r, top));
      b.quad(ring_point(k, r, bottom), ring_point(k + 1, r, bottom), ring_point(k + 1, r + 1, bottom),
             ring_point(k, r + 1, bottom));
    }
}

// The wall of hole h, facing the hole's axis (outward from the material).
void add_hole_wall(PartBuilder& b, const Lattice& lat, int h, int around) {
  const double cx = 2.0 * h + 1, cy = 1;
  auto point = [&](int k, int l) -> Vec3 {
    const double angle = 2 * std::numbers::pi * (k % around) / around;
    return {cx + kHoleRadius * std::cos(angle), cy + kHoleRadius * std::sin(angle), lat.z(l)};
  };
  for (int k = 0; k < around; ++k)
    for (int l = 0; l < lat.nz; ++l)
      b.quad(point(k, l), point(k, l + 1), point(k + 1, l + 1), point(k + 1, l));
}

// The four outer sides, walking the outline counter-clockwise seen from +z.
void add_sides(PartBuilder& b, const Lattice& lat) {
  std::vector<std::array<int, 2>> outline;
  for (int i = 0; i < lat.nx; ++i) outline.push_back({i, 0});
  for (int j = 0; j < lat.ny; ++j) outline.push_back({lat.nx, j});
  for (int i = lat.nx; i > 0; --i) outline.push_back({i, lat.ny});
  for (int j = lat.ny; j > 0; --j) outline.push_back({0, j});
  const std::size_t n = outline.size();
  for (std::size_t k = 0; k < n; ++k) {
    const auto [i0, j0] = outline[k];
    const auto [i1, j1] = outline[(k + 1) % n];
    for (int l = 0; l < lat.nz; ++l)
      b.quad({lat.x(i0), lat.y(j0), lat.z(l)}, {lat.x(i1), lat.y(j1), lat.z(l)},
             {lat.x(i1), lat.y(j1), lat.z(l + 1)}, {lat.x(i0), lat.y(j0), lat.z(l + 1)});
  }
}

// The fin: a one-sided sheet in the plane x = 2 on the lattice line shared by the two O-grids,
// from y = 1/2 to 3/2, so its lower edge is a chain of the top face's edges.
void add_fin(PartBuilder& b, const Lattice& lat) {
  const int j0 = lat.ny / 4, j1 = 3 * lat.ny / 4;
  const int layers = std::max(1, static_cast<int>(std::lround(kFinHeight * lat.nz)));
  const double x = lat.x(lat.nx / 2), top = lat.z(lat.nz);
  auto z = [&](int l) { return l == 0 ? top : top + kFinHeight * l / layers; };
  for (int j = j0; j < j1; ++j)
    for (int l = 0; l < layers; ++l)
      b.quad({x, lat.y(j), z(l)}, {x, lat.y(j + 1), z(l)}, {x, lat.y(j + 1), z(l + 1)},
             {x, lat.y(j), z(l + 1)});
}

}  // namespace

TriangleSoup make_sample_part(int around) {
  if (around < 16 || around % 16 != 0)
    throw std::invalid_argument("io::make_sample_part: around must be a multiple of 16, >= 16");
  // Square lattice cells of side 8 / around on the outline (each hole square has around / 4
  // per side), around / 8 per unit of height.
  const Lattice lat{around / 2, around / 4, around / 8};
  const int rings = around / 8;
  PartBuilder b;
  for (int h = 0; h < 2; ++h) {
    add_o_grids(b, lat, h, around, rings);
    add_hole_wall(b, lat, h, around);
  }
  add_sides(b, lat);
  add_fin(b, lat);
  return b.take();
}

}  // namespace delpsc::io
