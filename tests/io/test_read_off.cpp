#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <sys/stat.h>
#include <unistd.h>

#include <delpsc/io/read_model.h>

#include "support/model_files.h"

using namespace delpsc;
using delpsc::test::io_error_of;
using delpsc::test::read_bytes;

namespace {
const std::string kCube =
    "OFF\n"
    "# a unit cube, one quad per side\n"
    "8 6 12\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
    "0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
}  // namespace

TEST_CASE("OFF: a cube of quads becomes 12 triangles on 8 vertices") {
  const auto r = read_bytes(kCube, io::ModelFormat::off);
  CHECK(r.report.format == "OFF");
  CHECK(r.soup.vertices.size() == 8);
  REQUIRE(r.soup.triangles.size() == 12);
  CHECK(r.report.polygons == 6);
  CHECK(r.report.degenerate_triangles.empty());
  // Fan triangulation from the first corner keeps the orientation: 0 3 2 1 -> (0 3 2) (0 2 1).
  CHECK(r.soup.triangles[0] == std::array<std::uint32_t, 3>{0, 3, 2});
  CHECK(r.soup.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 1});
  CHECK(r.soup.vertices[6] == Vec3(1, 1, 1));
}

TEST_CASE("OFF: header variants, comments, colours and counts on the keyword line") {
  const std::string tri = "3 0 1 2 0.5 0.5 0.5\n";
  for (const std::string header : {"OFF 3 1 0\n", "COFF\n3 1 0\n", "3 1 0\n", "NOFF\n\n# c\n3 1\n"}) {
    const std::string text = header + "0 0 0 1 0 0 1\n1 0 0 # comment\n0 1 0 1 1 1 1\n" + tri;
    const auto r = read_bytes(text, io::ModelFormat::off);
    CHECK(r.soup.vertices.size() == 3);
    REQUIRE(r.soup.triangles.size() == 1);
    CHECK(r.soup.vertices[2] == Vec3(0, 1, 0));
  }
}

TEST_CASE("OFF: numbers in the spellings files use; anything else is garbage") {
  const auto r = read_bytes("OFF\n3 1 0\n+1.5e2 -0 .25\n1E-3 2. -7\n0 0 1\n3 0 1 2\n",
                            io::ModelFormat::off);
  CHECK(r.soup.vertices[0] == Vec3(150, 0, 0.25));
  CHECK(r.soup.vertices[1] == Vec3(0.001, 2, -7));
  for (const char* bad : {"0x1", "1.5.2", "1e", "--1", "+-1", "1,5"}) {
    const std::string text = std::string("OFF\n3 1 0\n") + bad + " 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const std::string msg = io_error_of([&] { read_bytes(text, io::ModelFormat::off); });
    CHECK_MESSAGE(msg.find("line 3") != std::string::npos, msg);
    CHECK_MESSAGE(msg.find("is not a number") != std::string::npos, msg);
  }
}

TEST_CASE("OFF: exactly duplicated vertices are merged, -0 equals +0") {
  // Two triangles sharing an edge whose endpoints are listed twice (as STL-converted files do).
  const auto r = read_bytes("OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n-0 0 0\n1 1 0\n"
                            "3 0 1 2\n3 3 5 4\n",
                            io::ModelFormat::off);
  CHECK(r.report.file_vertices == 6);
  CHECK(r.report.merged_vertices == 2);
  REQUIRE(r.soup.vertices.size() == 4);
  CHECK(r.soup.triangles[1] == std::array<std::uint32_t, 3>{1, 3, 0});
  // Nearly equal is not equal: merging is exact only.
  const auto s = read_bytes("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1.0000000000000002 0 0\n3 0 1 2\n",
                            io::ModelFormat::off);
  CHECK(s.soup.vertices.size() == 4);
}

