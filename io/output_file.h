// Writing an output file so that a failed write leaves no partial file behind: the bytes go to a
// temporary file beside the target, which replaces it only once everything is written and
// flushed. A disk that fills up halfway through used to leave a truncated .off or .vtu at the
// target path (and an empty JSON report) that looked like a result.
#pragma once

#include <string>
#include <string_view>

namespace delpsc::io {

/// Writes `bytes` to `path`. A regular file (or none yet) is replaced atomically by rename(2)
/// from a fresh `path`.delpsc-PID-N, created with the usual permissions (0666 less the umask;
/// a file replaced keeps its own) and removed on failure; anything else - a device such as
/// /dev/stdout, a FIFO, a symbolic link, a file with other hard links - is written in place, as
/// before, and so is a target whose temporary name would be too long or that cannot be renamed
/// onto (a bind-mounted file). Throws io::Error naming the path ("cannot open for writing",
/// "write failed (disk full?)"). O(bytes).
void write_output_file(const std::string& path, std::string_view bytes);

}  // namespace delpsc::io
