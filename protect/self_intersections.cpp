#include "self_intersections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/kernel/predicates.h>

#include "complex_build.h"

namespace delpsc::protect {

namespace {

bool segment_meets(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& t, bool coplanar) {
  return coplanar ? kernel::coplanar_segment_meets_triangle(p, q, t[0], t[1], t[2])
                  : static_cast<bool>(kernel::intersect_segment_triangle(p, q, t[0], t[1], t[2]));
}

/// Does edge k of x (opposite its vertex k) meet the closed triangle y?
bool opposite_edge_meets(const std::array<Vec3, 3>& x, int k, const std::array<Vec3, 3>& y, bool coplanar) {
  return segment_meets(x[(k + 1) % 3], x[(k + 2) % 3], y, coplanar);
}

enum class Sides { one_side, coplanar, other };

/// Where the vertices of y from `first` on (cyclically, `count` of them) lie against x's plane:
/// all strictly on one side, all on it, or otherwise. A degenerate x (collinear corners, which
/// the complex leaves out) has no plane: `other`, so that the callers take the general tests.
/// Exact.
Sides sides(const std::array<Vec3, 3>& x, const std::array<Vec3, 3>& y, int first, int count) {
  const int side = kernel::orient3d(x[0], x[1], x[2], y[first]);
  for (int k = 1; k < count; ++k)
    if (kernel::orient3d(x[0], x[1], x[2], y[(first + k) % 3]) != side) return Sides::other;
  if (side != 0) return Sides::one_side;
  return kernel::collinear(x[0].data(), x[1].data(), x[2].data()) ? Sides::other : Sides::coplanar;
}

// A vertex of at least this many triangles is worth certifying as a fan (below).
constexpr std::size_t kFanDegree = 16;

/// Per vertex v: whether its triangles, seen along an axis through v, cover angular sectors that
/// meet only along edges they share - so that any two of them sharing only v meet only there,
/// and two sharing an edge only along it, which the pair test below would find after a few exact
/// tests per pair. The pairs are what costs: a fan of d triangles around one vertex (a cap of a
/// CAD cylinder, a convex polygon fanned by the reader, the side of a cone around its apex) has
/// d²/2 of them, all overlapping boxes (20,000 made the check run 50 s on a flat cap, 24 s on a
/// cone). O(d log d) exact tests per vertex of degree at least kFanDegree; others are never
/// certified.
///
/// Why the sectors suffice. The axis is the line through v and a point w (any point off v would
/// do; the two tried below make the test succeed on flat fans and cones). A triangle (v, x, y)
/// with orient3d(v, w, x, y) != 0 has a plane that does not contain the axis' direction, so the
/// projection along the axis maps it one to one onto a triangle of the projection plane with a
/// corner at v's image and an angle below pi there; orient3d(v, w, x, y) is the exact sign of
/// that angle. If the sectors of two triangles that share only v meet only at v's image, a point
/// of both projects there, and within each triangle only v does; two sectors that share the ray
/// of a common vertex x meet only on it, whose preimage in each triangle is the edge vx. For a
/// flat fan the axis crosses the plane and the projection is the plane itself, seen askew.
std::vector<char> certified_fans(const Complex& complex) {
  const std::size_t nv = complex.vertices.size();
  // Each vertex's triangles, in one flat array (offsets as the complex's builders make them).
  kernel::LargeVector<std::uint32_t> triangles_at(nv, 0);
  for (const auto& t : complex.triangles)
    for (const std::uint32_t v : t) ++triangles_at[v];
  const kernel::LargeVector<std::uint32_t> first = detail::offsets_from_counts(triangles_at);
  kernel::LargeVector<std::uint32_t> around(first.back());
  {
    kernel::LargeVector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t t = 0; t < complex.triangles.size(); ++t)
      for (const std::uint32_t v : complex.triangles[t]) around[fill[v]++] = t;
  }
  std::vector<char> certified(nv, 0);
  struct Sector {
    std::uint32_t start, end;  // the other two vertices, counter-clockwise seen in the projection
  };
  std::vector<Sector> sectors;
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::size_t degree = first[v + 1] - first[v];
    if (degree < kFanDegree) continue;
    const double* c = complex.vertices[v].data();
    const auto others = [&](std::uint32_t t) {
      const auto& tri = complex.triangles[t];
      const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
      return std::array<std::uint32_t, 2>{tri[(k + 1) % 3], tri[(k + 2) % 3]};
    };
    const auto point = [&](std::uint32_t u) { return complex.vertices[u].data(); };
    // Two axes are tried: through v and w = v + the sum of the triangles' normals as given
    // (the axis of a consistently oriented cone, however steep), then + the sum with each normal
    // turned to agree with the first one's (a flat fan or a shallow cone in any orientation).
    // Any w off v is exact input to the tests below; a good one is far from every triangle's
    // plane.
    const Vec3& centre = complex.vertices[v];
    Vec3 as_given = Vec3::Zero(), agreeing = Vec3::Zero(), reference = Vec3::Zero();
    for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
      const auto [x, y] = others(around[i]);
      const Vec3 n = (complex.vertices[x] - centre).cross(complex.vertices[y] - centre);
      if (i == first[v]) reference = n;
      as_given += n;
      agreeing += n.dot(reference) < 0 ? Vec3(-n) : n;
    }
    const auto [p0, q0] = others(around[first[v]]);
    const double length = (complex.vertices[p0] - centre).norm();
    if (!(length > 0) || !std::isfinite(length)) continue;
    const auto disjoint_around = [&](const Vec3& normal) {
      const double size = normal.norm();
      if (!(size > 0) || !std::isfinite(size)) return false;
      const Vec3 axis_point = centre + (length / size) * normal;
      const double* w = axis_point.data();
      if (axis_point == centre || !axis_point.allFinite()) return false;
      const auto turn = [&](std::uint32_t x, std::uint32_t y) { return kernel::orient3d(c, w, point(x), point(y)); };
      sectors.clear();
      for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
        const auto [x, y] = others(around[i]);
        const int o = turn(x, y);
        if (o == 0) return false;  // a triangle whose plane holds the axis: its sector is no sector
        sectors.push_back(o > 0 ? Sector{x, y} : Sector{y, x});
      }
      // Directions around the axis by angle from the first sector's start r: [0, pi) then
      // [pi, 2 pi), each half ordered by the turn (exact; within a half two directions differ
      // by less than pi).
      const std::uint32_t r = sectors[0].start;
      // Whether x (in the plane of the axis and r, given turn(r, x) == 0, and off the axis as
      // every vertex here is) lies on r's side of the axis in that plane: on r's side of a
      // second plane through the axis, one that misses r (exact; some coordinate direction is
      // one).
      int r_side = 0;
      Vec3 side_point;
      for (int k = 0; k < 3 && r_side == 0; ++k) {
        side_point = centre + length * Vec3::Unit(k);
        r_side = kernel::orient3d(c, w, side_point.data(), point(r));
      }
      if (r_side == 0) return false;
      const auto same_way = [&](std::uint32_t x) { return kernel::orient3d(c, w, side_point.data(), point(x)) == r_side; };
      const auto half = [&](std::uint32_t x) {
        const int o = turn(r, x);
        return o > 0 || (o == 0 && same_way(x)) ? 0 : 1;
      };
      const auto before = [&](std::uint32_t x, std::uint32_t y) {
        const int hx = half(x), hy = half(y);
        return hx != hy ? hx < hy : turn(x, y) > 0;
      };
      std::sort(sectors.begin(), sectors.end(), [&](const Sector& s, const Sector& t) { return before(s.start, t.start); });
      // Disjoint: consecutive starts strictly increasing; a sector ends at the next one's start
      // vertex (a shared edge) or strictly before it; none wraps past r but the last, which
      // then ends at r's own vertex.
      for (std::size_t i = 0; i < sectors.size(); ++i) {
        const Sector& s = sectors[i];
        const bool wraps = before(s.end, s.start);
        if (i + 1 < sectors.size()) {
          const Sector& next = sectors[i + 1];
          if (wraps || !before(s.start, next.start) || !(s.end == next.start || before(s.end, next.start))) return false;
        } else if (wraps && s.end != sectors[0].start) {
          return false;
        }
      }
      return true;
    };
    certified[v] = disjoint_around(as_given) || disjoint_around(agreeing);
  }
  return certified;
}

}  // namespace