TEST_CASE("OFF: zero-area triangles are kept and reported") {
  // Face 1 repeats a vertex; face 2 is three exactly collinear points; face 0 is fine.
  const auto r = read_bytes("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 0\n"
                            "3 0 1 2\n3 0 1 1\n3 0 3 4\n",
                            io::ModelFormat::off);
  REQUIRE(r.soup.triangles.size() == 3);
  CHECK(r.report.degenerate_triangles == std::vector<std::uint32_t>{1, 2});
  REQUIRE(!r.report.warnings.empty());
  CHECK(r.report.warnings[0].find("2 zero-area") != std::string::npos);
}

TEST_CASE("OFF: errors name the line and the problem") {
  struct Case {
    std::string text, fragment;
  };
  const Case cases[] = {
      {"", "empty file"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "line 6: face 0: vertex index 3 out of range [0, 3)"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "vertex index -1 out of range"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "line 6: face 0 has 2 vertices; at least 3"},
      {"OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "line 4: vertex 1 has a NaN or infinite"},
      {"OFF\n3 1 0\n0 0 0\n1 1e999 0\n0 1 0\n3 0 1 2\n", "line 4: vertex 1 has a NaN or infinite"},
      {"OFF\n3 1 0\n0 0 0\n1 -2e42 0\n0 1 0\n3 0 1 2\n", "vertex 1 has a coordinate larger than 2^140"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n", "unexpected end of file in vertex 2 of 3"},
      {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "unexpected end of file in face 1 of 2"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1", "unexpected end of file in face 0 of 1"},
      {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n3 0 1 2\n",
       "line 6: face 0 says it has 4000000000 vertices, more than the model's 3 and than the rest of the file"},
      {"OFF\n99999999999 1 0\n0 0 0\n", "line 2: the header announces 99999999999 vertices"},
      {"OFF\n3 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n", "announces 4000000000 faces"},
      {"OFF\n-3 1 0\n", "negative vertex or face count"},
      {"OFF\n3 1 0 0 0 0 1 0 0 0 1 0 3 0 1 2\n", "line 2: more numbers follow the counts on their line"},
      {"OFF\nthree 1 0\n", "expected the vertex count, found 'three'"},
      {"4OFF\n3 1 0\n", "OFF variant '4OFF' is not supported"},
      {"OFF BINARY\n", "binary OFF is not supported"},
      {"PLY\n3 1 0\n", "expected the header 'OFF', found 'PLY'"},
      {"OFF\n0 0 0\n", "empty model"},
      {"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "no triangles"},
      {"\x7f\x45LF\x02\x01\x01", "expected the header 'OFF', found '\\x7fELF\\x02\\x01\\x01'"},
  };
  for (const Case& c : cases) {
    const std::string msg = io_error_of([&] { read_bytes(c.text, io::ModelFormat::off); });
    CHECK_MESSAGE(msg.rfind("mem.off: ", 0) == 0, msg);
    CHECK_MESSAGE(msg.find(c.fragment) != std::string::npos, "got: " << msg << "\nwant: " << c.fragment);
  }
}

TEST_CASE("OFF and OBJ: a UTF-8 byte-order mark before the text is skipped") {
  const std::string bom = "\xEF\xBB\xBF";
  const auto off = read_bytes(bom + kCube, io::ModelFormat::off);
  CHECK(off.soup.triangles.size() == 12);
  CHECK(off.report.warnings.empty());
  const auto obj = read_bytes(bom + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", io::ModelFormat::obj);
  CHECK(obj.soup.triangles.size() == 1);
  // Only at the very start: the same bytes anywhere else are still garbage.
  CHECK(!io_error_of([&] { read_bytes("OFF\n" + bom + "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", io::ModelFormat::off); })
             .empty());
}

TEST_CASE("ASCII STL and PLY after a byte-order mark are read; compressed data is named as such") {
  const std::string bom = "\xEF\xBB\xBF";
  const std::string stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                          "endloop\nendfacet\nendsolid t\n";
  CHECK(read_bytes(bom + stl, io::ModelFormat::stl).soup.triangles.size() == 1);  // was read as binary
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  CHECK(read_bytes(bom + ply, io::ModelFormat::ply).soup.triangles.size() == 1);
  for (const auto format : {io::ModelFormat::off, io::ModelFormat::stl, io::ModelFormat::ply, io::ModelFormat::obj}) {
    CHECK(io_error_of([&] { read_bytes(std::string("\x1f\x8b\x08\x00rest", 8), format); }).find("gzip-compressed") !=
          std::string::npos);
    CHECK(io_error_of([&] { read_bytes("PK\x03\x04rest", format); }).find("zip archive") != std::string::npos);
  }
  // A binary STL whose free-form header happens to start with those bytes, its size proving it
  // binary, is read.
  std::string binary(84 + 50, '\0');
  binary[0] = '\x1f', binary[1] = '\x8b', binary[80] = 1;
  for (int k = 0; k < 3; ++k) {
    const float corner[3] = {k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f, 0.0f};
    std::memcpy(&binary[84 + 12 + 12 * k], corner, sizeof corner);
  }
  CHECK(read_bytes(binary, io::ModelFormat::stl).soup.triangles.size() == 1);
}

TEST_CASE("OFF and OBJ: lines ended by a lone carriage return (classic Mac OS) read as lines") {
  std::string cr = kCube;  // its comment line would otherwise run to the end of the file
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  const auto off = read_bytes(cr, io::ModelFormat::off);
  CHECK(off.soup.triangles.size() == 12);
  CHECK(off.report.warnings.empty());
  const auto obj = read_bytes("v 0 0 0\rv 1 0 0\r# c\rv 0 1 0\rf 1 2 3\r", io::ModelFormat::obj);
  CHECK(obj.soup.triangles.size() == 1);
  // Errors name the line as an editor shows it; CRLF and lone CRs may mix.
  const std::string msg =
      io_error_of([&] { read_bytes("OFF\r\n3 1 0\r0 0 0\r1 x 0\r0 1 0\r3 0 1 2\r", io::ModelFormat::off); });
  CHECK_MESSAGE(msg.find("line 4") != std::string::npos, msg);
}

TEST_CASE("OFF: text after the last face is a warning, not an error") {
  const auto r = read_bytes("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", io::ModelFormat::off);
  CHECK(r.soup.triangles.size() == 1);
  REQUIRE(r.report.warnings.size() == 1);
  CHECK(r.report.warnings[0].find("line 7") != std::string::npos);
}

TEST_CASE("OFF: coordinates below the predicates' range are set to 0, with a warning") {
  const io::ReadResult r =
      io::read_model_from_memory("OFF\n3 1 0\n0 0 0\n1 1e-300 0\n0 -1e-43 1\n3 0 1 2\n", io::ModelFormat::off, "t.off");
  REQUIRE(r.soup.vertices.size() == 3);
  CHECK(r.soup.vertices[1] == Vec3(1, 0, 0));
  CHECK(r.soup.vertices[2] == Vec3(0, 0, 1));
  REQUIRE(r.report.warnings.size() == 1);
  CHECK(r.report.warnings[0].find("2 coordinate(s) smaller than 2^-140") != std::string::npos);
  // On a model that small itself, the same would change its shape: refused, with the way out.
  const std::string error = io_error_of([] {
    io::read_model_from_memory("OFF\n3 1 0\n0 0 0\n1e-40 3e-43 0\n0 -1e-43 1e-40\n3 0 1 2\n", io::ModelFormat::off,
                               "t.off");
  });
  CHECK(error.find("2 coordinate(s) smaller than 2^-140") != std::string::npos);
  CHECK(error.find("would change its shape; scale the model up") != std::string::npos);
  CHECK(error.find("on a model only 1e-40 across") != std::string::npos);
  // Every coordinate that small: no size of the model to print (it would read "0 across").
  const std::string all_tiny = io_error_of([] {
    io::read_model_from_memory("OFF\n3 1 0\n0 0 0\n1e-45 0 0\n0 1e-45 0\n3 0 1 2\n", io::ModelFormat::off, "t.off");
  });
  CHECK(all_tiny.find("up to 1e-45, and none of the model's is larger: setting them to 0 would change its shape") !=
        std::string::npos);
  CHECK(all_tiny.find("0 across") == std::string::npos);
}

namespace {
// 4√3 area / (sum of squared sides) of triangle t, and its normal's z (orientation in the xy plane).
double triangle_shape(const io::TriangleSoup& s, const std::array<std::uint32_t, 3>& t) {
  const Vec3 &a = s.vertices[t[0]], &b = s.vertices[t[1]], &c = s.vertices[t[2]];
  const double sides = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return 2 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / sides;
}
}  // namespace

TEST_CASE("OFF: a polygon whose fan would make slivers is split into well-shaped triangles") {
  // A convex hexagon with four corners nearly on its bottom edge (mpi.off's defect): the fan from
  // corner 0 makes (0 1 2) and (0 2 3), of angles ~0.001°, whose rounded normals mean nothing.
  const std::string text =
      "OFF\n6 1 0\n0 0 0\n1 -1e-5 0\n2 -1e-5 0\n3 0 0\n3 1 0\n0 1 0\n"
      "6 0 1 2 3 4 5\n";
  const auto r = read_bytes(text, io::ModelFormat::off);
  REQUIRE(r.soup.triangles.size() == 4);
  io::TriangleSoup fan = r.soup;
  fan.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
  double fan_worst = 1, worst = 1, area = 0;
  for (const auto& t : fan.triangles) fan_worst = std::min(fan_worst, triangle_shape(fan, t));
  for (const auto& t : r.soup.triangles) {
    worst = std::min(worst, triangle_shape(r.soup, t));
    const Vec3 &a = r.soup.vertices[t[0]], &b = r.soup.vertices[t[1]], &c = r.soup.vertices[t[2]];
    const double z = (b - a).cross(c - a).z();
    CHECK(z > 0);  // the polygon's orientation kept
    area += z / 2;
  }
  CHECK(fan_worst < 1e-4);
  CHECK(worst > 0.1);
  CHECK(area == doctest::Approx(3 + 2e-5));  // the whole polygon, once
  CHECK(r.report.degenerate_triangles.empty());
}

// A star-shaped polygon: corner i at radius 1 or 0.5 alternately, so every other corner is reflex.
std::string star_polygon_off(int corners) {
  // Appended piece by piece: GCC 12 sees a false overlap in "literal" + std::string (-Wrestrict).
  std::string text = "OFF\n";
  text += std::to_string(corners);
  text += " 1 0\n";
  char line[96];
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * M_PI * i / corners, r = i % 2 == 0 ? 1.0 : 0.5;
    std::snprintf(line, sizeof line, "%.17g %.17g 0\n", r * std::cos(angle), r * std::sin(angle));
    text += line;
  }
  text += std::to_string(corners);
  for (int i = 0; i < corners; ++i) {
    text += ' ';
    text += std::to_string(i);
  }
  text += '\n';
  return text;
}

// Concave polygons of more than 500 corners were fanned, and a fan from a reflex corner overlaps
// itself: a valid star-shaped 1,000-gon was refused as a self-intersecting model. Up to 5,000
// corners they are now clipped into triangles that cover the polygon once; beyond, fanned with
// a warning that says why a self-intersection may follow.
TEST_CASE("OFF: a concave polygon of 1,000 corners is split inside itself; one of 6,000 is fanned with a warning") {
  const auto r = read_bytes(star_polygon_off(1000), io::ModelFormat::off);
  REQUIRE(r.soup.triangles.size() == 998);
  double area = 0;
  bool all_up = true;
  for (const auto& t : r.soup.triangles) {
    const Vec3 &a = r.soup.vertices[t[0]], &b = r.soup.vertices[t[1]], &c = r.soup.vertices[t[2]];
    const double z = (b - a).cross(c - a).z();
    all_up &= z > 0;  // a fan from a reflex corner would turn some triangles over
    area += z / 2;
  }
  CHECK(all_up);
  // The star's area: 1,000 triangles (origin, corner i, corner i + 1) of sides 1 and 0.5.
  CHECK(area == doctest::Approx(1000 * 0.5 * 0.5 * std::sin(2 * M_PI / 1000)).epsilon(1e-4));
  const auto big = read_bytes(star_polygon_off(6000), io::ModelFormat::off);
  CHECK(big.soup.triangles.size() == 5998);
  REQUIRE(big.report.warnings.size() == 1);
  CHECK(big.report.warnings[0].find("has 6000 corners and does not look convex: fanned") != std::string::npos);
}

// read_model reads a file straight into a buffer of its size; a FIFO has no size, so the buffer
// starts at 64 KiB and grows until a read comes back short. Both must give the bytes exactly:
// a model of ~300 KiB read through each equals the same model parsed from memory.
TEST_CASE("OFF: a file and a FIFO larger than the first buffer read exactly as from memory") {
  std::string text = "OFF\n20000 10000 0\n";
  for (int i = 0; i < 20000; ++i)
    text += std::to_string(i % 97) + ".25 " + std::to_string(i / 97) + ".5 " + std::to_string(i % 13) + "\n";
  for (int t = 0; t < 10000; ++t)
    text += "3 " + std::to_string(2 * t) + " " + std::to_string(2 * t + 1) + " " + std::to_string((2 * t + 2) % 20000) + "\n";
  REQUIRE(text.size() > 4 * (std::size_t{1} << 16));
  const auto expected = read_bytes(text, io::ModelFormat::off);

  const std::string file = test::temp_path("big.off");
  test::write_file(file, text);
  const auto from_file = io::read_model(file);

  const std::string fifo = test::temp_path("big_fifo.off");
  std::remove(fifo.c_str());
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  std::thread writer([&] { test::write_file(fifo, text); });  // blocks until the reader opens it
  const auto from_fifo = io::read_model(fifo);
  writer.join();
  std::remove(fifo.c_str());

  for (const auto* r : {&from_file, &from_fifo}) {
    CHECK(r->report.file_vertices == 20000);
    CHECK(std::equal(r->soup.vertices.begin(), r->soup.vertices.end(), expected.soup.vertices.begin(),
                     expected.soup.vertices.end()));
    CHECK(std::equal(r->soup.triangles.begin(), r->soup.triangles.end(), expected.soup.triangles.begin(),
                     expected.soup.triangles.end()));
  }
}

// A FIFO that nobody opens for writing used to block read_model in open() for ever, past any
// --max-seconds. Now the wait polls PipeWait::stop and ends in ReadStopped, after telling the
// caller once that it waits; a writer that comes late, after the notice, is still read whole.
TEST_CASE("OFF: a FIFO without a writer stops when asked; a late writer is read") {
  const std::string fifo = test::temp_path("lonely_fifo.off");
  std::remove(fifo.c_str());
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  io::PipeWait wait;
  wait.poll_interval = std::chrono::milliseconds(10);
  wait.notice_after = std::chrono::milliseconds(30);
  int polls = 0, notices = 0;
  wait.stop = [&] { return ++polls == 8; };
  wait.waiting = [&] { ++notices; };
  std::string message;
  try {
    io::read_model(fifo, wait);
  } catch (const io::ReadStopped& e) {
    message = e.what();
  }
  CHECK(polls == 8);
  CHECK(notices == 1);
  CHECK(message.find(fifo) != std::string::npos);
  CHECK(message.find("no data came through the pipe") != std::string::npos);

  // The writer opens once the notice has come (it blocks in open until the reader is there), so
  // the read has waited before any data: no timing assumed.
  polls = notices = 0;
  std::atomic<bool> noticed{false};
  wait.stop = [&] { return ++polls > 100000; };  // a guard: ~17 minutes of polls
  wait.waiting = [&] {
    ++notices;
    noticed = true;
  };
  std::thread writer([&] {
    while (!noticed) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    test::write_file(fifo, kCube);
  });
  const auto late = io::read_model(fifo, wait);
  writer.join();
  std::remove(fifo.c_str());
  CHECK(notices == 1);
  CHECK(polls >= 1);
  CHECK(polls <= 100000);
  CHECK(late.soup.triangles.size() == 12);
  CHECK(late.soup.vertices.size() == 8);
}
