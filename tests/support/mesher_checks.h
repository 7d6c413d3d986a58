// What every mesher test asserts after Mesh2Complex (Dey & Levine 2009, §3): the loop ended by
// itself (not stuck, not at the vertex cap) with the disk condition holding at every vertex, and
// the output satisfies G1 (refine/skeleton_check.h). doctest CHECKs, so a failure names the test.
#pragma once

#include <delpsc/io/surface_mesh.h>
#include <delpsc/protect/balls.h>
#include <delpsc/refine/domain.h>
#include <delpsc/refine/mesher.h>
#include <delpsc/refine/skeleton_check.h>

namespace delpsc::test {

/// Runs `mesher` and checks that it terminated normally with the disk condition everywhere and
/// the triangulation valid (RegularTriangulation::is_valid) and admissible
/// (refine/admissibility_check.h); with `balls` (the set the mesher's ProtectedBalls refines),
/// also that the balls still satisfy C1-C3 and cover the curves after every RefineBall (§2).
/// `require_c3` false leaves C3 out: it is a condition of Lemma 2.2 (small balls and facets give
/// the disk condition), not of the output, whose G1 follows from the disk condition itself; a
/// curve folding back within a ball radius of itself can end with the disk condition everywhere
/// while a large ball still reaches across the fold where nothing fails.
void run_mesher_and_check(refine::Mesher& mesher, const protect::BallSet* balls = nullptr, bool require_c3 = true);

/// G1 of `mesh` against `domain`, vertices accepted within 1e-9 of the diagonal of the domain;
/// CHECKs it and returns the report (per-patch topology for G2 checks).
refine::SkeletonReport check_g1(const io::SurfaceMesh& mesh, const refine::Domain& domain);

}  // namespace delpsc::test
