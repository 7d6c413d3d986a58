#include "shapes.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

namespace delpsc::io {

namespace {

// Welds vertices by exact position while a model is generated: every generator computes a shared
// point by the same expression, so "equal doubles" is the right identity and no tolerance is
// involved. -0 is folded into +0 first.
class ShapeBuilder {
 public:
  std::uint32_t vertex(const Vec3& p) {
    const Vec3 q = p + Vec3::Zero();  // -0 + 0 = +0
    Key key;
    std::memcpy(key.bits.data(), q.data(), sizeof(key.bits));
    const auto [it, inserted] = index_.try_emplace(key, static_cast<std::uint32_t>(soup_.vertices.size()));
    if (inserted) soup_.vertices.push_back(q);
    return it->second;
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { soup_.triangles.push_back({a, b, c}); }
  /// Quad a b c d (counter-clockwise), split along a-c.
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  TriangleSoup take() { return std::move(soup_); }

 private:
  struct Key {
    std::array<std::uint64_t, 3> bits;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 0x9e3779b97f4a7c15ull;
      for (auto b : k.bits) h = (h ^ b) * 0xff51afd7ed558ccdull;
      return static_cast<std::size_t>(h ^ (h >> 33));
    }
  };
  TriangleSoup soup_;
  std::unordered_map<Key, std::uint32_t, KeyHash> index_;
};

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("io::shapes: ") + what);
}

// The i-th of n + 1 evenly spaced values from lo to hi, with both ends exact, so that grids
// meeting at a shared line compute the same doubles there.
double lerp_index(double lo, double hi, int i, int n) {
  if (i == 0) return lo;
  if (i == n) return hi;
  return lo + (hi - lo) * i / n;
}

// Adds the grid point(i, j), 0 <= i <= nu, 0 <= j <= nv, as quads (i, j) (i+1, j) (i+1, j+1)
// (i, j+1); the orientation is that of the parametrisation (du x dv).
template <class PointFn>
void add_grid(ShapeBuilder& b, int nu, int nv, PointFn point) {
  std::vector<std::uint32_t> id((nu + 1) * (nv + 1));
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) id[j * (nu + 1) + i] = b.vertex(point(i, j));
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      b.quad(id[j * (nu + 1) + i], id[j * (nu + 1) + i + 1], id[(j + 1) * (nu + 1) + i + 1],
             id[(j + 1) * (nu + 1) + i]);
}

// A planar cap: the closed polygon `boundary` (3D points in one plane) triangulated by `rings`
// rings shrinking towards `centre`; counter-clockwise as seen with the boundary turning
// counter-clockwise, reversed when `flip`. The outermost ring is the boundary itself (exact).
void add_ring_cap(ShapeBuilder& b, const Vec3& centre, const std::vector<Vec3>& boundary, int rings,
                  bool flip) {
  const int m = static_cast<int>(boundary.size());
  auto ring_point = [&](int k, int j) -> Vec3 {
    const Vec3& q = boundary[j % m];
    if (k == rings) return q;
    return centre + (q - centre) * (static_cast<double>(k) / rings);
  };
  auto tri = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    if (flip) b.triangle(x, z, y);
    else b.triangle(x, y, z);
  };
  const std::uint32_t c = b.vertex(centre);
  for (int j = 0; j < m; ++j) tri(c, b.vertex(ring_point(1, j)), b.vertex(ring_point(1, j + 1)));
  for (int k = 2; k <= rings; ++k)
    for (int j = 0; j < m; ++j) {
      const std::uint32_t i0 = b.vertex(ring_point(k - 1, j)), i1 = b.vertex(ring_point(k - 1, j + 1));
      const std::uint32_t o0 = b.vertex(ring_point(k, j)), o1 = b.vertex(ring_point(k, j + 1));
      tri(i0, o0, o1);
      tri(i0, o1, i1);
    }
}

void add_box(ShapeBuilder& b, const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells) {
  auto coord = [&](int axis, int i) { return lerp_index(lo[axis], hi[axis], i, cells[axis]); };
  // Face with normal along +-axis a; (u, v) = the two other axes in cyclic order, so that
  // e_u x e_v = e_a, and swapped on the low side to keep the normal outward.
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      int u = (a + 1) % 3, v = (a + 2) % 3;
      if (side == 0) std::swap(u, v);
      const double fixed = side == 0 ? lo[a] : hi[a];
      add_grid(b, cells[u], cells[v], [&](int i, int j) {
        Vec3 p;
        p[a] = fixed;
        p[u] = coord(u, i);
        p[v] = coord(v, j);
        return p;
      });
    }
  }
}

