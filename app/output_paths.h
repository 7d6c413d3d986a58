// Checking the files a subcommand will write before it starts the long part of its job: a
// typo in a directory name must fail in a second with exit 2, not after minutes of meshing.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "command.h"

namespace delpsc::app {

/// Throws Failure (bad input) naming `option` unless `path` can be created or overwritten: its
/// directory exists and is writable, and it is not itself a directory. Creates nothing.
inline void check_output_path(const std::string& path, const char* option) {
  namespace fs = std::filesystem;
  const std::string what = std::string(option) + " " + path + ": ";
  if (path.empty()) throw Failure{kBadInput, what + "empty file name"};
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Failure{kBadInput, what + "is a directory"};
  fs::path dir = fs::path(path).parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec)) throw Failure{kBadInput, what + "no such directory " + dir.string()};
  if (::access(dir.c_str(), W_OK) != 0) throw Failure{kBadInput, what + "cannot write in " + dir.string()};
  if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0) throw Failure{kBadInput, what + "not writable"};
}

/// check_output_path for a preview picture, which must be named *.svg.
inline void check_preview_path(const std::string& path) {
  if (!path.ends_with(".svg"))
    throw Failure{kBadInput, "--preview " + path + ": the preview is an SVG picture (name it *.svg)"};
  check_output_path(path, "--preview");
}

/// Throws Failure (bad input) when two of `files` - (option, path) pairs, the input model among
/// them - name the same file: `-o x.off --report x.off` wrote the mesh and then the JSON report
/// over it, and `-o model.off` on model.off replaced the input. The message starts with the
/// option that comes first in `files` (main lists --report first, so that a refused report is
/// not written). Paths are compared after resolving symbolic links and "..", where they exist,
/// and existing files by identity (hard links).
inline void check_distinct_files(const std::vector<std::pair<std::string, std::string>>& files) {
  namespace fs = std::filesystem;
  const auto resolved = [](const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(path, ec);
    return ec ? fs::absolute(path, ec).lexically_normal() : p;
  };
  for (std::size_t i = 0; i < files.size(); ++i)
    for (std::size_t j = i + 1; j < files.size(); ++j)
      if (std::error_code ec; resolved(files[i].second) == resolved(files[j].second) ||
                              fs::equivalent(files[i].second, files[j].second, ec))  // hard links too
        throw Failure{kBadInput, files[i].first + " " + files[i].second + ": the same file as " + files[j].first + " " +
                                     files[j].second + "; give each a name of its own"};
}

}  // namespace delpsc::app
