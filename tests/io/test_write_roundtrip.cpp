#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>

#include <delpsc/io/mesh_writer.h>
#include <delpsc/io/read_model.h>
#include <delpsc/io/shapes.h>

#include "support/model_files.h"

using namespace delpsc;
using delpsc::test::canonical_triangles;
using delpsc::test::canonical_triangles_as_float;
using delpsc::test::io_error_of;

namespace {

/// A torus whose coordinates are awkward for text: thirds, tiny and huge magnitudes, -0. The
/// tiny ones stay above 2^-140 (readers set smaller ones to 0: the predicates' exact range).
io::SurfaceMesh awkward_torus() {
  io::SurfaceMesh m = io::surface_mesh_from(io::make_torus(2, 0.75, 12, 8));
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    Vec3& p = m.vertices[i];
    p = p / 3.0 * (i % 3 == 0 ? 1e-20 : i % 3 == 1 ? 1e30 : 1.0);
  }
  m.vertices[5].z() = -0.0;
  return m;
}

io::TriangleSoup soup_of(const io::SurfaceMesh& m) {
  return {{m.vertices.begin(), m.vertices.end()}, {m.triangles.begin(), m.triangles.end()}};
}

}  // namespace

TEST_CASE("OFF, OBJ and PLY round-trip exactly; STL to float precision") {
  const io::SurfaceMesh mesh = awkward_torus();
  for (const char* name : {"rt.off", "rt.obj", "rt.ply", "rt.STL"}) {
    CAPTURE(name);
    const std::string path = test::temp_path(name);
    io::write_mesh(path, mesh);
    const auto r = io::read_model(path);
    const bool is_stl = std::string(name).ends_with(".STL");
    if (is_stl) {
      CHECK(r.report.format == "STL (binary)");
      CHECK(canonical_triangles(r.soup) == canonical_triangles_as_float(soup_of(mesh)));
    } else {
      // Same vertex numbering too: the indexed formats keep it and nothing is merged.
      CHECK(std::equal(r.soup.vertices.begin(), r.soup.vertices.end(), mesh.vertices.begin(), mesh.vertices.end()));
      CHECK(std::equal(r.soup.triangles.begin(), r.soup.triangles.end(), mesh.triangles.begin(), mesh.triangles.end()));
      CHECK(r.report.merged_vertices == 0);
    }
    CHECK(canonical_triangles_as_float(r.soup) == canonical_triangles_as_float(soup_of(mesh)));
    CHECK(r.report.degenerate_triangles.empty());
    std::remove(path.c_str());
  }
}

TEST_CASE("binary STL from the writer never looks like ASCII and carries unit normals") {
  io::SurfaceMesh m;
  m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 0}};
  m.triangles = {{0, 1, 2}, {0, 1, 3}};  // the second has zero area: normal 0
  const std::string bytes = io::format_mesh(m, io::MeshFormat::stl);
  REQUIRE(bytes.size() == 84 + 2 * 50);
  CHECK(bytes.rfind("solid", 0) == std::string::npos);
  float n[3];
  std::memcpy(n, bytes.data() + 84, sizeof n);
  CHECK(n[0] == 0.f);
  CHECK(n[1] == 0.f);
  CHECK(n[2] == 1.f);
  std::memcpy(n, bytes.data() + 134, sizeof n);
  CHECK((n[0] == 0.f && n[1] == 0.f && n[2] == 0.f));
}

TEST_CASE("triangles that rounding to STL's floats flattens are counted") {
  io::SurfaceMesh m;
  // Near the origin, a triangle of 1e-3 survives float; 1e9 away (float's spacing there is 64) a
  // triangle of size 1 loses its corners to one point, and one of size 100 keeps an area; a
  // needle whose apex rounds onto its base line is flat too.
  m.vertices = {{0, 0, 0}, {1e-3, 0, 0}, {0, 1e-3, 0},
                {1e9, 0, 0}, {1e9 + 1, 0, 0}, {1e9, 1, 0},
                {1e9, 0, 0}, {1e9 + 100, 0, 0}, {1e9, 100, 0},
                {0, 1, 0}, {1, 1, 0}, {0.5, 1 + 1e-9, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
  CHECK(io::triangles_collapsed_in_float(m) == 2);
  m.triangles = {{0, 1, 2}, {6, 7, 8}};
  CHECK(io::triangles_collapsed_in_float(m) == 0);
}

TEST_CASE("writers refuse unknown extensions and inconsistent meshes") {
  io::SurfaceMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}};
  const std::string path = test::temp_path("bad.xyz");
  CHECK(io_error_of([&] { io::write_mesh(path, m); }).find("unknown output format") != std::string::npos);
  m.triangles = {{0, 1, 3}};
  CHECK(io_error_of([&] { io::write_mesh(test::temp_path("bad.off"), m); })
            .find("triangle 0 uses vertex 3 of 3") != std::string::npos);
  m.triangles = {{0, 1, 2}};
  m.triangle_patch = {1, 2};
  CHECK(io_error_of([&] { io::format_mesh(m, io::MeshFormat::vtu); })
            .find("triangle_patch has 2 entries for 1 triangles") != std::string::npos);
  m.triangle_patch.clear();
  m.edges = {{0, 1}};
  m.edge_curve = {1, 2};
  CHECK(io_error_of([&] { io::format_mesh(m, io::MeshFormat::medit); }).find("edge_curve") != std::string::npos);
  m.edge_curve.clear();
  m.corners = {7};
  CHECK(io_error_of([&] { io::format_mesh(m, io::MeshFormat::medit); }).find("corner vertex 7") != std::string::npos);
  CHECK(io_error_of([&] { io::write_mesh("/nonexistent-dir/x.off", io::SurfaceMesh{}); })
            .find("cannot open for writing") != std::string::npos);
}