TriangleSoup append(TriangleSoup a, const TriangleSoup& b) {
  const auto offset = static_cast<std::uint32_t>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return a;
}

double radians(double degrees) { return degrees * std::numbers::pi / 180; }

}  // namespace

TriangleSoup make_box(const Vec3& lo, const Vec3& hi, const std::array<int, 3>& cells) {
  require(cells[0] >= 1 && cells[1] >= 1 && cells[2] >= 1, "make_box: cells must be >= 1");
  require(lo.x() < hi.x() && lo.y() < hi.y() && lo.z() < hi.z(), "make_box: need lo < hi");
  ShapeBuilder b;
  add_box(b, lo, hi, cells);
  return b.take();
}

TriangleSoup make_cube(int n, double size) {
  require(n >= 1, "make_cube: n must be >= 1");
  return make_box(Vec3::Zero(), Vec3::Constant(size), {n, n, n});
}

TriangleSoup make_prism(const std::vector<Eigen::Vector2d>& polygon, double height, double spacing) {
  require(polygon.size() >= 3, "make_prism: need at least 3 polygon vertices");
  require(spacing > 0 && height > 0, "make_prism: need spacing > 0 and height > 0");
  const int m = static_cast<int>(polygon.size());
  std::vector<Eigen::Vector2d> samples;  // boundary, polygon vertices exact
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (int k = 0; k < m; ++k) {
    const Eigen::Vector2d& p = polygon[k];
    const Eigen::Vector2d& q = polygon[(k + 1) % m];
    const int pieces = std::max(1, static_cast<int>(std::ceil((q - p).norm() / spacing)));
    for (int s = 0; s < pieces; ++s)
      samples.push_back(s == 0 ? p : Eigen::Vector2d(p + (q - p) * (static_cast<double>(s) / pieces)));
    centroid += p;
  }
  centroid /= m;
  const int n_side = static_cast<int>(samples.size());
  const int n_up = std::max(1, static_cast<int>(std::ceil(height / spacing)));
  double reach = 0;
  for (const auto& s : samples) reach = std::max(reach, (s - centroid).norm());
  const int rings = std::max(1, static_cast<int>(std::ceil(reach / spacing)));

  ShapeBuilder b;
  auto at = [&](int j, double z) { return Vec3(samples[j % n_side].x(), samples[j % n_side].y(), z); };
  add_grid(b, n_side, n_up, [&](int j, int i) { return at(j, lerp_index(0, height, i, n_up)); });
  std::vector<Vec3> bottom, top;
  for (int j = 0; j < n_side; ++j) {
    bottom.push_back(at(j, 0));
    top.push_back(at(j, height));
  }
  add_ring_cap(b, Vec3(centroid.x(), centroid.y(), 0), bottom, rings, true);
  add_ring_cap(b, Vec3(centroid.x(), centroid.y(), height), top, rings, false);
  return b.take();
}

TriangleSoup make_capped_cylinder(double radius, double height, int around, int along, int rings) {
  require(around >= 8 && along >= 1 && rings >= 1, "make_capped_cylinder: need around >= 8, along >= 1, rings >= 1");
  std::vector<Vec3> circle(around);
  for (int j = 0; j < around; ++j) {
    const double a = 2 * std::numbers::pi * j / around;
    circle[j] = Vec3(radius * std::cos(a), radius * std::sin(a), 0);
  }
  ShapeBuilder b;
  add_grid(b, around, along, [&](int j, int i) {
    Vec3 p = circle[j % around];
    p.z() = lerp_index(0, height, i, along);
    return p;
  });
  std::vector<Vec3> top = circle;
  for (auto& p : top) p.z() = height;
  add_ring_cap(b, Vec3(0, 0, 0), circle, rings, true);
  add_ring_cap(b, Vec3(0, 0, height), top, rings, false);
  return b.take();
}

TriangleSoup make_book(int sheets, int n) {
  require(sheets >= 1 && n >= 1, "make_book: need sheets >= 1 and n >= 1");
  ShapeBuilder b;
  for (int k = 0; k < sheets; ++k) {
    const double a = radians(360.0 * k / sheets + 10);
    const Vec3 dir(std::cos(a), std::sin(a), 0);
    add_grid(b, n, n, [&](int i, int j) {
      return Vec3(dir * lerp_index(0, 1, i, n) + Vec3(0, 0, lerp_index(0, 1, j, n)));
    });
  }
  return b.take();
}

TriangleSoup make_square_sheet(int n) {
  require(n >= 1, "make_square_sheet: n must be >= 1");
  ShapeBuilder b;
  add_grid(b, n, n, [&](int i, int j) { return Vec3(lerp_index(0, 1, i, n), lerp_index(0, 1, j, n), 0); });
  return b.take();
}

