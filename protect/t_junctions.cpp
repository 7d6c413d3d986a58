// Step 2b of build_complex: cracks zipped. A vertex lying on another triangle's edge, with no
// zero-area cap between them (the caps are step 1's), leaves a crack of zero width - a
// T-junction: the long edge and the short edges along it are each in one triangle only, so they
// would be boundary curves on top of each other, and the two sides touch along the segment
// (which the commands refuse as a self-intersection). Meshes whose faces were tessellated apart
// have them, often with vertices on both sides (a cube edge split in thirds by one face and in
// halves by the other). Each edge with vertices of the other side on it has its triangle split
// at them into a fan from its opposite vertex: exactly the same surface where they lie exactly
// on the edge (decided exactly). Where a file rounded them off it (split points of a slanted
// edge written as float32 STL or with six digits), they count as on it when the angle they make
// with the edge's ends is within kCrackRadians of 180°, or their distance from it is within what
// six digits of the file's coordinates could have rounded away (kCrackOfCoordinates), and the
// fan moves the surface by that distance. Left as they were, such cracks were refused as
// touching or ran towards the balls' cap (BENCHMARKS.md, session 43).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <delpsc/kernel/predicates.h>

#include "complex_build.h"

namespace delpsc::protect::detail {

namespace {

// n's distance from the line through p and q (q != p).
double distance_from_line(const Vec3& p, const Vec3& q, const Vec3& n) {
  return (n - p).cross(q - p).norm() / (q - p).norm();
}

// Whether n lies strictly between `from` and `to` along the segment from p to q, exactly on its
// line or near it. Exact when collinear: order along the axis where p and q differ most
// (collinear distinct points differ there). Near: ordered by the projection on p -> q (rounded;
// a misordered fan would cross itself, which the commands' input check refuses), and (p, n, q)
// flatter than kCrackRadians, or n nearer the line than the file's rounding (kCrackOfCoordinates).
bool between(const Vec3& p, const Vec3& q, const Vec3& from, const Vec3& to, const Vec3& n, const Vec3& file_offset) {
  if (kernel::collinear(p.data(), q.data(), n.data())) {
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(q[i] - p[i]) > std::abs(q[axis] - p[axis])) axis = i;
    return q[axis] > p[axis] ? from[axis] < n[axis] && n[axis] < to[axis] : to[axis] < n[axis] && n[axis] < from[axis];
  }
  const Vec3 d = q - p;
  const double s = (n - p).dot(d);
  if (!((from - p).dot(d) < s && s < (to - p).dot(d))) return false;
  const double flat = flatness(p, n, q);
  if (flat < kCrackRadians) return true;
  const double coordinates =
      std::max({(p + file_offset).cwiseAbs().maxCoeff(), (q + file_offset).cwiseAbs().maxCoeff(),
                (n + file_offset).cwiseAbs().maxCoeff()});
  return flat < kCrackMostRadians && distance_from_line(p, q, n) <= kCrackOfCoordinates * coordinates;
}

// One side of a crack as it is walked from the vertex where both sides start: its boundary edges
// in order, the vertex each was entered at, and where its walk has got to.
struct CrackSide {
  std::vector<std::uint32_t> edges, entered_at;
  std::uint32_t prev = kNoIndex, end = kNoIndex;
};

// A vertex of one side lying on an edge of the other: edges[edge] of sides[side] is split at it.
struct Insertion {
  int side;
  std::uint32_t edge;  // index into the side's edges
  std::uint32_t vertex;
};

class CrackZipper {
 public:
  explicit CrackZipper(Complex& complex)
      : c_(complex), file_offset_(complex.options.file_offset[0], complex.options.file_offset[1], complex.options.file_offset[2]) {
    // Boundary edges (one triangle), and at each of their vertices the boundary edges there,
    // as (vertex, edge) sorted by vertex: closed models have none and pay one pass.
    for (std::uint32_t e = 0; e < c_.edges.size(); ++e)
      if (c_.edge_triangle_offsets[e + 1] - c_.edge_triangle_offsets[e] == 1)
        for (const std::uint32_t v : c_.edges[e]) at_vertex_.emplace_back(v, e);
    std::sort(at_vertex_.begin(), at_vertex_.end());
    used_.assign(c_.edges.size(), 0);
    split_.assign(c_.triangles.size(), 0);
  }

  bool has_boundary() const { return !at_vertex_.empty(); }

