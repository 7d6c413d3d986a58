// Protect on real models from Debian's libcgal-demo (fandisk, part, anchor, joint, elephant),
// fetched by scripts/get-cgal-data.sh into data/cgal-demo/ (absent: see tests/support/cgal_demo_data.h).
// At λ = 4%, 1% and 0.25% of the diagonal: terminates, passes the checker, radii at most λ; and
// the mesher's pattern, refining the largest ball repeatedly, keeps the conditions.
#include <doctest/doctest.h>

#include <optional>
#include <string>

#include <delpsc/io/read_model.h>
#include <delpsc/protect/ball_checker.h>
#include <delpsc/protect/protect.h>

#include "support/problem_lines.h"
#include "support/cgal_demo_data.h"

using namespace delpsc;

namespace {

const char* const kModels[] = {"fandisk", "part", "anchor", "joint", "elephant"};

std::optional<io::TriangleSoup> load(const char* name) { return test::cgal_demo_soup(name); }

void require_valid(const protect::BallSet& balls) {
  const protect::BallCheck check = protect::check_balls(balls);
  CHECK_MESSAGE(check.ok(), test::problem_lines(check.problems));
}

}  // namespace

TEST_CASE("libcgal-demo models: protection at 4%, 1% and 0.25% of the diagonal") {
  for (const char* name : kModels) {
    const auto soup = load(name);
    if (!soup) continue;
    const std::string model = name;
    CAPTURE(model);
    const protect::Complex complex = protect::build_complex(*soup);
    const double diagonal = protect::BallSet(complex).diagonal();
    for (const double fraction : {0.04, 0.01, 0.0025}) {
      CAPTURE(fraction);
      const protect::BallSet balls = protect::protect(complex, fraction * diagonal);
      require_valid(balls);
      CHECK(balls.corner_ball_count() == complex.corner_count());
      CHECK(balls.radius_range().second <= fraction * diagonal);
    }
  }
}

TEST_CASE("libcgal-demo models: refining the largest ball 20 times keeps the conditions") {
  for (const char* name : kModels) {
    const auto soup = load(name);
    if (!soup) continue;
    const std::string model = name;
    CAPTURE(model);
    const protect::Complex complex = protect::build_complex(*soup);
    protect::BallSet balls = protect::protect(complex, 0.04 * protect::BallSet(complex).diagonal());
    const std::size_t before = balls.size();
    for (int step = 0; step < 20; ++step) protect::refine_ball(balls, balls.largest());
    require_valid(balls);
    CHECK(balls.size() > before);
  }
}