TriangleSoup make_pinched_sheet(int n) {
  require(n >= 2 && n % 2 == 0, "make_pinched_sheet: n must be even and >= 2");
  TriangleSoup s = make_square_sheet(n);
  const auto centre = static_cast<std::uint32_t>((n / 2) * (n + 1) + n / 2);
  std::vector<std::size_t> around;
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (const auto v : s.triangles[t])
      if (v == centre) around.push_back(t);
  const auto shares_edge = [&](std::size_t a, std::size_t b) {
    int common = 0;
    for (const auto u : s.triangles[a])
      for (const auto w : s.triangles[b]) common += u == w ? 1 : 0;
    return common == 2;
  };
  for (const std::size_t a : around)
    for (const std::size_t b : around) {
      if (a >= b || shares_edge(a, b)) continue;
      bool common_neighbour = false;
      for (const std::size_t c : around) common_neighbour |= c != a && c != b && shares_edge(a, c) && shares_edge(b, c);
      if (common_neighbour) continue;
      s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(b));
      s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(a));
      return s;
    }
  throw std::logic_error("make_pinched_sheet: no two triangles to drop at the centre");
}

TriangleSoup make_disc_sheet(int around, int rings) {
  require(around >= 8 && rings >= 1, "make_disc_sheet: need around >= 8 and rings >= 1");
  std::vector<Vec3> circle(around);
  for (int j = 0; j < around; ++j) {
    const double a = 2 * std::numbers::pi * j / around;
    circle[j] = Vec3(std::cos(a), std::sin(a), 0);
  }
  ShapeBuilder b;
  add_ring_cap(b, Vec3::Zero(), circle, rings, false);
  return b.take();
}

