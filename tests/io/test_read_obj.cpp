#include <doctest/doctest.h>

#include <delpsc/io/read_model.h>

#include "support/model_files.h"

using namespace delpsc;
using delpsc::test::io_error_of;
using delpsc::test::read_bytes;

TEST_CASE("OBJ: v/vt/vn face forms, other statements ignored") {
  const auto r = read_bytes(
      "# exported\nmtllib a.mtl\no square\n"
      "v 0 0 0\nv 1 0 0 1.0\nv 1 1 0 0.5 0.5 0.5\nv 0 1 0\n"
      "vt 0 0\nvt 1 1\nvn 0 0 1\ng side\nusemtl red\ns off\n"
      "f 1/1/1 2/2/1 3//1\n"
      "f 1/1 3 4//1 # mixed forms are tolerated\n"
      "l 1 2\n",
      io::ModelFormat::obj);
  CHECK(r.report.format == "OBJ");
  REQUIRE(r.soup.vertices.size() == 4);
  REQUIRE(r.soup.triangles.size() == 2);
  CHECK(r.soup.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
  CHECK(r.soup.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
  CHECK(r.soup.vertices[2] == Vec3(1, 1, 0));
  CHECK(r.report.warnings.empty());  // every statement skipped here is one OBJ defines
}

TEST_CASE("OBJ: negative indices count back from the last vertex defined so far") {
  const auto r = read_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
                            "v 0 0 1\nf -4 -2 -1\n",
                            io::ModelFormat::obj);
  REQUIRE(r.soup.triangles.size() == 2);
  CHECK(r.soup.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
  CHECK(r.soup.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
}

TEST_CASE("OBJ: polygons are fan-triangulated, duplicates merged, CRLF accepted") {
  const auto r = read_bytes("v 0 0 0\r\nv 1 0 0\r\nv 2 1 0\r\nv 1 2 0\r\nv 0 1 0\r\nv 1 0 0\r\n"
                            "f 1 2 3 4 5\r\nf 6 1 5\r\n",
                            io::ModelFormat::obj);
  REQUIRE(r.soup.triangles.size() == 4);
  CHECK(r.soup.vertices.size() == 5);
  CHECK(r.soup.triangles[2] == std::array<std::uint32_t, 3>{0, 3, 4});
  CHECK(r.soup.triangles[3] == std::array<std::uint32_t, 3>{1, 0, 4});  // vertex 6 is vertex 2
  CHECK(r.report.polygons == 2);
}

TEST_CASE("OBJ: errors name the line and the problem") {
  struct Case {
    std::string text, fragment;
  };
  const Case cases[] = {
      {"", "empty model"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no triangles"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "line 4: face vertex index 4 out of range: 3 vertices"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", "line 4: face vertex index -4 out of range"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "line 4: face vertex index 0 (OBJ indices start at 1)"},
      {"v 0 0 0\nv 1 0 0\nf 1 2\n", "line 3: face with 2 vertices; at least 3"},
      {"v 0 0 0\nv 1 0\n", "line 2: vertex with fewer than three coordinates"},
      {"v 0 0 0\nv 1 zero 0\n", "line 2: vertex coordinate 'zero' is not a number"},
      {"v 0 0 0\nv 1 0 inf\n", "line 2: vertex has a NaN or infinite coordinate"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/x\n", "line 4: face corner '3/x' is not a vertex reference"},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/1/1/1\n", "face corner '3/1/1/1' is not a vertex reference"},
      {"v 0 0 0\n\x01\x02\x03 garbage\n", "line 2: not an OBJ statement: '\\x01\\x02\\x03' (binary data?)"},
  };
  for (const Case& c : cases) {
    const std::string msg = io_error_of([&] { read_bytes(c.text, io::ModelFormat::obj); });
    CHECK_MESSAGE(msg.rfind("mem.obj: ", 0) == 0, msg);
    CHECK_MESSAGE(msg.find(c.fragment) != std::string::npos, "got: " << msg << "\nwant: " << c.fragment);
  }
}

TEST_CASE("OBJ: a statement OBJ does not know is skipped with a warning; a file of none is refused by name") {
  const auto r = read_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nfoo bar\ng part\nf 1 2 3\nbaz\n", io::ModelFormat::obj);
  CHECK(r.soup.triangles.size() == 1);
  REQUIRE(r.report.warnings.size() == 1);  // vt and g are known and skipped silently
  CHECK(r.report.warnings[0].find("2 line(s) with a statement OBJ does not know skipped, the first 'foo' at line 5") !=
        std::string::npos);
  // An OFF file named .obj: no v or f at all; it was refused as an empty model.
  const std::string error =
      io_error_of([] { read_bytes("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", io::ModelFormat::obj); });
  CHECK(error.find("line 1: no OBJ 'v' or 'f' statement, and 'OFF' is no OBJ statement") != std::string::npos);
}
