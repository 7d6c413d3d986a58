// io::write_output_file (io/output_file.h): a write that fails halfway - here a file-size limit
// standing in for a full disk - leaves the previous file whole and no temporary file behind;
// a write that succeeds replaces it, with the usual permissions.
#include <doctest/doctest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <delpsc/io/error.h>
#include <delpsc/io/output_file.h>

#include "support/model_files.h"

using namespace delpsc;

namespace {

// Files in `dir` whose name starts with `prefix`.
int files_starting_with(const std::filesystem::path& dir, const std::string& prefix) {
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    n += entry.path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

}  // namespace

TEST_CASE("a failed write keeps the old file and leaves no temporary one; a good one replaces it") {
  const std::string path = test::temp_path("output_file.off");
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  const std::string name = std::filesystem::path(path).filename().string();
  test::write_file(path, "old contents\n");

  // In a child: at most 4 KB a file (SIGXFSZ ignored, so write(2) fails with EFBIG instead of
  // killing the process), then 1 MB to write. Exit 0 when the write threw io::Error.
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      io::write_output_file(path, std::string(1 << 20, 'x'));
    } catch (const io::Error&) {
      _exit(0);
    }
    _exit(1);
  }
  int status = 0;
  waitpid(child, &status, 0);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(test::read_file(path) == "old contents\n");
  CHECK(files_starting_with(dir, name + ".delpsc-") == 0);

  io::write_output_file(path, "new contents\n");
  CHECK(test::read_file(path) == "new contents\n");
  CHECK(files_starting_with(dir, name + ".delpsc-") == 0);
  // 0666 less the umask, as fopen gives (not mkstemp's 0600).
  const mode_t mask = umask(0);
  umask(mask);
  struct stat st {};
  REQUIRE(stat(path.c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == (0666 & ~mask));
  // A file replaced keeps its permissions; one with another hard link is written in place, so
  // both names see the new contents.
  REQUIRE(chmod(path.c_str(), 0600) == 0);
  io::write_output_file(path, "private\n");
  REQUIRE(stat(path.c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0600);
  const std::string link = path + ".link";
  std::filesystem::remove(link);
  std::filesystem::create_hard_link(path, link);
  io::write_output_file(path, "both names\n");
  CHECK(test::read_file(link) == "both names\n");
  std::filesystem::remove(link);
  // Temporary files left by a killed run under this process id (the counter is below 10 here)
  // do not block the next write.
  for (int n = 0; n < 10; ++n) test::write_file(path + ".delpsc-" + std::to_string(getpid()) + "-" + std::to_string(n), "");
  CHECK_NOTHROW(io::write_output_file(path, "again\n"));
  for (int n = 0; n < 10; ++n) std::filesystem::remove(path + ".delpsc-" + std::to_string(getpid()) + "-" + std::to_string(n));
  std::filesystem::remove(path);

  // A name whose temporary sibling would be too long for the file system (255 bytes here):
  // written in place rather than refused.
  const std::string long_name = (dir / std::string(250, 'n')).string();
  CHECK_NOTHROW(io::write_output_file(long_name, "long\n"));
  CHECK(test::read_file(long_name) == "long\n");
  std::filesystem::remove(long_name);

  // Not a regular file: written in place (a temporary file cannot be renamed onto a device).
  CHECK_NOTHROW(io::write_output_file("/dev/null", "anything"));
  CHECK_THROWS_AS(io::write_output_file((dir / "no-such-directory" / "x.off").string(), "x"), io::Error);
}