bool triangles_intersect_improperly(const std::array<Vec3, 3>& a, const std::array<std::uint32_t, 3>& ia,
                                    const std::array<Vec3, 3>& b, const std::array<std::uint32_t, 3>& ib) {
  std::array<int, 3> in_b{-1, -1, -1};  // position in b of each vertex of a, -1 if not shared
  int shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ia[i] == ib[j]) {
        in_b[i] = j;
        ++shared;
      }
  switch (shared) {
    case 0: {
      // One triangle strictly on one side of the other's plane: disjoint. Three orient3d each
      // way settle most pairs whose boxes overlap, before the six edge tests below; b in a's
      // plane makes them coplanar, tested in that plane without orient3d's exact zeros.
      const Sides b_to_a = sides(a, b, 0, 3);
      if (b_to_a == Sides::one_side || (b_to_a == Sides::other && sides(b, a, 0, 3) == Sides::one_side)) return false;
      const bool coplanar = b_to_a == Sides::coplanar;
      // Two closed triangles meet iff an edge of one meets the other: a non-empty intersection
      // is convex, and a point of it extreme along any line lies on an edge of one of them.
      for (int k = 0; k < 3; ++k)
        if (opposite_edge_meets(a, k, b, coplanar) || opposite_edge_meets(b, k, a, coplanar)) return true;
      return false;
    }
    case 1: {
      // Sharing vertex v: if they also share p != v, follow the ray from v through p until it
      // leaves one of them, say a, at x. x is in b, and it lies on a's edge opposite v (when the
      // ray runs along an edge of a through v, x is that edge's far vertex, also on the opposite
      // edge). The converse holds since v is on neither opposite edge.
      const int i = static_cast<int>(std::find_if(in_b.begin(), in_b.end(), [](int j) { return j >= 0; }) - in_b.begin());
      // b's other two vertices strictly on one side of a's plane: b meets that plane only at v,
      // so the triangles meet only there (the usual case between neighbours of a curved surface);
      // likewise with a and b swapped. Both on it: the two are coplanar (the flat regions of CAD
      // models).
      const int j = in_b[i];
      const Sides b_to_a = sides(a, b, (j + 1) % 3, 2);
      if (b_to_a == Sides::one_side || (b_to_a == Sides::other && sides(b, a, (i + 1) % 3, 2) == Sides::one_side))
        return false;
      const bool coplanar = b_to_a == Sides::coplanar;
      return opposite_edge_meets(a, i, b, coplanar) || opposite_edge_meets(b, j, a, coplanar);
    }
    case 2: {
      // Sharing edge uv: in different planes they meet exactly in uv; in one plane they overlap
      // iff their third vertices are on the same side of uv (a fold).
      const int i = static_cast<int>(std::find(in_b.begin(), in_b.end(), -1) - in_b.begin());
      int j = 0;
      while (ib[j] == ia[(i + 1) % 3] || ib[j] == ia[(i + 2) % 3]) ++j;
      const Vec3& u = a[(i + 1) % 3];
      const Vec3& v = a[(i + 2) % 3];
      if (kernel::orient3d(u, v, a[i], b[j]) != 0) return false;
      return kernel::coplanar_orientation(u.data(), v.data(), a[i].data(), b[j].data()) > 0;
    }
    default:
      return true;  // the same triangle twice
  }
}

