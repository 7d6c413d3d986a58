// The restricted facets the mesher keeps incrementally (restricted_facets.h) checked against a
// scan of every facet of the final triangulation. The mesher never rescans: after each insertion
// it skips or carries over the facets on the cavity's boundary whose dual edge only shrank
// (RestrictedFacets::update), which is right only if that argument and its bookkeeping are. This
// checker recomputes the pairs (triangle, patch) from scratch and compares, for the tests.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <delpsc/delaunay/regular_triangulation.h>

#include "domain.h"
#include "restricted_facets.h"

namespace delpsc::refine {

/// The first problem of `kept`'s references from cells to records, if any
/// (RestrictedFacets::refs_consistent), alone; else one line per pair (triangle, patch) found by
/// only one of `kept` and a fresh scan of `dt` against `domain`, and per pair both find with a
/// different point of V_t ∩ σ or size (beyond 1e-9 of the box's diagonal: step 2 reads both, and
/// a record carried over keeps its point) (at most `max_problems` lines); empty iff they agree,
/// but for one kind of pair: one
/// the scan finds whose exact dual edge - on the triangle's line, from every vertex, not from its
/// two cells - misses the patch. The scan's edge, computed from nearly flat cells, can run where
/// the true one does not, and `kept` may rightly lack such a pair: RestrictedFacets::rebuild
/// skips facets whose dual edge cannot meet the domain without querying them. O(F) segment
/// queries for F finite facets, and O(V) per such pair.
std::vector<std::string> check_restricted_facets(const delaunay::RegularTriangulation& dt, const Domain& domain,
                                                 const RestrictedFacets& kept, std::size_t max_problems = 20);

}  // namespace delpsc::refine
