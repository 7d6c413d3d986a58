// hidden_back_faces (io/hidden_faces.h): on closed surfaces every triangle it hides is covered,
// seen from the viewer, by a triangle it keeps (checked by casting a ray from the hidden
// triangle's centroid towards the viewer, brute force), and every kept one faces the viewer;
// the orientation's sign does not matter; open, non-manifold or inconsistently oriented parts
// are never culled, while a closed part next to them still is.
#include <doctest/doctest.h>

#include <cstddef>
#include <optional>

#include <delpsc/io/hidden_faces.h>
#include <delpsc/io/sample_part.h>
#include <delpsc/io/shapes.h>

using namespace delpsc;

namespace {

const Vec3 kToward(0.55, -1.0, 0.75);

io::SurfaceMesh mesh_of(const io::TriangleSoup& soup) { return io::surface_mesh_from(soup); }

io::SurfaceMesh flipped(io::SurfaceMesh mesh) {
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  return mesh;
}

// Does the ray origin + s * direction, s > 0, cross triangle t (Möller-Trumbore)?
bool ray_hits(const io::SurfaceMesh& mesh, std::size_t t, const Vec3& origin, const Vec3& direction) {
  const Vec3 &a = mesh.vertices[mesh.triangles[t][0]], &b = mesh.vertices[mesh.triangles[t][1]],
             &c = mesh.vertices[mesh.triangles[t][2]];
  const Vec3 e1 = b - a, e2 = c - a, p = direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-14) return false;
  const Vec3 s = origin - a;
  const double u = s.dot(p) / det;
  const Vec3 q = s.cross(e1);
  const double v = direction.dot(q) / det, dist = e2.dot(q) / det;
  return u >= 0 && v >= 0 && u + v <= 1 && dist > 1e-9;
}

std::size_t count(const std::vector<bool>& flags) {
  std::size_t n = 0;
  for (const bool f : flags) n += f;
  return n;
}

// The hidden triangles not covered, seen from the viewer, by a kept one.
std::size_t uncovered(const io::SurfaceMesh& mesh, const std::vector<bool>& hidden) {
  REQUIRE(hidden.size() == mesh.triangles.size());
  std::size_t n = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!hidden[t]) continue;
    const auto& tri = mesh.triangles[t];
    const Vec3 centroid = (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3;
    bool covered = false;
    for (std::size_t s = 0; s < mesh.triangles.size() && !covered; ++s)
      covered = !hidden[s] && ray_hits(mesh, s, centroid, kToward);
    n += !covered;
  }
  return n;
}

}  // namespace

TEST_CASE("hidden faces: closed surfaces lose their back half, invisibly, either orientation") {
  for (const io::SurfaceMesh& mesh : {mesh_of(io::make_sphere(6)), mesh_of(io::make_torus(1, 0.3, 16, 8)),
                                       mesh_of(io::make_cube(3))}) {
    const std::vector<bool> hidden = io::hidden_back_faces(mesh, kToward);
    // Roughly half of a closed convex-ish surface faces away.
    CHECK(count(hidden) > mesh.triangles.size() / 3);
    CHECK(count(hidden) < 2 * mesh.triangles.size() / 3);
    CHECK(uncovered(mesh, hidden) == 0);
    // The check can fail: hiding the front half instead leaves it uncovered.
    std::vector<bool> front = hidden;
    front.flip();
    CHECK(uncovered(mesh, front) > 0);
    // Kept triangles face the viewer when the surface is oriented outward (as these are).
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const Vec3 n = (mesh.vertices[tri[1]] - mesh.vertices[tri[0]]).cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
      if (!hidden[t]) CHECK(n.dot(kToward) >= 0);
    }
    // Oriented inward: the same triangles are hidden.
    CHECK(io::hidden_back_faces(flipped(mesh), kToward) == hidden);
    // Far from the origin: the same.
    io::SurfaceMesh moved = mesh;
    for (auto& v : moved.vertices) v += Vec3(1e6, -2e6, 3e6);
    CHECK(io::hidden_back_faces(moved, kToward) == hidden);
  }
}

TEST_CASE("hidden faces: open, non-manifold and inconsistently oriented parts are kept") {
  io::SurfaceMesh cube = mesh_of(io::make_cube(2));
  // One triangle missing: a hole shows the inside.
  io::SurfaceMesh open = cube;
  open.triangles.pop_back();
  CHECK(count(io::hidden_back_faces(open, kToward)) == 0);
  // One triangle turned over: not consistently oriented.
  io::SurfaceMesh turned = cube;
  std::swap(turned.triangles[0][1], turned.triangles[0][2]);
  CHECK(count(io::hidden_back_faces(turned, kToward)) == 0);
  // A sheet and the sample part (with its fin: edges in three triangles).
  CHECK(count(io::hidden_back_faces(mesh_of(io::make_square_sheet(3)), kToward)) == 0);
  CHECK(count(io::hidden_back_faces(mesh_of(io::make_sample_part(16)), kToward)) == 0);

  // An open copy next to the closed cube: the cube is still culled, the open one not at all.
  io::SurfaceMesh both = cube;
  const auto offset = static_cast<std::uint32_t>(both.vertices.size());
  for (const auto& v : open.vertices) both.vertices.push_back(v + Vec3(3, 0, 0));
  for (const auto& t : open.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  const std::vector<bool> hidden = io::hidden_back_faces(both, kToward);
  const std::vector<bool> cube_alone = io::hidden_back_faces(cube, kToward);
  CHECK(count(cube_alone) > 0);
  for (std::size_t t = 0; t < both.triangles.size(); ++t)
    CHECK(hidden[t] == (t < cube.triangles.size() && cube_alone[t]));
}
