#include <doctest/doctest.h>

#include <limits>

#include <delpsc/io/read_model.h>

#include "support/model_files.h"

using namespace delpsc;
using delpsc::test::Bytes;
using delpsc::test::io_error_of;
using delpsc::test::read_bytes;

namespace {

// A square pyramid: 5 vertices, a quad base and 4 triangles (6 triangles after the fan).
const double kPyramid[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
const std::vector<std::vector<int>> kFaces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

// Properties in an awkward order, types mixed, extra elements before and after the faces and
// extra lists inside them: everything we do not read must still be skipped byte-exactly.
const char* kHeaderBody =
    "comment made by hand\n"
    "obj_info nothing\n"
    "element vertex 5\n"
    "property float nx\n"
    "property double z\n"
    "property uchar red\n"
    "property double x\n"
    "property float y\n"
    "element material 2\n"
    "property list uchar int ids\n"
    "property short shininess\n"
    "element face 5\n"
    "property uchar flags\n"
    "property list uchar int vertex_indices\n"
    "property list int float texcoord\n"
    "element edge 1\n"
    "property int vertex1\n"
    "property uint vertex2\n"
    "end_header\n";

std::string binary_pyramid(std::endian order) {
  Bytes b(order);
  b.text(std::string("ply\nformat ") +
         (order == std::endian::little ? "binary_little_endian" : "binary_big_endian") + " 1.0\n");
  b.text(kHeaderBody);
  for (const auto& p : kPyramid)
    b.put(0.5f).put(p[2]).put(std::uint8_t{200}).put(p[0]).put(static_cast<float>(p[1]));
  b.put(std::uint8_t{3}).put(1).put(2).put(3).put(std::int16_t{-7});
  b.put(std::uint8_t{0}).put(std::int16_t{9});
  for (const auto& f : kFaces) {
    b.put(std::uint8_t{1}).put(static_cast<std::uint8_t>(f.size()));
    for (int v : f) b.put(v);
    b.put(2).put(0.25f).put(0.75f);
  }
  b.put(0).put(1u);
  return b.str();
}

std::string ascii_pyramid() {
  std::string s = std::string("ply\r\nformat ascii 1.0\r\n") + kHeaderBody;
  for (const auto& p : kPyramid)
    s += "0.5 " + std::to_string(p[2]) + " 200 " + std::to_string(p[0]) + " " +
         std::to_string(p[1]) + "\n";
  s += "3 1 2 3 -7\n0 9\n";
  for (const auto& f : kFaces) {
    s += "1 ";
    s += std::to_string(f.size());
    for (int v : f) {
      s += ' ';  // (s += " " + to_string(v) trips GCC 12's -Wrestrict false positive)
      s += std::to_string(v);
    }
    s += " 2 0.25 0.75\n";
  }
  return s + "0 1\n";
}

void check_pyramid(const io::ReadResult& r) {
  REQUIRE(r.soup.vertices.size() == 5);
  for (int i = 0; i < 5; ++i) CHECK(r.soup.vertices[i] == Vec3(kPyramid[i][0], kPyramid[i][1], kPyramid[i][2]));
  REQUIRE(r.soup.triangles.size() == 6);
  CHECK(r.soup.triangles[0] == std::array<std::uint32_t, 3>{0, 3, 2});
  CHECK(r.soup.triangles[5] == std::array<std::uint32_t, 3>{3, 0, 4});
  CHECK(r.report.polygons == 5);
  CHECK(r.report.warnings.empty());
}

}  // namespace

TEST_CASE("PLY: ASCII and both binary byte orders read the same model") {
  const auto a = read_bytes(ascii_pyramid(), io::ModelFormat::ply);
  CHECK(a.report.format == "PLY (ASCII)");
  check_pyramid(a);
  const auto le = read_bytes(binary_pyramid(std::endian::little), io::ModelFormat::ply);
  CHECK(le.report.format == "PLY (binary little-endian)");
  check_pyramid(le);
  const auto be = read_bytes(binary_pyramid(std::endian::big), io::ModelFormat::ply);
  CHECK(be.report.format == "PLY (binary big-endian)");
  check_pyramid(be);
}

TEST_CASE("PLY: 'vertex_index', int counts, uint indices, short coordinates") {
  Bytes b(std::endian::big);
  b.text("ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty short x\n"
         "property short y\nproperty short z\nelement face 1\n"
         "property list int uint vertex_index\nend_header\n");
  b.put(std::int16_t{0}).put(std::int16_t{0}).put(std::int16_t{0});
  b.put(std::int16_t{-2}).put(std::int16_t{0}).put(std::int16_t{0});
  b.put(std::int16_t{0}).put(std::int16_t{300}).put(std::int16_t{0});
  b.put(3).put(0u).put(1u).put(2u);
  const auto r = read_bytes(b.str(), io::ModelFormat::ply);
  REQUIRE(r.soup.triangles.size() == 1);
  CHECK(r.soup.vertices[1] == Vec3(-2, 0, 0));
  CHECK(r.soup.vertices[2] == Vec3(0, 300, 0));
}

TEST_CASE("PLY: errors name the line or byte and the problem") {
  struct Case {
    std::string bytes, fragment;
  };
  const std::string ok_header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const auto body = [&](float y1, std::uint8_t n, int i2) {
    Bytes b;
    b.text(ok_header);
    b.put(0.f).put(0.f).put(0.f).put(1.f).put(y1).put(0.f).put(0.f).put(1.f).put(0.f);
    b.put(n);
    for (int k = 0; k < n; ++k) b.put(k == 2 ? i2 : k);
    return b.str();
  };
  const std::size_t body_at = ok_header.size();
  const Case cases[] = {
      {"", "line 1: not a PLY file"},
      {"ply 2\n", "line 1: not a PLY file"},
      {"ply\nformat ascii 1.0\nelement vertex 1\n", "line 4: the header has no 'end_header'"},
      {"ply\nformat utf8 1.0\n", "line 2: unknown PLY format 'utf8'"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\n", "line 4: unknown property type 'quad'"},
      {"ply\nformat ascii 1.0\nproperty float x\n", "line 3: 'property' before any 'element'"},
      {"ply\nformat ascii 1.0\nelement vertex -1\n", "line 3: expected 'element NAME COUNT'"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\n",
       "line 4: a list count must have an integer type"},
      {"ply\nformat ascii 1.0\nelemental\n", "line 3: unexpected header line starting with 'elemental'"},
      {"ply\nelement vertex 0\nend_header\n", "no 'format' line"},
      {"ply\nformat ascii 1.0\nelement point 1\nproperty float x\nend_header\n0\n", "no 'vertex' element"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n",
       "line 3: the vertex element has no property 'z'"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int indices\nend_header\n",
       "line 7: the face element has no list 'vertex_indices'"},
      {"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 3\n"
       "property float x\nproperty float y\nproperty float z\nend_header\n",
       "line 3: the face element comes before the vertex element"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "end_header\n0 0 0\n1 0 0\n0 1 0\n",
       "no triangles (a point cloud?)"},
      {"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000000\nproperty float x\n"
       "property float y\nproperty float z\nend_header\n",
       "line 3: more than 4294967295 vertices"},
      {"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty uchar x\n"
       "property uchar y\nproperty uchar z\nend_header\n",
       "line 3: the header announces 4000000000 'vertex' records but only 0 bytes follow"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
       "element junk 1000000000\nproperty uchar a\nend_header\n0 0 0\n",
       "line 7: the header announces 1000000000 'junk' records"},
      // Fixed-size records: the header's count is checked against the size, exactly.
      {body(0.f, 3, 2).substr(0, body_at + 30),
       "line 3: the header announces 3 'vertex' records but only 30 bytes follow (each needs at least 12)"},
      // Variable-size records (lists) run out of bytes while being read.
      {body(0.f, 3, 2).substr(0, body_at + 36 + 1 + 6),
       "byte " + std::to_string(body_at + 37 + 4) + ": unexpected end of file in 'face' record 0 of 1"},
      {body(0.f, 3, 3), "byte " + std::to_string(body_at + 36 + 1 + 8) +
                            ": 'face' record 0 of 1: vertex index 3 out of range [0, 3)"},
      {body(0.f, 3, -1), "vertex index -1 out of range"},
      {body(0.f, 2, 2), "byte " + std::to_string(body_at + 36) + ": 'face' record 0 of 1: a face with 2 vertices"},
      {body(std::numeric_limits<float>::infinity(), 3, 2), "'vertex' record 1 of 3: NaN or infinite"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 zero\n3 0 1 2\n",
       "line 12: 'vertex' record 2 of 3: 'zero' is not a number"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n",
       "line 13: 'face' record 0 of 1: '2.5' is not an integer"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",
       "line 13: 'face' record 0 of 1: negative list length"},
      {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "line 14: unexpected end of file in 'face' record 1 of 2"},
  };
  for (const Case& c : cases) {
    const std::string msg = io_error_of([&] { read_bytes(c.bytes, io::ModelFormat::ply); });
    CHECK_MESSAGE(msg.rfind("mem.ply: ", 0) == 0, msg);
    CHECK_MESSAGE(msg.find(c.fragment) != std::string::npos, "got: " << msg << "\nwant: " << c.fragment);
  }
}

TEST_CASE("PLY: trailing data is a warning") {
  const auto r = read_bytes(binary_pyramid(std::endian::little) + "xyz", io::ModelFormat::ply);
  REQUIRE(r.report.warnings.size() == 1);
  CHECK(r.report.warnings[0].find("3 bytes after the last element") != std::string::npos);
  const auto a = read_bytes(ascii_pyramid() + "\n7\n", io::ModelFormat::ply);
  REQUIRE(a.report.warnings.size() == 1);
  CHECK(a.report.warnings[0].find("line") != std::string::npos);
}
