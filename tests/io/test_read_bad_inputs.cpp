// Replays the corpus of bad model files (tests/io/bad_inputs/, listed with the message fragment
// each must produce in expected.txt; fuzzer finds are added there too): every one must give an
// io::Error naming the file and the problem, never a crash, a hang or another exception.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>

#include <delpsc/io/read_model.h>

#include "support/model_files.h"

using namespace delpsc;
namespace fs = std::filesystem;

namespace {

const fs::path kCorpus = fs::path(__FILE__).parent_path() / "bad_inputs";

std::map<std::string, std::string> expected_fragments() {
  std::map<std::string, std::string> out;
  std::ifstream in(kCorpus / "expected.txt");
  REQUIRE_MESSAGE(in, "cannot read " << (kCorpus / "expected.txt"));
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t bar = line.find(" | ");
    REQUIRE_MESSAGE(bar != std::string::npos, "malformed line in expected.txt: " << line);
    out[line.substr(0, bar)] = line.substr(bar + 3);
  }
  return out;
}

}  // namespace

TEST_CASE("every bad input gives an io::Error with the file name and the expected message") {
  const auto expected = expected_fragments();
  std::size_t replayed = 0;
  for (const auto& entry : fs::directory_iterator(kCorpus)) {
    const std::string name = entry.path().filename().string();
    if (name == "expected.txt" || name == "README.md") continue;
    CAPTURE(name);
    const auto it = expected.find(name);
    REQUIRE_MESSAGE(it != expected.end(), name << " has no line in expected.txt");
    const std::string path = entry.path().string();
    const std::string msg = test::io_error_of([&] { io::read_model(path); });
    CHECK_MESSAGE(msg.rfind(path + ": ", 0) == 0, "message does not start with the path: " << msg);
    CHECK_MESSAGE(msg.find(it->second) != std::string::npos, "got: " << msg << "\nwant: " << it->second);
    ++replayed;
  }
  CHECK(replayed == expected.size());  // no stale lines for files that are gone
  CHECK(replayed >= 50);
}

TEST_CASE("missing, unreadable and directory paths") {
  const std::string missing = test::temp_path("missing.off");
  std::string msg = test::io_error_of([&] { io::read_model(missing); });
  CHECK(msg == missing + ": cannot open for reading (No such file or directory)");

  const std::string dir = test::temp_path("dir.stl");
  fs::create_directory(dir);
  msg = test::io_error_of([&] { io::read_model(dir); });
  CHECK(msg == dir + ": is a directory, not a model file");
  fs::remove(dir);

  if (::geteuid() != 0) {  // root reads anything
    const std::string locked = test::temp_path("locked.obj");
    test::write_file(locked, "v 0 0 0\n");
    ::chmod(locked.c_str(), 0);
    msg = test::io_error_of([&] { io::read_model(locked); });
    CHECK(msg == locked + ": cannot open for reading (Permission denied)");
    fs::remove(locked);
  }
}

TEST_CASE("the extension chooses the format, in any case") {
  CHECK(io::model_format_from_path("a/b.c/Model.OFF") == io::ModelFormat::off);
  CHECK(io::model_format_from_path("x.Obj") == io::ModelFormat::obj);
  CHECK(io::model_format_from_path("x.stl") == io::ModelFormat::stl);
  CHECK(io::model_format_from_path("x.PLY") == io::ModelFormat::ply);
  CHECK(!io::model_format_from_path("x.off.gz"));
  CHECK(!io::model_format_from_path("off"));
  const std::string path = test::temp_path("upper.OFF");
  test::write_file(path, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  CHECK(io::read_model(path).soup.triangles.size() == 1);
  fs::remove(path);
}
