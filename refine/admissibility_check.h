// The admissibility invariant of DelPSC (Dey & Levine 2009, §2.1 and §3): no unweighted vertex
// of the triangulation lies in or on a protecting ball, i.e. every unweighted vertex has positive
// power distance to every weighted vertex. The mesher refuses such points as it goes
// (Mesher::insert_surface_point) and forgets the ones a new ball would cover; this checker
// verifies the end state independently, for the tests.
//
// Exact: each candidate pair is decided by kernel::power_distance_sign.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>

namespace delpsc::refine {

/// One line per unweighted vertex in or on a ball (at most `max_problems`); empty iff the
/// triangulation is admissible. Hidden and removed points are not vertices and are ignored.
/// O((U + B) log U + K) for U unweighted and B weighted vertices, K the candidate pairs (those
/// within the ball's x-extent, doubled for safety, and then the exact test).
std::vector<std::string> check_admissibility(const delaunay::RegularTriangulation& dt, std::size_t max_problems = 20);

}  // namespace delpsc::refine