  // Zips every crack that starts at a boundary vertex with two boundary edges running the same
  // way; returns how many edges were split. A triangle is split at most once a round.
  std::size_t zip_all() {
    std::size_t healed = 0;
    for (std::size_t i = 0; i < at_vertex_.size();) {
      std::size_t j = i;
      while (j < at_vertex_.size() && at_vertex_[j].first == at_vertex_[i].first) ++j;
      // Pairs of the boundary edges there (two on a sheet's boundary, four where two sheets
      // touch); a vertex with very many is the hub of a fan of separate triangles, no crack.
      constexpr std::size_t kMostEdges = 32;
      if (j - i > kMostEdges) {
        i = j;
        continue;
      }
      for (std::size_t a = i; a < j; ++a)
        for (std::size_t b = a + 1; b < j; ++b)
          if (!used_[at_vertex_[a].second] && !used_[at_vertex_[b].second])
            healed += zip(at_vertex_[i].first, at_vertex_[a].second, at_vertex_[b].second);
      i = j;
    }
    return healed;
  }

 private:
  std::uint32_t other_end(std::uint32_t e, std::uint32_t v) const {
    return c_.edges[e][0] == v ? c_.edges[e][1] : c_.edges[e][0];
  }
  const Vec3& at(std::uint32_t v) const { return c_.vertices[v]; }
  std::uint32_t triangle_of(std::uint32_t e) const { return c_.edge_triangles[c_.edge_triangle_offsets[e]]; }
  // Which of its triangle's edges e is (triangle edge k is opposite vertex k).
  int index_in_triangle(std::uint32_t e) const {
    const std::uint32_t t = triangle_of(e);
    int k = 0;
    while (c_.triangle_edges[t][k] != e) ++k;
    return k;
  }
  // The vertex of e's triangle opposite e.
  std::uint32_t opposite(std::uint32_t e) const { return c_.triangles[triangle_of(e)][index_in_triangle(e)]; }

  // Whether x's walk end lies on y's last edge, beyond what was already put on it.
  bool lies_on_last(const CrackSide& x, const CrackSide& y, std::uint32_t after) const {
    return between(at(y.prev), at(y.end), at(after), at(y.end), at(x.end), file_offset_);
  }

  // The boundary edge leaving v other than `from`: kNoIndex unless there is exactly one, unused.
  std::uint32_t next_edge(std::uint32_t v, std::uint32_t from) const {
    const auto [first, last] = std::equal_range(at_vertex_.begin(), at_vertex_.end(), std::pair{v, 0u},
                                                [](const auto& x, const auto& y) { return x.first < y.first; });
    std::uint32_t next = kNoIndex;
    for (auto it = first; it != last; ++it) {
      if (it->second == from) continue;
      if (next != kNoIndex || used_[it->second]) return kNoIndex;
      next = it->second;
    }
    return next;
  }

