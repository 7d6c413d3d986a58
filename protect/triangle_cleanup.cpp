// Step 1 of build_complex: weld coincident vertices, keep zero-area triangles out of the complex
// without opening fake boundaries (see complex.h).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <delpsc/kernel/predicates.h>

#include "complex_build.h"

namespace delpsc::protect::detail {

namespace {

std::uint64_t edge_key(std::uint32_t u, std::uint32_t v) {
  if (u > v) std::swap(u, v);
  return (static_cast<std::uint64_t>(u) << 32) | v;
}

// Canonical index of each vertex: the smallest index with exactly the same coordinates (-0 and
// +0 equal). Open addressing with linear probing on the coordinates' bits, table at most half
// full: O(V) expected, several times faster than sorting at a million vertices.
kernel::LargeVector<std::uint32_t> weld(std::span<const Vec3> vertices, std::size_t& welded) {
  const auto n = static_cast<std::uint32_t>(vertices.size());
  kernel::LargeVector<std::uint32_t> canonical(n);
  std::size_t slots = 16;
  while (slots < 2 * static_cast<std::size_t>(n)) slots *= 2;
  kernel::LargeVector<std::uint32_t> table(slots, kNoIndex);
  auto hash = [](const Vec3& p) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int i = 0; i < 3; ++i) {
      const double x = p[i] + 0.0;  // -0 + 0 = +0
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = (h ^ bits) * 0xff51afd7ed558ccdull;
      h ^= h >> 32;
    }
    return h;
  };
  welded = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    std::size_t slot = hash(vertices[v]) & (slots - 1);
    while (table[slot] != kNoIndex && vertices[table[slot]] != vertices[v]) slot = (slot + 1) & (slots - 1);
    if (table[slot] == kNoIndex) {
      table[slot] = v;
      canonical[v] = v;
    } else {
      canonical[v] = table[slot];
      ++welded;
    }
  }
  return canonical;
}

// For three exactly collinear, pairwise distinct points: the position (0, 1, 2) of the one
// strictly between the other two. Along the axis where the points spread most, their projections
// are pairwise distinct (the line is not perpendicular to it), so exact comparisons decide.
int middle_of_collinear(const std::array<Vec3, 3>& p) {
  int axis = 0;
  double best = -1;
  for (int i = 0; i < 3; ++i) {
    const double lo = std::min({p[0][i], p[1][i], p[2][i]}), hi = std::max({p[0][i], p[1][i], p[2][i]});
    if (hi - lo > best) {
      best = hi - lo;
      axis = i;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const double a = p[(k + 1) % 3][axis], b = p[(k + 2) % 3][axis], x = p[k][axis];
    if ((a < x && x < b) || (b < x && x < a)) return k;
  }
  return 0;  // unreachable for distinct collinear points
}

struct Cap {
  std::uint32_t source;      // soup index
  std::uint32_t a, mid, b;   // mid strictly between a and b
  bool resolved = false;
  bool flat = false;         // not exactly collinear: kept as it is if it cannot be healed
};

}  // namespace

// kFlatCapRadians (0.0057°): a triangle whose largest angle is this near 180° is healed like an
// exactly collinear cap, a numerical accident, not a shape. libcgal-demo's mpi_triang.off has
// one (its two small angles 2.6e-6 and 1.9e-6, its height 2e-5 over an edge of 14; the next
// flattest triangles' small angles are ~1e-3), and mpi.off's 8-gon, nearly flat with four corners
// nearly in line, has one in every split (small angles 1.2e-5 and 2.6e-6): their two long edges
// are sharp edges leaving a corner 0.00015° apart, which balls of 6e-10 of the diagonal would
// have to separate. Splitting the triangle across its long edge moves the surface by its height.
// (A needle - one short edge, one tiny angle - is not a cap: flipping its long edge would only
// move the needle.)
int flat_cap_middle(const std::array<Vec3, 3>& p) {
  int longest = 0;
  double longest2 = -1;
  for (int k = 0; k < 3; ++k) {
    const double l2 = (p[(k + 2) % 3] - p[(k + 1) % 3]).squaredNorm();
    if (l2 > longest2) {
      longest2 = l2;
      longest = k;
    }
  }
  return flatness(p[(longest + 1) % 3], p[longest], p[(longest + 2) % 3]) < kFlatCapRadians ? longest : -1;
}

double flatness(const Vec3& a, const Vec3& m, const Vec3& b) {
  const double height = (m - a).cross(b - a).norm() / (b - a).norm();
  return height / (m - a).norm() + height / (m - b).norm();
}

