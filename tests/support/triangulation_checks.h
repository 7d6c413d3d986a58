// Checkers for delaunay::RegularTriangulation shared by the test suites: canonical cell lists (to
// compare two triangulations, or one with CGAL's) and brute-force regularity.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>

namespace delpsc::test {

using Quad = std::array<std::uint32_t, 4>;

/// The finite cells of t as vertex quadruples, each sorted, the list sorted. Vertex v is written
/// names[v] (names empty: v itself), so triangulations of the same points numbered differently
/// can be compared.
std::vector<Quad> finite_cell_quads(const delaunay::RegularTriangulation& t,
                                    const std::vector<std::uint32_t>& names = {});

/// The ids (through names, as above) of the points with the given status, sorted.
std::vector<std::uint32_t> points_with_status(const delaunay::RegularTriangulation& t,
                                              delaunay::PointStatus status,
                                              const std::vector<std::uint32_t>& names = {});

/// The regular triangulation of `points` by brute force, O(n^5): every positively oriented
/// quadruple no point of which is in conflict with the orthosphere under the symbolic
/// perturbation (kernel::power_test_perturbed). Precondition: distinct positions. Returns sorted
/// quadruples of indices into points, sorted.
std::vector<Quad> brute_force_regular_cells(const std::vector<WeightedPoint>& points);

/// Checks every finite cell of t against every live point (vertex or hidden) of t, O(cells *
/// points): no point not a vertex of the cell is in conflict with it (for a point at a vertex's
/// position, the heavier must be the vertex). Empty string if fine, else what is wrong.
std::string check_regular_against_all_points(const delaunay::RegularTriangulation& t);

/// Checks that a ChangeSet is consistent with the triangulation after the operation: created
/// cells are alive; no id repeats within a list; `cells_before` - destroyed + created = live
/// cells now. Empty string if fine.
std::string check_change_set(const delaunay::RegularTriangulation& t, std::size_t cells_before,
                             const delaunay::ChangeSet& changes);

}  // namespace delpsc::test
