#include "input_bytes.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

namespace delpsc::io {

namespace {

// A pipe's bytes, read without ever blocking for good (PipeWait): opened non-blocking, so that
// the open itself does not wait for a writer, then poll() with a short timeout between reads,
// asking `wait.stop` each time nothing came. On Linux a FIFO that no writer has opened yet polls
// as "nothing to read" (not as hung up), so the wait lasts until a writer comes or stop says so;
// once data came, end of file is a read of 0 bytes after poll reports the writer gone.
kernel::LargeVector<char> read_pipe(const std::string& path, const PipeWait& wait) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw Error(path + ": cannot open for reading (" + std::strerror(errno) + ")");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } const closer{fd};
  kernel::LargeVector<char> bytes(std::size_t{1} << 16);
  std::size_t used = 0;
  // Wall time since the last data: under load a poll's timeout can last longer than asked.
  using Clock = std::chrono::steady_clock;
  auto last_data = Clock::now();
  bool noticed = false;
  for (;;) {
    pollfd ready{fd, POLLIN, 0};
    const int polled = ::poll(&ready, 1, static_cast<int>(wait.poll_interval.count()));
    if (polled < 0 && errno != EINTR) throw Error(path + ": waiting for data failed (" + std::strerror(errno) + ")");
    if (polled <= 0) {
      if (wait.stop && wait.stop())
        throw ReadStopped(path + ": no data came through the pipe" +
                          (used == 0 ? std::string(" (a FIFO without a writer?)") : std::string(" to end it")));
      if (!noticed && Clock::now() - last_data >= wait.notice_after && wait.waiting) {
        noticed = true;
        wait.waiting();
      }
      continue;
    }
    if (used == bytes.size()) bytes.resize(bytes.size() + bytes.size() / 2);
    const ssize_t n = ::read(fd, bytes.data() + used, bytes.size() - used);
    if (n == 0) break;  // the writer closed its end
    if (n < 0) {
      if (errno == EAGAIN || errno == EINTR) continue;
      throw Error(path + ": read failed (" + std::strerror(errno) + ")");
    }
    used += static_cast<std::size_t>(n);
    last_data = Clock::now();
  }
  bytes.resize(used);
  return bytes;
}

}  // namespace

kernel::LargeVector<char> read_input_bytes(const std::string& path, const std::string& what, const PipeWait& wait) {
  check_input_file(path, what);
  std::error_code ec;
  if (std::filesystem::is_fifo(path, ec)) return read_pipe(path, wait);
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw Error(path + ": cannot open for reading (" + std::strerror(errno) + ")");
  const auto size = std::filesystem::file_size(path, ec);
  // One byte more than the file's size, so that a single read meets the end; a file that grows
  // meanwhile makes the buffer grow until a read comes back short.
  kernel::LargeVector<char> bytes(ec ? std::size_t{1} << 16 : static_cast<std::size_t>(size) + 1);
  std::size_t used = 0;
  for (;;) {
    used += std::fread(bytes.data() + used, 1, bytes.size() - used, f.get());
    if (used < bytes.size()) break;
    bytes.resize(bytes.size() + bytes.size() / 2);
  }
  if (std::ferror(f.get())) throw Error(path + ": read failed (" + std::strerror(errno) + ")");
  bytes.resize(used);
  return bytes;
}

void check_input_file(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || fs::is_regular_file(st) || fs::is_fifo(st)) return;
  if (fs::is_directory(st)) throw Error(path + ": is a directory, not a " + what);
  throw Error(path + ": is a device or socket, not a " + what + ": it may never end (copy the data to a file)");
}

}  // namespace delpsc::io
