#include "skeleton_check.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <delpsc/kernel/bits.h>
#include <delpsc/kernel/large_array.h>

#include "edges_by_curve.h"
#include "link_shape.h"

namespace delpsc::refine {

namespace {

// Flat sorted arrays throughout (no node-based maps): the command checks every mesh it writes,
// and with maps and sets this took ~0.3 s on a 120,000-triangle mesh.

using Edge = std::pair<std::uint32_t, std::uint32_t>;
// On huge pages (kernel/large_array.h): a mesh of 100,000 triangles fills these arrays with
// megabytes that base pages would fault in 4 KiB at a time (~640 faults, ~7 ms, on the cube's
// 108,000 triangles).
template <class T>
using Array = kernel::LargeVector<T>;

Edge edge(std::uint32_t a, std::uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

bool contains(const Array<Edge>& sorted, const Edge& e) { return std::binary_search(sorted.begin(), sorted.end(), e); }

// Union-find over dense ids with path halving.
std::uint32_t find_root(Array<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Connected components of the graph with these edges (vertices: the ends met).
std::size_t components(const Array<Edge>& edges) {
  Array<std::uint32_t> ids;
  ids.reserve(2 * edges.size());
  for (const auto& [a, b] : edges) ids.push_back(a), ids.push_back(b);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const auto index = [&](std::uint32_t v) {
    return static_cast<std::uint32_t>(std::lower_bound(ids.begin(), ids.end(), v) - ids.begin());
  };
  Array<std::uint32_t> parent(ids.size());
  for (std::uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
  std::size_t count = ids.size();
  for (const auto& [a, b] : edges) {
    const std::uint32_t ra = find_root(parent, index(a)), rb = find_root(parent, index(b));
    if (ra != rb) parent[ra] = rb, --count;
  }
  return count;
}

// A patch's triangle sides, sorted: key (a << bits | b) for the edge a < b, value 3 i + k for side k
// (from corner k to k + 1) of the patch's i-th triangle. Radix-sorted (kernel/bits.h, stable: equal
// edges keep the triangles' order); the three std::sorts of pairs they replace were a third of
// checking the cube's 108,000 triangles at 0.456%, which `delpsc mesh` does on every run.
struct SortedSides {
  kernel::KeyedIndices sides;
  int bits = 1;  // vertex ids are below 2^bits
  Edge edge_of(std::size_t j) const {
    const std::uint64_t key = sides[j].first;
    return {static_cast<std::uint32_t>(key >> bits), static_cast<std::uint32_t>(key & ((std::uint64_t{1} << bits) - 1))};
  }
  std::uint32_t triangle_of(std::size_t j) const { return sides[j].second / 3; }
  /// End of the run of sides with the edge of side b.
  std::size_t run_end(std::size_t b) const {
    std::size_t e = b + 1;
    while (e < sides.size() && sides[e].first == sides[b].first) ++e;
    return e;
  }
  /// How many sides have edge (a, b), a < b.
  std::size_t count(const Edge& e) const {
    const std::uint64_t key = std::uint64_t{e.first} << bits | e.second;
    const auto [lo, hi] = std::equal_range(sides.begin(), sides.end(), std::pair<std::uint64_t, std::uint32_t>{key, 0},
                                           [](const auto& x, const auto& y) { return x.first < y.first; });
    return static_cast<std::size_t>(hi - lo);
  }
};

// The Euler characteristic and boundary loops of the triangles `tris` cut open along the edges
// in `slit` (sorted); `sorted` their sides. Each triangle corner is a copy of its vertex; two
// triangles sharing an edge that is not a slit glue their corners at its two ends. The cut
// surface's vertices are the glued classes of corners, its edges those of the triangles with each
// slit edge counted once per triangle, its boundary the edges of one triangle (original boundary
// and both sides of slits).
std::pair<int, std::size_t> cut_open_topology(const io::SurfaceMesh& mesh, const Array<std::size_t>& tris,
                                              const Array<Edge>& slit, const SortedSides& sorted) {
  const auto corner = [](std::size_t local, int k) { return static_cast<std::uint32_t>(3 * local + k); };
  Array<std::uint32_t> parent(3 * tris.size());
  for (std::uint32_t c = 0; c < parent.size(); ++c) parent[c] = c;
  // The corner of local triangle i at mesh vertex x.
  const auto corner_at = [&](std::size_t i, std::uint32_t x) {
    const auto& v = mesh.triangles[tris[i]];
    return corner(i, v[0] == x ? 0 : v[1] == x ? 1 : 2);
  };
  std::size_t edges = 0;
  Array<std::pair<std::size_t, std::size_t>> cut_runs;  // [begin, end) of sorted sides, cut edges
  for (std::size_t b = 0; b < sorted.sides.size();) {
    const std::size_t e = sorted.run_end(b);
    const Edge shared = sorted.edge_of(b);
    const bool cut = e - b == 1 || contains(slit, shared);
    edges += cut ? e - b : 1;
    if (cut) {
      cut_runs.emplace_back(b, e);
    } else {
      for (std::size_t j = b + 1; j < e; ++j)
        for (const std::uint32_t x : {shared.first, shared.second})
          parent[find_root(parent, corner_at(sorted.triangle_of(b), x))] = find_root(parent, corner_at(sorted.triangle_of(j), x));
    }
    b = e;
  }
  std::size_t vertices = 0;
  for (std::uint32_t c = 0; c < parent.size(); ++c) vertices += find_root(parent, c) == c;
  Array<Edge> boundary;  // between corner classes
  for (const auto& [b, e] : cut_runs)
    for (std::size_t j = b; j < e; ++j) {
      const Edge side = sorted.edge_of(j);
      boundary.push_back(edge(find_root(parent, corner_at(sorted.triangle_of(j), side.first)),
                              find_root(parent, corner_at(sorted.triangle_of(j), side.second))));
    }
  const int euler = static_cast<int>(vertices) - static_cast<int>(edges) + static_cast<int>(tris.size());
  return {euler, components(boundary)};
}

// Whether every label and index of the mesh names something that exists: one patch label per
// triangle and one curve label per edge, each a patch or curve of the domain, and vertex
// indices below the vertex count. A triangle labelled with no patch would otherwise belong to
// no Skl²|σ checked below and pass unseen. Reports through `problem`.
template <class Report>
bool mesh_labels_in_range(const io::SurfaceMesh& mesh, const Domain& domain, const Report& problem) {
  bool ok = true;
  const auto fail = [&](const std::string& what) {
    problem(what);
    ok = false;
  };
  if (mesh.triangle_patch.size() != mesh.triangles.size())
    fail(std::to_string(mesh.triangle_patch.size()) + " patch labels for " + std::to_string(mesh.triangles.size()) + " triangles");
  if (mesh.edge_curve.size() != mesh.edges.size())
    fail(std::to_string(mesh.edge_curve.size()) + " curve labels for " + std::to_string(mesh.edges.size()) + " edges");
  if (!ok) return false;
  const std::size_t n = mesh.vertices.size();
  const auto in_range = [n](std::span<const std::uint32_t> ids) {
    return std::all_of(ids.begin(), ids.end(), [n](std::uint32_t v) { return v < n; });
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::int32_t p = mesh.triangle_patch[t];
    if (p < 0 || static_cast<std::uint32_t>(p) >= domain.patch_count())
      fail("triangle " + std::to_string(t) + " is labelled " + std::to_string(p) + ", not a patch of the domain");
    if (!in_range(mesh.triangles[t])) fail("triangle " + std::to_string(t) + " has a vertex index out of range");
  }
  for (std::size_t i = 0; i < mesh.edges.size(); ++i) {
    const std::int32_t c = mesh.edge_curve[i];
    if (c < 0 || static_cast<std::uint32_t>(c) >= domain.curve_count())
      fail("edge " + std::to_string(i) + " is labelled " + std::to_string(c) + ", not a curve of the domain");
    if (!in_range(mesh.edges[i])) fail("edge " + std::to_string(i) + " has a vertex index out of range");
  }
  if (!in_range(mesh.corners)) fail("a corner index is out of range");
  return ok;
}

}  // namespace

SkeletonReport check_skeleton(const io::SurfaceMesh& mesh, const Domain& domain, double tolerance,
                              const std::function<bool()>& stop) {
  SkeletonReport report;
  const auto stopped = [&] { return stop && (report.stopped = stop()); };
  const auto general = [&](const std::string& what) {
    if (report.problems.size() < 50) report.problems.push_back(what);
  };
  auto problem = [&](std::uint32_t patch, const std::string& what) { general("patch " + std::to_string(patch) + ": " + what); };
  if (!mesh_labels_in_range(mesh, domain, general)) return report;  // the rest would read out of bounds
  // The bound of the vertices' closest-point searches (below); unbounded for a tolerance of 0 or
  // less, where the bound would refuse a vertex exactly on the domain.
  const double near_squared = tolerance > 0 ? 4 * tolerance * tolerance : HUGE_VAL;
  // Skl¹ and Skl⁰ on the complex: each feature edge's ends on its curve (ball centres lie on
  // their curves, §2.1), each corner vertex at a corner of the domain.
  // The ends are asked curve by curve in one batch each: a polyline curve of n segments answers
  // a batch in O(log n) a point on it, where one point at a time cost O(n) each (edges x
  // segments in all: quadratic on a fine mesh of a finely tessellated curve).
  {
    const EdgesByCurve edges = group_edges_by_curve(mesh, domain.curve_count());
    std::vector<Vec3> ends;
    std::vector<double> parameters;
    for (std::uint32_t c = 0; c < domain.curve_count(); ++c) {
      if (stopped()) return report;
      const std::span<const std::array<std::uint32_t, 3>> segments(edges.segments.data() + edges.offsets[c],
                                                                   edges.offsets[c + 1] - edges.offsets[c]);
      ends.clear();
      for (const auto& s : segments) ends.push_back(mesh.vertices[s[0]]), ends.push_back(mesh.vertices[s[1]]);
      parameters.resize(ends.size());
      domain.curve_closest_parameters(c, ends, parameters);
      for (std::size_t k = 0; k < ends.size(); ++k) {
        const double off = (domain.curve_point(c, parameters[k]) - ends[k]).norm();
        if (!(off <= tolerance))
          general("vertex " + std::to_string(segments[k / 2][k % 2]) + " of an edge of curve " + std::to_string(c) +
                  " is " + std::to_string(off) + " off that curve");
      }
    }
  }
  // (vertex, the domain corner it is at), sorted: a corner vertex lies on every patch of its
  // corner, which its closest point names only one of (two spheres touching at a corner).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> at_corner;
  for (const std::uint32_t v : mesh.corners) {
    double nearest = HUGE_VAL;
    std::uint32_t which = 0;
    for (std::uint32_t k = 0; k < domain.corner_count(); ++k)
      if (const double d = (domain.corner_point(k) - mesh.vertices[v]).norm(); d < nearest) nearest = d, which = k;
    if (!(nearest <= tolerance))
      general("corner vertex " + std::to_string(v) + " is at no corner of the domain");
    else
      at_corner.emplace_back(v, which);
  }
  std::sort(at_corner.begin(), at_corner.end());
  Array<std::uint32_t> on_curve;  // vertices of feature edges, sorted
  for (const auto& e : mesh.edges) on_curve.push_back(e[0]), on_curve.push_back(e[1]);
  std::sort(on_curve.begin(), on_curve.end());
  // Each patch's triangles, in mesh order.
  std::vector<Array<std::size_t>> by_patch(domain.patch_count());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    by_patch[static_cast<std::size_t>(mesh.triangle_patch[t])].push_back(t);  // in range, checked above
  }
  // Where σ touches itself at a corner (Domain::corner_pinch_fans) the triangles around the
  // corner vertex are one disk per fan of the input, each open one between the feature edges of
  // its two curves; elsewhere one disk.
  const auto pinch_fans_at = [&](std::uint32_t v, std::uint32_t sigma) {
    const auto k = std::lower_bound(at_corner.begin(), at_corner.end(), std::pair{v, std::uint32_t{0}});
    return k != at_corner.end() && k->first == v ? domain.corner_pinch_fans(k->second, sigma)
                                                 : std::span<const std::array<std::uint32_t, 2>>{};
  };
  std::vector<std::pair<Edge, std::uint32_t>> edge_curves;  // feature edges with their curves, sorted
  for (std::size_t i = 0; i < mesh.edges.size(); ++i)
    edge_curves.emplace_back(edge(mesh.edges[i][0], mesh.edges[i][1]), static_cast<std::uint32_t>(mesh.edge_curve[i]));
  std::sort(edge_curves.begin(), edge_curves.end());
  std::vector<LinkPiece> pieces;
  const auto fan_is_disks = [&](std::uint32_t v, std::uint32_t sigma, const auto& link) {
    const auto fans = pinch_fans_at(v, sigma);
    if (fans.empty()) return link_shape(link).simple;
    const auto on_its_curve = [&](std::uint32_t end, std::uint32_t curve) {
      return std::binary_search(edge_curves.begin(), edge_curves.end(), std::pair{edge(v, end), curve});
    };
    return link_pieces(link, pieces) && pieces_match_fans(pieces, fans, on_its_curve);
  };
  Array<Edge> boundary, expected, slit;
  Array<std::array<std::uint32_t, 2>> fan;  // a vertex's link, as link_shape.h takes it
  SortedSides sorted;
  sorted.bits = static_cast<int>(std::bit_width(std::max<std::size_t>(mesh.vertices.size(), 2) - 1));
  kernel::KeyedIndices corners;  // (vertex, 3 i + k) for corner k of the patch's i-th triangle
  std::size_t vertices_checked = 0;  // for the stop's polls
  for (std::uint32_t sigma = 0; sigma < domain.patch_count(); ++sigma) {
    PatchSkeleton ps;
    ps.patch = sigma;
    const Array<std::size_t>& tris = by_patch[sigma];
    ps.triangles = tris.size();
    sorted.sides.clear();
    corners.clear();
    for (std::uint32_t i = 0; i < tris.size(); ++i) {
      const auto& v = mesh.triangles[tris[i]];
      for (std::uint32_t k = 0; k < 3; ++k) {
        const Edge e = edge(v[k], v[(k + 1) % 3]);
        sorted.sides.push_back({std::uint64_t{e.first} << sorted.bits | e.second, 3 * i + k});
        corners.push_back({v[k], 3 * i + k});
      }
    }
    kernel::radix_sort_by_key(sorted.sides, 2 * sorted.bits);
    kernel::radix_sort_by_key(corners, sorted.bits);
    if (ps.triangles == 0) problem(sigma, "no triangle");
    // Edges with their triangle counts; the boundary is those in one triangle.
    boundary.clear();
    for (std::size_t b = 0; b < sorted.sides.size();) {
      const std::size_t e = sorted.run_end(b);
      const std::size_t k = e - b;
      if (k > 2) problem(sigma, "edge in " + std::to_string(k) + " triangles"), ps.manifold = false;
      if (k == 1) boundary.push_back(sorted.edge_of(b));
      ++ps.edges;
      b = e;
    }
    ps.boundary_loops = components(boundary);
    // Each vertex's fan: a path or a cycle (connected, degrees <= 2).
    for (std::size_t b = 0; b < corners.size();) {
      if ((++vertices_checked & 1023) == 0 && stopped()) return report;
      const auto v = static_cast<std::uint32_t>(corners[b].first);
      fan.clear();
      for (; b < corners.size() && corners[b].first == v; ++b) {
        const std::uint32_t i = corners[b].second / 3, k = corners[b].second % 3;
        const auto& t = mesh.triangles[tris[i]];
        const Edge opposite = edge(t[(k + 1) % 3], t[(k + 2) % 3]);
        fan.push_back({opposite.first, opposite.second});
      }
      ++ps.vertices;
      if (!fan_is_disks(v, sigma, fan))
        problem(sigma, "the triangles around vertex " + std::to_string(v) + " are not one disk" +
                           (pinch_fans_at(v, sigma).empty() ? "" : " per fan of the pinched patch there")),
            ps.manifold = false;
      // Bounded by four times the tolerance squared: the search then only opens the tree's nodes
      // near v (a third of this check's time went to closest points), and whenever v is within
      // the tolerance the answer is the unbounded one.
      const auto close = domain.closest_point(mesh.vertices[v], near_squared);
      if (!close || close->squared_distance > tolerance * tolerance)
        problem(sigma, "vertex " + std::to_string(v) + " is off the domain");
      else if (std::binary_search(on_curve.begin(), on_curve.end(), v))
        continue;
      else if (const auto k = std::lower_bound(at_corner.begin(), at_corner.end(), std::pair{v, std::uint32_t{0}});
               k != at_corner.end() && k->first == v) {
        const auto patches = domain.corner_patches(k->second);
        if (std::find(patches.begin(), patches.end(), sigma) == patches.end())
          problem(sigma, "vertex " + std::to_string(v) + " (corner " + std::to_string(k->second) + ") is not on it");
      } else if (close->patch != sigma) {
        problem(sigma, "vertex " + std::to_string(v) + " lies on patch " + std::to_string(close->patch));
      }
    }
    ps.euler = static_cast<int>(ps.vertices) - static_cast<int>(ps.edges) + static_cast<int>(ps.triangles);
    // The boundary must be the feature edges of the curves bounding σ once.
    const auto curves = domain.patch_curves(sigma);
    expected.clear();
    slit.clear();
    for (std::size_t i = 0; i < mesh.edges.size(); ++i) {
      const auto c = static_cast<std::uint32_t>(mesh.edge_curve[i]);
      const auto k = std::count(curves.begin(), curves.end(), c);
      if (k == 1) expected.push_back(edge(mesh.edges[i][0], mesh.edges[i][1]));
      if (k >= 2) slit.push_back(edge(mesh.edges[i][0], mesh.edges[i][1]));
    }
    for (auto* list : {&expected, &slit}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    for (const Edge& e : boundary)  // sorted and distinct
      if (!contains(expected, e)) problem(sigma, "boundary edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " is not on a boundary curve");
    for (const Edge& e : expected)
      if (!contains(boundary, e)) problem(sigma, "curve edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " is not on the boundary");
    for (const Edge& e : slit)
      if (sorted.count(e) != 2) problem(sigma, "slit edge not between two triangles");
    std::tie(ps.cut_euler, ps.cut_boundary_loops) = cut_open_topology(mesh, tris, slit, sorted);
    report.patches.push_back(ps);
  }
  return report;
}

}  // namespace delpsc::refine
