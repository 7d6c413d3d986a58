// io::drop_unused_vertices: vertices no triangle uses go, the triangles are renumbered, and the
// others keep their order and coordinates.
#include <doctest/doctest.h>

#include <delpsc/io/unused_vertices.h>

using namespace delpsc;

TEST_CASE("drop_unused_vertices removes what no triangle uses and renumbers the triangles") {
  io::TriangleSoup soup;
  // 0 and 4 unused; 1, 2, 3, 5 used (5 twice).
  soup.vertices = {Vec3(9, 9, 9), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1e30, 0, 0), Vec3(0, 0, 1)};
  soup.triangles = {{1, 2, 3}, {1, 5, 2}, {3, 5, 1}};
  const io::UnusedVertices dropped = io::drop_unused_vertices(soup);
  CHECK(dropped.count == 2);
  CHECK(dropped.first == 0);
  CHECK(dropped.first_point == Vec3(9, 9, 9));
  REQUIRE(soup.vertices.size() == 4);
  CHECK(soup.vertices[0] == Vec3(0, 0, 0));
  CHECK(soup.vertices[1] == Vec3(1, 0, 0));
  CHECK(soup.vertices[2] == Vec3(0, 1, 0));
  CHECK(soup.vertices[3] == Vec3(0, 0, 1));
  REQUIRE(soup.triangles.size() == 3);
  CHECK(soup.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
  CHECK(soup.triangles[1] == std::array<std::uint32_t, 3>{0, 3, 1});
  CHECK(soup.triangles[2] == std::array<std::uint32_t, 3>{2, 3, 0});

  // Nothing to drop: nothing changes.
  const io::TriangleSoup before = soup;
  CHECK(io::drop_unused_vertices(soup).count == 0);
  CHECK(soup.vertices == before.vertices);
  CHECK(soup.triangles == before.triangles);

  // No triangles at all: every vertex goes (the commands then report an empty model).
  io::TriangleSoup points;
  points.vertices = {Vec3(1, 2, 3), Vec3(4, 5, 6)};
  const io::UnusedVertices all = io::drop_unused_vertices(points);
  CHECK(all.count == 2);
  CHECK(all.first_point == Vec3(1, 2, 3));
  CHECK(points.vertices.empty());
}