kernel::LargeVector<std::uint32_t> clean_triangles(const io::TriangleSoup& soup, Complex& complex) {
  const auto vertex_count = soup.vertices.size();
  if (vertex_count >= kNoIndex) throw std::invalid_argument("build_complex: more than 2^32 - 2 vertices");
  if (soup.triangles.size() >= kNoIndex) throw std::invalid_argument("build_complex: more than 2^32 - 2 triangles");
  for (std::size_t v = 0; v < vertex_count; ++v)
    if (!soup.vertices[v].allFinite())
      throw std::invalid_argument("build_complex: vertex " + std::to_string(v) + " has a non-finite coordinate");
  for (std::size_t t = 0; t < soup.triangles.size(); ++t)
    for (auto v : soup.triangles[t])
      if (v >= vertex_count)
        throw std::invalid_argument("build_complex: triangle " + std::to_string(t) + " refers to vertex " +
                                    std::to_string(v) + " of " + std::to_string(vertex_count));

  complex.vertices.assign(soup.vertices.begin(), soup.vertices.end());
  const kernel::LargeVector<std::uint32_t> canonical = weld(soup.vertices, complex.cleanup.welded_vertices);

  kernel::LargeVector<std::array<std::uint32_t, 3>> tris;
  kernel::LargeVector<std::uint32_t> source;
  kernel::LargeVector<Cap> caps;
  tris.reserve(soup.triangles.size());
  source.reserve(soup.triangles.size());
  for (std::uint32_t t = 0; t < soup.triangles.size(); ++t) {
    const std::array<std::uint32_t, 3> tri = {canonical[soup.triangles[t][0]], canonical[soup.triangles[t][1]],
                                              canonical[soup.triangles[t][2]]};
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      // A repeated vertex: the triangle is an edge (or a point) traversed twice and takes no
      // part in any adjacency; dropping it changes nothing.
      complex.cleanup.zero_area_triangles.push_back(t);
      continue;
    }
    const std::array<Vec3, 3> p = {complex.vertices[tri[0]], complex.vertices[tri[1]], complex.vertices[tri[2]]};
    if (kernel::collinear(p[0].data(), p[1].data(), p[2].data())) {
      complex.cleanup.zero_area_triangles.push_back(t);
      const int m = middle_of_collinear(p);
      caps.push_back({t, tri[(m + 1) % 3], tri[m], tri[(m + 2) % 3]});
      continue;
    }
    if (const int m = flat_cap_middle(p); m >= 0) {
      complex.cleanup.flat_caps.push_back(t);
      caps.push_back({t, tri[(m + 1) % 3], tri[m], tri[(m + 2) % 3], false, true});
      continue;
    }
    tris.push_back(tri);
    source.push_back(t);
  }

  // Heal the caps: split the triangle across each cap's long edge at the middle vertex. A round
  // scans every triangle once to find, for each cap's long edge, how many other triangles use it
  // and which; a triangle split in a round is not split again in the same round (its edges have
  // changed), so caps sharing a partner wait for the next round. Caps whose long edge has no
  // other triangle lie on the boundary and are simply removed (the boundary passes through mid).
  struct EdgeUse {
    std::uint32_t count = 0;
    std::uint32_t triangle = kNoIndex;  // last ordinary triangle found on the edge
  };
  constexpr int kMaxRounds = 16;
  for (int round = 0; round < kMaxRounds; ++round) {
    std::unordered_map<std::uint64_t, EdgeUse> uses;
    std::size_t pending = 0;
    for (const Cap& cap : caps)
      if (!cap.resolved) {
        uses[edge_key(cap.a, cap.b)];
        ++pending;
      }
    if (pending == 0) break;
    for (std::uint32_t t = 0; t < tris.size(); ++t) {
      for (int k = 0; k < 3; ++k) {
        const auto it = uses.find(edge_key(tris[t][(k + 1) % 3], tris[t][(k + 2) % 3]));
        if (it == uses.end()) continue;
        ++it->second.count;
        it->second.triangle = t;
      }
    }
    for (const Cap& cap : caps) {  // unresolved caps use their own and each other's edges too
      if (cap.resolved) continue;
      for (auto [u, v] : {std::pair{cap.a, cap.mid}, std::pair{cap.mid, cap.b}, std::pair{cap.a, cap.b}}) {
        const auto it = uses.find(edge_key(u, v));
        if (it != uses.end()) ++it->second.count;
      }
    }
    kernel::LargeVector<char> split_now(tris.size(), 0);
    bool progress = false;
    for (Cap& cap : caps) {
      if (cap.resolved) continue;
      const EdgeUse& use = uses[edge_key(cap.a, cap.b)];
      const std::uint32_t others = use.count - 1;  // minus the cap itself
      if (others == 0) {
        cap.resolved = progress = true;
        continue;
      }
      if (others != 1 || use.triangle == kNoIndex || split_now[use.triangle]) continue;
      const std::uint32_t t = use.triangle;
      std::array<std::uint32_t, 3> first = tris[t], second = tris[t];
      for (int k = 0; k < 3; ++k) {
        if (first[k] == cap.b) first[k] = cap.mid;
        if (second[k] == cap.a) second[k] = cap.mid;
      }
      tris[t] = first;
      split_now[t] = 1;
      tris.push_back(second);
      source.push_back(source[t]);
      split_now.push_back(1);
      ++complex.cleanup.split_triangles;
      cap.resolved = progress = true;
    }
    if (!progress) break;
  }
  for (const Cap& cap : caps) {
    if (cap.resolved) continue;
    if (cap.flat) {  // a real triangle: dropping it would open a hole
      tris.push_back({cap.a, cap.b, cap.mid});
      source.push_back(cap.source);
    } else {
      ++complex.cleanup.dropped_caps;
    }
  }
  std::sort(complex.cleanup.zero_area_triangles.begin(), complex.cleanup.zero_area_triangles.end());

  complex.triangles = std::move(tris);
  complex.triangle_source = std::move(source);
  return canonical;
}

}  // namespace delpsc::protect::detail
