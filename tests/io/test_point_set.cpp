#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>
#include <iterator>
#include <thread>
#include <delpsc/io/error.h>
#include <delpsc/io/point_set.h>
#include <fstream>
#include <limits>
#include <string>

using namespace delpsc;

namespace {
std::string temp_path(const std::string& name) {
  return std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") + "/delpsc_" +
         std::to_string(::getpid()) + "_" + name;
}
void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}
std::string error_of(const std::string& path) {
  try {
    io::read_point_set(path);
  } catch (const io::Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("coordinates and weights outside the predicates' exact range are refused, naming them") {
  const std::string path = temp_path("range.txt");
  write_file(path, "0 0 0 0\n1e300 0 0 0\n");
  CHECK(error_of(path).find("line 2: x = 1e+300 is outside 0 or [2^-140, 2^140]") != std::string::npos);
  write_file(path, "0 -1e-300 0 0\n");
  CHECK(error_of(path).find("line 1: y = -1e-300 is outside") != std::string::npos);
  write_file(path, "0 0 1e-43 0\n");
  CHECK(error_of(path).find("z = ") != std::string::npos);
  write_file(path, "0 0 0 1e90\n");
  CHECK(error_of(path).find("w = 1e+90 is outside 0 or [2^-280, 2^280]") != std::string::npos);
  write_file(path, "0 0 0 0\n1e42 -1e-42 0 1e-84\n");  // just inside the bounds
  CHECK(error_of(path).empty());
  std::remove(path.c_str());
}

TEST_CASE("point sets round-trip exactly through both formats") {
  const std::vector<WeightedPoint> pts = {{0.1, -0x1p-140, 0x1p140, 0x1p280}, {1.0 / 3, 2, 3, 0.25}};
  for (const char* name : {"a.bin", "a.txt"}) {
    const std::string path = temp_path(name);
    io::write_point_set(path, pts);
    CHECK(io::read_point_set(path) == pts);
    std::remove(path.c_str());
  }
}

// Both formats through a FIFO (a pipe has no size: the binary reader took it from tellg and
// refused every pipe as "cannot determine the file size").
TEST_CASE("point sets read through a FIFO as from a file") {
  const std::vector<WeightedPoint> pts = {{0.5, -1, 2, 0}, {1.0 / 3, 2, 3, 0.25}, {7, 8, 9, 1}};
  for (const char* name : {"f.bin", "f.txt"}) {
    const std::string file = temp_path(std::string("file_") + name), fifo = temp_path(name);
    io::write_point_set(file, pts);
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::remove(fifo.c_str());
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    std::thread writer([&] { write_file(fifo, bytes); });  // blocks until the reader opens it
    const auto read = io::read_point_set(fifo);
    writer.join();
    CHECK(read == pts);
    std::remove(fifo.c_str());
    std::remove(file.c_str());
  }
}

TEST_CASE("text point sets: optional weight, comments, blank lines") {
  const std::string path = temp_path("b.txt");
  write_file(path, "# header\n1 2 3\n\n  4 5 6 0.5\n");
  const auto pts = io::read_point_set(path);
  REQUIRE(pts.size() == 2);
  CHECK(pts[0] == WeightedPoint{1, 2, 3, 0});
  CHECK(pts[1] == WeightedPoint{4, 5, 6, 0.5});
  std::remove(path.c_str());
}

TEST_CASE("bad point files get errors naming the file and the place") {
  const std::string path = temp_path("c.txt");
  CHECK(error_of(temp_path("missing.txt")).find("cannot open") != std::string::npos);
  write_file(path, "1 2 3\n1 2\n");
  CHECK(error_of(path).find("line 2") != std::string::npos);
  write_file(path, "1 2 three\n");
  CHECK(error_of(path).find("'three' is not a number") != std::string::npos);
  write_file(path, "1 2 nan\n");
  CHECK(error_of(path).find("not a finite number") != std::string::npos);
  write_file(path, "1 2 3 4 5\n");
  CHECK(error_of(path).find("more than four") != std::string::npos);
  const std::string bin = temp_path("d.bin");
  write_file(bin, std::string(33, '\0'));
  CHECK(error_of(bin).find("not a multiple of 32") != std::string::npos);
  const double rec[4] = {0, std::numeric_limits<double>::infinity(), 0, 0};
  write_file(bin, std::string(reinterpret_cast<const char*>(rec), 32));
  CHECK(error_of(bin).find("record 0") != std::string::npos);
  std::remove(path.c_str());
  std::remove(bin.c_str());
}
