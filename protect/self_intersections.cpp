#include "self_intersections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <delpsc/kernel/aabb_tree.h>
#include <delpsc/kernel/constructions.h>
#include <delpsc/kernel/predicates.h>

#include "certified_fans.h"
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

// A vertex of at least this many triangles is worth certifying as a fan (certified_fans.h): the
// pairs of a fan of d triangles are d²/2 (20,000 made the check run 50 s on a flat cap of a CAD
// cylinder, 24 s on a cone); below, the certificate costs more than the pairs.
constexpr std::size_t kFanDegree = 16;

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

std::optional<Vec3> improper_contact_point(const std::array<Vec3, 3>& a, const std::array<std::uint32_t, 3>& ia,
                                           const std::array<Vec3, 3>& b, const std::array<std::uint32_t, 3>& ib) {
  // The shared vertices, and the size against which "on" one of them is judged.
  std::vector<Vec3> shared;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (ia[i] == ib[j]) shared.push_back(a[i]);
  kernel::Box3 box;
  for (const Vec3& p : a) box.extend(p);
  for (const Vec3& p : b) box.extend(p);
  const double tolerance = 1e-9 * box.diagonal();
  const auto on_shared = [&](const Vec3& p) {
    for (const Vec3& v : shared)
      if ((p - v).norm() <= tolerance) return true;
    if (shared.size() == 2) {  // on the shared edge
      const Vec3 d = shared[1] - shared[0];
      const double s = std::clamp((p - shared[0]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      return (shared[0] + s * d - p).norm() <= tolerance;
    }
    return false;
  };
  for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}})
    for (int k = 0; k < 3; ++k) {
      const Vec3 &p = (*x)[(k + 1) % 3], &q = (*x)[(k + 2) % 3];
      const kernel::TriangleHit hit = kernel::intersect_segment_triangle(p, q, (*y)[0], (*y)[1], (*y)[2]);
      if (!hit) continue;
      std::vector<Vec3> candidates{hit.point};
      if (hit.contact == kernel::Contact::coplanar)
        for (const double t : {hit.t_exit, (hit.t + hit.t_exit) / 2}) candidates.push_back(p + t * (q - p));
      for (const Vec3& c : candidates)
        if (!on_shared(c)) return c;
    }
  return std::nullopt;
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
                                double tolerance, const std::function<bool()>& stop, CrossingPairs which) {
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
  std::vector<std::uint32_t> fan_at;  // per vertex: its fan's index, or kNoFan
  const std::vector<detail::Fan> fans =
      max_pairs > 0 ? detail::certify_fans(complex, kFanDegree, fan_at) : std::vector<detail::Fan>{};
  // Which of each triangle's corners are centres of fans it belongs to (bit k for corner k): a
  // fan may hold only part of its centre's star (certified_fans.h).
  std::vector<std::uint8_t> member_at(fans.empty() ? 0 : complex.triangles.size(), 0);
  for (const detail::Fan& fan : fans)
    for (const detail::Fan::Sector& s : fan.sectors) {
      const auto& tri = complex.triangles[s.triangle];
      member_at[s.triangle] |= static_cast<std::uint8_t>(tri[0] == fan.centre ? 1 : tri[1] == fan.centre ? 2 : 4);
    }
  // Two triangles sharing exactly one vertex, the centre of a certified fan holding both: they
  // meet only there.
  const auto only_fan_centre = [&](std::uint32_t a, std::uint32_t b) {
    const auto &ia = complex.triangles[a], &ib = complex.triangles[b];
    int shared_a = -1, shared_b = -1, count = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (ia[i] == ib[j]) shared_a = i, shared_b = j, ++count;
    return count == 1 && (member_at[a] >> shared_a & 1) != 0 && (member_at[b] >> shared_b & 1) != 0;
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
    // A distance that rounds to 0 is not a touch unless the exact test says so: a vertex 1.5e-17
    // off a triangle's edge (an exporter's rounding) was let through as touching, no crossing
    // was found either, and Protect spent 10 s and 1 GB on balls to separate the two curves.
    if (d2 < tolerance2 && (d2 > 0 || !kernel::intersect_segment_triangle(p, p, c[0], c[1], c[2]))) closest = candidate;
  };
  // A certified fan's own pairs meet only at its centre or along an edge they share: none is
  // tested. Each triangle joins the first certified fan holding it (fan_of, a fan's index),
  // and the descent below leaves out every pair of two triangles of fans, whole subtrees at a
  // time (one group for them all): a fan of d triangles has d²/2 pairs, all boxes overlapping -
  // 4e8 on a cylinder whose caps were fanned from 20,000 rim points, 5 s - and a cone's side and
  // its base fanned from the centre d² across the two, 20 s. Pairs across two fans are searched
  // by angle instead (across_fans).
  constexpr std::uint32_t kNoFan = detail::kNoFan;
  std::vector<std::uint32_t> fan_of, in_a_fan;
  if (!fans.empty()) {
    fan_of.assign(complex.triangles.size(), kNoFan);
    in_a_fan.assign(complex.triangles.size(), kernel::AabbTree::kNoGroup);
    for (std::uint32_t f = static_cast<std::uint32_t>(fans.size()); f-- > 0;)
      for (const detail::Fan::Sector& s : fans[f].sectors) {
        fan_of[s.triangle] = f;
        in_a_fan[s.triangle] = 0;
      }
  }
  struct Stopped {};  // thrown out of the descent when `stop` says so
  struct Enough {};   // thrown when max_pairs were found and any of them will do
  // Each fan's box: of the triangles it is the first fan of.
  std::vector<kernel::Box3> fan_box(fans.size());
  for (std::uint32_t t = 0; t < fan_of.size(); ++t)
    if (fan_of[t] != kNoFan)
      for (const std::uint32_t v : complex.triangles[t]) fan_box[fan_of[t]].extend(complex.vertices[v]);
  const auto box_of = [&](std::uint32_t t) {
    kernel::Box3 box;
    for (const std::uint32_t v : complex.triangles[t]) box.extend(complex.vertices[v]);
    return box;
  };
  // Fans searched whole, their triangles left out of the descent altogether: those whose own
  // triangles' boxes meet many more triangles of no fan (the descent's pairs for them) than the
  // fan's box holds (the whole search's). The chords of a cap fanned from a rim point are long,
  // and each box holds much of the rim's side triangles (d²/4 pairs on a cylinder, each tested
  // exactly: 5 s at 20,000 rim points). Their pairs with triangles of no fan are searched by
  // angle then (whole_fans), and their near contacts by angle (near_within_fans) or by vertex
  // (near_owned_by_whole).
  std::vector<char> whole(fans.size(), 0);
  {
    std::vector<std::uint32_t> own, near_box;
    std::vector<kernel::Box3> near_boxes;
    for (std::uint32_t f = 0; f < fans.size(); ++f) {
      if (stop && stop()) {  // a query of the fan's box each, before the search's try below
        found.stopped = true;
        return found;
      }
      own.clear();
      for (const detail::Fan::Sector& s : fans[f].sectors)
        if (fan_of[s.triangle] == f) own.push_back(s.triangle);
      if (own.empty()) continue;
      near_box.clear();
      tree.triangles_in_box(fan_box[f], near_box);
      near_boxes.clear();
      for (const std::uint32_t y : near_box)
        if (fan_of[y] == kNoFan) near_boxes.push_back(box_of(y));
      // The descent's pairs, estimated from own triangles spread over the fan.
      constexpr std::size_t kSamples = 8;
      std::size_t met = 0;
      for (std::size_t i = 0; i < kSamples; ++i) {
        const kernel::Box3 box = box_of(own[i * own.size() / kSamples]);
        met += static_cast<std::size_t>(
            std::count_if(near_boxes.begin(), near_boxes.end(), [&](const kernel::Box3& b) { return b.overlaps(box); }));
      }
      whole[f] = met * own.size() > 8 * kSamples * std::max<std::size_t>(near_boxes.size(), 1);
      if (whole[f])
        for (const std::uint32_t t : own) in_a_fan[t] = kernel::AabbTree::kLeaveOut;
    }
  }
  // Near contacts between triangles of fans, which the descent no longer pairs: for each fan,
  // the vertices near its box whose owner is in a fan (any owner, for a fan searched whole),
  // against its triangles in the sectors within the tolerance of the vertex (sectors_within;
  // near_vertex decides). A box query per vertex instead met every chord of a cap fanned from a
  // rim point whose box holds the vertex: most of the rim, d²/8 closest points.
  const auto near_within_fans = [&] {
    std::vector<std::uint32_t> near_box, reached;
    std::vector<std::uint32_t> seen(owner.size(), kNoFan);  // the last fan that looked at a vertex
    std::size_t looked = 0;
    for (std::uint32_t f = 0; f < fans.size(); ++f) {
      if (fan_box[f].empty()) continue;
      kernel::Box3 grown = fan_box[f];
      grown.lo -= Vec3::Constant(2 * tolerance);
      grown.hi += Vec3::Constant(2 * tolerance);
      near_box.clear();
      tree.triangles_in_box(grown, near_box);
      for (const std::uint32_t t : near_box)
        for (const std::uint32_t v : complex.triangles[t]) {
          if (seen[v] == f) continue;
          seen[v] = f;
          if (owner[v] == kNone || (fan_of[owner[v]] == kNoFan && !whole[f])) continue;
          if (stop && (++looked & 0xfffu) == 0 && stop()) throw Stopped{};
          const Vec3& p = complex.vertices[v];
          reached.clear();
          detail::sectors_within(complex, fans[f], p, tolerance, reached);
          for (const std::uint32_t k : reached)
            if (const std::uint32_t x = fans[f].sectors[k].triangle; fan_of[x] == f)
              near_vertex(v, p, x, corners(x), complex.triangles[x]);
        }
    }
  };
  // The vertices owned by a triangle of a fan searched whole against the triangles of no fan
  // near them (those of fans: near_within_fans).
  const auto near_owned_by_whole = [&] {
    std::vector<std::uint32_t> hits;
    for (std::uint32_t v = 0; v < owner.size(); ++v) {
      if (owner[v] == kNone || fan_of[owner[v]] == kNoFan || !whole[fan_of[owner[v]]]) continue;
      if (stop && (v & 0xfffu) == 0xfffu && stop()) throw Stopped{};
      const Vec3& p = complex.vertices[v];
      kernel::Box3 box;
      box.extend(p - Vec3::Constant(2 * tolerance));
      box.extend(p + Vec3::Constant(2 * tolerance));
      hits.clear();
      tree.triangles_in_box(box, hits);
      for (const std::uint32_t t : hits)
        if (fan_of[t] == kNoFan) near_vertex(v, p, t, corners(t), complex.triangles[t]);
    }
  };
  // Whether pair (first < second) is asked whether it crosses: not when max_pairs smaller ones
  // were found. Then, given its corners, the answer: the max_pairs smallest crossing pairs are
  // kept in a max-heap, so they are what a scan in order of (first, second) stopping at
  // max_pairs would give, whatever order the pairs come in. (A pair the descent lists has a
  // triangle of no fan, which a fan's centre may be a corner of but which belongs to no fan:
  // only_fan_centre matters across fans alone.)
  const auto asked = [&](const std::array<std::uint32_t, 2>& pair) {
    return max_pairs > 0 && !(pairs.size() == max_pairs && !(pair < pairs.front()));
  };
  const auto settle_crossing = [&](const std::array<std::uint32_t, 2>& pair, const std::array<Vec3, 3>& a,
                                   const std::array<Vec3, 3>& b) {
    if (!triangles_intersect_improperly(a, complex.triangles[pair[0]], b, complex.triangles[pair[1]])) return;
    pairs.push_back(pair);
    std::push_heap(pairs.begin(), pairs.end());
    if (which == CrossingPairs::first_found && pairs.size() == max_pairs && !near) throw Enough{};
    if (pairs.size() > max_pairs) {
      std::pop_heap(pairs.begin(), pairs.end());
      pairs.pop_back();
    }
  };
  // Pairs across two fans: each triangle y of a later fan whose box meets the box of fan A's own
  // triangles, against those of A's sectors its shadow along A's axis reaches (sectors_near: no
  // other triangle of A can meet y), the axis turned through the later fan's centre where A's
  // sectors allow it (fan_about; the few triangles it leaves out are tested against every y). A
  // cone's side against its base fanned from the centre: a few sectors per base triangle instead
  // of every side triangle; two caps fanned from rim vertices one above the other: the turned
  // axis runs through both, and leaves out the side triangles at the lower one.
  std::size_t tested = 0;
  const auto across_pair = [&](std::uint32_t x, std::uint32_t y, const std::array<Vec3, 3>& cy) {
    if (stop && (++tested & 0xfffu) == 0 && stop()) throw Stopped{};
    const std::array<std::uint32_t, 2> pair{std::min(x, y), std::max(x, y)};
    if (!asked(pair) || only_fan_centre(x, y)) return;
    const std::array<Vec3, 3> cx = corners(x);
    settle_crossing(pair, x < y ? cx : cy, x < y ? cy : cx);
  };
  const auto across_fans = [&] {
    std::vector<std::uint32_t> near_box, reached, left_out;
    for (std::uint32_t f = 0; f < fans.size(); ++f) {
      if (fan_box[f].empty()) continue;  // every triangle of its star is an earlier fan's
      near_box.clear();
      tree.triangles_in_box(fan_box[f], near_box);
      // The later fans' triangles, fan by fan.
      std::erase_if(near_box, [&](std::uint32_t y) { return fan_of[y] == kNoFan || fan_of[y] <= f; });
      std::sort(near_box.begin(), near_box.end(), [&](std::uint32_t x, std::uint32_t y) {
        return std::pair(fan_of[x], x) < std::pair(fan_of[y], y);
      });
      std::optional<detail::Fan> turned;
      for (std::size_t i = 0; i < near_box.size(); ++i) {
        const std::uint32_t y = near_box[i];
        if (i == 0 || fan_of[y] != fan_of[near_box[i - 1]]) {
          if (stop && stop()) throw Stopped{};  // O(d log d) each
          turned = detail::fan_about(complex, fans[f], complex.vertices[fans[fan_of[y]].centre], &left_out);
        }
        const detail::Fan& a = turned ? *turned : fans[f];
        reached.clear();
        detail::sectors_near(complex, a, complex.triangles[y], reached);
        std::sort(reached.begin(), reached.end());
        reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
        const std::array<Vec3, 3> cy = corners(y);
        for (const std::uint32_t k : reached)
          if (const std::uint32_t x = a.sectors[k].triangle; fan_of[x] == f) across_pair(x, y, cy);
        // (an earlier fan's x is paired from there)
        for (const std::uint32_t x : left_out)
          if (fan_of[x] == f) across_pair(x, y, cy);
      }
    }
  };
  // A fan searched whole against the triangles of no fan near its box: each against the fan's own
  // triangles in the sectors its shadow reaches whose boxes meet its own (the descent's pairs).
  const auto whole_fans = [&] {
    std::vector<std::uint32_t> near_box, reached;
    for (std::uint32_t f = 0; f < fans.size(); ++f) {
      if (!whole[f]) continue;
      near_box.clear();
      tree.triangles_in_box(fan_box[f], near_box);
      for (const std::uint32_t y : near_box) {
        if (fan_of[y] != kNoFan) continue;  // across_fans
        if (stop && (++tested & 0xfffu) == 0 && stop()) throw Stopped{};
        reached.clear();
        detail::sectors_near(complex, fans[f], complex.triangles[y], reached);
        std::sort(reached.begin(), reached.end());
        reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
        const kernel::Box3 box_y = box_of(y);
        const std::array<Vec3, 3> cy = corners(y);
        for (const std::uint32_t k : reached)
          if (const std::uint32_t x = fans[f].sectors[k].triangle; fan_of[x] == f && box_of(x).overlaps(box_y))
            across_pair(x, y, cy);
      }
    }
  };
  // Every box-overlapping pair once, from the tree against itself (a box query per triangle cost
  // twice as much), the boxes grown by the tolerance so that a vertex near a triangle pairs one
  // of its own triangles with that one (it lies in its own triangles' boxes). One descent for
  // both checks: the near contacts took a box query per vertex, a quarter of the checks on a
  // million triangles.
  std::size_t visited = 0;
  try {
  if (near && !fan_of.empty()) near_within_fans();
  if (near && !fan_of.empty()) near_owned_by_whole();
  if (max_pairs > 0 && !fan_of.empty()) across_fans();
  if (max_pairs > 0 && !fan_of.empty()) whole_fans();
  tree.for_each_overlapping_pair(
      [&](std::uint32_t x, std::uint32_t y) {
        if (stop && (++visited & 0xfffu) == 0 && stop()) throw Stopped{};
        const std::array<std::uint32_t, 2> pair{std::min(x, y), std::max(x, y)};
        const auto& ia = complex.triangles[pair[0]];
        const auto& ib = complex.triangles[pair[1]];
        // What this pair is asked, decided before the corners are read.
        const bool crossing = asked(pair);
        bool owns = false;
        for (int k = 0; near && k < 3; ++k) owns |= owner[ia[k]] == pair[0] || owner[ib[k]] == pair[1];
        if (!crossing && !owns) return;
        const std::array<Vec3, 3> a = corners(pair[0]), b = corners(pair[1]);
        if (owns)
          for (int k = 0; k < 3; ++k) {
            if (owner[ia[k]] == pair[0]) near_vertex(ia[k], a[k], pair[1], b, ib);
            if (owner[ib[k]] == pair[1]) near_vertex(ib[k], b[k], pair[0], a, ia);
          }
        if (crossing) settle_crossing(pair, a, b);
      },
      near ? tolerance : 0, in_a_fan);
  } catch (const Stopped&) {
    found.stopped = true;
  } catch (const Enough&) {
  }
  std::sort_heap(pairs.begin(), pairs.end());
  return found;
}

}  // namespace delpsc::protect
