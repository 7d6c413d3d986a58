// The one exception type of io/: a message that names the file and what is wrong with it.
#pragma once

#include <stdexcept>
#include <string>

namespace delpsc::io {

/// Thrown by every reader and writer. what() names the file, the place in it (line or byte
/// offset) when known, and the problem, in words a user can act on.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws Error naming `what` ("model file") unless `path` is something a reader can read to its
/// end: a regular file (or a symbolic link to one) or a pipe. A directory, or a device such as
/// /dev/zero or /dev/urandom behind a model's name, would fail obscurely or be read until memory
/// runs out; a missing file is left to the reader's "cannot open". Defined in input_bytes.cpp.
void check_input_file(const std::string& path, const std::string& what);

}  // namespace delpsc::io
