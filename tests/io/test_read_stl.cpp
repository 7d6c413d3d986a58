#include <doctest/doctest.h>

#include <delpsc/io/read_model.h>

#include "support/model_files.h"

using namespace delpsc;
using delpsc::test::Bytes;
using delpsc::test::io_error_of;
using delpsc::test::read_bytes;

namespace {

// A tetrahedron with outward-facing facets: 4 distinct points listed 12 times.
const float kTet[4][3][3] = {{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}},
                             {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                             {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                             {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

std::string binary_tet(std::string_view header_start, std::size_t facets = 4) {
  Bytes b(std::endian::little);
  std::string header(header_start);
  header.resize(80, ' ');
  b.text(header).put(static_cast<std::uint32_t>(facets));
  for (std::size_t f = 0; f < facets; ++f) {
    b.put(0.f).put(0.f).put(0.f);  // normal: ignored
    for (const auto& v : kTet[f % 4]) b.put(v[0]).put(v[1]).put(v[2]);
    b.put(std::uint16_t{0});
  }
  return b.str();
}

std::string ascii_tet(const char* solid = "solid", const char* facet = "facet") {
  std::string s = std::string(solid) + " tet\n";
  for (const auto& f : kTet) {
    s += std::string("  ") + facet + " normal 0 0 0\n    outer loop\n";
    for (const auto& v : f)
      s += "      vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
           std::to_string(v[2]) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid tet\n";
}

void check_tet(const io::ReadResult& r) {
  CHECK(r.soup.vertices.size() == 4);
  CHECK(r.report.file_vertices == 12);
  CHECK(r.report.merged_vertices == 8);
  REQUIRE(r.soup.triangles.size() == 4);
  CHECK(r.soup.vertices[r.soup.triangles[3][1]] == Vec3(0, 1, 0));
  CHECK(r.report.degenerate_triangles.empty());
}

}  // namespace

TEST_CASE("STL: binary, with and without a 'solid' header, vertices merged") {
  for (const char* header : {"binary tetrahedron", "solid tet exported by a CAD system"}) {
    const auto r = read_bytes(binary_tet(header), io::ModelFormat::stl);
    CHECK(r.report.format == "STL (binary)");
    check_tet(r);
  }
}

TEST_CASE("STL: ASCII, keywords in any case, several solids") {
  const auto r = read_bytes(ascii_tet(), io::ModelFormat::stl);
  CHECK(r.report.format == "STL (ASCII)");
  check_tet(r);
  check_tet(read_bytes(ascii_tet("SOLID", "FACET"), io::ModelFormat::stl));
  const auto two = read_bytes(ascii_tet() + ascii_tet(), io::ModelFormat::stl);
  CHECK(two.soup.triangles.size() == 8);
  CHECK(two.soup.vertices.size() == 4);
  CHECK(two.report.warnings.empty());
}

TEST_CASE("STL: a binary file with trailing bytes or a missing endsolid warns") {
  const auto padded = read_bytes(binary_tet("x") + "junk", io::ModelFormat::stl);
  REQUIRE(padded.report.warnings.size() == 1);
  CHECK(padded.report.warnings[0].find("4 bytes after the last triangle") != std::string::npos);
  std::string open = ascii_tet();
  open.resize(open.rfind("endsolid"));
  const auto r = read_bytes(open, io::ModelFormat::stl);
  REQUIRE(r.report.warnings.size() == 1);
  CHECK(r.report.warnings[0].find("endsolid") != std::string::npos);
}

TEST_CASE("STL: a 'solid' header with NUL bytes and a wrong size is binary, hence truncated") {
  std::string b = binary_tet("solid but binary");
  b.resize(b.size() - 10);
  const std::string msg = io_error_of([&] { read_bytes(b, io::ModelFormat::stl); });
  CHECK_MESSAGE(msg.find("byte 80: the header announces 4 triangles") != std::string::npos, msg);
}

TEST_CASE("STL: errors name the line or byte and the problem") {
  struct Case {
    std::string bytes, fragment;
  };
  std::string nan_tet = binary_tet("x");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan_tet[84 + 50 + 12 + 12 + 4], &nan, 4);  // facet 1, vertex 1, y
  std::string facet2 = ascii_tet();
  facet2.replace(facet2.find("vertex", facet2.find("facet", 20)), 6, "vortex");
  const Case cases[] = {
      {"", "empty file"},
      {std::string(40, 'x'), "byte 40: truncated: a binary STL starts with an 84-byte header"},
      {binary_tet("x").substr(0, 84 + 120), "byte 80: the header announces 4 triangles but only 120 bytes"},
      {binary_tet("x", 0), "empty model"},
      {nan_tet, "byte 158: triangle 1, vertex 1: NaN or infinite coordinate"},
      {"solid t\nendsolid t\n", "empty model"},
      {ascii_tet().substr(0, ascii_tet().find("vertex") + 16), "line 4: unexpected end of file in vertex (truncated?)"},
      {ascii_tet().substr(0, ascii_tet().find("loop") + 5), "line 4: unexpected end of file inside a facet"},
      {facet2, "line 11: expected 'vertex' or 'endloop', found 'vortex'"},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n",
       "line 6: facet with 2 vertices; at least 3"},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 inf 0\n",
       "line 6: vertex has a NaN or infinite coordinate"},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1,5 0\n",
       "line 6: vertex: '1,5' is not a number"},
      {"solid t\nfacet normal 0 0 1\nouter space\n", "line 3: expected 'loop', found 'space'"},
      {"solid t\nfacets\n", "line 2: expected 'facet' or 'endsolid', found 'facets'"},
      {"solid t\nendsolid\ngarbage\n", "line 3: expected 'solid' or the end of the file"},
  };
  for (const Case& c : cases) {
    const std::string msg = io_error_of([&] { read_bytes(c.bytes, io::ModelFormat::stl); });
    CHECK_MESSAGE(msg.rfind("mem.stl: ", 0) == 0, msg);
    CHECK_MESSAGE(msg.find(c.fragment) != std::string::npos, "got: " << msg << "\nwant: " << c.fragment);
  }
}
