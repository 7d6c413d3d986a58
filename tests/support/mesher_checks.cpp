#include "mesher_checks.h"

#include <doctest/doctest.h>

#include <delpsc/protect/ball_checker.h>
#include <delpsc/refine/admissibility_check.h>
#include <delpsc/refine/restricted_facets_check.h>

#include "support/problem_lines.h"
#include "support/triangulation_checks.h"

namespace delpsc::test {

namespace {
// Up to ~0.1 s of brute force a run (~7 cells a point).
constexpr std::size_t kBruteForceRegularityPoints = 1500;
}  // namespace

void run_mesher_and_check(refine::Mesher& mesher, const protect::BallSet* balls, bool require_c3) {
  mesher.run();
  INFO("message: " << mesher.stats().message);
  CHECK_FALSE(mesher.stats().stuck);
  CHECK_FALSE(mesher.stats().stopped_at_max_vertices);
  CHECK(mesher.failing_vertices().empty());
  // The regular triangulation itself after all the insertions and ball removals (§2.3 RefineBall).
  std::string why;
  CHECK_MESSAGE(mesher.triangulation().is_valid(&why), why);
  // And by brute force where that is affordable (O(cells x points)): is_valid's test is local,
  // and it is the triangulation's own code.
  if (mesher.triangulation().number_of_points() <= kBruteForceRegularityPoints) {
    const std::string brute = check_regular_against_all_points(mesher.triangulation());
    CHECK_MESSAGE(brute.empty(), brute);
  }
  // Admissibility (§2.1): no unweighted vertex in or on a protecting ball, checked independently.
  for (const std::string& p : refine::check_admissibility(mesher.triangulation())) FAIL_CHECK(p);
  // The restricted facets kept incrementally (some carried over, never rescanned) are those a
  // scan of the final triangulation finds.
  for (const std::string& p :
       refine::check_restricted_facets(mesher.triangulation(), mesher.domain(), mesher.restricted_facets()))
    FAIL_CHECK(p);
  if (balls != nullptr) {
    const protect::BallCheck check = protect::check_balls(*balls);
    CHECK_MESSAGE(check.ok(), test::problem_lines(check.problems));
    if (require_c3) CHECK(check.c3 == 0);  // which ok() leaves out (ball_checker.h); Lemma 2.1 rests on it
  }
}

refine::SkeletonReport check_g1(const io::SurfaceMesh& mesh, const refine::Domain& domain) {
  const kernel::Box3 box = domain.bounding_box();
  const refine::SkeletonReport report = refine::check_skeleton(mesh, domain, 1e-9 * (box.hi - box.lo).norm());
  CHECK_MESSAGE(report.ok(), test::problem_lines(report.problems));
  return report;
}

}  // namespace delpsc::test
