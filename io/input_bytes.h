// The bytes of an input file, whole, for the readers of models and point sets: a regular file
// read in one go into a buffer of its size, or a pipe (a named FIFO, /dev/fd/N from a shell's
// process substitution) read as its data comes, without ever blocking for good (PipeWait).
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include <delpsc/kernel/large_array.h>

#include "error.h"

namespace delpsc::io {

/// How a reader waits on a pipe (a named FIFO, or /dev/fd/N from a shell's process
/// substitution) that has no data yet: a FIFO nobody has opened for writing, or a writer that
/// holds it open and sends nothing, would otherwise block the reader for ever. A regular file
/// never waits.
struct PipeWait {
  /// Polled about every `poll_interval` while no data comes; true ends the read with ReadStopped.
  /// Empty: wait as long as it takes (as `cat` does), the writer may come later.
  std::function<bool()> stop;
  /// Called once, at the first poll after `notice_after` of wall time without data (a user's
  /// shell looks hung otherwise: the command tells them it waits, and on what).
  std::function<void()> waiting;
  std::chrono::milliseconds poll_interval{100};
  std::chrono::milliseconds notice_after{1000};
};

/// Thrown by read_input_bytes (so by read_model and read_point_set) when PipeWait::stop ended a
/// wait for data; what() names the file.
class ReadStopped : public Error {
 public:
  using Error::Error;
};

/// The whole content of `path` (`what` names it in messages: "model file"). Throws Error for a
/// directory, a device or socket (check_input_file), a file that cannot be opened or read, and
/// ReadStopped when `wait.stop` gave up on a pipe without data. O(size) time and memory.
kernel::LargeVector<char> read_input_bytes(const std::string& path, const std::string& what, const PipeWait& wait = {});

}  // namespace delpsc::io
