#include "output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <memory>

#include "error.h"

namespace delpsc::io {

namespace {

// Writes all of `bytes` to the descriptor, retrying short writes and EINTR.
bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

void write_in_place(const std::string& path, std::string_view bytes) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!f) throw Error(path + ": cannot open for writing");
  if (std::fwrite(bytes.data(), 1, bytes.size(), f.get()) != bytes.size() || std::fflush(f.get()) != 0)
    throw Error(path + ": write failed (disk full?)");
}

}  // namespace

void write_output_file(const std::string& path, std::string_view bytes) {
  struct stat st {};
  const bool exists = ::lstat(path.c_str(), &st) == 0;
  // In place: what is no regular file, and a file with other hard links (a rename would cut them
  // off: the other names would keep the old contents).
  if (exists && (!S_ISREG(st.st_mode) || st.st_nlink > 1)) {
    write_in_place(path, bytes);
    return;
  }
  // A fresh name: a run killed mid-write leaves its temporary file, and in a container the next
  // run may have the same process id.
  static std::atomic<unsigned> counter{0};
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temporary = path + ".delpsc-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0 && errno == ENAMETOOLONG) {  // the target's name fits, the temporary one's does not
    write_in_place(path, bytes);
    return;
  }
  if (fd < 0) throw Error(path + ": cannot open for writing");
  // A file replaced keeps its permissions (a private 0600 report stays private).
  if (exists) (void)::fchmod(fd, st.st_mode & 07777);
  const bool written = write_all(fd, bytes);
  const bool closed = ::close(fd) == 0;  // NFS and others report a full disk only here
  if (!written || !closed) {
    ::unlink(temporary.c_str());
    throw Error(path + ": write failed (disk full?)");
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    // A target that cannot be renamed onto (a bind-mounted file: EBUSY) is written in place.
    const int why = errno;
    ::unlink(temporary.c_str());
    if (why != EBUSY && why != EXDEV) throw Error(path + ": cannot replace it");
    write_in_place(path, bytes);
  }
}

}  // namespace delpsc::io
