#include "complex_topology.h"

#include <algorithm>
#include <stdexcept>

#include "edge_record_sort.h"

namespace delpsc::refine {

namespace {

// Union-find over dense ids with path halving; `parity` (optional) tracks, for the orientation
// test, whether an element's orientation is flipped relative to its root.
struct UnionFind {
  kernel::LargeVector<std::uint32_t> parent;
  kernel::LargeVector<std::uint8_t> parity;
  explicit UnionFind(std::size_t n) : parent(n), parity(n, 0) {
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
  }
  // Root of x and x's parity relative to it; the path is then pointed at the root (full path
  // compression keeping parities), so a long run of joins stays near-linear.
  std::pair<std::uint32_t, std::uint8_t> find(std::uint32_t x) {
    std::uint32_t r = x;
    std::uint8_t p = 0;
    while (parent[r] != r) p ^= parity[r], r = parent[r];
    for (std::uint8_t q = p; parent[x] != x;) {  // q: parity of x relative to r
      const std::uint32_t next = parent[x];
      const std::uint8_t q_next = q ^ parity[x];
      parent[x] = r, parity[x] = q;
      x = next, q = q_next;
    }
    return {r, p};
  }
  // Joins x and y with parity(x) ^ parity(y) == relation; false if they were already joined
  // with the other relation (an orientation conflict).
  bool join(std::uint32_t x, std::uint32_t y, std::uint8_t relation = 0) {
    const auto [rx, px] = find(x);
    const auto [ry, py] = find(y);
    if (rx == ry) return (px ^ py) == relation;
    parent[rx] = ry;
    parity[rx] = static_cast<std::uint8_t>(px ^ py ^ relation);
    return true;
  }
  std::uint32_t root(std::uint32_t x) { return find(x).first; }
};

// One side of an undirected edge: its ends (lo < hi), the triangle, and whether the triangle
// runs along it from lo to hi.
struct EdgeUse {
  std::uint32_t lo, hi, triangle;
  bool forward;
};

// Components of the graph of the given edges (pairs of vertex ids < vertex_bound).
std::size_t edge_components(const std::vector<std::array<std::uint32_t, 2>>& edges, std::size_t vertex_bound) {
  UnionFind uf(vertex_bound);
  std::vector<std::uint32_t> ends;
  for (const auto& [a, b] : edges) {
    uf.join(a, b);
    ends.push_back(a), ends.push_back(b);
  }
  std::vector<std::uint32_t> roots;
  for (const std::uint32_t v : ends) roots.push_back(uf.root(v));
  std::sort(roots.begin(), roots.end());
  return static_cast<std::size_t>(std::unique(roots.begin(), roots.end()) - roots.begin());
}

// The figures of `triangles` (vertex ids < vertex_bound, none repeated in a triangle), whose
// undirected edges `for_each_edge(visit)` lists, each once and in any order, as
// visit(lo, hi, degree, uses): the edge's ends (lo < hi), its number of triangles, and for an
// edge of two, `uses` its two (triangle, runs from lo to hi) pairs.
using EdgeSide = std::pair<std::uint32_t, bool>;
template <class ForEachEdge>
ComplexTopology figures(std::span<const std::array<std::uint32_t, 3>> triangles, std::uint32_t vertex_bound,
                        ForEachEdge for_each_edge) {
  ComplexTopology out;
  out.triangles = triangles.size();
  UnionFind vertices(vertex_bound);  // components: every triangle joins its vertices
  for (const auto& v : triangles) vertices.join(v[0], v[1]), vertices.join(v[1], v[2]);
  kernel::LargeVector<std::uint8_t> used(vertex_bound, 0);
  for (const auto& v : triangles) used[v[0]] = used[v[1]] = used[v[2]] = 1;
  kernel::LargeVector<std::uint8_t> is_root(vertex_bound, 0);
  for (std::uint32_t x = 0; x < vertex_bound; ++x)
    if (used[x]) ++out.vertices, is_root[vertices.root(x)] = 1;
  out.components = static_cast<std::size_t>(std::count(is_root.begin(), is_root.end(), 1));

  // Edges by degree; sheets and their orientation across the edges in exactly two triangles.
  // Two triangles are coherently oriented across an edge when they run along it in opposite
  // directions, so their orientations must differ (relation 1) when they run the same way.
  UnionFind sheets(triangles.size());
  kernel::LargeVector<std::uint8_t> conflict(triangles.size(), 0);
  std::vector<std::array<std::uint32_t, 2>> boundary, singular;
  for_each_edge([&](std::uint32_t lo, std::uint32_t hi, std::size_t degree, const std::array<EdgeSide, 2>& uses) {
    ++out.edges;
    if (degree == 1) boundary.push_back({lo, hi});
    if (degree >= 3) singular.push_back({lo, hi});
    if (degree == 2 && !sheets.join(uses[0].first, uses[1].first, uses[0].second == uses[1].second))
      conflict[uses[0].first] = 1;
  });
  out.euler = static_cast<long>(out.vertices) - static_cast<long>(out.edges) + static_cast<long>(out.triangles);
  out.boundary_loops = edge_components(boundary, vertex_bound);
  out.singular_curves = edge_components(singular, vertex_bound);
  kernel::LargeVector<std::uint8_t> sheet_root(triangles.size(), 0), sheet_conflict(triangles.size(), 0);
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const std::uint32_t r = sheets.root(t);
    sheet_root[r] = 1;
    sheet_conflict[r] |= conflict[t];
  }
  out.sheets = static_cast<std::size_t>(std::count(sheet_root.begin(), sheet_root.end(), 1));
  out.non_orientable_sheets = static_cast<std::size_t>(std::count(sheet_conflict.begin(), sheet_conflict.end(), 1));
  return out;
}

}  // namespace

