// Checks of a protect::Complex against its own mesh, written independently of the builder: the
// incidences it lists must agree with what the triangles and edges say.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <delpsc/protect/complex.h>

namespace delpsc::test {

/// Every inconsistency found, one line each (empty when the complex is consistent):
///  - each curve's corners exist and sit at its polyline's ends, closed iff they are equal, its
///    consecutive vertices are joined by feature edges labelled with the curve, its inner
///    vertices are not corners, its arc lengths increase to its length;
///  - every feature edge lies on exactly one curve, once;
///  - each corner lists as many curve ends as its feature degree;
///  - triangle_patch and the patch triangle lists agree;
///  - each patch's boundary curve list (with multiplicity m per curve) matches its boundary
///    edges: every edge of a listed curve has exactly m triangles of the patch, and every feature
///    edge with a triangle in the patch lies on a listed curve;
///  - each curve's patch list equals the patches of the triangles of every one of its edges.
std::vector<std::string> complex_problems(const protect::Complex& complex);

/// (Euler characteristic, boundary loops) of every patch, sorted, for comparisons.
std::vector<std::pair<int, int>> patch_topologies(const protect::Complex& complex);

/// Number of curves along which three or more triangles meet.
std::size_t non_manifold_curves(const protect::Complex& complex);

}  // namespace delpsc::test
