// The topology of a whole triangulated 2-complex - the union of all patches' triangles glued along
// shared vertices - for guarantee G2 of DelPSC (Dey & Levine 2009, Theorem 4.3: at a fine enough
// size |∪ Skl^i| is homeomorphic to the input complex |D|). The per-patch figures of
// skeleton_check.h cannot see how patches are glued (two sheets of a book swapped at the spine,
// a fin detached from its box, two touching spheres pulled apart); these figures can.
//
// Every figure is a topological invariant of the underlying space, so a homeomorphic output and
// input have equal figures whatever their triangulations, including non-manifold ones:
//  - components and the Euler characteristic V - E + F (a homotopy invariant of the 2-complex);
//  - the boundary: points with a half-disk neighbourhood, here the edges in exactly one triangle;
//    the number of connected components of their closure;
//  - the singular curves: points where three or more sheets meet, here the edges in three or more
//    triangles; the number of connected components of their closure;
//  - the sheets: the connected components of the complex minus its singular set, here triangles
//    glued across edges in exactly two triangles, and how many of them are not orientable.
// Equal figures are a necessary condition for a homeomorphism, not a proof of one.
//
// Compare like with like: the input's figures come from the cleaned triangles the mesher meshed
// (protect::Complex::triangles: zero-area triangles dropped, caps healed), not the raw file.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <delpsc/protect/complex.h>

namespace delpsc::refine {

struct ComplexTopology {
  std::size_t vertices = 0, edges = 0, triangles = 0;  ///< of the triangles given (vertices used)
  std::size_t components = 0;
  long euler = 0;                      ///< V - E + F
  std::size_t boundary_loops = 0;      ///< components of the edges in exactly one triangle
  std::size_t singular_curves = 0;     ///< components of the edges in three or more triangles
  std::size_t sheets = 0;              ///< triangles glued across edges in exactly two triangles
  std::size_t non_orientable_sheets = 0;
};

/// The figures of the complex made of `triangles` (vertex indices; a vertex index shared by two
/// triangles glues them). Preconditions: no triangle repeats a vertex. O(T log T) time, O(T + V)
/// memory for T triangles and largest vertex index V.
ComplexTopology complex_topology(std::span<const std::array<std::uint32_t, 3>> triangles);
/// The same figures for complex.triangles, read off the complex's own edge table: O(T + V), and
/// none of the other's 16-byte records per half-edge and their sort (96 MB at the peak of a
/// 1M-triangle input meshed coarsely).
ComplexTopology complex_topology(const protect::Complex& complex);

/// One line per figure in which `output` differs from `input` (components, Euler characteristic,
/// boundary loops, singular curves, sheets, non-orientable sheets); empty iff they agree.
/// Counts of vertices, edges and triangles are not compared (they depend on the triangulation).
std::vector<std::string> topology_differences(const ComplexTopology& output, const ComplexTopology& input);

}  // namespace delpsc::refine
