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

}  // namespace delpsc::io