TriangleSoup make_torus(double R, double r, int nu, int nv) {
  require(nu >= 8 && nv >= 8, "make_torus: need nu >= 8 and nv >= 8");
  require(R > r && r > 0, "make_torus: need R > r > 0");
  ShapeBuilder b;
  add_grid(b, nu, nv, [&](int i, int j) {
    const double u = 2 * std::numbers::pi * (i % nu) / nu, v = 2 * std::numbers::pi * (j % nv) / nv;
    return Vec3((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
  });
  return b.take();
}

TriangleSoup make_sphere(int n) {
  require(n >= 2, "make_sphere: n must be >= 2");
  ShapeBuilder cube;
  add_box(cube, Vec3::Constant(-1), Vec3::Constant(1), {n, n, n});
  TriangleSoup s = cube.take();
  for (auto& p : s.vertices) p.normalize();
  return s;
}

TriangleSoup make_touching_spheres(int n) {
  require(n >= 2 && n % 2 == 0, "make_touching_spheres: n must be even and >= 2");
  TriangleSoup s = make_sphere(n);
  const auto first = static_cast<std::uint32_t>(s.vertices.size());
  const std::size_t triangles = s.triangles.size();
  // 2 - z is exact at z = 1 (the face centre (0, 0, 1) normalises to itself): the two poles are
  // the same point, which the soup's weld makes one vertex.
  for (std::uint32_t i = 0; i < first; ++i) s.vertices.emplace_back(s.vertices[i].x(), s.vertices[i].y(), 2 - s.vertices[i].z());
  for (std::size_t t = 0; t < triangles; ++t) {
    const auto& v = s.triangles[t];
    s.triangles.push_back({v[0] + first, v[2] + first, v[1] + first});
  }
  return s;
}

TriangleSoup make_cone(double half_angle_degrees, int around, int rings) {
  require(half_angle_degrees > 0 && half_angle_degrees < 90 && around >= 8 && rings >= 1,
          "make_cone: need 0 < half-angle < 90 degrees, around >= 8, rings >= 1");
  const double radius = std::tan(radians(half_angle_degrees));
  std::vector<Vec3> base(around);
  for (int j = 0; j < around; ++j) {
    const double a = 2 * std::numbers::pi * j / around;
    base[j] = Vec3(radius * std::cos(a), radius * std::sin(a), 1);
  }
  ShapeBuilder b;
  // The side as a cap over the base circle fanned from the tip: rings of the cone itself.
  add_ring_cap(b, Vec3::Zero(), base, rings, true);
  add_ring_cap(b, Vec3(0, 0, 1), base, rings, false);
  return b.take();
}

TriangleSoup make_cone_on_sheet(double half_angle_degrees, int around, int rings) {
  TriangleSoup cone = make_cone(half_angle_degrees, around, rings);
  // The sheet: the unit disk in z = 0 fanned around the origin, which is the cone's tip (the
  // same doubles, so one vertex once welded below).
  std::vector<Vec3> rim(around);
  for (int j = 0; j < around; ++j) {
    const double a = 2 * std::numbers::pi * j / around;
    rim[j] = Vec3(std::cos(a), std::sin(a), 0);
  }
  ShapeBuilder b;
  for (const auto& t : cone.triangles)
    b.triangle(b.vertex(cone.vertices[t[0]]), b.vertex(cone.vertices[t[1]]), b.vertex(cone.vertices[t[2]]));
  add_ring_cap(b, Vec3::Zero(), rim, rings, false);
  return b.take();
}

TriangleSoup make_hairpin_sheet(double gap, int segments) {
  require(gap > 0 && segments >= 1, "make_hairpin_sheet: need gap > 0 and segments >= 1");
  std::vector<std::pair<double, double>> profile{{0.0, 0.0}};  // (x, z)
  for (int k = 0; k <= segments; ++k) {
    const double a = std::numbers::pi * k / segments;
    profile.emplace_back(1 + gap / 2 * std::sin(a), gap / 2 * (1 - std::cos(a)));
  }
  profile.emplace_back(0.0, gap);
  TriangleSoup soup;
  for (const auto& [x, z] : profile) {
    soup.vertices.emplace_back(x, 0, z);
    soup.vertices.emplace_back(x, 1, z);
  }
  for (std::uint32_t i = 0; i + 1 < profile.size(); ++i) {
    soup.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
    soup.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
  }
  return soup;
}

TriangleSoup make_box_with_fin(int n) {
  require(n >= 1, "make_box_with_fin: n must be >= 1");
  n = (n + 3) / 4 * 4;
  const Vec3 lo(0, 0, 0), hi(2, 1, 1);
  const std::array<int, 3> cells = {2 * n, n, n};
  ShapeBuilder b;
  add_box(b, lo, hi, cells);
  // The fin lies on grid lines of the bottom face, so its attachment edges are box edges.
  add_grid(b, n / 2, n / 2, [&](int j, int k) {
    return Vec3(lerp_index(lo.x(), hi.x(), n, 2 * n), lerp_index(lo.y(), hi.y(), j, n),
                lerp_index(lo.z(), hi.z(), n / 4 + k, n));
  });
  return b.take();
}

TriangleSoup make_wedge(double angle_degrees, double spacing) {
  require(angle_degrees > 0 && angle_degrees < 60, "make_wedge: need 0 < angle < 60 degrees");
  const double h = radians(angle_degrees / 2);
  return make_prism({{0, 0}, {std::cos(h), -std::sin(h)}, {std::cos(h), std::sin(h)}}, 0.5, spacing);
}

TriangleSoup make_crossed_ridges(double gap_fraction, int n) {
  require(n >= 1 && gap_fraction > 0, "make_crossed_ridges: need n >= 1 and gap_fraction > 0");
  const double half_diagonal = std::sqrt(0.5);  // of a unit square face
  const double gap = gap_fraction * std::sqrt(3.0);
  const TriangleSoup cube = make_box(Vec3::Constant(-0.5), Vec3::Constant(0.5), {n, n, n});
  const Eigen::Matrix3d about_x = Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d about_z = Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()).toRotationMatrix();
  TriangleSoup first = cube, second = cube;
  for (auto& p : first.vertices) p = about_x * p;
  const Vec3 lift(0, 2 * half_diagonal + gap, 0);
  for (auto& p : second.vertices) p = about_z * p + lift;
  return append(std::move(first), second);
}

TriangleSoup make_short_curve_prism(double cut, double spacing) {
  require(cut > 0 && cut < 0.5, "make_short_curve_prism: need 0 < cut < 0.5");
  const double h = radians(15);
  const double t = std::tan(h);
  return make_prism({{cut, -cut * t}, {std::cos(h), -std::sin(h)}, {std::cos(h), std::sin(h)}, {cut, cut * t}},
                    0.5, spacing);
}

TriangleSoup make_pleated_sheet(double wedge_degrees, double rise) {
  require(wedge_degrees > 0 && wedge_degrees < 10 && rise > 0, "make_pleated_sheet: need 0 < wedge < 10 and rise > 0");
  std::vector<Vec3> boundary;
  for (const double degrees : {0.0, 45.0, 90.0, 100.0, 100.0 - wedge_degrees, 135.0, 180.0, 225.0, 270.0, 315.0}) {
    const double a = radians(degrees);
    const double z = degrees == 100.0 ? rise : degrees == 100.0 - wedge_degrees ? -2 * rise : 0.0;
    boundary.emplace_back(std::cos(a), std::sin(a), z);
  }
  ShapeBuilder b;
  add_ring_cap(b, Vec3::Zero(), boundary, 3, false);
  return b.take();
}

}  // namespace delpsc::io
