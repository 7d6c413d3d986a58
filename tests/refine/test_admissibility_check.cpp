// refine/admissibility_check.h: the checker itself must be able to fail - an unweighted vertex
// inside, on, or just outside a ball, found whatever the vertex order and however far the ball
// sits from the origin.
#include <doctest/doctest.h>

#include <delpsc/delaunay/regular_triangulation.h>
#include <delpsc/refine/admissibility_check.h>

using namespace delpsc;

namespace {

// A tetrahedron of unweighted corners around a ball of squared radius w at c, and one more
// unweighted point q.
std::size_t problems_with(const Vec3& c, double w, const Vec3& q) {
  delaunay::RegularTriangulation dt;
  const double s = 10;
  std::vector<WeightedPoint> points = {
      {c.x() - s, c.y() - s, c.z() - s, 0}, {c.x() + s, c.y() - s, c.z() - s, 0},
      {c.x(), c.y() + s, c.z() - s, 0},     {c.x(), c.y(), c.z() + s, 0},
      {c.x(), c.y(), c.z(), w},             {q.x(), q.y(), q.z(), 0}};
  // The batch numbers points in spatial order: ids says which is the ball and which is q.
  std::vector<delaunay::PointId> ids;
  dt.insert(points, &ids);
  REQUIRE(dt.status(ids[4]) == delaunay::PointStatus::vertex);
  REQUIRE(dt.status(ids[5]) == delaunay::PointStatus::vertex);  // else the case would test nothing
  return refine::check_admissibility(dt).size();
}

}  // namespace

TEST_CASE("an unweighted vertex inside or on a ball is reported, one outside is not") {
  for (const Vec3& c : {Vec3(0, 0, 0), Vec3(1e6, -3e5, 2e4)}) {
    CAPTURE(c.transpose());
    CHECK(problems_with(c, 1, c + Vec3(0.5, 0, 0)) == 1);        // inside
    CHECK(problems_with(c, 1, c + Vec3(0, 1, 0)) == 1);          // on the sphere: power distance 0
    CHECK(problems_with(c, 1, c + Vec3(0, 0, 1.001)) == 0);      // just outside
    CHECK(problems_with(c, 1, c + Vec3(-3, 2, 1)) == 0);         // far
  }
}