std::vector<std::array<std::uint32_t, 2>> find_self_intersections(const Complex& complex, std::size_t max_pairs) {
  return find_self_intersections(complex, kernel::AabbTree(complex.vertices, complex.triangles), max_pairs);
}

std::vector<std::array<std::uint32_t, 2>> find_self_intersections(const Complex& complex, const kernel::AabbTree& tree,
                                                                  std::size_t max_pairs) {
  return find_input_defects(complex, tree, max_pairs, 0).crossing;
}

std::optional<std::array<std::uint32_t, 2>> find_near_contact(const Complex& complex, double tolerance) {
  return find_near_contact(complex, kernel::AabbTree(complex.vertices, complex.triangles), tolerance);
}

std::optional<std::array<std::uint32_t, 2>> find_near_contact(const Complex& complex, const kernel::AabbTree& tree,
                                                               double tolerance) {
  return find_input_defects(complex, tree, 0, tolerance).near_contact;
}

InputDefects find_input_defects(const Complex& complex, const kernel::AabbTree& tree, std::size_t max_pairs,
                                double tolerance, const std::function<bool()>& stop) {
  InputDefects found;
  const bool near = tolerance > 0;  // false for NaN too
  if (complex.triangles.empty() || (max_pairs == 0 && !near)) return found;
  std::vector<std::array<std::uint32_t, 2>>& pairs = found.crossing;
  std::optional<std::array<std::uint32_t, 2>>& closest = found.near_contact;
  const auto corners = [&](std::uint32_t t) {
    const auto& tri = complex.triangles[t];
    return std::array<Vec3, 3>{complex.vertices[tri[0]], complex.vertices[tri[1]], complex.vertices[tri[2]]};
  };
  const double tolerance2 = tolerance * tolerance;
  const std::vector<char> fan = max_pairs > 0 ? certified_fans(complex) : std::vector<char>{};
  // Two triangles sharing exactly one vertex, a certified fan's centre: they meet only there.
  const auto only_fan_centre = [&](const std::array<std::uint32_t, 3>& ia, const std::array<std::uint32_t, 3>& ib) {
    std::uint32_t shared = 0, count = 0;
    for (const std::uint32_t x : ia)
      if (x == ib[0] || x == ib[1] || x == ib[2]) shared = x, ++count;
    return count == 1 && fan[shared];
  };
  // Each vertex is tested from one of its triangles only, its first: a triangle t near vertex v
  // pairs with every triangle of v (each box holds v), so with that one too, and no (v, t) is
  // tested twice (a CAD vertex has up to dozens of triangles, each pairing with t).
  constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint32_t> owner(near ? complex.vertices.size() : 0, kNone);
  for (std::uint32_t t = 0; near && t < complex.triangles.size(); ++t)
    for (const std::uint32_t v : complex.triangles[t])
      if (owner[v] == kNone) owner[v] = t;
  // Vertex v (at p) of one triangle against triangle t (corners c, ids it) of the pair: a near
  // contact when v is no corner of t and lies within the tolerance of it but not on it. The
  // smallest such (v, t) is kept, so the answer does not depend on the descent's order.
  const auto near_vertex = [&](std::uint32_t v, const Vec3& p, std::uint32_t t, const std::array<Vec3, 3>& c,
                               const std::array<std::uint32_t, 3>& it) {
    if (v == it[0] || v == it[1] || v == it[2]) return;
    const std::array<std::uint32_t, 2> candidate{v, t};
    if (closest && !(candidate < *closest)) return;
    // Outside t's box grown by the tolerance: farther than it (and a box query per vertex
    // tested the same).
    for (int k = 0; k < 3; ++k)
      if (p[k] < std::min({c[0][k], c[1][k], c[2][k]}) - tolerance ||
          p[k] > std::max({c[0][k], c[1][k], c[2][k]}) + tolerance)
        return;
    const double d2 = (p - kernel::closest_point_on_triangle(p, c[0], c[1], c[2]).point).squaredNorm();
    if (d2 > 0 && d2 < tolerance2) closest = candidate;
  };
  // A certified fan's own pairs meet only at its centre or along an edge they share: none is
  // tested, and the descent below leaves them out whole (a fan of d triangles: d²/2 pairs, all
  // boxes overlapping - 4e8 on a cylinder whose caps were fanned from 20,000 rim points, 5 s).
  // Each triangle joins the fan of its smallest certified corner; pairs across two fans are
  // tested as before.
  constexpr std::uint32_t kNoFan = kernel::AabbTree::kNoGroup;
  std::vector<std::uint32_t> fan_of;
  if (std::find(fan.begin(), fan.end(), 1) != fan.end()) {
    fan_of.assign(complex.triangles.size(), kNoFan);
    for (std::uint32_t t = 0; t < complex.triangles.size(); ++t)
      for (const std::uint32_t v : complex.triangles[t])
        if (fan[v]) fan_of[t] = std::min(fan_of[t], v);
  }
  struct Stopped {};  // thrown out of the descent when `stop` says so
  // Near contacts between a fan's own triangles, which the descent no longer pairs: each vertex
  // whose owner is in a fan against that fan's triangles near it (a box query: the triangles
  // whose box meets the vertex's, grown by twice the tolerance for rounding; near_vertex decides).
  const auto near_within_fans = [&] {
    std::vector<std::uint32_t> hits;
    for (std::uint32_t v = 0; v < owner.size(); ++v) {
      if (stop && (v & 0xfffu) == 0xfffu && stop()) throw Stopped{};
      if (owner[v] == kNone || fan_of[owner[v]] == kNoFan) continue;
      const Vec3& p = complex.vertices[v];
      kernel::Box3 box;
      box.extend(p - Vec3::Constant(2 * tolerance));
      box.extend(p + Vec3::Constant(2 * tolerance));
      hits.clear();
      tree.triangles_in_box(box, hits);
      for (const std::uint32_t t : hits)
        if (fan_of[t] == fan_of[owner[v]]) near_vertex(v, p, t, corners(t), complex.triangles[t]);
    }
  };
  // Every box-overlapping pair once, from the tree against itself (a box query per triangle cost
  // twice as much), the boxes grown by the tolerance so that a vertex near a triangle pairs one
  // of its own triangles with that one (it lies in its own triangles' boxes). The max_pairs
  // smallest pairs that intersect are kept in a max-heap, so the crossing pairs are what a scan
  // in order of (first, second) stopping at max_pairs would give. One descent for both checks:
  // the near contacts took a box query per vertex, a quarter of the checks on a million
  // triangles.
  std::size_t visited = 0;
  try {
  if (near && !fan_of.empty()) near_within_fans();
  tree.for_each_overlapping_pair(
      [&](std::uint32_t x, std::uint32_t y) {
        if (stop && (++visited & 0xfffu) == 0 && stop()) throw Stopped{};
        const std::array<std::uint32_t, 2> pair{std::min(x, y), std::max(x, y)};
        const auto& ia = complex.triangles[pair[0]];
        const auto& ib = complex.triangles[pair[1]];
        // What this pair is asked, decided before the corners are read (a fan's pairs are most
        // of the pairs, and need neither test).
        const bool crossing = max_pairs > 0 && !(pairs.size() == max_pairs && !(pair < pairs.front())) &&
                              !only_fan_centre(ia, ib);
        bool owns = false;
        for (int k = 0; near && k < 3; ++k) owns |= owner[ia[k]] == pair[0] || owner[ib[k]] == pair[1];
        if (!crossing && !owns) return;
        const std::array<Vec3, 3> a = corners(pair[0]), b = corners(pair[1]);
        if (owns)
          for (int k = 0; k < 3; ++k) {
            if (owner[ia[k]] == pair[0]) near_vertex(ia[k], a[k], pair[1], b, ib);
            if (owner[ib[k]] == pair[1]) near_vertex(ib[k], b[k], pair[0], a, ia);
          }
        if (!crossing || !triangles_intersect_improperly(a, ia, b, ib)) return;
        pairs.push_back(pair);
        std::push_heap(pairs.begin(), pairs.end());
        if (pairs.size() > max_pairs) {
          std::pop_heap(pairs.begin(), pairs.end());
          pairs.pop_back();
        }
      },
      near ? tolerance : 0, fan_of);
  } catch (const Stopped&) {
    found.stopped = true;
  }
  std::sort_heap(pairs.begin(), pairs.end());
  return found;
}

}  // namespace delpsc::protect