ComplexTopology complex_topology(std::span<const std::array<std::uint32_t, 3>> triangles) {
  if (triangles.empty()) return {};
  std::uint32_t vertex_bound = 0;
  kernel::LargeVector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const auto& v = triangles[t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      throw std::invalid_argument("complex_topology: triangle " + std::to_string(t) + " repeats a vertex");
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
      vertex_bound = std::max(vertex_bound, a + 1);
    }
  }
  sort_edge_records(uses, vertex_bound, [](const EdgeUse& x, const EdgeUse& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
  return figures(triangles, vertex_bound, [&](const auto& visit) {
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i;
      while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
      visit(uses[i].lo, uses[i].hi, j - i,
            std::array<EdgeSide, 2>{EdgeSide{uses[i].triangle, uses[i].forward},
                                    EdgeSide{uses[i + 1 < j ? i + 1 : i].triangle, uses[i + 1 < j ? i + 1 : i].forward}});
      i = j;
    }
  });
}

ComplexTopology complex_topology(const protect::Complex& complex) {
  if (complex.triangles.empty()) return {};
  const auto runs_forward = [&](std::uint32_t t, std::uint32_t lo, std::uint32_t hi) {
    const auto& v = complex.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (v[k] == lo) return v[(k + 1) % 3] == hi;
    return false;  // unreachable: lo is a corner of every triangle of its edge
  };
  return figures(complex.triangles, static_cast<std::uint32_t>(complex.vertices.size()), [&](const auto& visit) {
    for (std::uint32_t e = 0; e < complex.edges.size(); ++e) {
      const auto [lo, hi] = complex.edges[e];
      const auto around = complex.edge_triangle_ids(e);
      const std::uint32_t t0 = around[0], t1 = around.size() > 1 ? around[1] : around[0];
      visit(lo, hi, around.size(),
            std::array<EdgeSide, 2>{EdgeSide{t0, runs_forward(t0, lo, hi)}, EdgeSide{t1, runs_forward(t1, lo, hi)}});
    }
  });
}

std::vector<std::string> topology_differences(const ComplexTopology& output, const ComplexTopology& input) {
  std::vector<std::string> out;
  const auto compare = [&](const char* what, long o, long i) {
    if (o != i) out.push_back(std::string(what) + ": output " + std::to_string(o) + ", input " + std::to_string(i));
  };
  const auto l = [](std::size_t x) { return static_cast<long>(x); };
  compare("components", l(output.components), l(input.components));
  compare("Euler characteristic", output.euler, input.euler);
  compare("boundary loops", l(output.boundary_loops), l(input.boundary_loops));
  compare("singular curves", l(output.singular_curves), l(input.singular_curves));
  compare("sheets", l(output.sheets), l(input.sheets));
  compare("non-orientable sheets", l(output.non_orientable_sheets), l(input.non_orientable_sheets));
  return out;
}

}  // namespace delpsc::refine