  // Walks the two boundary paths leaving p along e1 and e2 together, each step taking the side
  // whose end lies on the other's last edge (it is behind), until both reach one vertex: a crack
  // between two sheets (or two sides of one) whose vertices, from either side, lie on the other
  // side's edges in order. Then each edge with vertices of the other side on it is split there.
  // A walk that fails anywhere changes nothing.
  std::size_t zip(std::uint32_t p, std::uint32_t e1, std::uint32_t e2) {
    constexpr std::size_t kMaxSteps = 4096;  // vertices along one crack
    CrackSide* sides = sides_;  // reused: most walks end at their first step
    for (int k = 0; k < 2; ++k) {
      const std::uint32_t e = k == 0 ? e1 : e2;
      sides[k].edges.assign(1, e);
      sides[k].entered_at.assign(1, p);
      sides[k].prev = p;
      sides[k].end = other_end(e, p);
    }
    inserted_.clear();
    std::uint32_t last_on[2] = {p, p};  // the last vertex put on each side's last edge (or its start)
    for (std::size_t step = 0; sides[0].end != sides[1].end; ++step) {
      if (step == kMaxSteps) return 0;
      int behind = -1;
      if (lies_on_last(sides[1], sides[0], last_on[0]))
        behind = 1;
      else if (lies_on_last(sides[0], sides[1], last_on[1]))
        behind = 0;
      if (behind < 0) return 0;
      CrackSide &x = sides[behind], &y = sides[1 - behind];
      inserted_.push_back({1 - behind, static_cast<std::uint32_t>(y.edges.size() - 1), x.end});
      last_on[1 - behind] = x.end;
      const std::uint32_t f = next_edge(x.end, x.edges.back());
      if (f == kNoIndex) return 0;
      x.edges.push_back(f);
      x.entered_at.push_back(x.end);
      x.prev = x.end;
      x.end = other_end(f, x.end);
      last_on[behind] = x.prev;
    }
    if (inserted_.empty()) return 0;
    // Each edge's triangle once, none split already this round (two cracks ending at one triangle
    // wait for the next round, after the edge table is made again).
    std::vector<std::uint32_t> triangles;
    for (const Insertion& i : inserted_) triangles.push_back(triangle_of(sides[i.side].edges[i.edge]));
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    std::size_t groups = 0;  // edges with insertions; each must have a triangle of its own
    for (std::size_t i = 0; i < inserted_.size(); ++i)
      groups += i == 0 || inserted_[i].side != inserted_[i - 1].side || inserted_[i].edge != inserted_[i - 1].edge;
    if (groups != triangles.size()) return 0;
    for (const std::uint32_t t : triangles)
      if (split_[t]) return 0;
    // Nothing may span the gap: a triangle to split whose opposite vertex lies on the other side
    // (a thin strip of triangles between the two paths, or one nearly flat triangle whose two
    // edges leave p together) is no crack - its fan would repeat that vertex or overlap the strip.
    for (const Insertion& i : inserted_) {
      const CrackSide& other = sides[1 - i.side];
      const std::uint32_t x = opposite(sides[i.side].edges[i.edge]);
      if (x == other.end || std::find(other.entered_at.begin(), other.entered_at.end(), x) != other.entered_at.end())
        return 0;
    }
    for (const CrackSide& side : sides_)
      for (const std::uint32_t e : side.edges) used_[e] = 1;
    // The insertions come in walk order, so those on one edge are consecutive and ordered.
    std::size_t healed = 0;
    for (std::size_t i = 0; i < inserted_.size();) {
      std::size_t j = i;
      while (j < inserted_.size() && inserted_[j].side == inserted_[i].side && inserted_[j].edge == inserted_[i].edge) ++j;
      const CrackSide& side = sides[inserted_[i].side];
      split_edge(side.edges[inserted_[i].edge], side.entered_at[inserted_[i].edge], i, j);
      ++healed;
      i = j;
    }
    return healed;
  }

  // Splits e's triangle into a fan at inserted_[i, j) (listed from `from`, one end of e), in the
  // triangle's orientation.
  void split_edge(std::uint32_t e, std::uint32_t from, std::size_t i, std::size_t j) {
    const std::uint32_t t = triangle_of(e);
    const int k = index_in_triangle(e);
    const auto tri = c_.triangles[t];
    const std::uint32_t x = tri[k], p = tri[(k + 1) % 3], q = tri[(k + 2) % 3];
    chain_.clear();
    for (std::size_t m = i; m < j; ++m) chain_.push_back(inserted_[m].vertex);
    if (from != p) std::reverse(chain_.begin(), chain_.end());
    double gap = 0;
    for (const std::uint32_t n : chain_)
      if (!kernel::collinear(at(p).data(), at(q).data(), at(n).data())) gap = std::max(gap, distance_from_line(at(p), at(q), at(n)));
    split_[t] = 1;
    c_.triangles[t] = {x, p, chain_.front()};
    for (std::size_t m = 0; m < chain_.size(); ++m) {
      c_.triangles.push_back({x, chain_[m], m + 1 < chain_.size() ? chain_[m + 1] : q});
      c_.triangle_source.push_back(c_.triangle_source[t]);
    }
    c_.cleanup.split_triangles += chain_.size();
    if (gap > 0) {
      ++c_.cleanup.near_t_junctions;
      c_.cleanup.t_junction_gap = std::max(c_.cleanup.t_junction_gap, gap);
    }
  }

  Complex& c_;
  const Vec3 file_offset_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> at_vertex_;
  std::vector<char> used_;   // a boundary edge in a crack zipped this round
  std::vector<char> split_;  // a triangle split this round
  CrackSide sides_[2];
  std::vector<Insertion> inserted_;
  std::vector<std::uint32_t> chain_;
};

}  // namespace

std::size_t heal_t_junctions(Complex& complex) {
  constexpr int kMaxRounds = 8;
  std::size_t healed = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    CrackZipper zipper(complex);
    if (!zipper.has_boundary()) break;
    const std::size_t healed_now = zipper.zip_all();
    if (healed_now == 0) break;
    healed += healed_now;
    build_edge_table(complex);
  }
  return healed;
}

}  // namespace delpsc::protect::detail
